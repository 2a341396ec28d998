/**
 * The compiled CLI as a user runs it, one process per run: which modules a
 * run loads (recorded by a module hook), the cache of compiled models, and
 * the physics of what it prints, checked against closed forms.
 */
import { execFile } from 'node:child_process';
import { copyFileSync, mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { beforeAll, beforeEach, describe, expect, it } from 'vitest';
import { ensureCli, freshEntry, OUT_DIR, ROOT } from '../../../bin/cli-bundle.mjs';
import { parseCSV } from '../../../core/tables/csv-read.ts';

const BIN = join(ROOT, 'bin/phasebook.mjs');
const HOOK = join(import.meta.dirname, '../support/record-loads.mjs');

interface Run {
  code: number;
  stdout: string;
  stderr: string;
  /** URLs of every module the process loaded */
  loaded: string[];
}

let scratch: string;
let cache: string;
let runs = 0;

/** Runs `phasebook …args` with the load recorder and the given cache folder. */
function phasebook(args: string[], cacheDir = cache): Promise<Run> {
  const log = join(scratch, `loads-${runs++}.txt`);
  writeFileSync(log, '');
  const env = { ...process.env, PHASEBOOK_CACHE_DIR: cacheDir, PHASEBOOK_LOAD_LOG: log };
  return new Promise((resolve) => {
    execFile('node', ['--import', HOOK, BIN, ...args], { env }, (error, stdout, stderr) => {
      const code = error ? Number((error as { code?: unknown }).code ?? 1) : 0;
      resolve({ code, stdout, stderr, loaded: readFileSync(log, 'utf8').split('\n').filter(Boolean) });
    });
  });
}

/** The bundle's files that hold any of mathjs or acorn, as the loader names them. */
let parserChunks: { mathjs: string[]; acorn: string[] };
let entryUrl: string;

const loadsMathjs = (run: Run) => run.loaded.some((url) => parserChunks.mathjs.includes(url) || /\/node_modules\/mathjs\//.test(url));
const loadsAcorn = (run: Run) => run.loaded.some((url) => parserChunks.acorn.includes(url) || /\/node_modules\/acorn\//.test(url));

beforeAll(async () => {
  await ensureCli();
  const entry = freshEntry();
  expect(entry, 'the compiled CLI is in place and up to date').toBeDefined();
  entryUrl = pathToFileURL(entry!).href;
  const meta = JSON.parse(readFileSync(join(OUT_DIR, 'metafile.json'), 'utf8')) as { outputs: Record<string, { inputs: Record<string, unknown> }> };
  const holding = (pkg: string) =>
    Object.entries(meta.outputs)
      .filter(([, output]) => Object.keys(output.inputs).some((input) => input.startsWith(`node_modules/${pkg}/`)))
      .map(([file]) => pathToFileURL(join(ROOT, file)).href);
  parserChunks = { mathjs: holding('mathjs'), acorn: holding('acorn') };
  // Code splitting kept them out of the entry: otherwise every check below would be vacuous or fail.
  expect(parserChunks.mathjs.length).toBeGreaterThan(0);
  expect(parserChunks.acorn.length).toBeGreaterThan(0);
  expect([...parserChunks.mathjs, ...parserChunks.acorn]).not.toContain(entryUrl);
});

beforeEach(() => {
  scratch = mkdtempSync(join(tmpdir(), 'phasebook-process-'));
  cache = join(scratch, 'cache');
});

// ω is a parameter, so one compiled model serves every frequency.
const OSCILLATOR = ['simulate', '--hamiltonian', 'p^2/2 + w^2*q^2/2', '--dof', '1', '--initial', '1,0', '--t-end', '1', '--every', '500'];
const JS_OSCILLATOR = ['simulate', '--hamiltonian', '(t, qp) => { let [q, p] = qp; return p**2/2 + w**2*q**2/2; }', '--dof', '1', '--initial', '1,0', '--t-end', '1', '--every', '500'];
const FIELD = ['simulate', '--vector-field', '(t, x, dxdt) => { dxdt[0] = x[1]; dxdt[1] = -w*w*x[0]; }', '--dof', '1', '--initial', '1,0', '--t-end', '1', '--every', '500'];

/**
 * Checks every row against the closed form q = cos ωt, p = −ω sin ωt (and
 * H = ω²/2 where there is an H column). RK 3/8's global error here is about
 * (ω dt)⁴·ωt/120 ≈ 1e-13 for ω ≤ 3 up to t = 1; 1e-11 leaves room for
 * rounding and fails for any real mistake in the equations.
 */
function expectOscillator(run: Run, w: number): void {
  expect(run.stderr).toBe('');
  expect(run.code).toBe(0);
  const table = parseCSV(run.stdout);
  expect(table.rows).toBe(5);
  const width = table.columns.length;
  for (let r = 0; r < table.rows; r++) {
    const [t, q, p] = table.data.subarray(r * width, r * width + 3);
    expect(Math.abs(q - Math.cos(w * t))).toBeLessThan(1e-11);
    expect(Math.abs(p + w * Math.sin(w * t))).toBeLessThan(1e-11);
    if (width === 4) expect(Math.abs(table.data[r * width + 3] - (w * w) / 2)).toBeLessThan(1e-11);
  }
}

describe('phasebook simulate, as a process', () => {
  it('compiles H with mathjs on the first run; the next runs take it from the cache and load neither mathjs nor acorn', async () => {
    const first = await phasebook([...OSCILLATOR, '--param', 'w=2']);
    expectOscillator(first, 2);
    expect(first.loaded).toContain(entryUrl);
    expect(loadsMathjs(first)).toBe(true);
    expect(readdirSync(cache)).toHaveLength(1);

    const second = await phasebook([...OSCILLATOR, '--param', 'w=2']);
    expect(second.loaded).toContain(entryUrl);
    expect(loadsMathjs(second)).toBe(false);
    expect(loadsAcorn(second)).toBe(false);
    expect(second.stdout).toBe(first.stdout);

    // Parameter values are not part of the key: another ω reuses the compiled model, with its own physics.
    const other = await phasebook([...OSCILLATOR, '--param', 'w=3']);
    expectOscillator(other, 3);
    expect(loadsMathjs(other)).toBe(false);
  });

  it('translates a JS function H with acorn on the first run, and takes it from the cache on the next', async () => {
    const first = await phasebook([...JS_OSCILLATOR, '--param', 'w=2']);
    expectOscillator(first, 2);
    expect(loadsAcorn(first)).toBe(true);
    const second = await phasebook([...JS_OSCILLATOR, '--param', 'w=2']);
    expect(second.stdout).toBe(first.stdout);
    expect(loadsAcorn(second) || loadsMathjs(second)).toBe(false);
  });

  it('integrates a --vector-field with neither mathjs nor acorn, and caches nothing', async () => {
    const run = await phasebook([...FIELD, '--param', 'w=3']);
    expectOscillator(run, 3);
    expect(parseCSV(run.stdout).columns).toEqual(['t', 'q', 'p']);
    expect(run.loaded).toContain(entryUrl);
    expect(loadsMathjs(run) || loadsAcorn(run)).toBe(false);
    expect(() => readdirSync(cache)).toThrow(/ENOENT/);

    const withH = await phasebook([...FIELD, '--param', 'w=3', '--hamiltonian', '(t, x) => x[1]**2/2 + w*w*x[0]**2/2']);
    expectOscillator(withH, 3);
    expect(parseCSV(withH.stdout).columns).toEqual(['t', 'q', 'p', 'H']);
    expect(loadsMathjs(withH) || loadsAcorn(withH)).toBe(false);
  });

  it.each([
    ['text that is not a cache file', () => 'not a cache file'],
    ['a file cut short', (text: string) => text.slice(0, text.length >> 1)],
    ['generated code altered under an intact first line', (text: string) => text.replace('return', 'retrun')],
    ['a JSON body altered under an intact first line', (text: string) => text.replace(/"w"/, '"v"')],
  ])('compiles afresh, prints the same rows and repairs the entry when the cache file is %s', async (_, damage) => {
    const good = await phasebook([...OSCILLATOR, '--param', 'w=2']);
    const [file] = readdirSync(cache);
    const path = join(cache, file);
    const damaged = damage(readFileSync(path, 'utf8'));
    writeFileSync(path, damaged);
    const again = await phasebook([...OSCILLATOR, '--param', 'w=2']);
    expect(again.stderr).toBe('');
    expect(again.stdout).toBe(good.stdout);
    expect(loadsMathjs(again)).toBe(true);
    expect(readFileSync(path, 'utf8')).not.toBe(damaged);
    expect(loadsMathjs(await phasebook([...OSCILLATOR, '--param', 'w=2']))).toBe(false);
  });

  it('compiles afresh when the file under its name holds another model (a hash collision, a stale copy)', async () => {
    await phasebook([...OSCILLATOR, '--param', 'w=2']);
    const [oscillatorFile] = readdirSync(cache);
    const quartic = ['simulate', '--hamiltonian', 'p^2/2 + w*q^4', '--dof', '1', '--initial', '1,0', '--t-end', '1', '--every', '500', '--param', 'w=2'];
    const good = await phasebook(quartic);
    const quarticFile = readdirSync(cache).find((f) => f !== oscillatorFile)!;
    copyFileSync(join(cache, oscillatorFile), join(cache, quarticFile));
    const again = await phasebook(quartic);
    expect(again.stdout).toBe(good.stdout);
    expect(loadsMathjs(again)).toBe(true);
  });

  it('runs, compiling each time, when the cache folder cannot be made', async () => {
    const blocker = join(scratch, 'a-file');
    writeFileSync(blocker, '');
    const unwritable = join(blocker, 'models');
    const first = await phasebook([...OSCILLATOR, '--param', 'w=2'], unwritable);
    expectOscillator(first, 2);
    const second = await phasebook([...OSCILLATOR, '--param', 'w=2'], unwritable);
    expectOscillator(second, 2);
    expect(loadsMathjs(second)).toBe(true);
  });

  it('neither reads nor writes the cache with --no-cache', async () => {
    await phasebook([...OSCILLATOR, '--param', 'w=2']);
    const uncached = await phasebook([...OSCILLATOR, '--param', 'w=2', '--no-cache']);
    expectOscillator(uncached, 2);
    expect(loadsMathjs(uncached)).toBe(true);
    await phasebook([...JS_OSCILLATOR, '--param', 'w=2', '--no-cache']);
    expect(readdirSync(cache)).toHaveLength(1);
  });

  it.each([
    [['--vector-field', '(t, x, dxdt) => { dxdt[0] = x[1] +* 2; }'], /^phasebook: syntax error in --vector-field: /],
    [['--vector-field', 'x[1]'], /^phasebook: --vector-field must be a JS function/],
    [['--vector-field', '(t, x) => [x[1], -x[0]]'], /^phasebook: the vector field gives no finite dx\/dt for q \(dxdt\[0\]\)/],
    [['--vector-field', '(t, x, dxdt) => { dxdt[0] = x[1]; }'], /^phasebook: the vector field gives no finite dx\/dt for p \(dxdt\[1\]\)/],
    [['--vector-field', '(t, x, dxdt) => { dxdt[0] = k*x[1]; }'], /^phasebook: the vector field fails at t = 0: k is not defined/],
    [['--vector-field', '(t, x, dxdt) => { dxdt[0] = x[1]; dxdt[1] = -x[0]; }', '--hamiltonian', 'p^2/2'], /^phasebook: with --vector-field, --hamiltonian must be a JS function/],
  ])('refuses %j with one line on stderr, status 2 and no output file', async (args, message) => {
    const out = join(scratch, 'out.csv');
    const run = await phasebook(['simulate', ...args, '--dof', '1', '--initial', '1,0', '--output', out]);
    expect(run.code).toBe(2);
    expect(run.stderr).toMatch(message);
    expect(run.stderr.trim().split('\n')).toHaveLength(1);
    expect(readdirSync(scratch).filter((f) => !f.startsWith('loads-'))).toEqual([]);
  });
});
