/**
 * The advance policy of a running widget: how many steps each animation
 * frame integrates. Real time sets a target (speed · elapsed / dt steps); a
 * time budget per frame caps it. Integration runs in chunks sized from a
 * running estimate of the cost of a step, so the clock is read every ~1 ms
 * and a slow model falls behind real time instead of freezing the page: when
 * the budget runs out the backlog is forgotten rather than carried forward,
 * so it can never snowball.
 */

export interface Budget {
  /** integration time allowed per frame, ms */
  frameMs: number;
  /** integration time per chunk between clock reads, ms */
  chunkMs: number;
  /** real time counted for one frame at most, ms: a stall or a background tab does not cause a burst */
  maxElapsedMs: number;
}

export const DEFAULT_BUDGET: Budget = { frameMs: 6, chunkMs: 1, maxElapsedMs: 100 };

/** Steps of the first chunk, once a single probe step (see integrateFrame) was too quick to time. */
export const FIRST_CHUNK = 16;

/** Steps owed at the start of a frame: what was carried plus speed · elapsed / dt. */
export function owedSteps(carry: number, elapsedMs: number, speed: number, dt: number, budget: Budget = DEFAULT_BUDGET): number {
  const elapsed = Math.min(Math.max(0, elapsedMs), budget.maxElapsedMs);
  return carry + (speed * elapsed) / 1000 / dt;
}

/** The next chunk: about chunkMs of work (never more than the time left), at least 1 step, at most `left` steps. */
export function chunkSteps(costMs: number, leftSteps: number, leftMs: number, budget: Budget = DEFAULT_BUDGET): number {
  const whole = Math.floor(leftSteps);
  if (whole < 1) return 0;
  if (!(costMs > 0)) return Math.min(whole, FIRST_CHUNK);
  return Math.max(1, Math.min(whole, Math.floor(Math.min(budget.chunkMs, leftMs) / costMs)));
}

/** Smallest time a chunk is taken to have cost, ms: coarse clocks can report 0. */
const CLOCK_FLOOR_MS = 0.005;

/** The running estimate of the cost of one step, ms: an exponential average of chunk measurements. */
export function updateCost(costMs: number, chunkMs: number, steps: number): number {
  if (steps < 1) return costMs;
  const sample = Math.max(chunkMs, CLOCK_FLOOR_MS) / steps;
  return costMs > 0 ? 0.7 * costMs + 0.3 * sample : sample;
}

/** What carries into the next frame: the remainder, or only its fractional part if the budget ran out. */
export function carryOver(owed: number, done: number, outOfBudget: boolean): number {
  const rest = Math.max(0, owed - done);
  return outOfBudget ? rest - Math.floor(rest) : rest;
}

/** What a frame's integration did. */
export interface FrameWork {
  steps: number;
  ms: number;
  outOfBudget: boolean;
  /** the updated cost estimate */
  costMs: number;
}

/**
 * Integrates up to `owed` steps in chunks until done, out of budget, or the
 * simulation stops (a blow-up). `run` advances and returns the steps taken;
 * `clock` is performance.now or a fake one in tests.
 */
export function integrateFrame(
  run: (steps: number) => number,
  owed: number,
  costMs: number,
  clock: () => number,
  budget: Budget = DEFAULT_BUDGET,
): FrameWork {
  const start = clock();
  let steps = 0;
  let now = start;
  let cost = costMs;
  if (!(cost > 0) && owed >= 1) {
    // Before any cost is known, one step is timed before a chunk is committed to: a model whose H is an opaque
    // JavaScript function may take milliseconds per call and tens of calls per step (16 steps of a 5 ms H took 7.5 s).
    const taken = run(1);
    const after = clock();
    if (after - now > CLOCK_FLOOR_MS) cost = (after - now) / Math.max(1, taken);
    now = after;
    steps += taken;
    if (taken < 1) return { steps, ms: now - start, outOfBudget: false, costMs: cost };
  }
  for (let chunks = 0; chunks < 10_000; chunks++) {
    const left = budget.frameMs - (now - start);
    const n = chunkSteps(cost, owed - steps, left);
    if (n === 0) break;
    if (left <= 0 && steps > 0) return { steps, ms: now - start, outOfBudget: true, costMs: cost };
    const taken = run(n);
    const after = clock();
    cost = updateCost(cost, after - now, taken);
    now = after;
    steps += taken;
    if (taken < n) break;
  }
  return { steps, ms: now - start, outOfBudget: false, costMs: cost };
}
