/**
 * What the researcher of issue 9 also found, each checked: --t0 and listed
 * output times (against the oscillator's closed form), the README's three
 * spectrum peaks, user mistakes said in words (never "internal error"), the
 * output checked before anything is computed, a JS H that returns a string,
 * a binary file given to spectrum, and expressions with named coordinates,
 * min, max, atan2, conditionals and parameters written as arithmetic.
 */
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { main } from '../../../cli/main.ts';
import { parseCSV } from '../../../core/tables/csv-read.ts';
import { captureWrites, useScratchCache } from '../support/cli-harness.ts';

let dir: string;
let stderr: string[];
let stdout: string[];
useScratchCache({ compiledCli: false });
beforeEach(() => {
  dir = mkdtempSync(join(tmpdir(), 'phasebook-found-'));
  stderr = captureWrites(process.stderr);
  stdout = captureWrites(process.stdout);
});
afterEach(() => vi.restoreAllMocks());

const simulate = (...args: string[]) => main(['simulate', ...args, '--workers', '1']);
const rows = (text: string) => {
  const table = parseCSV(text);
  const w = table.columns.length;
  return { columns: table.columns, rows: Array.from({ length: table.rows }, (_, r) => Array.from(table.data.subarray(r * w, (r + 1) * w))) };
};
const oneLine = () => expect(stderr.join('').trim().split('\n')).toHaveLength(1);

describe('time', () => {
  it('starts at --t0, for an H that depends on t: the driven oscillator q̈ = −q + cos 2t', async () => {
    // H = p²/2 + q²/2 − q cos 2t; from q(t0) = q0, p(t0) = p0 the solution is
    // q = A cos t + B sin t − cos(2t)/3 with A, B fixed by the state at t0 (any ODE text, e.g. Arnold §26).
    const t0 = 1.3;
    const out = join(dir, 'driven.csv');
    expect(await simulate('--hamiltonian', 'p^2/2 + q^2/2 - q*cos(2*t)', '--dof', '1', '--initial', '0.5,0', '--t0', String(t0), '--t-end', String(t0 + 3), '--every', '1000', '--output', out)).toBe(0);
    const { rows: data } = rows(readFileSync(out, 'utf8'));
    // q(t0) = 0.5, q̇(t0) = 0: solve for A, B.
    const c = 0.5 + Math.cos(2 * t0) / 3;
    const d = -(2 * Math.sin(2 * t0)) / 3;
    const A = c * Math.cos(t0) - d * Math.sin(t0);
    const B = c * Math.sin(t0) + d * Math.cos(t0);
    expect(data[0][0]).toBe(t0);
    for (const [t, q] of data) expect(Math.abs(q - (A * Math.cos(t) + B * Math.sin(t) - Math.cos(2 * t) / 3))).toBeLessThan(1e-12);
  });

  it('writes exactly the --times asked for, between steps too (oscillator: q = cos t)', async () => {
    const out = join(dir, 'times.csv');
    const times = [0.1, 0.25, 1.00001, 2.5];
    expect(await simulate('--hamiltonian', 'p^2/2 + q^2/2', '--dof', '1', '--initial', '1,0', '--times', times.join(','), '--output', out)).toBe(0);
    const { rows: data } = rows(readFileSync(out, 'utf8'));
    expect(data.map((r) => r[0])).toEqual(times);
    for (const [t, q, p] of data) {
      expect(Math.abs(q - Math.cos(t))).toBeLessThan(1e-12);
      expect(Math.abs(p + Math.sin(t))).toBeLessThan(1e-12);
    }
  });
});

