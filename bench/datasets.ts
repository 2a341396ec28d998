/**
 * `npm run bench`, dataset part: `phasebook simulate` over many initial
 * conditions as whole processes, beside a C program (bench/c/pendulum-dataset.c,
 * gcc -O2) and scipy's solve_ivp (bench/python/pendulum_scipy.py, when
 * python3 has numpy and scipy), all in this one run, each figure the median
 * of BENCH_REPEATS rounds (3 by default) in which every contender runs once
 * in turn. The targets are issue 9's:
 * - the 1000-trajectory pendulum dataset (10 time units, a sample every 0.1)
 *   in at most 2× the C program's time, and at least 10× faster per
 *   trajectory than scipy's DOP853 at equal or better accuracy, measured
 *   against scipy at rtol 1e-13;
 * - --workers 2 at least 1.7× faster than --workers 1 for 10 000 trajectories;
 * - peak memory the same within 10 % from 1e5 to 1e8 output values.
 */
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { cpus, loadavg, tmpdir } from 'node:os';
import { join } from 'node:path';
import { ensureCli, ROOT } from '../bin/cli-bundle.mjs';
import { runOnce, timeInterleaved, type Command } from './process-time.ts';

const REPEATS = Number(process.env.BENCH_REPEATS ?? 3);
const BIN = join(ROOT, 'bin/phasebook.mjs');
const work = mkdtempSync(join(tmpdir(), 'phasebook-bench-data-'));
const env = { PHASEBOOK_CACHE_DIR: join(work, 'cache') };
const PENDULUM = ['--hamiltonian', 'p^2/2 - cos(q)', '--dof', '1'];
const DT = 5e-4;
/** 10 time units, a sample every 0.1: 20 000 steps, every 200th written. */
const STEPS = 20_000;
const EVERY = 200;
const SAMPLES = STEPS / EVERY + 1;
const TRAJECTORIES = 1000;
/** scipy solving one trajectory per call is slow: its time per trajectory is taken on this many. */
const SCIPY_EACH = 100;
/** The accuracy yardstick: scipy DOP853 at rtol 1e-13, on the first trajectories. */
const REFERENCE_COUNT = 100;
/** scipy's tolerance in the timed runs: the solve_ivp runs used 1e-9. */
const SCIPY_RTOL = 1e-9;

const seconds = (s: number) => (s < 1 ? `${(s * 1000).toFixed(0)} ms` : `${s.toFixed(2)} s`);
const outcomes: { label: string; met: boolean }[] = [];
function target(label: string, met: boolean): string {
  outcomes.push({ label, met });
  return met ? 'met' : '**missed**';
}

const phasebook = (name: string, args: string[]): Command => ({ name, argv: ['node', BIN, 'simulate', ...PENDULUM, ...args], env });

function python(): boolean {
  return spawnSync('python3', ['-c', 'import numpy, scipy'], { encoding: 'utf8' }).status === 0;
}

/** Max |a − b| over the first `count` trajectories of two (M, T, 2) arrays read by numpy. */
function maxError(a: string, b: string, count: number): number {
  const out = execFileSync(
    'python3',
    ['-c', `import sys, numpy as np\ndef load(p):\n    return np.load(p)['x'] if p.endswith('.npz') else np.load(p)\na = load(sys.argv[1])[:${count}]\nb = load(sys.argv[2])[:${count}]\nprint(float(np.max(np.abs(a - b))))`, a, b],
    { encoding: 'utf8' },
  );
  return Number(out.trim());
}

/** The initial states: a seeded sample in the box, written by phasebook itself as q,p rows for every contender. */
function initialStates(): string {
  const run = runOnce(phasebook('initial states', ['--sample', String(TRAJECTORIES), '--seed', '1', '--box', 'q=-2.5:2.5,p=-1:1', '--t-end', '0']));
  const lines = run.stdout.trim().split('\n').slice(1).map((line) => line.split(',').slice(2, 4).join(','));
  const file = join(work, 'initial.csv');
  writeFileSync(file, `q,p\n${lines.join('\n')}\n`);
  return file;
}

function compileC(): string | undefined {
  const binary = join(work, 'pendulum-dataset');
  try {
    execFileSync('gcc', ['-O2', '-o', binary, join(ROOT, 'bench/c/pendulum-dataset.c'), '-lm'], { stdio: 'pipe' });
    return binary;
  } catch (error) {
    console.log(`(no C comparison: gcc -O2 failed: ${(error as Error).message.split('\n')[0]})\n`);
    return undefined;
  }
}

