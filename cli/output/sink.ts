import { closeSync, constants, fstatSync, futimesSync, lstatSync, openSync, renameSync, statSync, unlinkSync, writeSync } from 'node:fs';
import { dirname } from 'node:path';
import type { InterruptGuard } from '../interrupt.ts';
import { OutputError, outputError } from './output-error.ts';
import { createPartial, removeStalePartials, STALE_AFTER_MS } from './partial-file.ts';

/** How often a partial's modification time is renewed while its run lives. */
const HEARTBEAT_MS = STALE_AFTER_MS / 24;

/** Where the CLI writes: stdout, or a file that appears only when complete. */
export interface Sink {
  write(data: string | Uint8Array): void;
  /** the output is complete: make it visible */
  commit(): void;
  /** something failed: leave nothing behind; never throws */
  abandon(): void;
}

/** Writes all of `text`: a write may take only part of it (a disk filling up does that before it says ENOSPC). */
function writeAll(fd: number, data: string | Uint8Array): void {
  const bytes = typeof data === 'string' ? Buffer.from(data) : data;
  let offset = 0;
  while (offset < bytes.length) offset += writeSync(fd, bytes, offset);
}

/**
 * The output `--output path` names. A regular file (new or not) is written
 * through a partial file that appears under its name only when complete; a
 * character device or a FIFO (/dev/null, /dev/stdout, a named pipe) is
 * written as it is, since renaming a file onto a device node would replace
 * the node. `guard` catches interrupts while a partial exists, so that an
 * interrupted run can remove it.
 */
export function fileSink(path: string, guard?: InterruptGuard): Sink {
  let existing: ReturnType<typeof statSync>;
  try {
    existing = statSync(path, { throwIfNoEntry: false });
  } catch (error) {
    throw outputError(error, path);
  }
  if (existing?.isDirectory()) throw new OutputError(`cannot write ${path}: it is a directory`);
  if (existing?.isCharacterDevice() || existing?.isFIFO()) {
    const sink = streamSink(path);
    if (sink) return sink;
  } else if (existing && !existing.isFile()) {
    throw new OutputError(`cannot write ${path}: it is neither a regular file nor a character device or pipe`);
  }
  return partialSink(path, guard);
}

/** A device or pipe opened for writing as it is; undefined if `path` turned into a regular file meanwhile. */
function streamSink(path: string): Sink | undefined {
  let fd: number;
  try {
    // No O_CREAT and no O_TRUNC: opening never makes or empties a file, whatever is at `path` by now.
    fd = openSync(path, constants.O_WRONLY);
  } catch (error) {
    throw outputError(error, path);
  }
  if (fstatSync(fd).isFile()) {
    closeSync(fd);
    return undefined;
  }
  const close = once(() => closeSync(fd));
  return {
    write: (text) => {
      try {
        writeAll(fd, text);
      } catch (error) {
        throw outputError(error, path);
      }
    },
    commit: () => {
      try {
        close();
      } catch (error) {
        throw outputError(error, path);
      }
    },
    abandon: () => quietly(close),
  };
}

/**
 * Writes to a partial file beside the target (partial-file.ts) and renames it
 * into place on success, so an error or an interrupt never leaves a partial
 * or empty file under the target's name. Stale partials of killed runs in the
 * same directory are removed first.
 */
function partialSink(path: string, guard?: InterruptGuard): Sink {
  removeStalePartials(dirname(path));
  // Held before the partial exists, so that no moment has a partial and a signal that would kill the process outright.
  guard?.hold();
  let partial: { path: string; fd: number };
  try {
    partial = createPartial(path);
  } catch (error) {
    guard?.release();
    throw outputError(error, path);
  }
  const identity = fstatSync(partial.fd, { bigint: true });
  // The name could have been replaced (in a directory others can write to); only the file this run made is published or removed.
  const stillOurs = () => {
    const now = lstatSync(partial.path, { bigint: true, throwIfNoEntry: false });
    return now !== undefined && now.ino === identity.ino && now.dev === identity.dev;
  };
  // Another run removes a partial untouched for STALE_AFTER_MS as abandoned; a live run with rows far apart says it is alive.
  const heartbeat = setInterval(() => quietly(() => futimesSync(partial.fd, new Date(), new Date())), HEARTBEAT_MS);
  heartbeat.unref();
  const close = once(() => {
    clearInterval(heartbeat);
    closeSync(partial.fd);
  });
  return {
    write: (text) => {
      try {
        writeAll(partial.fd, text);
      } catch (error) {
        throw outputError(error, path);
      }
    },
    commit: () => {
      try {
        // close() reports a deferred write error (NFS, some quota systems): the file is not whole then.
        close();
        if (!stillOurs()) throw new OutputError(`cannot write ${path}: its partial file was replaced or removed by another process`);
        renameSync(partial.path, path);
      } catch (error) {
        throw outputError(error, path);
      }
      guard?.release();
    },
    abandon: () => {
      quietly(close);
      quietly(() => stillOurs() && unlinkSync(partial.path));
      guard?.release();
    },
  };
}

/** stdout, written synchronously so that rows keep their order and nothing is lost on exit. */
export function stdoutSink(): Sink {
  return {
    write: (data) => {
      let offset = 0;
      const bytes = typeof data === 'string' ? Buffer.from(data) : data;
      while (offset < bytes.length) {
        try {
          offset += writeSync(1, bytes, offset);
        } catch (error) {
          // A pipe that is full says EAGAIN; a closed one (| head) says EPIPE: stop quietly then.
          const code = (error as NodeJS.ErrnoException).code;
          if (code === 'EPIPE') process.exit(0);
          if (code !== 'EAGAIN') throw outputError(error);
        }
      }
    },
    commit: () => {},
    abandon: () => {},
  };
}

/** `action` run at most once, however often called. */
function once(action: () => void): () => void {
  let done = false;
  return () => {
    if (done) return;
    done = true;
    action();
  };
}

/** Cleaning up after a failure must not hide the failure. */
function quietly(action: () => unknown): void {
  try {
    action();
  } catch {
    // The first error is the one to report.
  }
}