describe('spectrum', () => {
  it('prints the three peaks of the README\'s example for --top 3: ω, 2ω and 3ω', async () => {
    const data = join(dir, 'nonlinear.csv');
    const nonlinear = ['--hamiltonian', 'p^2/2 + omega0^2*q^2/2 + alpha*q^3 + beta*q^4', '--dof', '1', '--initial', '1,0', '--param', 'omega0=10', '--param', 'alpha=-2', '--param', 'beta=-3'];
    expect(await simulate(...nonlinear, '--t-end', '100', '--every', '10', '--output', data)).toBe(0);
    expect(await main(['spectrum', '--input', data, '--column', 'q', '--top', '3'])).toBe(0);
    const lines = stdout.join('').trim().split('\n');
    expect(lines).toHaveLength(4);
    const f = lines.slice(1).map((line) => Number(/f = (\S+)/.exec(line)![1]));
    // Landau & Lifshitz §28: the line at ω ≈ 9.535 rad per unit time and its harmonics at 2ω and 3ω.
    expect(f[0]).toBeCloseTo(9.535 / (2 * Math.PI), 2);
    expect(f[1] / f[0]).toBeCloseTo(2, 3);
    expect(f[2] / f[0]).toBeCloseTo(3, 3);
  });

  it.each([
    ['a binary file', Buffer.from([0, 1, 2, 3, 0, 255, 10, 0]), /is binary; spectrum reads CSV, JSON, NPZ or Parquet files as phasebook writes them/],
    ['a damaged NPZ', Buffer.from('PK\x03\x04rest of an archive', 'latin1'), /input\.dat is not a ZIP archive \(NPZ\) that can be read: no end of central directory/],
    ['a NaN sample', Buffer.from('t,q\n0,1\n1,NaN\n2,0\n3,1\n4,0\n'), /q is NaN at t = 1 in \S+; a spectrum needs finite samples/],
  ])('says what is wrong with %s, in one line', async (_, bytes, message) => {
    const file = join(dir, 'input.dat');
    writeFileSync(file, bytes);
    expect(await main(['spectrum', '--input', file, '--column', 'q'])).toBe(2);
    expect(stderr.join('')).toMatch(message);
    expect(stderr.join('')).not.toMatch(/internal error/);
    oneLine();
  });

  it.each(['npz', 'parquet', 'json', 'csv'])('reads one trajectory of a %s dataset, as simulate wrote it: the lines of that trajectory alone', async (format) => {
    // Three oscillators of amplitudes from the grid; ω = 1, so every line is at f = 1/2π whatever the format.
    const set = join(dir, `set.${format}`);
    expect(await simulate('--hamiltonian', 'p^2/2 + q^2/2', '--dof', '1', '--grid', 'q=1:3:3,p=0', '--t-end', '60', '--every', '40', '--output', set)).toBe(0);
    expect(await main(['spectrum', '--input', set, '--column', 'q', '--trajectory', '2', '--top', '1', '--format', 'json'])).toBe(0);
    const { peaks } = JSON.parse(stdout.join(''));
    expect(peaks[0].frequency).toBeCloseTo(1 / (2 * Math.PI), 2);
    expect(peaks[0].amplitude).toBeCloseTo(3, 1);
    expect(await main(['spectrum', '--input', set, '--column', 'q'])).toBe(2);
    expect(stderr.join('')).toBe(`phasebook: ${set} holds 3 trajectories: choose one with --trajectory J\n`);
  });
});

