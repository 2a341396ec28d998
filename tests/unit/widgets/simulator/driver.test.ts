/**
 * The driver's animation loop in Node, with the page's clocks and observers
 * replaced by ones the test works by hand: frames run when the test says,
 * and the test says when the simulator goes out of view and back.
 */
import { afterEach, beforeAll, beforeEach, describe, expect, it, vi } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { Simulation } from '../../../../core/simulation.ts';
import { Driver } from '../../../../widgets/simulator/driver.ts';
import { PRINT_SPAN, PRINT_WORK, printSteps } from '../../../../widgets/simulator/print-frame.ts';

/** requestAnimationFrame by hand: `frames(n)` runs n frames 1/60 s apart. */
function animationFrames() {
  let pending = new Map<number, FrameRequestCallback>();
  let id = 0;
  let now = 1000;
  vi.stubGlobal('requestAnimationFrame', (callback: FrameRequestCallback) => (pending.set(++id, callback), id));
  vi.stubGlobal('cancelAnimationFrame', (handle: number) => pending.delete(handle));
  return {
    get scheduled() {
      return pending.size;
    },
    frames(n: number) {
      for (let i = 0; i < n; i++) {
        now += 1000 / 60;
        const due = pending;
        pending = new Map();
        for (const callback of due.values()) callback(now);
      }
    },
  };
}

/** IntersectionObserver by hand: `deliver(...states)` hands the driver one batch of entries, oldest first. */
function viewObserver() {
  let callback: ((entries: { isIntersecting: boolean }[]) => void) | undefined;
  vi.stubGlobal(
    'IntersectionObserver',
    class {
      constructor(cb: typeof callback) {
        callback = cb;
      }
      observe() {}
      disconnect() {}
    },
  );
  return { deliver: (...states: boolean[]) => callback!(states.map((isIntersecting) => ({ isIntersecting }))) };
}

/** A Worker that only counts how often it is made (the page never hears back, so it goes on integrating). */
function countedWorkers() {
  const made = { count: 0 };
  vi.stubGlobal(
    'Worker',
    class {
      constructor() {
        made.count++;
      }
      postMessage() {}
      terminate() {}
    },
  );
  return made;
}

describe('Driver', () => {
  let model: Awaited<ReturnType<typeof canonicalEquations>>;
  beforeAll(async () => {
    model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2' });
  });
  beforeEach(() => {
    vi.stubGlobal('document', { visibilityState: 'visible', addEventListener() {}, removeEventListener() {} });
  });
  afterEach(() => vi.unstubAllGlobals());

  it('goes on computing when the view reports, in one delivery, that the simulator left and came back', () => {
    const raf = animationFrames();
    const view = viewObserver();
    const simulation = new Simulation(model, { initial: [1, 0], dt: 1e-3 });
    const driver = new Driver(simulation, [], { element: { isConnected: true } as HTMLElement, worker: false });
    driver.play();
    raf.frames(3);
    expect(simulation.t).toBeGreaterThan(0);

    // Out of view: nothing is computed, and no frame is asked for.
    view.deliver(false);
    raf.frames(3);
    const paused = simulation.t;
    expect(raf.scheduled).toBe(0);

    // Back in view, reported together with an older "out": the present is the last entry.
    view.deliver(false, true);
    raf.frames(30);
    // 30 frames of 1/60 s at speed 1 (the first after the pause counts as one frame).
    expect(simulation.t - paused).toBeCloseTo(30 / 60, 2);
    driver.dispose();
  });

  it('keeps a cheap model on the page, and moves one that costs the page more than offloadMs a frame to a worker', async () => {
    const raf = animationFrames();
    viewObserver();
    const workers = countedWorkers();

    // At speed 1, 1000 steps a second: a few microseconds a frame.
    const cheap = new Driver(new Simulation(model, { initial: [1, 0], dt: 1e-3 }), [], { element: { isConnected: true } as HTMLElement });
    cheap.play();
    raf.frames(120);
    await new Promise((resolve) => setTimeout(resolve, 50));
    expect(workers.count).toBe(0);
    expect(cheap.simulation.t).toBeGreaterThan(1.9);
    cheap.dispose();

    // At speed 10⁴, 10⁷ steps a second: far more than a frame can hold on the page.
    const costly = new Driver(new Simulation(model, { initial: [1, 0], dt: 1e-3, capacity: 1000 }), [], {
      element: { isConnected: true } as HTMLElement,
      speed: 1e4,
    });
    costly.play();
    raf.frames(30);
    await vi.waitFor(() => expect(workers.count).toBe(1));
    costly.dispose();
  });

  it('gives no verdict on its pace while it starts, and judges a model that keeps up as keeping up', () => {
    const raf = animationFrames();
    viewObserver();
    const driver = new Driver(new Simulation(model, { initial: [1, 0], dt: 1e-3 }), [], { element: { isConnected: true } as HTMLElement, worker: false });
    expect(driver.stats.pace).toBeNull();
    driver.play();
    raf.frames(60); // the first second: warming up, whatever it achieved
    expect(driver.stats.pace).toBeNull();
    raf.frames(180);
    expect(driver.stats.pace).toBeGreaterThan(0.99);
    // A new speed is a new run: judged anew, after its own warm-up.
    driver.setSpeed(2);
    raf.frames(60);
    expect(driver.stats.pace).toBeNull();
    driver.dispose();
  });

  it('before printing, integrates a paused simulator up to the printed span and draws it: q(t) = cos t of the unit oscillator', () => {
    animationFrames();
    viewObserver();
    const printHandlers: (() => void)[] = [];
    vi.stubGlobal('addEventListener', (type: string, handler: () => void) => type === 'beforeprint' && printHandlers.push(handler));
    vi.stubGlobal('removeEventListener', () => {});
    const drawn: number[] = [];
    const view = { element: {}, reset() {}, draw: (sim: Simulation) => drawn.push(sim.t), dispose() {} };
    const simulation = new Simulation(model, { initial: [1, 0], dt: 1e-3 });
    const driver = new Driver(simulation, [view as never], { element: { isConnected: true } as HTMLElement, worker: false });
    expect(driver.playing).toBe(false);
    printHandlers.forEach((print) => print());
    // The span, at once, with no animation frame: H = (p² + q²)/2 from (1, 0) is q = cos t, p = −sin t (closed form).
    expect(simulation.t).toBeCloseTo(PRINT_SPAN, 9);
    expect(drawn).toEqual([simulation.t]);
    expect(simulation.state[0]).toBeCloseTo(Math.cos(PRINT_SPAN), 9);
    expect(simulation.state[1]).toBeCloseTo(-Math.sin(PRINT_SPAN), 9);
    // A simulator already past the span prints what it has.
    simulation.run(5000);
    const t = simulation.t;
    printHandlers.forEach((print) => print());
    expect(simulation.t).toBe(t);
    driver.dispose();
  });
});

describe('printSteps', () => {
  it('asks for the steps up to t0 + span, none once there, and fewer for a batch than the work allows', () => {
    expect(printSteps({ t: 0, t0: 0, dt: 5e-4, count: 1 })).toBe(PRINT_SPAN / 5e-4);
    expect(printSteps({ t: 4, t0: 2, dt: 0.5, count: 1 }, 10)).toBe(16);
    expect(printSteps({ t: 12, t0: 2, dt: 0.5, count: 1 }, 10)).toBe(0);
    expect(printSteps({ t: 0, t0: 0, dt: 5e-4, count: 10_000 })).toBe(PRINT_WORK / 10_000);
  });
});
