/**
 * The progress bar as a person sees it: `phasebook simulate` over many
 * trajectories on two worker threads, run on a pseudo-terminal (util-linux's
 * `script`), draws one bar over all the trajectories, redrawn in place, with
 * the count done and the time left, and clears it at the end; with stderr
 * not a terminal it draws nothing. The run is made long enough (4e8 steps,
 * several seconds even on a quiet machine, where the batch stepper takes
 * ~15 ns a step) that the bar, which waits a second before it appears, has to show.
 */
import { execFile, spawnSync } from 'node:child_process';
import { mkdtempSync, readdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { ensureCli, ROOT } from '../../../bin/cli-bundle.mjs';

const BIN = join(ROOT, 'bin/phasebook.mjs');
const HAS_SCRIPT = spawnSync('script', ['--version'], { encoding: 'utf8' }).status === 0;
const COUNT = 1000;
/** 1000 trajectories × tEnd/5e-4 steps. */
const RUN = (tEnd: number) => ['simulate', '--hamiltonian', 'p^2/2 + q^2/2', '--dof', '1', '--sample', String(COUNT), '--seed', '1', '--box', 'q=-1:1,p=-1:1', '--t-end', String(tEnd), '--every', '1000', '--workers', '2'];

let dir: string;
beforeAll(async () => {
  await ensureCli();
  dir = mkdtempSync(join(tmpdir(), 'phasebook-progress-'));
});

const quote = (s: string) => `'${s.replace(/'/g, `'\\''`)}'`;

function run(file: string, args: string[]): Promise<{ code: number; output: string }> {
  return new Promise((resolve) => {
    execFile(file, args, { maxBuffer: 1 << 24, timeout: 120_000 }, (error, stdout, stderr) => {
      resolve({ code: error ? Number((error as { code?: unknown }).code ?? 1) : 0, output: stdout + stderr });
    });
  });
}

describe('the progress bar', () => {
  it.skipIf(!HAS_SCRIPT)('on a terminal: one bar over all the trajectories, with the time left, cleared at the end (needs script)', async () => {
    const out = join(dir, 'set.npz');
    const command = ['node', BIN, ...RUN(200), '--output', out].map(quote).join(' ');
    const { code, output } = await run('script', ['-qec', command, '/dev/null']);
    expect(code).toBe(0);
    const frames = [...output.matchAll(/\r([█░]{30}) +(\d+)%  (\d+)\/(\d+) trajectories(?:  ETA ([^\x1b]+))?\x1b\[K/g)];
    expect(frames.length).toBeGreaterThan(0);
    // Nothing but frames and the final clearing: the bar is redrawn in place, never a new line.
    expect(output.replace(/\r[█░]{30}[^\x1b]*\x1b\[K/g, '').replace(/\r\x1b\[K$/, '')).toBe('');
    let last = -1;
    for (const [, bar, percent, done, total, eta] of frames) {
      // One bar over the whole set: the total is every trajectory, whichever worker did them.
      expect(Number(total)).toBe(COUNT);
      expect(Number(done)).toBeGreaterThanOrEqual(last);
      last = Number(done);
      expect(Number(done)).toBeLessThanOrEqual(COUNT);
      // The bar's filling and the percentage tell the same fraction.
      const filled = [...bar].filter((c) => c === '█').length;
      expect(Math.abs(filled - (Number(percent) * 30) / 100)).toBeLessThanOrEqual(1);
      if (Number(percent) > 0 && Number(percent) < 100) expect(eta).toMatch(/^\d+ s$|^\d+ min \d+ s$|^\d+ h \d+ min$/);
    }
    expect(output.endsWith('\r\x1b[K')).toBe(true);
    expect(readdirSync(dir)).toContain('set.npz');
  });

  it('draws nothing when stderr is not a terminal', async () => {
    const out = join(dir, 'quiet.npz');
    const { code, output } = await run('node', [BIN, ...RUN(50), '--output', out]);
    expect(code).toBe(0);
    expect(output).toBe('');
  });
});
