/**
 * Builds the extension into vscode/dist/: the builtins' catalogue (from the
 * book's TypeScript), the extension bundle (one file for `main` and
 * `browser`), the preview webview's script and styles (with KaTeX's fonts)
 * and, with `--tests`, the in-host test suite into vscode/dist-test/.
 *
 *   tsx vscode/build/build.ts [--tests] [--minify]
 *   tsx vscode/build/build.ts --catalogue     (the catalogue alone, for the type check)
 */
import { mkdir, rm, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import * as esbuild from 'esbuild';
import { bookModules } from './book-modules.ts';
import { generateCatalogue } from './catalogue.ts';
import { findWorkers, webWorkers } from './web-workers.ts';

const here = path.dirname(fileURLToPath(import.meta.url));
export const EXTENSION_DIR = path.resolve(here, '..');
const ROOT = path.resolve(EXTENSION_DIR, '..');

/** Options every bundle shares: browser platform (the web extension host and the webview), ES2022. */
const common: esbuild.BuildOptions = {
  bundle: true,
  platform: 'browser',
  target: 'es2022',
  sourcemap: 'linked',
  logLevel: 'warning',
  plugins: [bookModules()],
  // Some of unified's helpers test process.env.NODE_ENV; the web extension host has no `process`.
  define: { 'process.env.NODE_ENV': '"production"' },
};

/** The builtins' catalogue, which the extension's bundle (and its type check) imports. */
export async function writeCatalogue(): Promise<void> {
  const generated = path.join(EXTENSION_DIR, 'generated');
  await mkdir(generated, { recursive: true });
  await writeFile(path.join(generated, 'catalogue.json'), JSON.stringify(generateCatalogue(ROOT), null, 1));
}

/** `minify` is for the package: minified and without source maps; the tests' builds keep them readable. */
export async function build({ tests = false, minify = false } = {}): Promise<void> {
  await writeCatalogue();

  const dist = path.join(EXTENSION_DIR, 'dist');
  // Nothing of an earlier build (source maps of a test build, say) may end up in a package.
  await rm(dist, { recursive: true, force: true });
  const workers = await findWorkers(path.join(ROOT, 'widgets'));
  const browser = { ...common, plugins: [bookModules(), webWorkers()], ...(minify ? { sourcemap: false } : {}) };
  await Promise.all([
    ...workers.map((worker) => esbuild.build({ ...browser, minify, entryPoints: { [worker.name]: worker.file }, outdir: path.join(dist, 'workers'), format: 'iife' })),
    // The extension: CommonJS, which both the desktop's Node host and the web worker host load; `vscode` is the host's.
    // The `worker` condition: packages that have one give their DOM-free code, which the extension host (a web worker, or Node) needs.
    esbuild.build({ ...browser, minify, entryPoints: { extension: path.join(EXTENSION_DIR, 'src/extension.ts') }, outdir: dist, format: 'cjs', external: ['vscode'], conditions: ['worker'] }),
    // The webview's script, one file: it loads from the extension's resources, where lazy chunks would cost a round trip each.
    esbuild.build({
      ...browser,
      minify,
      entryPoints: { preview: path.join(EXTENSION_DIR, 'src/preview/main.ts') },
      outdir: dist,
      format: 'iife',
      define: { ...common.define, PHASEBOOK_WORKERS: JSON.stringify(workers.map((w) => w.name)) },
    }),
    esbuild.build({
      ...common,
      minify,
      ...(minify ? { sourcemap: false } : {}),
      entryPoints: { preview: path.join(EXTENSION_DIR, 'src/preview/preview.css') },
      outdir: dist,
      loader: { '.woff2': 'file', '.woff': 'file', '.ttf': 'file' },
      assetNames: 'fonts/[name]',
    }),
    tests
      ? esbuild.build({ ...browser, entryPoints: { suite: path.join(EXTENSION_DIR, 'test/host/index.ts') }, outdir: path.join(EXTENSION_DIR, 'dist-test'), format: 'cjs', external: ['vscode'], conditions: ['worker'] })
      : Promise.resolve(),
  ]);
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const run = process.argv.includes('--catalogue') ? writeCatalogue() : build({ tests: process.argv.includes('--tests'), minify: process.argv.includes('--minify') });
  run.catch((error: unknown) => {
    console.error(error);
    process.exit(1);
  });
}
