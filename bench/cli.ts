/**
 * `npm run bench`, second part: `phasebook simulate` as whole processes,
 * against `node -e 0`, a C program (bench/c/rk38.c, gcc -O2) and the paper's
 * algorithm run as a Node process of its own, all in this one run, each
 * figure the median of BENCH_REPEATS rounds (5 by default) in which every
 * contender runs once in turn.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { cpus, loadavg, tmpdir } from 'node:os';
import { join } from 'node:path';
import { build } from 'esbuild';
import { ensureCli, ROOT } from '../bin/cli-bundle.mjs';
import { runOnce, timeInterleaved, type Command, type Timing } from './process-time.ts';

const REPEATS = Number(process.env.BENCH_REPEATS ?? 5);
/** Start-up runs take a tenth of a second: more rounds cost little and steady the medians. */
const STARTUP_REPEATS = Math.max(11, REPEATS);
const DT = 5e-4;
const C_STEPS = 20_000_000;
const PAPER_STEPS = 1_000_000;

interface Model {
  name: string;
  /** model name in rk38.c */
  c: string;
  dof: number;
  initial: number[];
  params: Record<string, number>;
  expression: string;
  /** H as the paper wrote it: a JS function of t and the state array */
  jsFunction: string;
  /** speed-up over the paper's algorithm that the JS-function route must reach */
  paperTarget: number;
}

const MODELS: Model[] = [
  {
    name: 'default model (eq. 7)',
    c: 'default',
    dof: 1,
    initial: [2, 0],
    params: { u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 10, f: 20 },
    expression: 'p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t + beta)',
    jsFunction: '(t, qp) => { let [q, p] = qp; return p**2/2 + omega**2*(1 + u*cos(gamma*t))*q**2/2 - f*q*cos(kappa*t + beta); }',
    paperTarget: 2,
  },
  {
    name: 'Kepler (7.1)',
    c: 'kepler',
    dof: 4,
    initial: [-3, -3, 3, 3, 2, -3, -2, 3],
    params: {},
    expression: 'p0^2 + p1^2 + p2^2 + p3^2 - 500/sqrt((q0-q2)^2 + (q1-q3)^2)',
    jsFunction:
      '(t, qp) => { let [x1, y1, x2, y2, px1, py1, px2, py2] = qp; return px1**2 + py1**2 + px2**2 + py2**2 - 500 / hypot(x1-x2, y1-y2); }',
    paperTarget: 5,
  },
];

const BIN = join(ROOT, 'bin/phasebook.mjs');
const work = mkdtempSync(join(tmpdir(), 'phasebook-bench-'));
/** A cache of our own, so that "cached" and "uncached" mean what they say whatever the user's cache holds. */
const env = { PHASEBOOK_CACHE_DIR: join(work, 'cache') };

const seconds = (s: number) => (s < 1 ? `${(s * 1000).toFixed(0)} ms` : `${s.toFixed(2)} s`);
const verdict = (met: boolean) => (met ? 'met' : '**missed**');
const outcomes: { label: string; met: boolean }[] = [];
function target(label: string, met: boolean): string {
  outcomes.push({ label, met });
  return verdict(met);
}

/**
 * Targets are for the run a user repeats, with H compiled once and cached; a
 * first run adds the compile (mathjs, and acorn for a JS function), shown
 * beside it but not counted.
 */
const firstRun = (met: boolean) => `first run, ${met ? 'within it too' : '**outside it**'}`;

/** `phasebook simulate` for `model` over `steps` steps, writing a row every 10 000 (output is negligible). */
function simulate(model: Model, hamiltonian: string, steps: number, extra: string[] = []): string[] {
  const params = Object.entries(model.params).flatMap(([name, value]) => ['--param', `${name}=${value}`]);
  const tEnd = String(steps * DT);
  return ['node', BIN, 'simulate', '--hamiltonian', hamiltonian, '--dof', String(model.dof), `--initial=${model.initial.join(',')}`, ...params, '--t-end', tEnd, '--every', '10000', ...extra];
}

/** The state in the last CSV row (without t and H). */
function lastRow(csv: string, dim: number): number[] {
  const lines = csv.trim().split('\n');
  return lines[lines.length - 1].split(',').slice(1, 1 + dim).map(Number);
}

const maxDifference = (a: number[], b: number[]) => Math.max(...a.map((v, i) => Math.abs(v - b[i])));

