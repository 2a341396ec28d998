/**
 * What a simulator does frame by frame, counted rather than timed, so that
 * what the tests assert holds on a machine however busy: a busy machine
 * stretches every task and thins the frames, but does not change how many
 * steps a frame integrates within its budget, where they are integrated, or
 * whether the page runs a timer between two frames.
 */

/**
 * Watches the simulator `selector` for its next `count` drawn frames
 * (widgets/simulator/driver.ts emits 'frame' after each): for each, the steps
 * it integrated (`stats.steps`) and where the integration ran then
 * ('worker' or 'page'); the steps the page integrated itself
 * (Simulation.run, which the worker's samples never go through), the
 * simulated time gained, and, for the record only, the longest main-thread
 * task seen (PerformanceObserver 'longtask') and the frames per second;
 * and the simulator's speed and dt.
 * With `probeTimers`, it also posts a zero timeout after each one runs, and
 * reports for each how many steps the page integrated between posting it and
 * running it: how long a reader's click would wait, in steps of H.
 * Gives up after `limitMs` (a guard against a hang, not a measure) and says
 * how many frames came.
 * @param {import('playwright-core').Page} page
 * @param {string} selector
 * @param {number} count
 * @param {{ probeTimers?: boolean, limitMs?: number }} [options]
 */
export function watchFrames(page, selector, count, { probeTimers = false, limitMs = 120_000 } = {}) {
  return page.evaluate(
    ([selector, count, probeTimers, limitMs]) =>
      new Promise((done) => {
        const handle = document.querySelector(selector).simulator;
        const simulation = handle.simulation;
        const run = simulation.run;
        let pageSteps = 0;
        simulation.run = function (steps) {
          const taken = run.call(this, steps);
          pageSteps += taken;
          return taken;
        };
        let longest = 0;
        const observer = new PerformanceObserver((list) => {
          for (const entry of list.getEntries()) longest = Math.max(longest, entry.duration);
        });
        observer.observe({ type: 'longtask' });
        const frames = [];
        const timers = [];
        let probing = probeTimers;
        const probe = () => {
          const asked = pageSteps;
          setTimeout(() => {
            timers.push(pageSteps - asked);
            if (probing) probe();
          }, 0);
        };
        if (probing) probe();
        const t0 = simulation.t;
        const started = performance.now();
        const finish = (complete) => {
          off();
          clearTimeout(limit);
          probing = false;
          observer.disconnect();
          delete simulation.run;
          const seconds = (performance.now() - started) / 1000;
          done({ complete, frames, pageSteps, timers, gained: simulation.t - t0, speed: handle.driver.speed, dt: simulation.dt, longest, fps: frames.length / seconds });
        };
        const off = handle.driver.on('frame', (stats) => {
          frames.push({ steps: stats.steps, integrator: handle.driver.integrator });
          if (frames.length >= count) finish(true);
        });
        const limit = setTimeout(() => finish(false), limitMs);
      }),
    [selector, count, probeTimers, limitMs],
  );
}

/**
 * The most steps a frame may integrate: what real time owes it for at most
 * maxElapsedMs (100 ms, widgets/simulator/frame-budget.ts), at the watched
 * simulator's speed and dt, plus a step carried over; twice that where the
 * worker integrates, whose frames may keep what one starved frame was owed.
 * A frame that took more had integrated a backlog: the page would freeze
 * for it.
 * @param {{ speed: number, dt: number }} seen what watchFrames returned
 */
export function mostStepsInAFrame({ speed, dt }, { worker = false } = {}) {
  const owed = (speed * 0.1) / dt;
  return (worker ? 2 : 1) * owed + 1;
}
