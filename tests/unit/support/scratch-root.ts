/**
 * vitest's global set-up: every temporary file and folder the unit tests make
 * (theirs, the CLI's they start, its sandbox's) goes under one folder for
 * the run, removed at its end, so that a run leaves nothing in the system's
 * temporary folder, whichever test forgot to tidy up or was stopped first.
 * os.tmpdir() reads TMPDIR when called, and the test workers and the
 * processes they start inherit it.
 */
import { chmodSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

export default function setup(): () => void {
  const root = mkdtempSync(join(tmpdir(), 'phasebook-unit-'));
  // Others may pass through it (not list it): the permission test runs the CLI as another user, from a folder of its own inside.
  chmodSync(root, 0o711);
  const before = process.env.TMPDIR;
  process.env.TMPDIR = root;
  return () => {
    if (before === undefined) delete process.env.TMPDIR;
    else process.env.TMPDIR = before;
    rmSync(root, { recursive: true, force: true });
  };
}
