import { mkdtempSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { main } from '../../../../cli/main.ts';
import { byteSize, checkRunSize, count, OUTPUT_LIMIT, runSize, STEP_LIMIT } from '../../../../cli/dataset/size.ts';

describe('runSize(shape)', () => {
  it('counts the steps as the run takes them, t-end reached by whole steps', () => {
    expect(runSize({ tEnd: 10, dt: 5e-4, every: 1, columns: 4, format: 'csv' })).toMatchObject({ steps: 20_000, rows: 20_001 });
    expect(runSize({ tEnd: 10, dt: 5e-4, every: 7, columns: 4, format: 'csv' }).rows).toBe(2858);
    expect(runSize({ tEnd: 10, dt: 1e-300, every: 1, columns: 4, format: 'csv' }).steps / 1e301).toBeCloseTo(1, 12);
  });

  describe('estimates the bytes of real output within a fifth', () => {
    let dir: string;
    const userCache = process.env.PHASEBOOK_CACHE_DIR;
    beforeEach(() => {
      dir = mkdtempSync(join(tmpdir(), 'phasebook-size-'));
      process.env.PHASEBOOK_CACHE_DIR = join(dir, 'cache');
      vi.spyOn(process.stderr, 'write').mockImplementation(() => true);
    });
    afterEach(() => {
      vi.restoreAllMocks();
      if (userCache === undefined) delete process.env.PHASEBOOK_CACHE_DIR;
      else process.env.PHASEBOOK_CACHE_DIR = userCache;
    });

    it.each([
      ['csv', 1, ['p^2/2 + omega0^2*q^2/2 + alpha*q^3 + beta*q^4', '--param', 'omega0=10', '--param', 'alpha=-2', '--param', 'beta=-3']],
      ['json', 1, ['p^2/2 + omega0^2*q^2/2 + alpha*q^3 + beta*q^4', '--param', 'omega0=10', '--param', 'alpha=-2', '--param', 'beta=-3']],
      ['csv', 3, ['p0^2/2 + p1^2/2 + p2^2/2 + q0^2/2 + q1^2/2 + q2^2/2 + q0^2*q1/10']],
    ] as const)('%s, %i degree(s) of freedom', async (format, dof, [hamiltonian, ...params]) => {
      const out = join(dir, `out.${format}`);
      const initial = Array.from({ length: 2 * dof }, (_, i) => (i < dof ? 1 - i / 10 : 0)).join(',');
      const args = ['simulate', '--hamiltonian', hamiltonian, ...params, '--dof', String(dof), '--initial', initial, '--t-end', '20', '--format', format, '--output', out];
      expect(await main(args)).toBe(0);
      const estimate = runSize({ tEnd: 20, dt: 5e-4, every: 1, columns: 2 + 2 * dof, format }).bytes;
      expect(estimate / statSync(out).size).toBeGreaterThan(0.8);
      expect(estimate / statSync(out).size).toBeLessThan(1.25);
    });
  });
});

describe('checkRunSize(size, force)', () => {
  const size = (steps: number, bytes: number) => ({ steps, rows: steps + 1, bytes });

  it('lets through a run within both limits, and any run with --force', () => {
    expect(() => checkRunSize(size(STEP_LIMIT, OUTPUT_LIMIT), false)).not.toThrow();
    expect(() => checkRunSize(size(1e301, 1e303), true)).not.toThrow();
  });

  it('refuses a run over either limit with both estimates on one line, annotating the limits exceeded', () => {
    expect(() => checkRunSize(size(1e301, 7.2e302), false)).toThrow(
      'this run would take 1e+301 steps (the limit is 1e+9; raise --dt or lower --t-end) and write about 7.2e+302 bytes of output (the limit is 1 GiB; raise --every or lower --t-end); add --force to run it anyway',
    );
    expect(() => checkRunSize(size(2e9, 150_000), false)).toThrow(
      'this run would take 2e+9 steps (the limit is 1e+9; raise --dt or lower --t-end) and write about 146 KiB of output; add --force to run it anyway',
    );
    expect(() => checkRunSize(size(2e8, 1.5e10), false)).toThrow(
      'this run would take 2e+8 steps and write about 14 GiB of output (the limit is 1 GiB; raise --every or lower --t-end); add --force to run it anyway',
    );
  });

  it('refuses a step count that overflows even with --force: that run could never end', () => {
    expect(() => checkRunSize(size(Infinity, Infinity), true)).toThrow(/too many steps to count/);
  });
});

describe('count and byteSize', () => {
  it('print as a person reads them', () => {
    expect([count(20_001), count(2.5e7), count(1e301), count(1234567)]).toEqual(['20001', '2.5e+7', '1e+301', '1.23e+6']);
    expect([byteSize(512), byteSize(13_067_945), byteSize(2 ** 30), byteSize(1e30)]).toEqual(['512 bytes', '12.5 MiB', '1 GiB', '1e+30 bytes']);
  });
});
