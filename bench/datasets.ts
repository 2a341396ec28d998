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
 *   against scipy at rtol 1e-13: for scipy at the issue's rtol 1e-9 and at
 *   1e-12, against the fastest of phasebook's runs (three steps) that is at
 *   least as accurate (scipy timed by its integration alone);
 * - --workers 2 at least 1.7× faster than --workers 1 for 10 000 trajectories
 *   of the same dataset, with each process's CPU time beside its wall time,
 *   since the machine may be shared;
 * - peak memory the same within 10 % from 1e5 to 1e8 output values.
 */
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { cpus, loadavg, tmpdir } from 'node:os';
import { join } from 'node:path';
import { ensureCli, ROOT } from '../bin/cli-bundle.mjs';
import { runOnce, type Command } from './process-time.ts';

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

/** Wall seconds and the process's CPU seconds (user + system, its threads summed), by /usr/bin/time when it is there. */
interface Measured {
  wall: number;
  cpu?: number;
  stdout: string;
}

const TIME = '/usr/bin/time';

function measure(command: Command): Measured {
  if (!existsSync(TIME)) {
    const run = runOnce(command);
    return { wall: run.seconds, stdout: run.stdout };
  }
  const [file, ...args] = command.argv;
  const start = performance.now();
  const run = spawnSync(TIME, ['-f', 'cpu %U %S', file, ...args], { env: { ...process.env, ...command.env }, encoding: 'utf8', maxBuffer: 1 << 28 });
  const wall = (performance.now() - start) / 1000;
  if (run.status !== 0) throw new Error(`${command.name} failed (status ${run.status}): ${run.stderr}`);
  const cpu = /cpu (\S+) (\S+)\s*$/.exec(run.stderr);
  return { wall, cpu: cpu ? Number(cpu[1]) + Number(cpu[2]) : undefined, stdout: run.stdout };
}

interface Rounds {
  median: number;
  best: number;
  /** median CPU seconds, when measured */
  cpu?: number;
  /** medians of the numbers the process printed on its last line (scipy's seconds spent integrating: wall, CPU) */
  printed?: number[];
}

/** Every command once per round, in turn, so a change of the machine's load shifts them all alike. */
function rounds(commands: readonly Command[], count: number): Rounds[] {
  const runs = commands.map(() => [] as Measured[]);
  for (let r = 0; r < count; r++) commands.forEach((command, i) => runs[i].push(measure(command)));
  const median = (values: number[]) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
  return runs.map((list) => {
    const cpus = list.map((m) => m.cpu).filter((c): c is number => c !== undefined);
    const printed = list.map((m) => m.stdout.trim().split('\n').pop()!.split(/\s+/).map(Number));
    const numeric = printed.every((p) => p.length > 0 && p.every((v) => Number.isFinite(v) && v > 0));
    return {
      median: median(list.map((m) => m.wall)),
      best: Math.min(...list.map((m) => m.wall)),
      cpu: cpus.length ? median(cpus) : undefined,
      printed: numeric ? printed[0].map((_, k) => median(printed.map((p) => p[k]))) : undefined,
    };
  });
}

/**
 * Work against precision. phasebook runs the dataset at its default step and
 * at two longer ones (a sample every 0.1 each time), scipy's DOP853 one
 * trajectory per call at the rtol 1e-9 and at 1e-12; each is
 * measured against scipy at rtol 1e-13. For each scipy tolerance, the target
 * compares it with the fastest phasebook run that is at least as accurate.
 */