function startup(): void {
  const tiny = ['simulate', '--hamiltonian', 'p^2/2+q^2/2', '--dof', '1', '--initial', '1,0', '--t-end', '0.01'];
  runOnce({ name: 'cache warm-up', argv: ['node', BIN, ...tiny], env });
  const commands: Command[] = [
    { name: '`node -e 0`', argv: ['node', '-e', '0'] },
    { name: 'phasebook, model cached', argv: ['node', BIN, ...tiny], env },
    { name: 'phasebook --no-cache (compiles H with mathjs)', argv: ['node', BIN, ...tiny, '--no-cache'], env },
    {
      name: 'phasebook --vector-field (no H to compile)',
      argv: ['node', BIN, 'simulate', '--vector-field', '(t, x, dxdt) => { dxdt[0] = x[1]; dxdt[1] = -x[0]; }', '--dof', '1', '--initial', '1,0', '--t-end', '0.01'],
      env,
    },
    {
      // What bin/phasebook.mjs did before: tsx compiles the TypeScript at every start; there was no cache.
      name: 'before: TypeScript compiled by tsx at start, no cache',
      argv: ['node', '--input-type=module', '-e', "import { register } from 'tsx/esm/api'; register(); const { main } = await import('./cli/main.ts'); process.exitCode = await main(process.argv.slice(1));", ...tiny, '--no-cache'],
      cwd: ROOT,
      env,
    },
  ];
  const timings = timeInterleaved(commands, STARTUP_REPEATS);
  const node = timings[0].median;
  console.log(`### Start-up: \`phasebook ${tiny.join(' ')}\` (${STARTUP_REPEATS} rounds)\n`);
  console.log('| process | median | best | × `node -e 0` | target |');
  console.log('|---|---|---|---|---|');
  commands.forEach((command, i) => {
    const ratio = timings[i].median / node;
    const goal = i === 1 ? `≤ 2.5: ${target('cached tiny run ≤ 2.5× node -e 0', ratio <= 2.5)}` : '';
    console.log(`| ${command.name} | ${seconds(timings[i].median)} | ${seconds(timings[i].best)} | ${ratio.toFixed(2)} | ${goal} |`);
  });
  console.log('');
}

/** Compiles rk38.c into the scratch folder; undefined (and a note) when there is no C compiler. */
function compileC(): string | undefined {
  const binary = join(work, 'rk38');
  try {
    execFileSync('gcc', ['-O2', '-o', binary, join(ROOT, 'bench/c/rk38.c'), '-lm'], { stdio: 'pipe' });
    return binary;
  } catch (error) {
    console.log(`(no C comparison: gcc -O2 failed: ${(error as Error).message.split('\n')[0]})\n`);
    return undefined;
  }
}

let correct = true;

function againstC(binary: string): void {
  const steps = C_STEPS;
  console.log(`### Expression route against C (gcc -O2, analytic gradient): ${steps.toExponential(0)} steps of dt = ${DT}, a row every 10 000 steps (${REPEATS} rounds)\n`);
  console.log(
    'Agreement: the CLI and C take the same RK 3/8 steps, so their final states differ by rounding only. ' +
      'E, the RK 3/8 truncation error of C\'s final state (Richardson: 16/15·|x(dt) − x(dt/2)|), is what any change to the ' +
      'discretisation (another rule, a wrong stage time, a step too many) would show; the check asks for a difference below E/4.\n',
  );
  console.log('| model | process | median | best | × C | target | max \\|CLI − C\\| at the end | E/4 |');
  console.log('|---|---|---|---|---|---|---|---|');
  for (const model of MODELS) {
    const dim = 2 * model.dof;
    const cCommand = (n: number, dt: number) => ({ name: 'C', argv: [binary, model.c, String(n), String(dt)] });
    const half = runOnce(cCommand(2 * steps, DT / 2)).stdout.trim().split(' ').map(Number);
    runOnce({ name: 'cache warm-up', argv: simulate(model, model.expression, 1), env });
    const commands: Command[] = [
      cCommand(steps, DT),
      { name: 'phasebook, model cached', argv: simulate(model, model.expression, steps), env },
      { name: 'phasebook --no-cache', argv: simulate(model, model.expression, steps, ['--no-cache']), env },
    ];
    const timings = timeInterleaved(commands, REPEATS);
    const c = timings[0].stdout.trim().split(' ').map(Number);
    const tolerance = ((16 / 15) * maxDifference(c, half)) / 4;
    commands.forEach((command, i) => {
      const ratio = timings[i].median / timings[0].median;
      const goal = i === 0 ? '' : i === 1 ? `≤ 1.3: ${target(`${model.name}, cached: ≤ 1.3× C`, ratio <= 1.3)}` : firstRun(ratio <= 1.3);
      let agreement = '';
      if (i > 0) {
        const difference = maxDifference(lastRow(timings[i].stdout, dim), c);
        if (!(difference <= tolerance)) correct = false;
        agreement = `${difference.toExponential(1)}${difference <= tolerance ? '' : ' **too large**'}`;
      }
      console.log(
        `| ${model.name} | ${command.name} | ${seconds(timings[i].median)} | ${seconds(timings[i].best)} | ${ratio.toFixed(2)} | ${goal} | ${agreement} | ${i === 0 ? '' : tolerance.toExponential(1)} |`,
      );
    });
  }
  console.log('');
}

