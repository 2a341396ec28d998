/**
 * `npm run bench`: steps per second of the core's routes beside a plain
 * implementation of the paper's algorithm and hand-written analytic loops,
 * all measured in this one run so that the ratios compare like with like.
 * Accuracy: the largest error of the final state against the hand-written
 * loop run at dt/8 (4096× smaller truncation error).
 */
import { canonicalEquations, type HamiltonianSpec } from '../core/model/canonical-equations.ts';
import type { Model } from '../core/types.ts';
import * as hand from './hand-written.ts';
import { canonicalEquation, plainRk38, type PlainHamiltonian } from './paper-reference.ts';

const DT = 5e-4;
const REPEATS = Number(process.env.BENCH_REPEATS ?? 5);

interface Case {
  name: string;
  dof: number;
  count: number;
  initial: number[];
  expression: string;
  jsFunction: string;
  params: Record<string, number>;
  plain: PlainHamiltonian;
  hand: (x: Float64Array, dt: number, steps: number) => void;
  /** steps per timed run (per trajectory) for fast and for slow implementations */
  steps: number;
  plainSteps: number;
  /** span of the accuracy run */
  tEnd: number;
}

const DEFAULT_PARAMS = { u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 10, f: 20 };
const beamStart = Array.from({ length: 30 }, (_, i) => [-20, (i - 15) * 0.3, 4, 0]).flat();

const CASES: Case[] = [
  {
    name: 'default model (eq. 7), 1 DOF',
    dof: 1,
    count: 1,
    initial: [2, 0],
    expression: 'p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t + beta)',
    jsFunction: '(t, qp) => { let [q, p] = qp; return p**2/2 + omega**2*(1 + u*cos(gamma*t))*q**2/2 - f*q*cos(kappa*t + beta); }',
    params: DEFAULT_PARAMS,
    plain: (t, [q, p]) => {
      const { u, gamma, beta, kappa, omega, f } = DEFAULT_PARAMS;
      return p ** 2 / 2 + (omega ** 2 * (1 + u * Math.cos(gamma * t)) * q ** 2) / 2 - f * q * Math.cos(kappa * t + beta);
    },
    hand: hand.defaultModel,
    steps: 2_000_000,
    plainSteps: 200_000,
    tEnd: 10,
  },
  {
    name: 'Kepler (7.1), 4 DOF',
    dof: 4,
    count: 1,
    initial: [-3, -3, 3, 3, 2, -3, -2, 3],
    expression: 'p0^2 + p1^2 + p2^2 + p3^2 - 500/sqrt((q0-q2)^2 + (q1-q3)^2)',
    jsFunction: '(t, qp) => { let [x1, y1, x2, y2, px1, py1, px2, py2] = qp; return px1**2 + py1**2 + px2**2 + py2**2 - 500 / hypot(x1-x2, y1-y2); }',
    params: {},
    plain: (t, [x1, y1, x2, y2, px1, py1, px2, py2]) => px1 ** 2 + py1 ** 2 + px2 ** 2 + py2 ** 2 - 500 / Math.hypot(x1 - x2, y1 - y2),
    hand: hand.kepler,
    steps: 2_000_000,
    plainSteps: 100_000,
    tEnd: 10,
  },
  {
    name: 'beam of 30 particles (7.3), 2 DOF each',
    dof: 2,
    count: 30,
    initial: beamStart,
    expression: 'p0^2 + p1^2 + 30/sqrt(q0^2 + q1^2)',
    jsFunction: '(t, qp) => { let [x, y, px, py] = qp; return px**2 + py**2 + 30/hypot(x, y); }',
    params: {},
    plain: (t, [x, y, px, py]) => px ** 2 + py ** 2 + 30 / Math.hypot(x, y),
    hand: (x, dt, steps) => hand.beam(x, 30, dt, steps),
    steps: 100_000,
    plainSteps: 5_000,
    tEnd: 10,
  },
];

/** Median and best time per step (per trajectory), in ns. */
function time(run: () => void, stepsPerRun: number): { median: number; best: number } {
  run(); // warm-up: the JIT compiles the hot loop
  const times: number[] = [];
  for (let r = 0; r < REPEATS; r++) {
    const start = performance.now();
    run();
    times.push(((performance.now() - start) * 1e6) / stepsPerRun);
  }
  times.sort((a, b) => a - b);
  return { median: times[Math.floor(times.length / 2)], best: times[0] };
}

