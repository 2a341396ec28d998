/**
 * The CLI as a process, under the faults it must survive: real signals,
 * symbolic links planted where it writes, runs too large to be meant, a full
 * disk, a directory it may not write in, and the partial files a killed run
 * leaves behind.
 */
import { spawn, spawnSync, type StdioOptions } from 'node:child_process';
import {
  chmodSync,
  closeSync,
  cpSync,
  existsSync,
  lstatSync,
  mkdirSync,
  mkdtempSync,
  openSync,
  readdirSync,
  readFileSync,
  rmSync,
  symlinkSync,
  utimesSync,
  writeFileSync,
} from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { afterEach, beforeAll, beforeEach, describe, expect, it } from 'vitest';
import { ensureCli, ROOT } from '../../../bin/cli-bundle.mjs';
import { pidSpace } from '../../../cli/output/partial-file.ts';
import { parseCSV } from '../../../core/tables/csv-read.ts';

const BIN = join(ROOT, 'bin/phasebook.mjs');
const OSCILLATOR = ['simulate', '--hamiltonian', 'p^2/2 + q^2/2', '--dof', '1', '--initial', '1,0'];
/** 8e8 steps, under the step limit: tens of seconds at the fastest, so a signal always finds it running. */
const LONG = [...OSCILLATOR, '--t-end', '4e5', '--every', '100000'];
const PARTIAL = /^\.out\.csv\.phasebook-[0-9a-f]{8}-\d+-[0-9a-f]{32}\.partial$/;

/** The compiled CLI's entry (build/cli/main.js). */
let entry: string;
let scratch: string;
let dir: string;
let cache: string;

beforeAll(async () => {
  // The spawned runs use the compiled CLI; built here if the sources are newer.
  entry = await ensureCli();
});
beforeEach(() => {
  scratch = mkdtempSync(join(tmpdir(), 'phasebook-faults-'));
  dir = join(scratch, 'out');
  cache = join(scratch, 'cache');
  mkdirSync(dir);
});
afterEach(() => {
  chmodSync(dir, 0o755);
  rmSync(scratch, { recursive: true, force: true });
});

interface Exit {
  code: number | null;
  signal: NodeJS.Signals | null;
  stdout: string;
  stderr: string;
}

/** Starts `phasebook …args` (`bin`: the script to run, bin/phasebook.mjs unless given); `exited` settles when it ends. */
function start(args: string[], options: { stdio?: StdioOptions; uid?: number; gid?: number; bin?: string } = {}) {
  const child = spawn(process.execPath, [options.bin ?? BIN, ...args], {
    env: { ...process.env, PHASEBOOK_CACHE_DIR: cache },
    stdio: options.stdio ?? ['ignore', 'pipe', 'pipe'],
    uid: options.uid,
    gid: options.gid,
  });
  let stdout = '';
  let stderr = '';
  child.stdout?.on('data', (chunk) => (stdout += chunk));
  child.stderr?.on('data', (chunk) => (stderr += chunk));
  const exited = new Promise<Exit>((resolve) => {
    child.on('close', (code, signal) => resolve({ code, signal, stdout, stderr }));
  });
  return { child, exited };
}

const phasebook = (args: string[], options?: Parameters<typeof start>[1]) => start(args, options).exited;

/** Resolves once `condition` holds, checking every 10 ms. */
async function until(condition: () => boolean, what: string, timeoutMs = 20_000): Promise<void> {
  const deadline = performance.now() + timeoutMs;
  while (!condition()) {
    if (performance.now() > deadline) throw new Error(`timed out waiting until ${what}`);
    await new Promise((resolve) => setTimeout(resolve, 10));
  }
}

const partials = () => readdirSync(dir).filter((name) => PARTIAL.test(name));
const oneLine = (text: string) => text.trim().split('\n');

/** Starts a long run into dir/out.csv, waits until it is integrating, and sends `signal`. */
async function interrupt(args: string[], signal: NodeJS.Signals) {
  const run = start([...args, '--output', join(dir, 'out.csv')]);
  await until(() => partials().length === 1, 'the partial file exists');
  // Past the setup and into the integration's stretches.
  await new Promise((resolve) => setTimeout(resolve, 300));
  run.child.kill(signal);
  return run.exited;
}

/**
 * Prepares what nobody (uid 65534) must read to run the CLI: the checkout may sit in a folder only its owner
 * may enter (as `mktemp -d` makes it, and as many home folders are), so the compiled CLI is copied into
 * `folder`, which nobody may read, with a script that starts it. Returns that script, or, when nobody still
 * cannot run it (this Node itself, or the temp folder, out of its reach), why, in words.
 */