const OUR_STEPS = [DT, 2.5e-3, 5e-3];
const SCIPY_RTOLS = [1e-9, 1e-12];

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
  const ourFile = (dt: number) => (dt === DT ? npz : join(work, `dt-${dt}.npz`));
  for (const dt of OUR_STEPS.slice(1)) {
    commands.push(phasebook(`phasebook --format npz --dt ${dt} (all cores)`, ['--initial-file', initial, '--t-end', '10', '--dt', String(dt), '--every', String(Math.round(0.1 / dt)), '--output', ourFile(dt)]));
  }
  const script = join(ROOT, 'bench/python/pendulum_scipy.py');
  const each = (rtol: number) => join(work, `each-${rtol}.npy`);
  if (scipy) {
    commands.push({ name: `scipy DOP853, whole set as one vectorised system, rtol ${SCIPY_RTOL}`, argv: ['python3', script, 'batch', initial, '10', String(SAMPLES), String(SCIPY_RTOL), join(work, 'batch.npy')] });
    for (const rtol of SCIPY_RTOLS) {
      commands.push({ name: `scipy DOP853, one call per trajectory (${SCIPY_EACH} of them), rtol ${rtol}`, argv: ['python3', script, 'each', initial, '10', String(SAMPLES), String(rtol), each(rtol), String(SCIPY_EACH)] });
    }
  }
  const timings = rounds(commands, REPEATS);
  const at = (prefix: string) => commands.findIndex((command) => command.name.startsWith(prefix));
  const cTime = c ? timings[at('C,')].median : undefined;
  const ours = timings[at('phasebook --format npz (all')].median;
  const ourIndex = (dt: number) => at(dt === DT ? 'phasebook --format npz (all' : `phasebook --format npz --dt ${dt} `);
  // scipy's per-trajectory time is its integration alone (the seconds it prints), without Python's start-up: the
  // comparison favours scipy. phasebook's is its whole process over the whole set.
  const perTrajectory = (i: number) => (commands[i].name.includes('one call per trajectory') ? (timings[i].printed?.[0] ?? timings[i].median) / SCIPY_EACH : timings[i].median / TRAJECTORIES);
  // The same in CPU time, which a busy machine disturbs far less than the wall clock.
  const cpuPerTrajectory = (i: number) =>
    commands[i].name.includes('one call per trajectory') ? (timings[i].printed?.[1] ?? NaN) / SCIPY_EACH : (timings[i].cpu ?? NaN) / TRAJECTORIES;

  const errors = new Map<number, number>();
  if (scipy) {
    const reference = join(work, 'reference.npy');
    runOnce({ name: 'scipy reference', argv: ['python3', script, 'reference', initial, '10', String(SAMPLES), '1e-13', reference, String(REFERENCE_COUNT)] });
    for (const dt of OUR_STEPS) errors.set(ourIndex(dt), maxError(ourFile(dt), reference, REFERENCE_COUNT));
    errors.set(at('scipy DOP853, whole set'), maxError(join(work, 'batch.npy'), reference, REFERENCE_COUNT));
    for (const rtol of SCIPY_RTOLS) errors.set(at(`scipy DOP853, one call per trajectory (${SCIPY_EACH} of them), rtol ${rtol}`), maxError(each(rtol), reference, REFERENCE_COUNT));
  }
  console.log('| process | median | best | CPU (median) | per trajectory | × C | max \\|x − scipy rtol 1e-13\\| (first 100) | target |');
  console.log('|---|---|---|---|---|---|---|---|');
  commands.forEach((command, i) => {
    const t = timings[i];
    let goal = '';
    if (command.name.startsWith('phasebook --format npz (all') && cTime) {
      const cCpu = timings[at('C,')].cpu;
      const byCpu = t.cpu !== undefined && cCpu !== undefined ? ` (${(t.cpu / cCpu).toFixed(2)}× in CPU time)` : '';
      goal = `≤ 2× C${byCpu}: ${target('pendulum dataset ≤ 2× C', t.median <= 2 * cTime)}`;
    }
    const rtol = SCIPY_RTOLS.find((r) => command.name.includes('one call per trajectory') && command.name.endsWith(`rtol ${r}`));
    if (rtol !== undefined) {
      const theirs = errors.get(i)!;
      // The fastest phasebook run at least as accurate as this scipy run.
      const match = OUR_STEPS.map(ourIndex)
        .filter((j) => errors.get(j)! <= theirs)
        .sort((x, y) => timings[x].median - timings[y].median)[0];
      const label = `≥ 10× scipy DOP853 rtol ${rtol} per trajectory at equal or better accuracy`;
      if (match === undefined) goal = `no phasebook run as accurate: ${target(label, false)}`;
      else {
        const ratio = perTrajectory(i) / perTrajectory(match);
        const cpuRatio = cpuPerTrajectory(i) / cpuPerTrajectory(match);
        goal = `phasebook${/--dt \S+/.exec(commands[match].name)?.[0].replace(/^/, ' ') ?? ' (default dt)'}: ${ratio.toFixed(1)}× faster per trajectory (${cpuRatio.toFixed(1)}× in CPU time), error ${errors.get(match)!.toExponential(1)}: ≥ 10×: ${target(label, ratio >= 10)}`;
      }
    }
    const error = errors.get(i);
    const cpu = t.cpu === undefined ? '' : seconds(t.cpu);
    console.log(
      `| ${command.name} | ${seconds(t.median)} | ${seconds(t.best)} | ${cpu} | ${(perTrajectory(i) * 1e3).toFixed(3)} ms | ${cTime ? (t.median / cTime).toFixed(2) : ''} | ${error === undefined ? '' : error.toExponential(1)} | ${goal} |`,
    );
  });
  if (scipy) {
    console.log(`\nscipy's per-trajectory times are its integration alone (the seconds it reports), Python's start-up left out; phasebook's are its whole process over the whole set, start-up included.`);
    const b = at('scipy DOP853, whole set');
    console.log(`The vectorised scipy run takes ${seconds(timings[b].median)} for the whole set: phasebook's default run is ${(timings[b].median / ours).toFixed(1)}× its speed at ${(errors.get(b)! / errors.get(ourIndex(DT))!).toFixed(0)}× its accuracy.`);
  }
  console.log('');
}