function maxError(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  return worst;
}

function runModel(model: Model, c: Case, steps: number, dt = DT): Float64Array {
  const x = Float64Array.from(c.initial);
  model.stepper.advance(x, c.count, model.params, 0, 0, dt, steps);
  return x;
}

function runPlain(c: Case, steps: number): number[] {
  const f = canonicalEquation(c.dof, c.plain);
  const out: number[] = [];
  const n = 2 * c.dof;
  for (let m = 0; m < c.count; m++) out.push(...plainRk38(f, c.initial.slice(m * n, m * n + n), DT, steps));
  return out;
}

const fmt = (ns: number) => (ns >= 1000 ? `${(ns / 1000).toFixed(2)} µs` : `${ns.toFixed(0)} ns`);
const rate = (ns: number) => `${(1e3 / ns).toFixed(2)} M/s`;

async function main(): Promise<void> {
  console.log(`Node ${process.version}, dt = ${DT}, ${REPEATS} timed runs after a warm-up; time per step per trajectory (median / best)\n`);
  const summary: string[] = [];
  for (const c of CASES) {
    const spec = (hamiltonian: string, extra: Partial<HamiltonianSpec> = {}): HamiltonianSpec => ({ dof: c.dof, hamiltonian, params: c.params, ...extra });
    const expression = await canonicalEquations(spec(c.expression));
    const jsFunction = await canonicalEquations(spec(c.jsFunction));
    const stencil = await canonicalEquations(spec(c.jsFunction, { differentiation: 'stencil' }));

    const accuracySteps = Math.round(c.tEnd / DT);
    const reference = Float64Array.from(c.initial);
    if (c.count === 1) c.hand(reference, DT / 8, accuracySteps * 8);
    else hand.beam(reference, c.count, DT / 8, accuracySteps * 8);

    const handState = Float64Array.from(c.initial);
    c.hand(handState, DT, accuracySteps);
    const rows: [string, { median: number; best: number }, number][] = [
      ['hand-written analytic loop', time(() => c.hand(Float64Array.from(c.initial), DT, c.steps), c.steps * c.count), maxError(handState, reference)],
      [`expression route (${expression.route})`, time(() => runModel(expression, c, c.steps), c.steps * c.count), maxError(runModel(expression, c, accuracySteps), reference)],
      [`JS-function route (${jsFunction.route})`, time(() => runModel(jsFunction, c, c.steps), c.steps * c.count), maxError(runModel(jsFunction, c, accuracySteps), reference)],
      [`JS-function, forced differences (${stencil.route})`, time(() => runModel(stencil, c, c.steps / 10), (c.steps / 10) * c.count), maxError(runModel(stencil, c, accuracySteps), reference)],
      ['plain paper implementation (2-point, h = 1e-6)', time(() => runPlain(c, c.plainSteps), c.plainSteps * c.count), maxError(runPlain(c, accuracySteps), reference)],
    ];
    const handNs = rows[0][1].median;
    const plainNs = rows[4][1].median;
    console.log(`### ${c.name} — error after t = ${c.tEnd}\n`);
    console.log('| implementation | time/step (median / best) | steps/s | × hand-written | speed-up over plain | max error |');
    console.log('|---|---|---|---|---|---|');
    for (const [name, t, error] of rows) {
      console.log(`| ${name} | ${fmt(t.median)} / ${fmt(t.best)} | ${rate(t.median)} | ${(t.median / handNs).toFixed(2)} | ${(plainNs / t.median).toFixed(1)}× | ${error.toExponential(1)} |`);
    }
    console.log('');
    summary.push(
      `${c.name}: expression ${(rows[1][1].median / handNs).toFixed(2)}× hand-written (target ≤ 1.5); ` +
        `JS function ${(plainNs / rows[2][1].median).toFixed(1)}× faster than plain, error ${rows[2][2].toExponential(1)} vs ${rows[4][2].toExponential(1)}`,
    );
  }
  console.log(summary.join('\n'));
}

await main();
