/**
 * `reproduce` and `merge` take a dataset file as data from whoever made it
 * (issue 20): the JavaScript its meta carries runs only if it translates to
 * an expression or with --trust-code, and then in the sandbox; a damaged
 * meta, row or file is said in one line naming the file; and both stop on
 * SIGINT and SIGTERM as simulate does, leaving no partial file.
 */
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeAll, beforeEach, describe, expect, it } from 'vitest';
import { ensureCli } from '../../../bin/cli-bundle.mjs';
import { parseJSON, toJSON } from '../../../core/index.ts';
import { startCli, type CliExit } from '../support/cli-harness.ts';


let scratch: string;
let marker: string;

beforeAll(async () => {
  await ensureCli();
});
beforeEach(() => {
  scratch = mkdtempSync(join(tmpdir(), 'phasebook-files-'));
  marker = join(scratch, 'MARKER');
});
afterEach(() => rmSync(scratch, { recursive: true, force: true }));

type Exit = CliExit;

/** `phasebook …args` as a process; its temporary files go to the scratch folder, where a test can see them. */
const start = (args: string[], env: Record<string, string> = {}) => startCli(args, { PHASEBOOK_CACHE_DIR: join(scratch, 'cache'), TMPDIR: scratch, ...env });
const phasebook = (args: string[], env?: Record<string, string>) => start(args, env).exited;

async function simulate(args: string[]): Promise<void> {
  const exit = await phasebook(['simulate', ...args]);
  expect(exit.stderr).toBe('');
  expect(exit.code).toBe(0);
}

const oneLine = (exit: Exit) => expect(exit.stderr.trim().split('\n')).toHaveLength(1);
const partials = () => readdirSync(scratch).filter((name) => name.endsWith('.partial'));

/** An H the translator cannot take (an if), which writes the marker when it can: in the CLI's own process, as H once ran. */
const WRITES_MARKER = () =>
  `(t, [q, p]) => { try { process.getBuiltinModule('fs').writeFileSync(${JSON.stringify(marker)}, 'x'); } catch {} if (q > 9) return 0; return p * p / 2 + q * q / 2; }`;
const SET = ['--dof', '1', '--sample', '3', '--seed', '1', '--box', 'q=-1:1,p=-1:1', '--t-end', '0.2', '--every', '20'];

/** A JSON dataset whose meta's H is replaced by `hamiltonian`: a file as anyone could edit it. */
async function craftedJson(hamiltonian: string): Promise<string> {
  const file = join(scratch, 'crafted.json');
  await simulate(['--hamiltonian', '(t, [q, p]) => { if (q > 9) return 0; return p * p / 2 + q * q / 2; }', ...SET, '--output', file]);
  const { meta, table } = parseJSON(readFileSync(file, 'utf8'));
  writeFileSync(file, toJSON(table, { ...meta, hamiltonian }));
  return file;
}

