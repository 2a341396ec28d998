/**
 * `npm run bench`, last part: how the cost of building a model from an
 * expression H grows with the degrees of freedom. Two families whose H grows
 * in proportion to dof (bench/chains.ts): uncoupled oscillators and the
 * FPU-β chain. Each build is timed stage by stage:
 *
 * - parse: mathjs parse, names resolved and checked;
 * - derivatives: the 2·dof partial derivatives, tidied;
 * - code: the fused stepper, the evaluators and the LaTeX, as source text;
 * - new Function: the model made from that text (model-from-compiled.ts) and
 *   called once each (one step, one field, one H), since V8 compiles a
 *   function's body only at its first call and that is part of the wait.
 *
 * The growth exponent is the least-squares slope of log(time) against
 * log(dof) over dof ≥ 8, where fixed costs no longer dominate: a polynomial
 * cost gives a constant slope, an exponential one a slope that grows with
 * the range (the build this replaced doubled per degree of freedom).
 */
import { COMPILED_FORMAT, type CompiledModel } from '../core/model/compiled-model.ts';
import { generateCode, hamiltonEquations, parseHamiltonian } from '../core/expression/compile-expression.ts';
import { loadMathjs } from '../core/expression/mathjs.ts';
import { modelFromCompiled } from '../core/model/model-from-compiled.ts';
import { fpuSource, harmonicSource } from './chains.ts';

const DOFS = [1, 2, 4, 8, 16, 32, 64, 100];
/**
 * Builds per point, fewer where one build is slow, to keep the run short.
 * Each stage's best time is reported: the machine's other work only ever
 * adds to a time, and the growth with dof is what is measured.
 */
const MAX_RUNS = 15;
const POINT_BUDGET_MS = 1500;
const FIT_FROM = 8;

const STAGES = ['parse', 'derivatives', 'code', 'new Function'] as const;
type Timing = Record<(typeof STAGES)[number] | 'total', number>;

interface Family {
  name: string;
  source: (dof: number) => string;
  params: Record<string, number>;
}

const FAMILIES: Family[] = [
  { name: 'Σ (p_i² + q_i²)/2', source: harmonicSource, params: {} },
  { name: 'FPU-β chain, fixed ends', source: fpuSource, params: { beta: 0.1 } },
];

async function buildOnce(family: Family, dof: number): Promise<Timing> {
  const math = await loadMathjs();
  const source = family.source(dof);
  const paramNames = Object.keys(family.params);
  const t0 = performance.now();
  const parsed = parseHamiltonian(math, { source, dof, paramNames });
  const t1 = performance.now();
  const equations = await hamiltonEquations(math, parsed);
  const t2 = performance.now();
  const { code, latex } = generateCode(parsed, equations);
  const t3 = performance.now();
  const compiled: CompiledModel = { format: COMPILED_FORMAT, key: '', route: 'expression', dof, names: parsed.names, paramNames, source, code, latex };
  const model = modelFromCompiled(compiled, family.params);
  const x = new Float64Array(2 * dof).fill(0.1);
  model.stepper.advance(x, 1, model.params, 0, 0, 1e-3, 1);
  model.field(0, x, new Float64Array(2 * dof));
  model.hamiltonian!(0, x);
  const t4 = performance.now();
  return { parse: t1 - t0, derivatives: t2 - t1, code: t3 - t2, 'new Function': t4 - t3, total: t4 - t0 };
}

async function measure(family: Family, dof: number): Promise<Timing> {
  const runs: Timing[] = [];
  const start = performance.now();
  do runs.push(await buildOnce(family, dof));
  while (runs.length < MAX_RUNS && performance.now() - start < POINT_BUDGET_MS);
  const best = (key: keyof Timing) => Math.min(...runs.map((r) => r[key]));
  return { parse: best('parse'), derivatives: best('derivatives'), code: best('code'), 'new Function': best('new Function'), total: best('total') };
}

/** Least-squares slope of log y against log x. */
function logLogSlope(xs: readonly number[], ys: readonly number[]): number {
  const lx = xs.map(Math.log);
  const ly = ys.map(Math.log);
  const mx = lx.reduce((a, b) => a + b, 0) / lx.length;
  const my = ly.reduce((a, b) => a + b, 0) / ly.length;
  let sxy = 0;
  let sxx = 0;
  for (let i = 0; i < lx.length; i++) {
    sxy += (lx[i] - mx) * (ly[i] - my);
    sxx += (lx[i] - mx) ** 2;
  }
  return sxy / sxx;
}

const ms = (t: number) => (t >= 100 ? t.toFixed(0) : t >= 10 ? t.toFixed(1) : t.toFixed(2));

async function main(): Promise<void> {
  console.log(`\n## Building a model from an expression H, by degrees of freedom (Node ${process.version})\n`);
  console.log(`Best of up to ${MAX_RUNS} builds per row (each stage and the total separately), in ms; slope = d log t / d log dof, least squares over dof ≥ ${FIT_FROM}.\n`);
  // Warm-up: mathjs loaded and its code, and the compiler's, through the JIT once.
  for (const family of FAMILIES) await buildOnce(family, 16);

  for (const family of FAMILIES) {
    const rows: { dof: number; timing: Timing }[] = [];
    for (const dof of DOFS) rows.push({ dof, timing: await measure(family, dof) });
    console.log(`### H = ${family.name}\n`);
    console.log(`| dof | ${STAGES.join(' | ')} | total |`);
    console.log(`|---:|${STAGES.map(() => '---:|').join('')}---:|`);
    for (const { dof, timing } of rows) console.log(`| ${dof} | ${STAGES.map((s) => ms(timing[s])).join(' | ')} | ${ms(timing.total)} |`);
    const fitted = rows.filter((r) => r.dof >= FIT_FROM);
    const slope = (key: keyof Timing) => logLogSlope(fitted.map((r) => r.dof), fitted.map((r) => r.timing[key])).toFixed(2);
    console.log(`| slope | ${STAGES.map((s) => slope(s)).join(' | ')} | **${slope('total')}** |\n`);
  }
}

await main();