describe('user mistakes said in words, status 2, no file', () => {
  const oscillator = ['--hamiltonian', 'p^2/2 + q^2/2', '--dof', '1', '--initial', '1,0', '--t-end', '1'];
  it.each([
    ['an output path that is a directory', () => [...oscillator, '--output', dir], /cannot write \S+: it is a directory/],
    ['an output in a missing directory', () => [...oscillator, '--output', join(dir, 'no', 'such', 'x.csv')], /the directory \S+ does not exist/],
    ['a non-ASCII parameter name', () => ['--hamiltonian', 'p^2/2 + ω*q^2', '--dof', '1', '--initial', '1,0', '--param', 'ω=2'], /the parameter name "ω" is not a valid name \(a name is ASCII letters, digits and _: write omega/],
    ['a JS H that throws during the run', () => ['--hamiltonian', '(t, x) => { if (t > 0.01) throw new Error("too late"); return x[1]**2/2 + x[0]**2/2; }', '--dof', '1', '--initial', '1,0', '--t-end', '1'], /H fails between t = \S+ and t = \S+: too late/],
    ['a JS H that returns a string', () => ['--hamiltonian', '(t, x) => "1.5"', '--dof', '1', '--initial', '1,0'], /H must return a number, but returns the string "1\.5" at t = 0/],
    ['an operator H may not use', () => ['--hamiltonian', 'p^2/2 + q % 2', '--dof', '1', '--initial', '1,0'], /H may not use the operator %/],
  ])('%s', async (_, args, message) => {
    const before = readdirSync(dir);
    expect(await simulate(...args())).toBe(2);
    expect(stderr.join('')).toMatch(message);
    expect(stderr.join('')).not.toMatch(/internal error/);
    oneLine();
    expect(readdirSync(dir)).toEqual(before);
  });

  it('finds an unwritable output before anything is computed: before an energy no point reaches is even looked for', async () => {
    const locked = join(dir, 'locked');
    mkdirSync(locked);
    const args = ['--hamiltonian', 'p^2/2 + q^2/2', '--dof', '1', '--sample', '5', '--box', 'q=-1:1,p=-1:1', '--energy', '-3'];
    expect(await simulate(...args, '--output', join(dir, 'missing', 'out.npz'))).toBe(2);
    expect(stderr.join('')).toMatch(/cannot write .*missing\/out\.npz: the directory \S+ does not exist/);
    stderr.length = 0;
    expect(await simulate(...args, '--output', join(locked, 'out.npz'))).toBe(2);
    expect(stderr.join('')).toMatch(/no point of the box reaches H = -3/);
    expect(readdirSync(locked)).toEqual([]);
  });
});

describe('expressions', () => {
  it('name coordinates and momenta with --coordinates and --momenta', async () => {
    const out = join(dir, 'named.csv');
    expect(await simulate('--hamiltonian', 'px^2/2 + py^2/2 + x^2/2 + 2*y^2', '--coordinates', 'x,y', '--momenta', 'px,py', '--dof', '2', '--initial', '1,1,0,0', '--t-end', '2', '--every', '1000', '--output', out)).toBe(0);
    const { columns, rows: data } = rows(readFileSync(out, 'utf8'));
    expect(columns).toEqual(['t', 'x', 'y', 'px', 'py', 'H']);
    // Two oscillators, ω = 1 and ω = 2: x = cos t, y = cos 2t.
    for (const [t, x, y] of data) {
      expect(Math.abs(x - Math.cos(t))).toBeLessThan(1e-12);
      expect(Math.abs(y - Math.cos(2 * t))).toBeLessThan(1e-11);
    }
  });

  it('take a parameter written as arithmetic: ω = 2*pi makes the period 1', async () => {
    const out = join(dir, 'period.csv');
    expect(await simulate('--hamiltonian', 'p^2/2 + w^2*q^2/2', '--param', 'w=2*pi', '--dof', '1', '--initial', '1,0', '--t-end', '1', '--every', '2000', '--output', out)).toBe(0);
    const { rows: data } = rows(readFileSync(out, 'utf8'));
    expect(data[1][0]).toBe(1);
    // RK 3/8 at ω·dt = π/1000: error ~ (ω dt)⁴ ω t / 120 ≈ 5e-13.
    expect(Math.abs(data[1][1] - 1)).toBeLessThan(1e-10);
  });

  it.each([
    ['max(q, -q)', 'max'],
    ['min(q, -q) + 2*max(q, -q)', 'min and max'],
    ['(q > 0 ? q : -q)', 'a conditional'],
  ])('differentiate %s (%s) exactly: a V-shaped well, q = 1 − t²/2 until q = 0', async (potential) => {
    // |q| pushes back with a constant unit force: from (1, 0), q = 1 − t²/2 and p = −t for t < √2.
    // RK 3/8 is exact for motion quadratic in t, so only rounding remains.
    const out = join(dir, 'v.csv');
    expect(await simulate('--hamiltonian', `p^2/2 + ${potential}`, '--dof', '1', '--initial', '1,0', '--t-end', '1.2', '--every', '400', '--output', out)).toBe(0);
    for (const [t, q, p] of rows(readFileSync(out, 'utf8')).rows) {
      expect(Math.abs(q - (1 - (t * t) / 2))).toBeLessThan(1e-13);
      expect(Math.abs(p + t)).toBeLessThan(1e-13);
    }
  });

  it('differentiate atan2 exactly: ∂atan2(y, x)/∂x = −y/(x² + y²), ∂/∂y = x/(x² + y²)', async () => {
    const out = join(dir, 'atan2.csv');
    expect(await simulate('--hamiltonian', 'p0^2/2 + p1^2/2 + atan2(q1, q0)', '--dof', '2', '--initial', '0.6,-0.8,0,0', '--t-end', '0', '--derivatives', '--output', out)).toBe(0);
    const [[, , , , , , , , dp0, dp1]] = rows(readFileSync(out, 'utf8')).rows;
    const [x, y] = [0.6, -0.8];
    expect(dp0).toBeCloseTo(y / (x * x + y * y), 15);
    expect(dp1).toBeCloseTo(-x / (x * x + y * y), 15);
  });
});
