/**
 * The hidden file an output is written into before it is renamed onto the
 * target: `.NAME.phasebook-SPACE-PID-RANDOM.partial`, beside the target.
 *
 * RANDOM is 128 bits from the system's CSPRNG, and the file is created
 * exclusively (O_CREAT|O_EXCL), which fails on anything already there,
 * a symbolic link included: a link planted at a guessed name is never written
 * through. SPACE and PID say which process wrote it, so that a later run can
 * remove a partial that a killed run (SIGKILL, a crash, a power cut) left
 * behind, and only those: SPACE is a hash of the host name and the PID
 * namespace, since a PID means nothing on another host or in another
 * container sharing the directory.
 */
import { createHash, randomBytes } from 'node:crypto';
import { lstatSync, openSync, readdirSync, readlinkSync, unlinkSync } from 'node:fs';
import { hostname } from 'node:os';
import { basename, dirname, join } from 'node:path';

/** A partial whose writer is gone is removed by the next run; one untouched this long is removed whoever wrote it. */
export const STALE_AFTER_MS = 24 * 60 * 60 * 1000;

/** Long target names are cut in the partial's name, which must stay under the file system's 255-byte limit. */
const NAME_CHARS = 100;
const PARTIAL = /^\..*\.phasebook-([0-9a-f]{8})-([1-9][0-9]{0,9})-[0-9a-f]{32}\.partial$/s;

/** Whose PIDs this process can test: the same host and the same PID namespace (Linux names it in /proc). */
export function pidSpace(): string {
  let namespace = '';
  try {
    namespace = readlinkSync('/proc/self/ns/pid');
  } catch {
    // No /proc (macOS, BSD): the host name alone.
  }
  return createHash('sha256').update(`${hostname()}\n${namespace}`).digest('hex').slice(0, 8);
}

/** The name a partial for `target` would get, with a fresh random part. */
export function partialName(target: string, pid = process.pid, space = pidSpace()): string {
  const name = basename(target).slice(0, NAME_CHARS);
  return `.${name}.phasebook-${space}-${pid}-${randomBytes(16).toString('hex')}.partial`;
}

/** The writer of a partial named `name`, or undefined if the name is not one phasebook gives. */
export function partialOwner(name: string): { space: string; pid: number } | undefined {
  const match = PARTIAL.exec(name);
  return match ? { space: match[1], pid: Number(match[2]) } : undefined;
}

/** Creates the partial for `target`, exclusively; returns its path and descriptor ('wx+' to read it back too). */
export function createPartial(target: string, flags: 'wx' | 'wx+' = 'wx'): { path: string; fd: number } {
  const path = join(dirname(target), partialName(target));
  // 'wx' is O_CREAT|O_EXCL: it never opens an existing file nor follows a link. The mode is a plain
  // file's (0666 less the umask), so the renamed output has the permissions any new file would.
  const fd = openSync(path, flags, 0o666);
  return { path, fd };
}

/** Whether a process `pid` exists here; EPERM means it does, but belongs to another user. */
export function processAlive(pid: number): boolean {
  try {
    process.kill(pid, 0);
    return true;
  } catch (error) {
    return (error as NodeJS.ErrnoException).code === 'EPERM';
  }
}

export interface StaleCheck {
  now?: number;
  space?: string;
  alive?: (pid: number) => boolean;
}

/**
 * Removes from `directory` the partials that no running phasebook will
 * finish: those of a dead process of this PID space, and any not modified for
 * STALE_AFTER_MS (a live run writes its partial as it goes). Only regular
 * files with a partial's name are touched. Cleaning is a courtesy: a
 * directory that cannot be read or a file that cannot be removed is left as
 * it is. Returns the names removed.
 */
export function removeStalePartials(directory: string, check: StaleCheck = {}): string[] {
  const { now = Date.now(), space = pidSpace(), alive = processAlive } = check;
  const removed: string[] = [];
  let names: string[];
  try {
    names = readdirSync(directory);
  } catch {
    return removed;
  }
  for (const name of names) {
    const owner = partialOwner(name);
    if (!owner) continue;
    const path = join(directory, name);
    try {
      const stat = lstatSync(path);
      if (!stat.isFile()) continue;
      const abandoned = owner.space === space && owner.pid !== process.pid && !alive(owner.pid);
      if (abandoned || now - stat.mtimeMs > STALE_AFTER_MS) {
        unlinkSync(path);
        removed.push(name);
      }
    } catch {
      // Gone already (another run cleaned it), or not ours to remove.
    }
  }
  return removed;
}