describe('reproduce runs no code of a file’s without --trust-code', () => {
  it.each(['json', 'npz', 'parquet'])('refuses a %s file whose H is JavaScript that does not translate: one line with the code, status 2, nothing run', async (format) => {
    const file = join(scratch, `data.${format}`);
    // Made by simulate, where the code runs in the sandbox and so writes nothing.
    await simulate(['--hamiltonian', WRITES_MARKER(), ...SET, '--output', file]);
    expect(existsSync(marker)).toBe(false);
    const exit = await phasebook(['reproduce', file]);
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).toContain(`phasebook: ${file}: its H is JavaScript that does not translate to an expression, so reproducing it would run its author's code: (t, [q, p]) => { try { process.getBuiltinModule('fs').writeFileSync(`);
    expect(exit.stderr).toMatch(/ — pass --trust-code if you trust its author\n$/);
    expect(existsSync(marker)).toBe(false);
  });

  it('refuses a vector field likewise, and shows a long code cut to a line', async () => {
    const file = join(scratch, 'field.npz');
    const padding = Array.from({ length: 60 }, (_, i) => `const unused${i} = ${i};`).join('\n');
    await simulate(['--vector-field', `(t, x, dxdt) => {\n${padding}\ndxdt[0] = x[1]; dxdt[1] = -x[0]; }`, ...SET, '--output', file]);
    const exit = await phasebook(['reproduce', file]);
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).toMatch(/: its vector field is JavaScript, so reproducing it would run its author's code: \(t, x, dxdt\) => \{ const unused0 = 0; .*… \(\d+ characters\) — pass --trust-code/);
  });

  it('reproduces an H that translates to an expression without the flag: none of its code runs', async () => {
    const file = join(scratch, 'translated.json');
    await simulate(['--hamiltonian', '(t, x) => x[1]**2/2 + x[0]**2/2', ...SET, '--output', file]);
    const exit = await phasebook(['reproduce', file]);
    expect(exit.stderr).toBe('');
    expect(exit.code).toBe(0);
    expect(exit.stdout).toMatch(/: reproduced, 3 trajectories × 21 samples, all 252 numbers identical\n$/);
  });

  it('reproduces code it may run with --trust-code, in the sandbox: the marker is still not written', async () => {
    const file = join(scratch, 'data.npz');
    await simulate(['--hamiltonian', WRITES_MARKER(), ...SET, '--output', file]);
    const exit = await phasebook(['reproduce', file, '--trust-code', '--workers', '2']);
    expect(exit.stderr).toBe('');
    expect(exit.code).toBe(0);
    expect(exit.stdout).toMatch(/: reproduced, 3 trajectories × 21 samples, all 252 numbers identical\n$/);
    expect(existsSync(marker)).toBe(false);
  });

  it.each([
    ['writes a file', () => `(t, x) => { process.getBuiltinModule('fs').writeFileSync(${JSON.stringify(marker)}, 'x'); return 1; }`],
    ['starts a process', () => `(t, x) => { process.getBuiltinModule('child_process').execSync('touch ${marker}'); return 1; }`],
    ['reads /etc/passwd', () => `(t, x) => { throw new Error(process.getBuiltinModule('fs').readFileSync('/etc/passwd', 'utf8')); }`],
    ['reads the environment', () => `(t, x) => { throw new Error(JSON.stringify(process.env)); }`],
    ['exits', () => `(t, x) => { process.exit(7); }`],
    ['imports a module', () => `(t, x) => { import('node:fs').then((fs) => fs.writeFileSync(${JSON.stringify(marker)}, 'x')); return 1; }`],
  ])('contains, with --trust-code, a file’s H that %s: one line naming the file, status 2, nothing written or leaked', async (_, h) => {
    const file = await craftedJson(h());
    const exit = await phasebook(['reproduce', file, '--trust-code'], { PHASEBOOK_SECRET: 'hunter2-secret' });
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).toMatch(new RegExp(`^phasebook: ${file.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}: `));
    expect(exit.stderr).not.toMatch(/hunter2-secret|root:/);
    // The import fails in its own time, after H has returned: give it a moment to have written, were it able to.
    await new Promise((resolve) => setTimeout(resolve, 100));
    expect(existsSync(marker)).toBe(false);
    expect(partials()).toEqual([]);
  });

  it('never runs a file’s H that is a call making a function, trusted or not', async () => {
    const file = await craftedJson(`(() => { process.getBuiltinModule('fs').writeFileSync(${JSON.stringify(marker)}, 'x'); return (t, x) => 1; })()`);
    for (const trust of [[], ['--trust-code']]) {
      const exit = await phasebook(['reproduce', file, ...trust]);
      expect(exit.code).toBe(2);
      oneLine(exit);
      expect(exit.stderr).toMatch(/: H must be one JS function, \(t, x\) => …, not a call/);
    }
    expect(existsSync(marker)).toBe(false);
  });
});