function workerSpeedUp(): void {
  const count = 10_000;
  console.log(`### Worker threads: ${count} pendulum trajectories, 10 time units, a sample every 0.1, NPZ (${REPEATS} rounds, ${cpus().length} cores)\n`);
  const common = ['--sample', String(count), '--seed', '2', '--box', 'q=-2.5:2.5,p=-1:1', '--t-end', '10', '--every', String(EVERY)];
  const commands = [1, 2].map((k) => phasebook(`--workers ${k}`, [...common, '--workers', String(k), '--output', join(work, `w${k}.npz`)]));
  const before = loadavg()[0];
  const timings = rounds(commands, REPEATS);
  const same = readFileSync(join(work, 'w1.npz')).equals(readFileSync(join(work, 'w2.npz')));
  const speedUp = timings[0].median / timings[1].median;
  const cpu = (t: Rounds) => (t.cpu === undefined ? '' : seconds(t.cpu));
  console.log('| process | median | best | CPU (median) | speed-up | target |');
  console.log('|---|---|---|---|---|---|');
  console.log(`| --workers 1 | ${seconds(timings[0].median)} | ${seconds(timings[0].best)} | ${cpu(timings[0])} | | |`);
  console.log(`| --workers 2 | ${seconds(timings[1].median)} | ${seconds(timings[1].best)} | ${cpu(timings[1])} | ${speedUp.toFixed(2)}× | ≥ 1.7×: ${target('--workers 2 ≥ 1.7× --workers 1', speedUp >= 1.7)} |`);
  if (timings[0].cpu !== undefined && timings[1].cpu !== undefined) {
    // With two idle cores, two workers take the CPU time of one plus their overhead, split in two, plus the serial start.
    // The load counts this benchmark's own processes too; well above the core count, others were running, the
    // workers had less than a core each, and the speed-up is understated.
    console.log(`\nTwo workers spend ${((timings[1].cpu / timings[0].cpu - 1) * 100).toFixed(0)} % more CPU time than one; one-minute load average ${before.toFixed(2)} before, ${loadavg()[0].toFixed(2)} after (this benchmark's processes included), on ${cpus().length} cores.`);
  }
  console.log(`\nThe two files are ${same ? 'identical, byte for byte' : '**different**'}.\n`);
  if (!same) process.exitCode = 1;
}

function flatMemory(): void {
  const time = TIME;
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