/** Bundles paper-run.ts (with paper-reference.ts) into a plain .mjs, so that the paper's process starts as fast as ours. */
async function paperScript(): Promise<string> {
  const outfile = join(work, 'paper-run.mjs');
  await build({ entryPoints: [join(ROOT, 'bench/paper-run.ts')], outfile, bundle: true, format: 'esm', platform: 'node', target: 'node20', logLevel: 'silent' });
  return outfile;
}

async function againstPaper(): Promise<void> {
  const script = await paperScript();
  console.log(`### JS-function route against the paper's algorithm (plain arrays, 2-point differences, its own Node process): ${PAPER_STEPS.toExponential(0)} steps (${REPEATS} rounds)\n`);
  console.log('| model | process | median | best | speed-up over the paper | target | max \\|CLI − paper\\| at the end |');
  console.log('|---|---|---|---|---|---|---|');
  for (const model of MODELS) {
    const dim = 2 * model.dof;
    runOnce({ name: 'cache warm-up', argv: simulate(model, model.jsFunction, 1), env });
    const paper: Command = {
      name: 'paper',
      argv: ['node', script, String(model.dof), String(PAPER_STEPS), String(DT), model.initial.join(','), JSON.stringify(model.params), model.jsFunction],
    };
    const commands: Command[] = [
      paper,
      { name: 'phasebook, model cached', argv: simulate(model, model.jsFunction, PAPER_STEPS), env },
      { name: 'phasebook --no-cache (acorn + mathjs)', argv: simulate(model, model.jsFunction, PAPER_STEPS, ['--no-cache']), env },
    ];
    const timings = timeInterleaved(commands, REPEATS);
    const paperState = timings[0].stdout.trim().split(' ').map(Number);
    commands.forEach((command, i) => {
      const speedUp = timings[0].median / timings[i].median;
      const met = speedUp >= model.paperTarget;
      const goal = i === 0 ? '' : i === 1 ? `≥ ${model.paperTarget}: ${target(`${model.name}, cached: ≥ ${model.paperTarget}× the paper`, met)}` : firstRun(met);
      const difference = i === 0 ? '' : maxDifference(lastRow(timings[i].stdout, dim), paperState).toExponential(1);
      console.log(`| ${model.name} | ${command.name} | ${seconds(timings[i].median)} | ${seconds(timings[i].best)} | ${speedUp.toFixed(1)}× | ${goal} | ${difference} |`);
    });
  }
  console.log('\n(The paper\'s fixed-h 2-point gradient is the larger part of the last column: bench/core.ts measures both errors against a reference.)\n');
}

async function main(): Promise<void> {
  await ensureCli();
  const load = () => loadavg().map((l) => l.toFixed(2)).join(', ');
  const gcc = (() => {
    try {
      return execFileSync('gcc', ['--version'], { encoding: 'utf8' }).split('\n')[0];
    } catch {
      return 'no gcc';
    }
  })();
  console.log(`\n## The command line, whole processes\n`);
  console.log(`Node ${process.version}, ${gcc}, ${cpus().length} × ${cpus()[0]?.model ?? 'unknown CPU'}; load average at the start ${load()}\n`);
  startup();
  const binary = compileC();
  if (binary) againstC(binary);
  await againstPaper();
  console.log(`Load average at the end: ${load()}\n`);
  const missed = outcomes.filter((o) => !o.met);
  console.log(missed.length === 0 ? `All ${outcomes.length} targets met.` : `Missed ${missed.length} of ${outcomes.length} targets: ${missed.map((o) => o.label).join('; ')}.`);
  if (!correct) {
    console.log('The CLI and C disagree by more than E/4: the CLI is not taking the same RK 3/8 steps.');
    process.exitCode = 1;
  }
}

try {
  await main();
} finally {
  rmSync(work, { recursive: true, force: true });
}