function pendulumDataset(initial: string, c: string | undefined, scipy: boolean): void {
  console.log(`### The pendulum dataset: ${TRAJECTORIES} trajectories of H = p²/2 − cos q, 10 time units, a sample every 0.1 (${REPEATS} rounds)\n`);
  const npz = join(work, 'phasebook.npz');
  const common = ['--initial-file', initial, '--t-end', '10', '--every', String(EVERY)];
  runOnce(phasebook('cache warm-up', [...common, '--output', npz]));
  const commands: Command[] = [];
  if (c) commands.push({ name: 'C, gcc -O2, RK 3/8, CSV', argv: ['sh', '-c', `"$0" "$1" ${STEPS} ${DT} ${EVERY} > "$2"`, c, initial, join(work, 'c.csv')] });
  commands.push(phasebook('phasebook --format npz (all cores)', [...common, '--output', npz]));
  commands.push(phasebook('phasebook --format csv (all cores)', [...common, '--output', join(work, 'phasebook.csv')]));
  commands.push(phasebook('phasebook --format parquet (all cores)', [...common, '--output', join(work, 'phasebook.parquet')]));
  commands.push(phasebook('phasebook --format npz --workers 1', [...common, '--workers', '1', '--output', join(work, 'one.npz')]));
  const script = join(ROOT, 'bench/python/pendulum_scipy.py');
  if (scipy) {
    commands.push({ name: `scipy DOP853, whole set as one vectorised system, rtol ${SCIPY_RTOL}`, argv: ['python3', script, 'batch', initial, '10', String(SAMPLES), String(SCIPY_RTOL), join(work, 'batch.npy')] });
    commands.push({ name: `scipy DOP853, one call per trajectory (${SCIPY_EACH} of them), rtol ${SCIPY_RTOL}`, argv: ['python3', script, 'each', initial, '10', String(SAMPLES), String(SCIPY_RTOL), join(work, 'each.npy'), String(SCIPY_EACH)] });
  }
  const timings = timeInterleaved(commands, REPEATS);
  const at = (prefix: string) => commands.findIndex((command) => command.name.startsWith(prefix));
  const cTime = c ? timings[at('C,')].median : undefined;
  const ours = timings[at('phasebook --format npz (all')].median;
  const perTrajectory = (i: number) => (commands[i].name.includes('one call per trajectory') ? timings[i].median / SCIPY_EACH : timings[i].median / TRAJECTORIES);

  let errors: Record<string, number> = {};
  if (scipy) {
    const reference = join(work, 'reference.npy');
    runOnce({ name: 'scipy reference', argv: ['python3', script, 'reference', initial, '10', String(SAMPLES), '1e-13', reference, String(REFERENCE_COUNT)] });
    errors = {
      phasebook: maxError(npz, reference, REFERENCE_COUNT),
      batch: maxError(join(work, 'batch.npy'), reference, REFERENCE_COUNT),
      each: maxError(join(work, 'each.npy'), reference, REFERENCE_COUNT),
    };
  }
  const errorOf = (name: string) => (name.startsWith('phasebook --format npz (all') ? errors.phasebook : name.includes('vectorised') ? errors.batch : name.includes('one call') ? errors.each : undefined);
  console.log('| process | median | best | per trajectory | × C | max \\|x − scipy rtol 1e-13\\| (first 100) | target |');
  console.log('|---|---|---|---|---|---|---|');
  commands.forEach((command, i) => {
    const t = timings[i];
    let goal = '';
    if (command.name.startsWith('phasebook --format npz (all') && cTime) goal = `≤ 2× C: ${target('pendulum dataset ≤ 2× C', t.median <= 2 * cTime)}`;
    if (command.name.includes('one call per trajectory')) {
      const ratio = perTrajectory(i) / (ours / TRAJECTORIES);
      const accurate = errors.phasebook <= errors.each;
      goal = `phasebook ${ratio.toFixed(1)}× faster per trajectory, ${accurate ? 'at better accuracy' : '**less accurate**'}: ≥ 10×: ${target('≥ 10× scipy DOP853 per trajectory at equal or better accuracy', ratio >= 10 && accurate)}`;
    }
    const error = errorOf(command.name);
    console.log(
      `| ${command.name} | ${seconds(t.median)} | ${seconds(t.best)} | ${(perTrajectory(i) * 1e3).toFixed(3)} ms | ${cTime ? (t.median / cTime).toFixed(2) : ''} | ${error === undefined ? '' : error.toExponential(1)} | ${goal} |`,
    );
  });
  if (scipy) {
    const batch = timings[at('scipy DOP853, whole set')].median;
    console.log(`\nThe vectorised scipy run takes ${seconds(batch)} for the whole set: phasebook is ${(batch / ours).toFixed(1)}× faster than that too, and ${(errors.batch / errors.phasebook).toFixed(0)}× more accurate.`);
  }
  console.log('');
}

