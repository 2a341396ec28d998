/**
 * The compiled command line: cli/main.ts bundled by esbuild into plain
 * JavaScript in build/cli/, once at `npm install` (the `prepare` script) and by
 * `npm run build:cli`, so that a run starts without compiling TypeScript.
 *
 * Code splitting puts mathjs (the factories of
 * core/expression/mathjs-instance.ts), acorn and the model compiler in
 * chunks of their own, which `import()` loads only when a model must be
 * compiled: a run whose model is in the cache, or that is given a vector
 * field, never reads them.
 *
 * Beside the bundle, manifest.json lists the project files it was built from
 * with their sizes, and the time the build started. The bundle is fresh when
 * no listed file has changed size or been modified since then: a few dozen
 * stat calls, well under a millisecond. esbuild's full metafile is kept as
 * metafile.json, for tests and for anyone asking what went where.
 */
import { existsSync, mkdirSync, readFileSync, renameSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

/** The project root: the folder holding bin/. */
export const ROOT = fileURLToPath(new URL('..', import.meta.url));
export const OUT_DIR = join(ROOT, 'build', 'cli');
const ENTRY = 'cli/main.ts';
const WORKER_ENTRY = 'cli/dataset/worker-thread.ts';
/** The sandbox in which the user's JavaScript runs, a process of its own (cli/sandbox/sandbox-process.ts). */
const SANDBOX_ENTRY = 'cli/sandbox/sandbox-child.ts';
/** Bumped when the manifest's layout changes, so an old one reads as stale. */
const MANIFEST_FORMAT = 1;

/**
 * Files outside the import graph that still decide the bundle: the compiler
 * options, this build recipe, and npm's record of node_modules, which npm
 * rewrites whenever an install changes a dependency.
 */
const BUILD_INPUTS = ['tsconfig.json', 'bin/cli-bundle.mjs', 'node_modules/.package-lock.json'];

/**
 * The path of the bundle's entry when the bundle in `outDir` is up to date
 * with every file it was built from, else undefined (missing, damaged or
 * stale).
 */
export function freshEntry(outDir = OUT_DIR, root = ROOT) {
  try {
    const manifest = JSON.parse(readFileSync(join(outDir, 'manifest.json'), 'utf8'));
    if (manifest.format !== MANIFEST_FORMAT || typeof manifest.entry !== 'string') return undefined;
    for (const [path, size] of manifest.inputs) {
      const stat = statSync(join(root, path), { throwIfNoEntry: false });
      // Size as well as time: a file restored with its old mtime (cp -p, an unpacked archive) still differs in size, usually.
      if (!stat || stat.size !== size || stat.mtimeMs > manifest.builtAt) return undefined;
    }
    return join(outDir, manifest.entry);
  } catch {
    // No manifest, or not one this code wrote: build afresh.
    return undefined;
  }
}

/** Writes a file whole or not at all: a concurrent run reads the old file or the new, never half of one. */
function writeAtomically(path, contents) {
  // Unique per writer: two builds at once (parallel test workers) each rename a whole file of their own.
  const temporary = `${path}.${process.pid}.${Math.random().toString(36).slice(2)}.tmp`;
  try {
    writeFileSync(temporary, contents);
    renameSync(temporary, path);
  } catch (error) {
    rmSync(temporary, { force: true });
    throw error;
  }
}

/**
 * Bundles the CLI into `outDir`. `clean` empties the folder first (the
 * scripts do; a rebuild by a running CLI does not, since another run may still
 * be about to load a chunk of the previous bundle). The manifest is written
 * last, so a bundle is never called fresh before all of it is in place.
 */
export async function buildCli({ outDir = OUT_DIR, root = ROOT, clean = false } = {}) {
  const { build } = await import('esbuild');
  // Taken before esbuild reads anything, so a file saved during the build is newer and the bundle reads as
  // stale; less a margin, since file times come from a clock that may lag Date.now() by a tick (a few ms).
  const builtAt = Date.now() - 50;
  const result = await build({
    absWorkingDir: root,
    // The worker threads of a dataset run load their own entry (cli/dataset/executors.ts), and so does the sandbox
    // (cli/sandbox/sandbox-process.ts). Named, so that all three land at the top of outDir whatever folders their
    // sources are in.
    entryPoints: Object.fromEntries(
      [
        ['main', ENTRY],
        ['worker-thread', WORKER_ENTRY],
        ['sandbox-child', SANDBOX_ENTRY],
      ].filter(([, entry]) => existsSync(join(root, entry))),
    ),
    outdir: outDir,
    bundle: true,
    splitting: true,
    format: 'esm',
    platform: 'node',
    target: 'node20',
    // Names in stack traces and error messages stay readable; whitespace and syntax shrink the mathjs chunk a third.
    minifyWhitespace: true,
    minifySyntax: true,
    write: false,
    metafile: true,
    logLevel: 'silent',
  });
  if (clean) rmSync(outDir, { recursive: true, force: true });
  mkdirSync(outDir, { recursive: true });
  for (const file of result.outputFiles) {
    mkdirSync(dirname(file.path), { recursive: true });
    writeAtomically(file.path, file.contents);
  }
  const sources = Object.keys(result.metafile.inputs).filter((path) => !path.startsWith('node_modules/'));
  const inputs = [...sources, ...BUILD_INPUTS].flatMap((path) => {
    const stat = statSync(join(root, path), { throwIfNoEntry: false });
    return stat ? [[path, stat.size]] : [];
  });
  writeAtomically(join(outDir, 'metafile.json'), JSON.stringify(result.metafile));
  writeAtomically(join(outDir, 'manifest.json'), JSON.stringify({ format: MANIFEST_FORMAT, builtAt, entry: 'main.js', inputs }));
  return join(outDir, 'main.js');
}

/** Builds the bundle unless it is fresh; returns its entry. */
export async function ensureCli(options = {}) {
  return freshEntry(options.outDir, options.root) ?? (await buildCli(options));
}
