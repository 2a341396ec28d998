/**
 * `npm run bench`, methods: the cost per step of every integration method
 * beside RK 3/8's, on the same model in the same run (the paper's default
 * model and Kepler, expression route), with each one's error at t = 10
 * against the hand-written RK 3/8 loop at dt/8 and its relative energy
 * error at t = 10 (Kepler only: the default model is driven, so H is not
 * conserved). The adaptive method's "step" is one interval dt between
 * samples; its own steps are counted beside it.
 */
import { canonicalEquations, type HamiltonianSpec } from '../core/model/canonical-equations.ts';
import type { AdaptiveStats } from '../core/integrators/dormand-prince.ts';
import { METHOD_NAMES, methodChoice, type MethodName } from '../core/integrators/methods.ts';
import type { MidpointStats } from '../core/integrators/midpoint.ts';
import type { Model } from '../core/types.ts';
import * as hand from './hand-written.ts';

const DT = 5e-4;
const T_END = 10;
const REPEATS = Number(process.env.BENCH_REPEATS ?? 5);

interface Case {
  name: string;
  spec: HamiltonianSpec;
  initial: number[];
  hand: (x: Float64Array, dt: number, steps: number) => void;
  conserved: boolean;
}

const CASES: Case[] = [
  {
    name: 'default model (eq. 7), 1 DOF',
    spec: {
      dof: 1,
      hamiltonian: 'p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t + beta)',
      params: { u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 10, f: 20 },
    },
    initial: [2, 0],
    hand: hand.defaultModel,
    conserved: false,
  },
  {
    name: 'Kepler (7.1), 4 DOF',
    spec: { dof: 4, hamiltonian: 'p0^2 + p1^2 + p2^2 + p3^2 - 500/sqrt((q0-q2)^2 + (q1-q3)^2)' },
    initial: [-3, -3, 3, 3, 2, -3, -2, 3],
    hand: hand.kepler,
    conserved: true,
  },
];

/** Steps per timed run: the implicit and adaptive methods are slower per step. */
const TIMED_STEPS: Record<MethodName, number> = { rk38: 2_000_000, verlet: 2_000_000, yoshida4: 2_000_000, midpoint: 100_000, adaptive: 400_000 };

function median(run: () => void, steps: number): number {
  run();
  const times: number[] = [];
  for (let r = 0; r < REPEATS; r++) {
    const start = performance.now();
    run();
    times.push(((performance.now() - start) * 1e6) / steps);
  }
  times.sort((a, b) => a - b);
  return times[Math.floor(times.length / 2)];
}

const fmt = (ns: number) => (ns >= 1000 ? `${(ns / 1000).toFixed(2)} µs` : `${ns.toFixed(1)} ns`);

function advance(model: Model, initial: number[], steps: number): Float64Array {
  const x = Float64Array.from(initial);
  model.stepper.advance(x, 1, model.params, 0, 0, DT, steps);
  return x;
}

async function main(): Promise<void> {
  console.log(`\n## Integration methods: cost per step beside RK 3/8 (dt = ${DT}, median of ${REPEATS} runs after a warm-up)\n`);
  const steps = Math.round(T_END / DT);
  for (const c of CASES) {
    const reference = Float64Array.from(c.initial);
    c.hand(reference, DT / 8, steps * 8);
    console.log(`### ${c.name}\n`);
    console.log(`| method | time/step | × RK 3/8 | work per step | max error at t = ${T_END} | ${c.conserved ? `relative energy error at t = ${T_END}` : 'energy error (driven: H not conserved)'} |`);
    console.log('|---|---|---|---|---|---|');
    let rk38Ns = NaN;
    for (const name of METHOD_NAMES) {
      const model = await canonicalEquations({ ...c.spec, method: methodChoice(name) });
      const n = TIMED_STEPS[name];
      const ns = median(() => advance(model, c.initial, n), n);
      if (name === 'rk38') rk38Ns = ns;
      // The accuracy run, with fresh counters for the work it takes.
      const counted = await canonicalEquations({ ...c.spec, method: methodChoice(name) });
      const end = advance(counted, c.initial, steps);
      let error = 0;
      for (let i = 0; i < end.length; i++) error = Math.max(error, Math.abs(end[i] - reference[i]));
      const h = counted.hamiltonian!;
      const h0 = h(0, Float64Array.from(c.initial));
      const energy = c.conserved ? (Math.abs(h(T_END, end) - h0) / Math.abs(h0)).toExponential(1) : '—';
      console.log(`| ${name} | ${fmt(ns)} | ${(ns / rk38Ns).toFixed(2)} | ${work(name, counted, steps)} | ${error.toExponential(1)} | ${energy} |`);
    }
    console.log('');
  }
}

/** What one step costs in evaluations, from the method's definition or its counters. */
function work(name: MethodName, model: Model, steps: number): string {
  if (name === 'rk38') return '4 field evaluations';
  if (name === 'verlet') return '1 ∂V/∂q + 1 ∂T/∂p (force carried over)';
  if (name === 'yoshida4') return '3 ∂V/∂q + 3 ∂T/∂p (force carried over)';
  if (name === 'midpoint') {
    const stats = (model.stepper as unknown as { stats: MidpointStats }).stats;
    return `${(stats.iterations / stats.steps).toFixed(2)} Newton iterations (field + Jacobian + solve each)`;
  }
  const stats = (model.stepper as unknown as { stats: AdaptiveStats }).stats;
  return `${(stats.evaluations / steps).toFixed(2)} field evaluations; ${(stats.accepted / steps).toFixed(3)} own steps (${stats.rejected} rejected in all), rtol 1e-9`;
}

await main();
