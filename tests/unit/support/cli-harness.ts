/**
 * What every test of `phasebook`'s commands sets up: compiled models go to a
 * scratch cache, not the user's (restored afterwards), and, for tests that
 * spawn it, the compiled CLI is built first if stale; and a command run in
 * this process has what it writes captured.
 */
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, vi } from 'vitest';
import { ensureCli } from '../../../bin/cli-bundle.mjs';

export function useScratchCache({ compiledCli = true } = {}): void {
  const userCache = process.env.PHASEBOOK_CACHE_DIR;
  beforeAll(async () => {
    process.env.PHASEBOOK_CACHE_DIR = mkdtempSync(join(tmpdir(), 'phasebook-cache-'));
    if (compiledCli) await ensureCli();
  });
  afterAll(() => {
    if (userCache === undefined) delete process.env.PHASEBOOK_CACHE_DIR;
    else process.env.PHASEBOOK_CACHE_DIR = userCache;
  });
}

/** Everything written to `stream` from now until vi.restoreAllMocks(), a chunk per entry; nothing reaches the terminal. */
export function captureWrites(stream: NodeJS.WriteStream): string[] {
  const written: string[] = [];
  vi.spyOn(stream, 'write').mockImplementation((chunk) => (written.push(String(chunk)), true));
  return written;
}
