/**
 * Output streams in chunks, so memory stays flat however long the run: a
 * run writing many times more than the memory the process is allowed
 * (node --max-old-space-size and --max-semi-space-size: the heap where
 * strings and arrays of numbers live) completes, and its peak resident memory is about that of the same
 * run writing ten times less.
 */
import { execFile } from 'node:child_process';
import { mkdtempSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { ensureCli } from '../../../../bin/cli-bundle.mjs';

const HEAP_MB = 48;
let entry: string;
let dir: string;

beforeAll(async () => {
  entry = await ensureCli();
  dir = mkdtempSync(join(tmpdir(), 'phasebook-memory-'));
});

/** Runs `phasebook simulate …args` in a process whose heap is capped; returns its status and peak RSS in bytes. */
function capped(args: string[]): Promise<{ code: number; stderr: string; maxRss: number }> {
  const script = join(dir, 'capped.mjs');
  writeFileSync(script, `const m = await import(${JSON.stringify(pathToFileURL(entry).href)});
const code = await m.main(process.argv.slice(2));
process.stderr.write('maxRss ' + process.resourceUsage().maxRSS * 1024 + '\\n');
process.exitCode = code;`);
  return new Promise((resolve) => {
    execFile('node', [`--max-old-space-size=${HEAP_MB}`, '--max-semi-space-size=4', script, 'simulate', ...args], (error, _, stderr) => {
      const rss = /maxRss (\d+)/.exec(stderr);
      resolve({ code: error ? Number((error as { code?: unknown }).code ?? 1) : 0, stderr: stderr.replace(/maxRss \d+\n/, ''), maxRss: rss ? Number(rss[1]) : NaN });
    });
  });
}

const OSCILLATOR = ['--hamiltonian', 'p^2/2 + q^2/2', '--dof', '1'];

describe('memory stays flat', () => {
  // Each pair takes the same steps on the same trajectories and writes ten times more in the second run (--every 10, then 1).
  it.each([
    ['csv', 'one trajectory', ['--initial', '1,0', '--t-end', '600']],
    ['csv', '24 trajectories on 2 workers', ['--sample', '24', '--box', 'q=-1:1,p=-1:1', '--workers', '2', '--t-end', '25']],
    ['npz', '24 trajectories on 2 workers', ['--sample', '24', '--box', 'q=-1:1,p=-1:1', '--workers', '2', '--derivatives', '--t-end', '50']],
    ['parquet', '24 trajectories on 2 workers', ['--sample', '24', '--box', 'q=-1:1,p=-1:1', '--workers', '2', '--t-end', '60']],
  ])('%s, %s: 10× the output in about the same memory, the larger past the heap allowed', async (format, _, set) => {
    const run = async (every: string) => {
      const out = join(dir, `out.${format}`);
      const result = await capped([...OSCILLATOR, ...set, '--every', every, '--format', format, '--output', out]);
      expect(result.stderr).toBe('');
      expect(result.code).toBe(0);
      const size = statSync(out).size;
      rmSync(out);
      return { ...result, size };
    };
    const small = await run('10');
    const large = await run('1');
    expect(large.size).toBeGreaterThan(9 * small.size);
    expect(large.size).toBeGreaterThan(1.5 * HEAP_MB * 2 ** 20);
    // Flat: within a third of the smaller run's peak (the young generations' and the allocator's slack).
    expect(large.maxRss).toBeLessThan(1.35 * small.maxRss);
  });
});