function nobodyCanRun(folder: string): { bin: string } | string {
  const cli = join(folder, 'cli');
  cpSync(dirname(entry), cli, { recursive: true });
  const bin = join(cli, 'phasebook.mjs');
  writeFileSync(bin, "import { main } from './main.js';\nprocess.exitCode = await main(process.argv.slice(2));\n");
  for (const path of [folder, cli]) chmodSync(path, 0o755);
  const probe = spawnSync(process.execPath, [bin, '--version'], { uid: 65534, gid: 65534, encoding: 'utf8', env: { ...process.env, PHASEBOOK_CACHE_DIR: cache } });
  if (probe.error || probe.status !== 0) {
    return `nobody (uid 65534) cannot run ${process.execPath} on a copy of the CLI in ${cli}: ${probe.error?.message ?? probe.stderr.trim().split('\n')[0]}`;
  }
  return { bin };
}

describe('signals', () => {
  it.each([
    ['SIGINT', 130],
    ['SIGTERM', 143],
  ] as const)('%s stops a long run at once: status %i, one line on stderr, no output and no partial left', async (signal, status) => {
    const exit = await interrupt(LONG, signal);
    expect(exit.signal).toBeNull();
    expect(exit.code).toBe(status);
    expect(oneLine(exit.stderr)).toHaveLength(1);
    const stopped = new RegExp(`^phasebook: stopped by ${signal} at t = (\\S+) of 400000; \\S*out\\.csv was not written\\n$`).exec(exit.stderr);
    expect(stopped).not.toBeNull();
    expect(readdirSync(dir)).toEqual([]);
    // At once, told by the work done rather than by a clock: the signal comes some 300 ms into a run of tens
    // of seconds at the fastest (a busy machine only makes that share smaller), so a run that stops at once
    // has done a small part of it, and one that ran on to the end, or for many seconds, would not have.
    expect(Number(stopped![1])).toBeLessThan(400000 / 4);
  });

  it.each(['npz', 'csv'])('stops a dataset on worker threads (%s): status 130, no partial and no spill file left', async (format) => {
    const args = ['simulate', '--hamiltonian', 'p^2/2 + q^2/2', '--dof', '1', '--sample', '2000', '--box', 'q=-1:1,p=-1:1', '--t-end', '200', '--every', '10', '--derivatives', '--workers', '2', '--force', '--format', format];
    const run = start([...args, '--output', join(dir, `out.${format}`)]);
    // An NPZ keeps its later arrays aside in spill files, partials too: all are there once x streams.
    const ours = () => readdirSync(dir).filter((name) => /^\.out\.\w+(\.\w+)?\.phasebook-[0-9a-f]{8}-\d+-[0-9a-f]{32}\.partial$/.test(name));
    await until(() => ours().length === (format === 'npz' ? 3 : 1), 'the partial files exist');
    await new Promise((resolve) => setTimeout(resolve, 300));
    run.child.kill('SIGINT');
    const exit = await run.exited;
    expect(exit.code).toBe(130);
    expect(oneLine(exit.stderr)).toHaveLength(1);
    expect(exit.stderr).toMatch(/^phasebook: stopped by SIGINT after \d+ of 2000 trajectories; \S*out\.\w+ was not written\n$/);
    expect(readdirSync(dir)).toEqual([]);
  });

  it('leaves a run writing to stdout to the default action: it dies of the signal at once', async () => {
    const run = start(LONG);
    await new Promise((resolve) => setTimeout(resolve, 1000));
    run.child.kill('SIGINT');
    const exit = await run.exited;
    expect(exit.signal).toBe('SIGINT');
  });
});

