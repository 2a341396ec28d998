import { closeSync, openSync, renameSync, rmSync, writeSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';

/** Where the CLI writes: stdout, or a file that appears only when complete. */
export interface Sink {
  write(text: string): void;
  /** the output is complete: make it visible */
  commit(): void;
  /** something failed: leave nothing behind */
  abandon(): void;
}

/**
 * Writes to a temporary file beside the target and renames it into place on
 * success, so an error or an interrupt never leaves a partial or empty file.
 */
export function fileSink(path: string): Sink {
  const temporary = join(dirname(path), `.${basename(path)}.${process.pid}.partial`);
  const fd = openSync(temporary, 'w');
  let open = true;
  const close = () => {
    if (open) closeSync(fd);
    open = false;
  };
  const onSignal = () => {
    close();
    rmSync(temporary, { force: true });
    process.exit(130);
  };
  process.once('SIGINT', onSignal);
  process.once('SIGTERM', onSignal);
  return {
    write: (text) => {
      writeSync(fd, text);
    },
    commit: () => {
      close();
      renameSync(temporary, path);
      process.off('SIGINT', onSignal);
      process.off('SIGTERM', onSignal);
    },
    abandon: () => {
      close();
      rmSync(temporary, { force: true });
    },
  };
}

/** stdout, written synchronously so that rows keep their order and nothing is lost on exit. */
export function stdoutSink(): Sink {
  return {
    write: (text) => {
      let offset = 0;
      const bytes = Buffer.from(text);
      while (offset < bytes.length) {
        try {
          offset += writeSync(1, bytes, offset);
        } catch (error) {
          // A pipe that is full says EAGAIN; a closed one (| head) says EPIPE: stop quietly then.
          const code = (error as NodeJS.ErrnoException).code;
          if (code === 'EPIPE') process.exit(0);
          if (code !== 'EAGAIN') throw error;
        }
      }
    },
    commit: () => {},
    abandon: () => {},
  };
}