function workerSpeedUp(): void {
  const count = 10_000;
  console.log(`### Worker threads: ${count} pendulum trajectories, 2 time units, a sample every 0.1, NPZ (${REPEATS} rounds, ${cpus().length} cores)\n`);
  const common = ['--sample', String(count), '--seed', '2', '--box', 'q=-2.5:2.5,p=-1:1', '--t-end', '2', '--every', String(EVERY)];
  const commands = [1, 2].map((k) => phasebook(`--workers ${k}`, [...common, '--workers', String(k), '--output', join(work, `w${k}.npz`)]));
  const timings = timeInterleaved(commands, REPEATS);
  const same = readFileSync(join(work, 'w1.npz')).equals(readFileSync(join(work, 'w2.npz')));
  const speedUp = timings[0].median / timings[1].median;
  console.log('| process | median | best | speed-up | target |');
  console.log('|---|---|---|---|---|');
  console.log(`| --workers 1 | ${seconds(timings[0].median)} | ${seconds(timings[0].best)} | | |`);
  console.log(`| --workers 2 | ${seconds(timings[1].median)} | ${seconds(timings[1].best)} | ${speedUp.toFixed(2)}× | ≥ 1.7×: ${target('--workers 2 ≥ 1.7× --workers 1', speedUp >= 1.7)} |`);
  console.log(`\nThe two files are ${same ? 'identical, byte for byte' : '**different**'}.\n`);
  if (!same) process.exitCode = 1;
}

function flatMemory(): void {
  const time = '/usr/bin/time';
  if (!existsSync(time)) {
    console.log('(no peak-memory table: /usr/bin/time is not installed)\n');
    return;
  }
  const steps = 33_333;
  console.log(`### Peak memory: ${TRAJECTORIES} pendulum trajectories of ${steps} steps each, NPZ, every 1000 … 1 step written (one round each)\n`);
  console.log('| output values | file | peak resident memory | × the smallest | target |');
  console.log('|---|---|---|---|---|');
  let smallest = 0;
  for (const every of [1000, 100, 10, 1]) {
    const out = join(work, 'memory.npz');
    const args = [...PENDULUM, '--sample', String(TRAJECTORIES), '--seed', '3', '--box', 'q=-2.5:2.5,p=-1:1', '--t-end', String(steps * DT), '--every', String(every), '--force', '--output', out];
    const run = spawnSync(time, ['-f', '%M', 'node', BIN, 'simulate', ...args], { encoding: 'utf8', env: { ...process.env, ...env } });
    if (run.status !== 0) throw new Error(`the memory run failed: ${run.stderr}`);
    const kb = Number(run.stderr.trim().split('\n').pop());
    const samples = Math.floor(steps / every) + 1;
    const values = TRAJECTORIES * samples * 3 + samples;
    const size = statSync(out).size;
    rmSync(out);
    smallest ||= kb;
    const ratio = kb / smallest;
    const goal = every === 1 ? `within 10 %: ${target('peak memory flat within 10 % from 1e5 to 1e8 values', ratio <= 1.1)}` : '';
    console.log(`| ${values.toExponential(1)} | ${(size / 2 ** 20).toFixed(0)} MiB | ${(kb / 1024).toFixed(0)} MiB | ${ratio.toFixed(2)} | ${goal} |`);
  }
  console.log('');
}

async function main(): Promise<void> {
  await ensureCli();
  const load = () => loadavg().map((l) => l.toFixed(2)).join(', ');
  console.log('\n## Datasets: many trajectories in one command\n');
  console.log(`Node ${process.version}, ${cpus().length} × ${cpus()[0]?.model ?? 'unknown CPU'}; load average at the start ${load()}\n`);
  const scipy = python();
  if (!scipy) console.log('(no scipy comparison: python3 with numpy and scipy is not installed; `pip install numpy scipy` adds it)\n');
  const initial = initialStates();
  pendulumDataset(initial, compileC(), scipy);
  workerSpeedUp();
  flatMemory();
  console.log(`Load average at the end: ${load()}\n`);
  const missed = outcomes.filter((o) => !o.met);
  console.log(missed.length === 0 ? `All ${outcomes.length} dataset targets met.` : `Missed ${missed.length} of ${outcomes.length} dataset targets: ${missed.map((o) => o.label).join('; ')}.`);
}

try {
  await main();
} finally {
  rmSync(work, { recursive: true, force: true });
}