describe('planted symbolic links', () => {
  it('never writes through a link at the old predictable partial name or at guesses of the new one', async () => {
    const victim = join(scratch, 'victim.txt');
    writeFileSync(victim, 'precious\n');
    const out = join(dir, 'out.csv');
    const run = start([...OSCILLATOR, '--t-end', '1', '--every', '100', '--output', out]);
    // The pid is known as soon as the process exists, well before the CLI has loaded.
    const pid = run.child.pid!;
    const planted = [
      `.out.csv.${pid}.partial`,
      `.out.csv.phasebook-${pidSpace()}-${pid}-${'0'.repeat(32)}.partial`,
      `.out.csv.phasebook-${pidSpace()}-${pid}-${'f'.repeat(32)}.partial`,
      `.out.csv.phasebook-${pidSpace()}-${pid}.partial`,
    ];
    for (const name of planted) symlinkSync(victim, join(dir, name));
    const exit = await run.exited;
    expect(exit.stderr).toBe('');
    expect(exit.code).toBe(0);
    expect(readFileSync(victim, 'utf8')).toBe('precious\n');
    expect(parseCSV(readFileSync(out, 'utf8')).rows).toBe(21);
    // The links are not phasebook's files, so they are left as they were.
    for (const name of planted) expect(lstatSync(join(dir, name)).isSymbolicLink()).toBe(true);
    expect(readdirSync(dir).sort()).toEqual([...planted, 'out.csv'].sort());
  });

  it('replaces a link at the target itself with the file, leaving what it pointed to alone', async () => {
    const victim = join(scratch, 'victim.txt');
    writeFileSync(victim, 'precious\n');
    const out = join(dir, 'out.csv');
    symlinkSync(victim, out);
    const exit = await phasebook([...OSCILLATOR, '--t-end', '1', '--every', '100', '--output', out]);
    expect(exit.code).toBe(0);
    expect(readFileSync(victim, 'utf8')).toBe('precious\n');
    expect(lstatSync(out).isFile()).toBe(true);
  });
});

describe('runs too large to be meant', () => {
  it('refuses --dt 1e-300 with the estimate and status 2, and runs it with --force until interrupted', async () => {
    const args = [...OSCILLATOR, '--dt', '1e-300'];
    const refused = await phasebook([...args, '--output', join(dir, 'out.csv')]);
    expect(refused.code).toBe(2);
    expect(oneLine(refused.stderr)).toHaveLength(1);
    expect(refused.stderr).toMatch(/^phasebook: this run would take 1e\+301 steps \(the limit is 1e\+9; .*\) and write about \S+ bytes of output .*--force/);
    expect(readdirSync(dir)).toEqual([]);

    const forced = await interrupt([...args, '--force'], 'SIGINT');
    expect(forced.code).toBe(130);
    expect(forced.stderr).toMatch(/^phasebook: stopped by SIGINT at t = \S+e-\d+ of 10;/);
    expect(readdirSync(dir)).toEqual([]);
  });

  it('refuses an output estimated over 1 GiB, naming --every, and prints nothing', async () => {
    const exit = await phasebook([...OSCILLATOR, '--t-end', '1e5', '--format', 'json']);
    expect(exit.code).toBe(2);
    expect(exit.stdout).toBe('');
    expect(exit.stderr).toMatch(/^phasebook: this run would take 2e\+8 steps and write about 1[0-9.]* GiB of output \(the limit is 1 GiB; raise --every or lower --t-end\); add --force/);
  });
});

describe('files that cannot be written', () => {
  it('says "no space left" for a full device, as --output and as stdout', async (context) => {
    if (!existsSync('/dev/full')) context.skip('this system has no /dev/full to stand for a full disk');
    // Through a link of our own: a CLI that renamed a file onto the device node, as root, would replace /dev/full itself.
    const full = join(scratch, 'full');
    symlinkSync('/dev/full', full);
    const asOutput = await phasebook([...OSCILLATOR, '--output', full]);
    expect(asOutput.code).toBe(2);
    expect(asOutput.stderr).toBe(`phasebook: cannot write ${full}: no space left on the device\n`);
    expect(lstatSync(full).isSymbolicLink()).toBe(true);

    const device = openSync('/dev/full', 'w');
    try {
      const asStdout = await phasebook(OSCILLATOR, { stdio: ['ignore', device, 'pipe'] });
      expect(asStdout.code).toBe(2);
      expect(asStdout.stderr).toBe('phasebook: cannot write stdout: no space left on the device\n');
    } finally {
      closeSync(device);
    }
  });

  it('says "permission denied" for a directory it may not write in', async (context) => {
    chmodSync(dir, 0o555);
    let asUser: { uid?: number; gid?: number; bin?: string } = {};
    let writable = true;
    try {
      writeFileSync(join(dir, 'probe'), '');
    } catch {
      writable = false;
    }
    if (writable) {
      rmSync(join(dir, 'probe'));
      // Root ignores the mode; an unprivileged user (nobody) does not, if this process may become one.
      if (process.getuid?.() !== 0) context.skip('the read-only directory is writable here, and this process cannot run as another user');
      chmodSync(scratch, 0o755);
      const prepared = nobodyCanRun(scratch);
      if (typeof prepared === 'string') return context.skip(prepared);
      asUser = { uid: 65534, gid: 65534, bin: prepared.bin };
    }
    const out = join(dir, 'out.csv');
    const exit = await phasebook([...OSCILLATOR, '--no-cache', '--output', out], asUser);
    expect(exit.code).toBe(2);
    expect(exit.stderr).toBe(`phasebook: cannot write ${out}: permission denied (it takes write permission on the directory ${dir})\n`);
    expect(readdirSync(dir)).toEqual([]);
  });

  it.each([
    ['a missing directory', () => join(scratch, 'missing', 'out.csv'), /^phasebook: cannot write \S+out\.csv: the directory \S+missing does not exist\n$/],
    ['a directory', () => dir, /^phasebook: cannot write \S+: it is a directory\n$/],
    ['a path through a file', () => join(scratch, 'file', 'out.csv'), /^phasebook: cannot write \S+: a part of the path is not a directory\n$/],
  ])('says so in words for %s', async (_, target, message) => {
    writeFileSync(join(scratch, 'file'), '');
    const exit = await phasebook([...OSCILLATOR, '--output', target()]);
    expect(exit.code).toBe(2);
    expect(exit.stderr).toMatch(message);
  });
});

