/**
 * The CLI's cache of compiled models (see core/model/compiled-model.ts): one file
 * per model, so that a second run of the same H skips mathjs and acorn
 * altogether and starts in about the time Node itself does.
 *
 * A file is named by a hash of the model's key and holds the SHA-256 of its
 * body on the first line, then the compiled model as JSON. The core checks
 * the full key inside (a hash collision or another version's file is simply
 * a miss); the checksum catches a truncated or damaged file whose JSON still
 * parses, whose generated code would otherwise fail to run. The cache is only
 * ever a shortcut: any problem reading or writing it means "compile", never
 * an error.
 *
 * A cache file is code the CLI runs with the user's rights, so only a file
 * the user owns, and that no one else may write, is read: a cache folder
 * shared on a cluster ($PHASEBOOK_CACHE_DIR), where others could plant a
 * file under a model's name, then costs a compile, not the user's account.
 */
import { createHash, randomBytes } from 'node:crypto';
import { closeSync, fstatSync, mkdirSync, openSync, readFileSync, renameSync, rmSync, type Stats, writeFileSync } from 'node:fs';
import { homedir } from 'node:os';
import { isAbsolute, join } from 'node:path';
import type { CompiledModel, CompiledModelStore } from '../../core/index.ts';

const sha256 = (text: string) => createHash('sha256').update(text).digest('hex');

/**
 * Where compiled models are kept: `$PHASEBOOK_CACHE_DIR`, else
 * `$XDG_CACHE_HOME/phasebook/models`, else `~/.cache/phasebook/models`. The
 * XDG base directory spec says a relative XDG_CACHE_HOME is to be ignored.
 */
export function modelCacheDirectory(env: NodeJS.ProcessEnv = process.env, home: () => string = homedir): string {
  if (env.PHASEBOOK_CACHE_DIR) return env.PHASEBOOK_CACHE_DIR;
  const xdg = env.XDG_CACHE_HOME;
  const base = xdg && isAbsolute(xdg) ? xdg : join(home(), '.cache');
  return join(base, 'phasebook', 'models');
}

/** The file of a model's key; 128 bits of the hash name it, the key inside decides. */
export function modelCacheFile(directory: string, key: string): string {
  return join(directory, `${sha256(key).slice(0, 32)}.json`);
}

/** Whether a cache file's code may run: owned by this user, writable by no one else (POSIX; Windows has no such bits). */
export function writtenByUserAlone(stat: Pick<Stats, 'uid' | 'mode'>, uid: number | undefined = process.getuid?.()): boolean {
  if (uid === undefined) return true;
  return stat.uid === uid && (stat.mode & 0o022) === 0;
}

/** A cache file's text, if it is one whose code may run. */
function readTrusted(file: string): string | undefined {
  const fd = openSync(file, 'r');
  try {
    // Checked on the descriptor, so the file judged is the file read.
    return writtenByUserAlone(fstatSync(fd)) ? readFileSync(fd, 'utf8') : undefined;
  } finally {
    closeSync(fd);
  }
}

/** A store of compiled models as files in `directory`, which is created on the first write. */
export function diskModelStore(directory: string): CompiledModelStore {
  return {
    get(key: string): CompiledModel | undefined {
      try {
        const text = readTrusted(modelCacheFile(directory, key));
        if (text === undefined) return undefined;
        const newline = text.indexOf('\n');
        const body = text.slice(newline + 1);
        if (newline !== 64 || sha256(body) !== text.slice(0, 64)) return undefined;
        // The core's isCompiledModel checks the shape and the key before any of it runs.
        return JSON.parse(body) as CompiledModel;
      } catch {
        return undefined;
      }
    },
    put(model: CompiledModel): void {
      const file = modelCacheFile(directory, model.key);
      // Unique per writer, and renamed into place whole: two runs compiling one H at once both succeed.
      const temporary = `${file}.${process.pid}.${randomBytes(4).toString('hex')}.tmp`;
      try {
        mkdirSync(directory, { recursive: true });
        const body = JSON.stringify(model);
        // Writable by the user alone whatever the umask, or the next run would not read it back.
        writeFileSync(temporary, `${sha256(body)}\n${body}`, { mode: 0o644 });
        renameSync(temporary, file);
      } catch {
        try {
          rmSync(temporary, { force: true });
        } catch {
          // Nothing was left, or nothing can be done about it.
        }
      }
    },
  };
}
