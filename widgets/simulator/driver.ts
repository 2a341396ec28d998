import { MAX_SPEED, outside, type Simulation } from '../../core/index.ts';
import { carryOver, DEFAULT_BUDGET, integrateFrame, owedSteps, type Budget } from './frame-budget.ts';
import type { View } from '../plots/view.ts';
import { PaceMeter } from './pace.ts';
import { printSteps } from './print-frame.ts';
import type { WorkerIntegrator } from './worker-integrator.ts';

/** Measurements of the last frames, for readouts and tests. */
export interface FrameStats {
  /** integration time of the last frame, ms */
  integrateMs: number;
  /** drawing time of the last frame (all views), ms */
  drawMs: number;
  /** steps integrated in the last frame */
  steps: number;
  /** smoothed steps per real second actually achieved while playing */
  stepsPerSecond: number;
  /**
   * achieved / requested steps over the last frames, once a run has warmed up (pace.ts); below 1 when the model
   * cannot keep up with real time; null until judged
   */
  pace: number | null;
  frames: number;
}

export interface DriverEvents {
  /** after each drawn frame */
  frame: FrameStats;
  /** play, pause or a blow-up */
  state: { playing: boolean; error: Error | null };
  /** restart, or a new simulation (new dt) */
  reset: Simulation;
  dispose: undefined;
}

export interface DriverOptions {
  /** simulated time per real second (default 1: 2000 steps/s at dt = 5e-4) */
  speed?: number;
  budget?: Budget;
  /** when given, computing stops while it is detached from the page */
  element?: HTMLElement;
  /** how long the element may stay detached before the driver disposes itself (default 60 s) */
  detachedLimitMs?: number;
  /** integrate a model of generated code in a worker once it has loaded (default true); false keeps it on the page */
  worker?: boolean;
}

const clock = (): number => performance.now();

/** See Driver.offloadMs. */
const OFFLOAD_MS = DEFAULT_BUDGET.frameMs / 6;
/** Frames in a row over offloadMs that start the worker: a sixth of a second at 60 Hz, longer than one preempted chunk keeps the smoothed cost up. */
const COSTLY_FRAMES = 10;

/**
 * Runs a simulation in real time on requestAnimationFrame: each frame
 * integrates the steps real time asks for within a time budget (see
 * frame-budget.ts), then asks every view to draw what is new. It computes
 * nothing while paused, while the tab is hidden, while its element is off
 * the page or scrolled out of view (so a page whose widgets are out of
 * sight goes idle; they resume, where they were, when scrolled back), and
 * pauses with the error on a blow-up.
 *
 * A model of generated code (an expression H, portable-model.ts) moves to
 * a worker (worker-integrator.ts) once its integration would cost the page
 * more than `offloadMs` a frame, the page integrating until the worker has loaded
 * and passed it: frames then only append the samples it computed ahead, so
 * the model's cost falls on no frame. A cheap model (the book's oscillators
 * at speed 1 cost microseconds a frame) stays on the page: a worker would
 * cost it a thread and a download for nothing. An opaque JS function, or a
 * page where no worker can run, integrates here within the frame budget.
 */
export class Driver {
  playing = false;
  speed: number;
  readonly stats: FrameStats = { integrateMs: 0, drawMs: 0, steps: 0, stepsPerSecond: 0, pace: null, frames: 0 };
  /**
   * Integration time on the page that a 60 Hz frame asks for at this speed, ms, above which the worker takes
   * over: a sixth of the frame budget. Below zero it takes over at once, whatever the model costs.
   */
  offloadMs = OFFLOAD_MS;
  private raf = 0;
  private last = NaN;
  private carry = 0;
  private cost = NaN;
  private disposed = false;
  private wasConnected = false;
  private readonly budget: Budget;
  private readonly listeners = new Map<keyof DriverEvents, Set<(value: never) => void>>();
  private readonly onVisibility = (): void => this.visibilityChanged();
  private readonly onPrint = (): void => this.printFrame();
  /** False while the element is scrolled out of view (see the class comment). */
  private inView = true;
  private readonly viewObserver: IntersectionObserver | null;
  /** The worker that integrates for this driver: undefined until a frame costs more than offloadMs, null when there is none. */
  private offload: WorkerIntegrator | null | undefined;
  /** True while the worker's module is on its way. */
  private offloading = false;
  /** Frames in a row whose share of real time would cost the page more than offloadMs. */
  private costlyFrames = 0;
  private readonly paceMeter = new PaceMeter();

  constructor(
    public simulation: Simulation,
    readonly views: readonly View[],
    private readonly options: DriverOptions = {},
  ) {
    this.speed = checkSpeed(options.speed ?? 1);
    this.budget = options.budget ?? DEFAULT_BUDGET;
    views.forEach((v) => v.setPlaying?.(false));
    document.addEventListener('visibilitychange', this.onVisibility);
    // A Node test or a worker has no window to print.
    globalThis.addEventListener?.('beforeprint', this.onPrint);
    const element = options.element;
    this.viewObserver =
      element && typeof IntersectionObserver !== 'undefined'
        ? // The last entry is the present: a busy page may deliver several at once (out of view, then back in).
          new IntersectionObserver((entries) => this.viewChanged(entries[entries.length - 1].isIntersecting), { rootMargin: '20% 0px' })
        : null;
    if (element) this.viewObserver?.observe(element);
  }