describe('partial files left by killed runs', () => {
  it('removes the partial a SIGKILLed run left when the next run writes in that directory', async () => {
    const run = start([...LONG, '--output', join(dir, 'out.csv')]);
    await until(() => partials().length === 1, 'the partial file exists');
    run.child.kill('SIGKILL');
    expect((await run.exited).signal).toBe('SIGKILL');
    expect(partials()).toHaveLength(1);
    const next = await phasebook([...OSCILLATOR, '--t-end', '1', '--every', '100', '--output', join(dir, 'other.csv')]);
    expect(next.code).toBe(0);
    expect(readdirSync(dir)).toEqual(['other.csv']);
  });

  it('removes partials of dead processes and day-old ones, and nothing else', async () => {
    const space = pidSpace();
    const dead = spawnSync('node', ['-e', '']).pid!;
    const random = () => Math.random().toString(16).slice(2).padEnd(32, '0').slice(0, 32);
    const file = (name: string, ageDays = 0) => {
      writeFileSync(join(dir, name), 'rows\n');
      const time = Date.now() / 1000 - ageDays * 86_400;
      utimesSync(join(dir, name), time, time);
      return name;
    };
    const stale = [
      file(`.out.csv.phasebook-${space}-${dead}-${random()}.partial`),
      file(`.a,b.csv.phasebook-${space}-${dead}-${random()}.partial`),
      file(`.elsewhere.csv.phasebook-0000abcd-${process.pid}-${random()}.partial`, 2),
      file(`.running.csv.phasebook-${space}-${process.pid}-${random()}.partial`, 2),
    ];
    const kept = [
      // A live writer here; a writer elsewhere, whose PID means nothing here, recently at work.
      file(`.running.csv.phasebook-${space}-${process.pid}-${random()}.partial`),
      file(`.elsewhere.csv.phasebook-0000abcd-${dead}-${random()}.partial`),
      // Not phasebook's: the old pattern anyone could use, near misses, and plain files, however old.
      file(`.out.csv.${dead}.partial`, 3),
      file(`.out.csv.phasebook-${space}-${dead}-${random().slice(1)}.partial`, 3),
      file(`.out.csv.phasebook-${space}-${dead}-${random()}.partial.keep`, 3),
      file(`out.csv.phasebook-${space}-${dead}-${random()}.partiaL`, 3),
      file('notes.txt', 3),
    ];
    const link = `.link.csv.phasebook-${space}-${dead}-${random()}.partial`;
    symlinkSync(join(dir, 'notes.txt'), join(dir, link));
    mkdirSync(join(dir, `.sub.phasebook-${space}-${dead}-${random()}.partial`));

    const exit = await phasebook([...OSCILLATOR, '--t-end', '1', '--every', '100', '--output', join(dir, 'out.csv')]);
    expect(exit.code).toBe(0);
    const left = readdirSync(dir);
    for (const name of stale) expect(left).not.toContain(name);
    for (const name of [...kept, link]) expect(left).toContain(name);
    expect(left).toHaveLength(kept.length + 3);
    expect(readFileSync(join(dir, 'notes.txt'), 'utf8')).toBe('rows\n');
  });
});
