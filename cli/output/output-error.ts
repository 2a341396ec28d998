/**
 * A file the CLI cannot write, said in words. A full disk or a read-only
 * directory is the user's situation to fix, not a bug, so it gets one line
 * naming the file and the cause, and exit status 2 like any bad input —
 * never "internal error" and never a stack trace.
 */
import { existsSync } from 'node:fs';
import { dirname } from 'node:path';

export class OutputError extends Error {
  override name = 'OutputError';
}

/**
 * What an error code means for someone writing the file `path` (undefined
 * for stdout); undefined for a code with no sentence of its own.
 */
function cause(code: string, path: string | undefined): string | undefined {
  const directory = path === undefined ? undefined : dirname(path);
  switch (code) {
    case 'ENOSPC':
      return 'no space left on the device';
    case 'EDQUOT':
      return 'the disk quota is used up';
    case 'EFBIG':
      return 'the file would be larger than the file system allows';
    case 'EACCES':
    case 'EPERM':
      return directory === undefined ? 'permission denied' : `permission denied (it takes write permission on the directory ${directory})`;
    case 'EROFS':
      return 'the file system is read-only';
    case 'EISDIR':
      return 'it is a directory';
    case 'ENOENT':
      if (directory === undefined) return 'no such file';
      // A directory that exists but takes no new files (/proc) says ENOENT as well.
      return existsSync(directory) ? 'the directory takes no new files' : `the directory ${directory} does not exist`;
    case 'EEXIST':
      // Only a file planted under its partial file's name, 128 random bits guessed, gets here: it is left alone.
      return 'another file has taken the name of its partial file';
    case 'ENOTDIR':
      return 'a part of the path is not a directory';
    case 'ENAMETOOLONG':
      return 'the name is too long';
    case 'ELOOP':
      return 'the path has too many symbolic links';
    case 'EIO':
      return 'an input/output error on the device';
    case 'EMFILE':
    case 'ENFILE':
      return 'too many files are open';
    default:
      return undefined;
  }
}

/**
 * `error`, thrown by a node:fs call while writing the file `path` (or stdout
 * when `path` is undefined), as an OutputError that says what happened. An
 * error with no system code is a bug, and is passed on as it is.
 */
export function outputError(error: unknown, path?: string): Error {
  const code = (error as NodeJS.ErrnoException | undefined)?.code;
  if (typeof code !== 'string') return error as Error;
  // Node's own message ("EBUSY: resource busy or locked, open '…'") for a code with no sentence here.
  const reason = cause(code, path) ?? String((error as Error).message).split('\n')[0];
  return new OutputError(`cannot write ${path ?? 'stdout'}: ${reason}`);
}
