/**
 * The CLI's cache of compiled models (see core/compiled-model.ts): one file
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
 */
import { createHash, randomBytes } from 'node:crypto';
import { mkdirSync, readFileSync, renameSync, rmSync, writeFileSync } from 'node:fs';
import { homedir } from 'node:os';
import { isAbsolute, join } from 'node:path';
import type { CompiledModel, CompiledModelStore } from '../core/index.ts';

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

/** A store of compiled models as files in `directory`, which is created on the first write. */
export function diskModelStore(directory: string): CompiledModelStore {
  return {
    get(key: string): CompiledModel | undefined {
      try {
        const text = readFileSync(modelCacheFile(directory, key), 'utf8');
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
        writeFileSync(temporary, `${sha256(body)}\n${body}`);
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
