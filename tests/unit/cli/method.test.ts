/**
 * `phasebook simulate --method`: the method and the adaptive tolerances go
 * into the file's meta, `phasebook reproduce` runs the same method again
 * (bit for bit), and a bad choice is one line on stderr with status 2.
 */
import { execFile } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { main } from '../../../cli/main.ts';
import { parseJSON } from '../../../core/index.ts';
import { captureWrites, useScratchCache } from '../support/cli-harness.ts';

const PENDULUM = ['--hamiltonian', 'p^2/2 - cos(q)', '--dof', '1', '--initial', '2,0'];

let dir: string;
let stderr: string[];
let stdout: string[];
const BIN = join(import.meta.dirname, '../../../bin/phasebook.mjs');
useScratchCache();
beforeEach(() => {
  dir = mkdtempSync(join(tmpdir(), 'phasebook-method-'));
  stderr = captureWrites(process.stderr);
  stdout = captureWrites(process.stdout);
});
afterEach(() => vi.restoreAllMocks());

describe('phasebook simulate --method', () => {
  for (const method of ['verlet', 'yoshida4', 'midpoint', 'adaptive']) {
    it(`records --method ${method} in the meta, and reproduce runs it again bit for bit`, async () => {
      const out = join(dir, `${method}.json`);
      const tolerances = method === 'adaptive' ? ['--rtol', '1e-7', '--atol', '1e-10'] : [];
      const code = await main(['simulate', ...PENDULUM, '--method', method, ...tolerances, '--dt', '0.01', '--t-end', '5', '--every', '10', '--output', out]);
      expect(stderr.join('')).toBe('');
      expect(code).toBe(0);
      const { meta } = parseJSON(readFileSync(out, 'utf8'));
      expect(meta.method).toBe(method);
      if (method === 'adaptive') expect(meta).toMatchObject({ rtol: 1e-7, atol: 1e-10 });
      else expect(meta.rtol).toBeUndefined();
      expect(await main(['reproduce', out, '--workers', '1'])).toBe(0);
      expect(stdout.join('')).toMatch(/reproduced, 1 trajectories × 51 samples, all 204 numbers identical/);
    });
  }

  it('reproduce honours the meta: the same file relabelled as another method no longer reproduces', async () => {
    const out = join(dir, 'run.json');
    expect(await main(['simulate', ...PENDULUM, '--method', 'yoshida4', '--dt', '0.01', '--t-end', '1', '--output', out])).toBe(0);
    const text = readFileSync(out, 'utf8');
    writeFileSync(out, text.replace('"method":"yoshida4"', '"method":"verlet"'));
    expect(await main(['reproduce', out, '--workers', '1'])).toBe(1);
    expect(stdout.join('')).toMatch(/differs at sample 1, q/);
    // And with the tolerances of an adaptive run changed.
    const adaptive = join(dir, 'adaptive.json');
    expect(await main(['simulate', ...PENDULUM, '--method', 'adaptive', '--rtol', '1e-6', '--dt', '0.01', '--t-end', '1', '--output', adaptive])).toBe(0);
    writeFileSync(adaptive, readFileSync(adaptive, 'utf8').replace('"rtol":0.000001', '"rtol":1e-10'));
    expect(await main(['reproduce', adaptive, '--workers', '1'])).toBe(1);
  });

  it('writes rk38 as the method by default, as before', async () => {
    const out = join(dir, 'default.json');
    expect(await main(['simulate', ...PENDULUM, '--dt', '0.01', '--t-end', '0.1', '--output', out])).toBe(0);
    const { meta } = parseJSON(readFileSync(out, 'utf8'));
    expect(meta.method).toBe('rk38');
    expect('rtol' in meta).toBe(false);
  });

  it.each([
    [['--method', 'rk4'], /^phasebook: the method must be one of rk38, verlet, yoshida4, midpoint, adaptive, not "rk4"\n$/],
    [['--method', 'verlet', '--rtol', '1e-8'], /^phasebook: --rtol and --atol are tolerances of --method adaptive\n$/],
    [['--method', 'adaptive', '--rtol', 'tight'], /^phasebook: --rtol must be a number, not "tight"\n$/],
    [['--method', 'adaptive', '--rtol', '1e-17'], /^phasebook: rtol 1e-17 asks for more than double precision holds; give rtol ≥ 1e-14\n$/],
  ])('%j gives one line on stderr and status 2', async (extra, message) => {
    const code = await main(['simulate', ...PENDULUM, ...(extra as string[]), '--t-end', '0.1']);
    expect(code).toBe(2);
    expect(stderr.join('')).toMatch(message as RegExp);
  });

  it('the installed command exits with status 2 and one line on stderr for a bad --method', async () => {
    const failure = await promisify(execFile)('node', [BIN, 'simulate', ...PENDULUM, '--method', 'leapfrog']).then(
      () => undefined,
      (error: { code: number; stderr: string; stdout: string }) => error,
    );
    expect(failure?.code).toBe(2);
    expect(failure?.stdout).toBe('');
    expect(failure?.stderr).toBe('phasebook: the method must be one of rk38, verlet, yoshida4, midpoint, adaptive, not "leapfrog"\n');
  });

  it('a splitting method on an H that does not separate gives one line on stderr and status 2', async () => {
    const code = await main(['simulate', '--hamiltonian', 'p^2/2*(1 + q^2)', '--dof', '1', '--initial', '1,0', '--method', 'verlet', '--t-end', '0.1']);
    expect(code).toBe(2);
    const text = stderr.join('');
    expect(text.split('\n').filter(Boolean)).toHaveLength(1);
    expect(text).toMatch(/^phasebook: the method verlet needs H = T\(p\) \+ V\(q, t\), and this H does not separate: ∂H\/∂q = .* depends on p/);
  });
});
