/**
 * What every test of `phasebook`'s commands sets up: compiled models go to a
 * scratch cache, not the user's (restored afterwards), and, for tests that
 * spawn it, the compiled CLI is built first if stale; and a command run in
 * this process has what it writes captured; and the compiled CLI started as
 * a user starts it, in a process of its own.
 */
import { spawn, type ChildProcess } from 'node:child_process';
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, vi } from 'vitest';
import { ensureCli, ROOT } from '../../../bin/cli-bundle.mjs';

const BIN = join(ROOT, 'bin/phasebook.mjs');

/** How a `phasebook` process ended: its status (null when a signal ended it), and all it wrote. */
export interface CliExit {
  code: number | null;
  stdout: string;
  stderr: string;
}

/**
 * `phasebook …args` as a process, with `env` added to this one's; `exited`
 * settles once it has ended and its output is all read.
 */
export function startCli(args: string[], env: Record<string, string> = {}): { child: ChildProcess; exited: Promise<CliExit> } {
  const child = spawn(process.execPath, [BIN, ...args], { env: { ...process.env, ...env }, stdio: ['ignore', 'pipe', 'pipe'] });
  let stdout = '';
  let stderr = '';
  child.stdout!.on('data', (chunk) => (stdout += chunk));
  child.stderr!.on('data', (chunk) => (stderr += chunk));
  const exited = new Promise<CliExit>((resolve) => child.on('close', (code) => resolve({ code, stdout, stderr })));
  return { child, exited };
}

/** `phasebook …args` run to its end (see startCli). */
export const runCli = (args: string[], env?: Record<string, string>): Promise<CliExit> => startCli(args, env).exited;

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