  /** Subscribes to an event; returns the unsubscribe. */
  on<K extends keyof DriverEvents>(type: K, listener: (value: DriverEvents[K]) => void): () => void {
    if (!this.listeners.has(type)) this.listeners.set(type, new Set());
    const set = this.listeners.get(type)!;
    set.add(listener as (value: never) => void);
    return () => set.delete(listener as (value: never) => void);
  }

  private emit<K extends keyof DriverEvents>(type: K, value: DriverEvents[K]): void {
    for (const listener of this.listeners.get(type) ?? []) (listener as (v: DriverEvents[K]) => void)(value);
  }

  get error(): Error | null {
    return this.simulation.error;
  }

  /** Where the integration runs now: in the simulation worker, or on the page (also while the worker starts). */
  get integrator(): 'worker' | 'page' {
    return this.offload?.serving ? 'worker' : 'page';
  }

  play(): void {
    if (this.disposed || this.playing || this.simulation.error) return;
    this.playing = true;
    this.last = NaN;
    this.carry = 0;
    this.views.forEach((v) => v.setPlaying?.(true));
    this.emit('state', { playing: true, error: null });
    this.schedule();
  }

  pause(): void {
    if (!this.playing) return;
    this.playing = false;
    this.views.forEach((v) => v.setPlaying?.(false));
    this.emit('state', { playing: false, error: this.simulation.error });
  }

  toggle(): void {
    if (this.playing) this.pause();
    else this.play();
  }

  /** Pauses and advances by one sample (every · dt). */
  step(): void {
    this.pause();
    if (this.disposed || this.simulation.error) return;
    if (this.offload?.live) this.offload.step(this.simulation, this.simulation.every);
    else this.simulation.run(this.simulation.every);
    this.drawNow();
  }

  /** Back to the initial state; keeps playing if it was. */
  restart(): void {
    this.simulation.restart();
    this.afterReset();
  }

  /** Swaps in a new simulation (a new dt) and resets the views. */
  replace(simulation: Simulation): void {
    this.simulation = simulation;
    this.afterReset();
  }

  setSpeed(speed: number): void {
    this.speed = checkSpeed(speed);
    this.carry = 0;
    this.paceMeter.reset();
  }

  /** Requested steps per real second at the current speed. */
  get targetRate(): number {
    return this.speed / this.simulation.dt;
  }

