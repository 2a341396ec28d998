/**
 * Building a model from a large expression H: derivatives right, work
 * growing linearly with the degrees of freedom (the build once took time
 * exponential in the terms of H, through mathjs's simplify), and a build
 * that can be watched and cancelled.
 */
import type { MathNode } from 'mathjs';
import { describe, expect, it } from 'vitest';
import { fpuSource, harmonicSource } from '../../../../bench/chains.ts';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { compileModel } from '../../../../core/model/compile-model.ts';
import { generateCode, hamiltonEquations, parseHamiltonian } from '../../../../core/expression/compile-expression.ts';
import { loadMathjs } from '../../../../core/expression/mathjs.ts';
import { Partials } from '../../../../core/expression/partials.ts';

/** An irregular, reproducible sequence in (−1, 1): the fractional parts of i·(golden ratio). */
function irregular(i: number, shift = 0): number {
  const golden = (Math.sqrt(5) - 1) / 2;
  return 2 * (((i + shift) * golden + 0.5) % 1) - 1;
}

/**
 * The FPU-β equations of motion, written from the physics (Fermi, Pasta &
 * Ulam, Los Alamos report LA-1940, 1955; unit masses and springs, fixed
 * ends q_{-1} = q_n = 0):
 *   q̇_i = p_i,
 *   ṗ_i = (q_{i+1} − 2q_i + q_{i−1}) + β[(q_{i+1} − q_i)³ − (q_i − q_{i−1})³].
 * Also the sum of the magnitudes of the force's parts, the scale its
 * rounding error is relative to.
 */
function fpuRates(q: readonly number[], p: readonly number[], beta: number): { rates: number[]; scale: number[] } {
  const n = q.length;
  const at = (i: number) => (i < 0 || i >= n ? 0 : q[i]);
  const rates = [...p];
  const scale = p.map(Math.abs);
  for (let i = 0; i < n; i++) {
    const right = at(i + 1) - q[i];
    const left = q[i] - at(i - 1);
    rates.push(right - left + beta * (right ** 3 - left ** 3));
    scale.push(Math.abs(right) + Math.abs(left) + Math.abs(beta) * (Math.abs(right) ** 3 + Math.abs(left) ** 3));
  }
  for (let i = 0; i < n; i++) scale[i] = Math.max(scale[i], Math.abs(p[i]));
  return { rates, scale };
}

function nodeCount(node: MathNode): number {
  let count = 0;
  node.traverse(() => count++);
  return count;
}

describe('building a model from a large H', () => {
  it('gives the FPU-β chain of 32 masses the equations of motion of the chain, to 1e-12 relative', async () => {
    const dof = 32;
    const beta = 0.7;
    const model = await canonicalEquations({ dof, hamiltonian: fpuSource(dof), params: { beta } });
    const q = Array.from({ length: dof }, (_, i) => 1.5 * irregular(i));
    const p = Array.from({ length: dof }, (_, i) => irregular(i, 100));
    const rate = new Float64Array(2 * dof);
    model.field(0, Float64Array.from([...q, ...p]), rate);
    const truth = fpuRates(q, p, beta);
    for (let i = 0; i < 2 * dof; i++) {
      expect(Math.abs(rate[i] - truth.rates[i])).toBeLessThanOrEqual(1e-12 * truth.scale[i]);
    }
  });

  it('does work linear in dof: derivative trees, tidied rates and generated code double, not more, from dof 25 to 50', async () => {
    const math = await loadMathjs();
    const work = async (dof: number) => {
      const parsed = parseHamiltonian(math, { source: harmonicSource(dof), dof });
      // The derivatives as mathjs returns them, before any clean-up: the work of differentiating.
      const partials = new Partials(math, parsed.hamiltonian, parsed.names);
      const raw = parsed.names.reduce((sum, name) => sum + nodeCount(partials.of(name)), 0);
      const equations = await hamiltonEquations(math, parsed);
      const tidied = equations.rates.reduce((sum, rate) => sum + nodeCount(rate.node), 0);
      const { code } = generateCode(parsed, equations);
      return { raw, tidied, code: code.stepper.length + code.field.length + code.hamiltonian.length };
    };
    const small = await work(25);
    const large = await work(50);
    for (const key of ['raw', 'tidied', 'code'] as const) {
      expect(large[key] / small[key], key).toBeGreaterThan(1.5);
      expect(large[key] / small[key], key).toBeLessThan(2.5);
    }
    // and the model is right: each oscillator turns at unit frequency.
    const model = await canonicalEquations({ dof: 50, hamiltonian: harmonicSource(50) });
    const x = new Float64Array(100);
    x.fill(1, 0, 50);
    model.stepper.advance(x, 1, model.params, 0, 0, 1e-3, 1000);
    for (let i = 0; i < 50; i++) {
      expect(x[i]).toBeCloseTo(Math.cos(1), 10);
      expect(x[i + 50]).toBeCloseTo(-Math.sin(1), 10);
    }
  });
});

describe('watching and cancelling a build', () => {
  const spec = { dof: 8, hamiltonian: fpuSource(8), params: { beta: 1 } };

  it('reports each derivative and the code, up to the total, and then gives the model', async () => {
    const reports: [number, number][] = [];
    const compiled = await compileModel(spec, { progress: (done, total) => reports.push([done, total]) });
    const total = 2 * spec.dof + 1;
    expect(reports).toEqual(Array.from({ length: total }, (_, i) => [i + 1, total]));
    expect(compiled.route).toBe('expression');
  });

  it('refuses to start with an aborted signal, with an AbortError', async () => {
    const controller = new AbortController();
    controller.abort();
    const reports: number[] = [];
    const error = await compileModel(spec, { signal: controller.signal, progress: (done) => reports.push(done) }).catch((e: unknown) => e);
    expect((error as Error).name).toBe('AbortError');
    expect(reports).toEqual([]);
  });

  it('stops between two derivatives once aborted, through canonicalEquations too', async () => {
    const controller = new AbortController();
    const reports: number[] = [];
    const progress = (done: number) => {
      reports.push(done);
      if (done === 3) controller.abort();
    };
    const error = await canonicalEquations(spec, { signal: controller.signal, progress }).catch((e: unknown) => e);
    expect((error as Error).name).toBe('AbortError');
    expect(reports).toEqual([1, 2, 3]);
  });

  it('lets the event loop run during a long build, so that an abort sent meanwhile arrives', async () => {
    const dof = 400; // some 100 ms of work: several slices
    const controller = new AbortController();
    let last = 0;
    let total = 0;
    const build = compileModel(
      { dof, hamiltonian: harmonicSource(dof) },
      {
        signal: controller.signal,
        progress: (done, all) => {
          last = done;
          total = all;
        },
      },
    );
    setTimeout(() => controller.abort(), 0);
    const error = await build.catch((e: unknown) => e);
    expect((error as Error).name).toBe('AbortError');
    expect(last).toBeGreaterThan(0);
    expect(last).toBeLessThan(total);
  });
});
