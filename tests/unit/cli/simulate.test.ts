import { execFile } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { main } from '../../../cli/main.ts';
import { canonicalEquations } from '../../../core/model/canonical-equations.ts';
import { parseCSV } from '../../../core/tables/csv-read.ts';
import { parseJSON } from '../../../core/index.ts';
import { Simulation } from '../../../core/simulation.ts';
import { captureWrites, useScratchCache } from '../support/cli-harness.ts';

const run = promisify(execFile);
const BIN = join(import.meta.dirname, '../../../bin/phasebook.mjs');
const NONLINEAR = ['--hamiltonian', 'p^2/2 + omega0^2*q^2/2 + alpha*q^3 + beta*q^4', '--dof', '1', '--initial', '1,0'];
const NONLINEAR_PARAMS = ['--param', 'omega0=10', '--param', 'alpha=-2', '--param', 'beta=-3'];

let dir: string;
let stderr: string[];
useScratchCache();
beforeEach(() => {
  dir = mkdtempSync(join(tmpdir(), 'phasebook-cli-'));
  stderr = captureWrites(process.stderr);
});
afterEach(() => vi.restoreAllMocks());

describe('phasebook simulate', () => {
  it('writes rows every K steps from t = 0, with the values an in-process simulation gives', async () => {
    const out = join(dir, 'run.csv');
    const code = await main(['simulate', ...NONLINEAR, ...NONLINEAR_PARAMS, '--t-end', '2', '--every', '7', '--output', out]);
    expect(code).toBe(0);
    const table = parseCSV(readFileSync(out, 'utf8'));
    expect(table.columns).toEqual(['t', 'q', 'p', 'H']);
    expect(table.rows).toBe(Math.floor(4000 / 7) + 1);
    const model = await canonicalEquations({ dof: 1, hamiltonian: NONLINEAR[1], params: { omega0: 10, alpha: -2, beta: -3 } });
    const sim = new Simulation(model, { initial: [1, 0], every: 7 });
    sim.run(4000);
    expect(Array.from(table.data)).toEqual(Array.from(sim.record.table().data));
  });

  it('writes JSON whose meta is enough to reproduce the file', async () => {
    const out = join(dir, 'run.json');
    const args = ['simulate', ...NONLINEAR, ...NONLINEAR_PARAMS, '--t-end', '0.5', '--dt', '1e-3', '--format', 'json', '--output', out];
    expect(await main(args)).toBe(0);
    const { meta, table } = parseJSON(readFileSync(out, 'utf8'));
    expect(meta).toMatchObject({ hamiltonian: NONLINEAR[1], params: { omega0: 10, alpha: -2, beta: -3 }, dof: 1, dt: 1e-3, method: 'rk38', every: 1, initial: [1, 0] });
    const again = join(dir, 'again.csv');
    const params = Object.entries(meta.params).flatMap(([k, v]) => ['--param', `${k}=${v}`]);
    await main(['simulate', '--hamiltonian', meta.hamiltonian, '--dof', String(meta.dof), '--initial', meta.initial.join(','), ...params, '--dt', String(meta.dt), '--t-end', '0.5', '--output', again]);
    expect(Array.from(parseCSV(readFileSync(again, 'utf8')).data)).toEqual(Array.from(table.data));
  });

  it('integrates a --vector-field as written, with its source and H in the JSON meta', async () => {
    const out = join(dir, 'pendulum.json');
    const field = '(t, [q, p], dxdt) => { dxdt[0] = p; dxdt[1] = -g*sin(q); }';
    const h = '(t, [q, p]) => p*p/2 - g*cos(q)';
    const args = ['simulate', '--vector-field', field, '--hamiltonian', h, '--param', 'g=9.81', '--dof', '1', '--initial', '1,0'];
    expect(await main([...args, '--t-end', '10', '--every', '100', '--format', 'json', '--output', out])).toBe(0);
    const { meta, table } = parseJSON(readFileSync(out, 'utf8'));
    expect(meta).toMatchObject({ route: 'vector-field', vectorField: field, hamiltonian: h, params: { g: 9.81 } });
    expect(table.columns).toEqual(['t', 'q', 'p', 'H']);
    expect(table.rows).toBe(201);
    // The pendulum conserves H = −g cos 1; RK 3/8 at dt = 5e-4 drifts by ~1e-13 over 10 time units.
    for (let r = 0; r < table.rows; r++) expect(Math.abs(table.data[4 * r + 3] + 9.81 * Math.cos(1))).toBeLessThan(1e-10);
  });

  it.each([
    [['--hamiltonian', 'p^2/2 + (q', '--dof', '1', '--initial', '1,0'], /syntax error in H at column/],
    [['--hamiltonian', '(t, x) => x[1]**2/2 + * 2', '--dof', '1', '--initial', '1,0'], /syntax error in H at line 1, column 23/],
    [['--hamiltonian', 'p^2/2', '--dof', '1', '--initial', '1,0,3'], /--initial has 3 values; 1 degree\(s\) of freedom need 2/],
    [['--hamiltonian', 'p^2/2', '--dof', '1', '--initial', '1,zero'], /--initial value 2 must be a number, not "zero"/],
    [['--hamiltonian', 'p^2/2', '--dof', '1', '--initial', '1,0', '--dt', '0'], /--dt must be positive/],
    [['--hamiltonian', 'p^2/2', '--dof', '1', '--initial', '1,0', '--dt', '-1e-3'], /--dt must be positive/],
    [['--hamiltonian', 'p^2/2', '--dof', '1', '--initial', '1,0', '--speed', '2'], /unknown option --speed/],
    [['--hamiltonian', 'p^2/2 + k*q^2', '--dof', '1', '--initial', '1,0'], /unknown name k in H/],
    [['--hamiltonian', '(t, x) => x[1]**2/2 + k*x[0]**2', '--dof', '1', '--initial', '1,0'], /H fails at t = 0: k is not defined/],
    [['--hamiltonian', 'p0^2 + p1^2 + p2^2 + p3^2 - 500/sqrt((q0-q2)^2 + (q1-q3)^2)', '--dof', '4', '--initial', '1,1,1,1,0,0,0,0'], /NaN at t = 0\.0005 in q0/],
  ])('refuses %j with one line on stderr, status 2 and no file', async (args, message) => {
    const out = join(dir, 'out.csv');
    const code = await main(['simulate', ...args, '--output', out]);
    expect(code).toBe(2);
    expect(stderr.join('')).toMatch(message);
    expect(stderr.join('').trim().split('\n')).toHaveLength(1);
    expect(readdirSync(dir)).toEqual([]);
  });

  it('leaves no partial file when the state blows up after rows were written', async () => {
    // V = −q⁴ sends q to infinity in finite time (q̈ = 4q³; from (1, 0) at t = ∫₁^∞ dq/√(2(q⁴ − 1)) ≈ 0.93), after thousands of rows.
    const out = join(dir, 'blowup.csv');
    const code = await main(['simulate', '--hamiltonian', 'p^2/2 - q^4', '--dof', '1', '--initial', '1,0', '--t-end', '5', '--output', out]);
    expect(code).toBe(2);
    expect(stderr.join('')).toMatch(/at t = 0\.\d+ in [qp]/);
    expect(existsSync(out)).toBe(false);
    expect(readdirSync(dir)).toEqual([]);
  });
});