  /** Draws at the next frame even when paused (after a resize, or at start). */
  requestDraw(): void {
    this.schedule();
  }

  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.playing = false;
    if (this.raf) cancelAnimationFrame(this.raf);
    this.offload?.dispose();
    document.removeEventListener('visibilitychange', this.onVisibility);
    globalThis.removeEventListener?.('beforeprint', this.onPrint);
    this.viewObserver?.disconnect();
    this.views.forEach((v) => v.dispose());
    this.emit('dispose', undefined);
    this.listeners.clear();
  }

  /**
   * Draws, now, a frame worth printing (print-frame.ts): the page prints right after `beforeprint`, with no
   * animation frame between. Integrates on the page up to the printed span unless the worker holds the state,
   * which has then been running and is drawn as it is.
   */
  printFrame(): void {
    if (this.disposed) return;
    const sim = this.simulation;
    if (!this.offload?.live && !sim.error) sim.run(printSteps(sim));
    this.drawNow();
    if (sim.error) this.pause();
  }

  private afterReset(): void {
    this.carry = 0;
    this.last = NaN;
    // A new generation: nothing the worker computed for the old state reaches the record.
    if (this.offload?.live) this.offload.sync(this.simulation);
    this.views.forEach((v) => v.reset(this.simulation));
    this.emit('reset', this.simulation);
    this.emit('state', { playing: this.playing, error: null });
    this.drawNow();
    if (this.playing) this.schedule();
  }

  /** Starts the worker, whose module loads only now: a page whose models are all cheap never fetches it. */
  private startWorker(): void {
    if (this.offload !== undefined || this.offloading || this.options.worker === false) return;
    this.offloading = true;
    import('./worker-integrator.ts').then(
      ({ WorkerIntegrator }) => {
        this.offloading = false;
        if (this.disposed) return;
        this.offload = WorkerIntegrator.start(
          this.simulation,
          () => {
            if (this.disposed) return;
            // The page integrated until now; the worker goes on from exactly here.
            this.offload?.sync(this.simulation);
            this.carry = 0;
          },
          () => {
            // The page takes over from the simulation's present state, which is always consistent.
            this.offload = null;
            this.carry = 0;
          },
        );
      },
      () => {
        // Offline after the page loaded, say: the page goes on integrating.
        this.offloading = false;
        this.offload = null;
      },
    );
  }

  private schedule(): void {
    if (this.disposed || this.raf || document.visibilityState === 'hidden') return;
    this.raf = requestAnimationFrame((now) => this.frame(now));
  }

  private viewChanged(inView: boolean): void {
    if (inView === this.inView) return;
    this.inView = inView;
    if (inView && this.playing) {
      // Resume where it was: the time out of view is not owed.
      this.last = NaN;
      this.schedule();
    }
  }

  private visibilityChanged(): void {
    if (document.visibilityState === 'hidden') {
      if (this.raf) cancelAnimationFrame(this.raf);
      this.raf = 0;
    } else if (this.playing) {
      this.last = NaN;
      this.schedule();
    }
  }

  /** True while the element (if any) is on the page, or has not been put there yet. */
  private attached(): boolean {
    const element = this.options.element;
    if (!element) return true;
    if (element.isConnected) this.wasConnected = true;
    return element.isConnected || !this.wasConnected;
  }

  private frame(now: number): void {
    this.raf = 0;
    if (this.disposed) return;
    // A run starts afresh (play, a restart, back in view or on the page): its pace is judged anew.
    if (Number.isNaN(this.last)) this.paceMeter.reset();
    const elapsed = Number.isNaN(this.last) ? 1000 / 60 : now - this.last;
    this.last = now;
    let steps = 0;
    let integrateMs = 0;
    if (this.playing && this.attached()) {
      const sim = this.simulation;
      const owed = owedSteps(this.carry, elapsed, this.speed, sim.dt, this.budget);
      const offload = this.offload;
      if (offload?.live && !offload.handingOver(sim)) {
        const work = offload.advance(sim, owed, clock, this.budget);
        // Waiting on the worker (a slow model): what is owed is kept, up to one long frame's worth.
        const most = owedSteps(0, this.budget.maxElapsedMs, this.speed, sim.dt, this.budget);
        this.carry = work.starved ? Math.min(owed - work.steps, most) : carryOver(owed, work.steps, work.outOfBudget);
        offload.request(sim, this.targetRate);
        steps = work.steps;
        integrateMs = work.ms;
      } else {
        const work = integrateFrame((n) => sim.run(n), owed, this.cost, clock, this.budget);
        this.cost = work.costMs;
        this.carry = carryOver(owed, work.steps, work.outOfBudget);
        steps = work.steps;
        integrateMs = work.ms;
        // Until the worker has passed the page (handingOver), it is asked ahead of where the page is.
        offload?.request(sim, this.targetRate);
        // What real time asks of a 60 Hz frame, from the smoothed cost of a step: one slow frame (a cold JIT, a
        // collection, a busy machine) is no reason to start a worker; a model that is costly frame after frame is.
        const demandMs = (this.cost * this.targetRate) / 60;
        this.costlyFrames = demandMs > this.offloadMs ? this.costlyFrames + 1 : 0;
        if (this.costlyFrames >= COSTLY_FRAMES) this.startWorker();
      }
      const counted = Math.max(1, Math.min(elapsed, this.budget.maxElapsedMs));
      const rate = (steps * 1000) / counted;
      const s = this.stats;
      s.stepsPerSecond = s.frames === 0 ? rate : 0.9 * s.stepsPerSecond + 0.1 * rate;
      this.paceMeter.frame(now, (this.targetRate * counted) / 1000, steps);
      s.pace = this.paceMeter.pace;
    }
    this.drawNow(steps, integrateMs);
    if (this.simulation.error) this.pause();
    if (this.playing) {
      if (!this.attached()) this.waitForAttach();
      else if (this.inView) this.schedule();
    }
  }

  private drawNow(steps = 0, integrateMs = 0): void {
    const start = clock();
    for (const view of this.views) view.draw(this.simulation);
    const s = this.stats;
    s.drawMs = clock() - start;
    s.integrateMs = integrateMs;
    s.steps = steps;
    s.frames++;
    this.emit('frame', s);
  }

  /**
   * While detached, checks once a second whether the element came back; after
   * `detachedLimitMs` off the page it gives up and disposes, releasing the record.
   */
  private waitForAttach(): void {
    const since = clock();
    const limit = this.options.detachedLimitMs ?? 60_000;
    const poll = (): void => {
      if (this.disposed || !this.playing) return;
      if (this.attached()) {
        this.last = NaN;
        this.schedule();
      } else if (clock() - since > limit) this.dispose();
      else setTimeout(poll, 1000);
    };
    setTimeout(poll, 1000);
  }
}

function checkSpeed(speed: number): number {
  if (!(speed > 0) || !Number.isFinite(speed)) throw new Error(`speed must be a positive number of time units per second, not ${speed}`);
  const bound = outside('speed', speed, 0, MAX_SPEED, ' time units per second');
  if (bound) throw new Error(bound);
  return speed;
}