describe('damaged files, said with their names', () => {
  it.each([
    ['a dt that is not a number', (meta: Record<string, unknown>) => (meta.dt = 'x'), /its meta gives dt as "x", not a finite number, so it cannot be run again/],
    ['a box with a component missing', (meta: Record<string, unknown>) => delete (meta.initialSet as { box: Record<string, unknown> }).box.p, /its meta gives the box of p as nothing/],
    ['more degrees of freedom than names', (meta: Record<string, unknown>) => (meta.dof = 1e8), /its meta lists 2 state names for 100000000 degree\(s\) of freedom/],
    ['a parameter name that is code', (meta: Record<string, unknown>) => (meta.params = { 'a=1;evil()': 1 }), /its meta has a parameter whose name "a=1;evil\(\)" is not a valid name/],
  ])('reproduce refuses a meta with %s in one line naming the file', async (_, damage, message) => {
    const file = join(scratch, 'data.json');
    await simulate(['--hamiltonian', 'p^2/2 + q^2/2', ...SET, '--output', file]);
    const { meta, table } = parseJSON(readFileSync(file, 'utf8'));
    damage(meta);
    writeFileSync(file, toJSON(table, meta));
    const exit = await phasebook(['reproduce', file]);
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).toContain(`phasebook: ${file}: `);
    expect(exit.stderr).toMatch(message);
  });

  it('merge refuses a JSON shard whose row lacks a value: status 2, the file named, no output', async () => {
    for (const i of [1, 2]) await simulate(['--hamiltonian', 'p^2/2 + q^2/2', ...SET, '--shard', `${i}/2`, '--output', join(scratch, `s${i}.json`)]);
    const shard = join(scratch, 's2.json');
    const lines = readFileSync(shard, 'utf8').split('\n');
    // The fifth line is a row: [trajectory, t, q, p, H], less its last value.
    lines[4] = lines[4].replace(/,[^,\]]+\](,?)$/, ']$1');
    writeFileSync(shard, lines.join('\n'));
    const out = join(scratch, 'merged.json');
    const exit = await phasebook(['merge', '--output', out, join(scratch, 's1.json'), shard]);
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).toBe(`phasebook: ${shard} line 5: data row 1 has 4 values, expected 5\n`);
    expect(existsSync(out)).toBe(false);
    expect(partials()).toEqual([]);
  });

  it.each(['merge', 'reproduce'])('%s refuses an NPZ with one bit of x flipped, by its CRC: one line naming the file, status 2, no output', async (command) => {
    for (const i of [1, 2]) await simulate(['--hamiltonian', 'p^2/2 + q^2/2', ...SET, '--shard', `${i}/2`, '--output', join(scratch, `s${i}.npz`)]);
    const shard = join(scratch, 's2.npz');
    const bytes = readFileSync(shard);
    // x.npy's local header is 30 bytes, its name 5, no extra field (a small file), then the 128-byte NPY header: the 40th byte of q₀.
    const data = bytes.indexOf('x.npy') + 5 + 128;
    bytes[data + 40] ^= 0x01;
    writeFileSync(shard, bytes);
    const out = join(scratch, 'merged.npz');
    const exit = await phasebook(command === 'merge' ? ['merge', '--output', out, join(scratch, 's1.npz'), shard] : ['reproduce', shard]);
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).toMatch(new RegExp(`^phasebook: ${shard.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')} is not a ZIP archive \\(NPZ\\) that can be read: x\\.npy is damaged: its bytes' CRC-32 is `));
    expect(existsSync(out)).toBe(false);
    expect(partials()).toEqual([]);
  });

  it.each(['merge', 'reproduce'])('%s says a damaged Parquet file is damaged, naming it, instead of an internal error', async (command) => {
    for (const i of [1, 2]) await simulate(['--hamiltonian', 'p^2/2 + q^2/2', ...SET, '--shard', `${i}/2`, '--output', join(scratch, `s${i}.parquet`)]);
    const shard = join(scratch, 's1.parquet');
    const bytes = readFileSync(shard);
    // Scrambled between the magic numbers: the footer and the pages hyparquet parses.
    for (let i = 8; i < bytes.length - 8; i++) bytes[i] ^= 0x5a;
    writeFileSync(shard, bytes);
    const args = command === 'merge' ? ['merge', '--output', join(scratch, 'merged.parquet'), shard, join(scratch, 's2.parquet')] : ['reproduce', shard];
    const exit = await phasebook(args);
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).toMatch(new RegExp(`^phasebook: ${shard.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}( is damaged|:)`));
    expect(exit.stderr).not.toMatch(/internal error/);
  });
});

describe('signals', () => {
  /** Two JSON shards of 400 000 values each: seconds of reading and writing, far past the moment a signal is sent. */
  async function bigShards(): Promise<string[]> {
    const shards = [1, 2].map((i) => join(scratch, `s${i}.json`));
    const args = ['--hamiltonian', 'p^2/2 + q^2/2', '--dof', '1', '--sample', '200', '--box', 'q=-1:1,p=-1:1', '--t-end', '10', '--every', '10'];
    await Promise.all(shards.map((file, i) => simulate([...args, '--shard', `${i + 1}/2`, '--output', file])));
    return shards;
  }

  it.each([
    ['SIGINT', 130],
    ['SIGTERM', 143],
  ] as const)('%s stops merge once it writes: status %i, one line, no output and no partial', async (signal, status) => {
    const shards = await bigShards();
    const out = join(scratch, 'merged.json');
    const run = start(['merge', '--output', out, ...shards]);
    await until(() => partials().length === 1, 'the partial file exists');
    run.child.kill(signal);
    const exit = await run.exited;
    expect(exit.code).toBe(status);
    expect(exit.stderr).toBe(`phasebook: stopped by ${signal}; ${out} was not written\n`);
    expect(existsSync(out)).toBe(false);
    expect(partials()).toEqual([]);
  });

  it('SIGTERM stops reproduce once it writes its run again: status 143, one line naming the file, no temporary file left', async () => {
    const [file] = await bigShards();
    const run = start(['reproduce', file]);
    await until(() => partials().length === 1, 'the run again is being written');
    run.child.kill('SIGTERM');
    const exit = await run.exited;
    expect(exit.code).toBe(143);
    expect(exit.stderr).toBe(`phasebook: stopped by SIGTERM; ${file} was not reproduced\n`);
    expect(partials()).toEqual([]);
  });
});

/** Resolves once `condition` holds, checking every 10 ms. */
async function until(condition: () => boolean, what: string, timeoutMs = 30_000): Promise<void> {
  const deadline = performance.now() + timeoutMs;
  while (!condition()) {
    if (performance.now() > deadline) throw new Error(`timed out waiting until ${what}`);
    await new Promise((resolve) => setTimeout(resolve, 10));
  }
}