describe('phasebook spectrum', () => {
  it('finds the nonlinear oscillator at 1.518 cycles per unit time, strongest first, as JSON', async () => {
    const data = join(dir, 'nl.csv');
    await main(['simulate', ...NONLINEAR, ...NONLINEAR_PARAMS, '--t-end', '60', '--every', '10', '--output', data]);
    const write = vi.spyOn(process.stdout, 'write').mockImplementation(() => true);
    expect(await main(['spectrum', '--input', data, '--column', 'q', '--top', '3', '--format', 'json'])).toBe(0);
    const { peaks } = JSON.parse(String(write.mock.calls[0][0]));
    expect(peaks).toHaveLength(3);
    // Landau & Lifshitz §28: ω ≈ 9.535 rad per unit time, i.e. 1.5175 cycles per unit time, to O(b²).
    expect(peaks[0].frequency).toBeCloseTo(9.535 / (2 * Math.PI), 2);
    expect(peaks[0].amplitude).toBeGreaterThan(peaks[1].amplitude);
  });

  it.each([
    [['--input', 'missing.csv', '--column', 'q'], /cannot read missing\.csv: no such file/],
    [['--column', 'q'], /--input is required/],
    [['--input', '@DATA', '--column', 'x'], /no column "x"/],
    [['--input', '@DATA', '--column', 'q', '--window', 'hann'], /--window must be hamming or none/],
  ])('refuses %j with one line and status 2', async (args, message) => {
    const data = join(dir, 'd.csv');
    writeFileSync(data, 't,q\n0,1\n1,0\n2,-1\n3,0\n4,1\n');
    const code = await main(['spectrum', ...args.map((a) => a.replace('@DATA', data))]);
    expect(code).toBe(2);
    expect(stderr.join('')).toMatch(message);
  });
});

describe('bin/phasebook.mjs', () => {
  it('prints CSV to stdout, and takes a negative value as a separate argument', async () => {
    const { stdout } = await run('node', [BIN, 'simulate', '--hamiltonian', 'sqrt(p^2 + 10) - 0.8 q', '--dof', '1', '--initial', '-10,-10', '--t-end', '1', '--every', '1000']);
    const table = parseCSV(stdout);
    expect(table.rows).toBe(3);
    // Closed form (paper 7.4): p = −10 + 0.8t.
    expect(table.data[2 * 4 + 2]).toBeCloseTo(-9.2, 10); // rounding of 2000 additions
  });

  it('exits with status 2 and one stderr line on bad input', async () => {
    const error = await run('node', [BIN, 'simulate', '--dof', '1']).catch((e: { code: number; stderr: string }) => e);
    expect((error as { code: number }).code).toBe(2);
    expect((error as { stderr: string }).stderr.trim().split('\n')).toHaveLength(1);
    expect((error as { stderr: string }).stderr).toMatch(/^phasebook: --hamiltonian is required/);
  });
});
