/**
 * bin/phasebook.mjs and cli-bundle.mjs on a stand-in project: a copy of bin/
 * beside a two-file cli/, so that sources can be edited without
 * touching the real ones. The launcher must never run code older than the
 * sources, whatever state build/cli/ is in.
 */
import { execFile } from 'node:child_process';
import { cpSync, mkdirSync, mkdtempSync, rmSync, statSync, symlinkSync, utimesSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { beforeEach, describe, expect, it } from 'vitest';
import { freshEntry, ROOT } from '../../../bin/cli-bundle.mjs';

const run = promisify(execFile);
let root: string;
let outDir: string;

/** cli/main.ts printing what words.ts says, as the real entry's shape: main(argv) → exit status. */
function writeSources(word: string): void {
  writeFileSync(join(root, 'cli/words.ts'), `export const word: string = ${JSON.stringify(word)};\n`);
}

beforeEach(() => {
  root = mkdtempSync(join(tmpdir(), 'phasebook-bundle-'));
  outDir = join(root, 'build/cli');
  cpSync(join(ROOT, 'bin'), join(root, 'bin'), { recursive: true });
  symlinkSync(join(ROOT, 'node_modules'), join(root, 'node_modules'), 'dir');
  writeFileSync(join(root, 'package.json'), '{ "type": "module" }\n');
  mkdirSync(join(root, 'cli'), { recursive: true });
  writeFileSync(
    join(root, 'cli/main.ts'),
    `import { word } from './words.ts';\nexport async function main(argv: readonly string[]): Promise<number> {\n  process.stdout.write(word + ' ' + argv.join(' ') + '\\n');\n  return 3;\n}\n`,
  );
  writeSources('first');
});

async function launch(...args: string[]): Promise<{ stdout: string; code: number }> {
  try {
    const { stdout } = await run('node', [join(root, 'bin/phasebook.mjs'), ...args]);
    return { stdout, code: 0 };
  } catch (error) {
    const e = error as { stdout: string; code: number; stderr: string };
    return { stdout: e.stdout, code: e.code };
  }
}

describe('bin/phasebook.mjs', () => {
  it('builds a missing bundle, runs it with the arguments and passes on the exit status', async () => {
    expect(freshEntry(outDir, root)).toBeUndefined();
    expect(await launch('a', '-b')).toEqual({ stdout: 'first a -b\n', code: 3 });
    expect(freshEntry(outDir, root)).toBe(join(outDir, 'main.js'));
  });

  it('rebuilds after a source is edited, so the edit is what runs', async () => {
    await launch();
    writeSources('second');
    expect(freshEntry(outDir, root)).toBeUndefined();
    expect((await launch()).stdout).toBe('second \n');
    expect(freshEntry(outDir, root)).toBeDefined();
  });

  it('falls back to compiling with tsx when no bundle can be written', async () => {
    writeFileSync(join(root, 'build'), 'a file where the build folder should be');
    expect(await launch('x')).toEqual({ stdout: 'first x\n', code: 3 });
  });
});

describe('freshEntry(outDir, root)', () => {
  it('calls the bundle stale when a source changes size even with an old time, or disappears, or the manifest is damaged', async () => {
    await launch();
    const words = join(root, 'cli/words.ts');
    const { mtime } = statSync(words);
    writeSources('a different length');
    utimesSync(words, mtime, mtime);
    expect(freshEntry(outDir, root)).toBeUndefined();
    writeSources('first');
    utimesSync(words, mtime, mtime);
    expect(freshEntry(outDir, root)).toBeDefined();
    for (const damaged of ['{"format":1,', '{"format":1,"builtAt":0,"entry":"main.js","inputs":[5]}', 'null']) {
      writeFileSync(join(outDir, 'manifest.json'), damaged);
      expect(freshEntry(outDir, root)).toBeUndefined();
    }
    await launch();
    rmSync(words);
    expect(freshEntry(outDir, root)).toBeUndefined();
  });
});
