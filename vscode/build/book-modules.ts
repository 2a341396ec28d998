/**
 * An esbuild plugin that lets the extension's browser bundles import the
 * book's modules as they are:
 *
 * - `node:crypto`, which site/lib/remark-cells.mjs imports to hash cell
 *   sources, becomes a small stand-in (src/shims/node-crypto.ts);
 * - site/lib/precompile.ts, the build's headless run of the cells, which
 *   remark-cells.mjs imports but the extension never calls, is marked free
 *   of side effects so that it (and mathjs, KaTeX and acorn with it) stays
 *   out of the bundles unless something really uses it.
 */
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Plugin } from 'esbuild';

const here = path.dirname(fileURLToPath(import.meta.url));
const CRYPTO_SHIM = path.resolve(here, '../src/shims/node-crypto.ts');

export function bookModules(): Plugin {
  return {
    name: 'phasebook-book-modules',
    setup(build) {
      build.onResolve({ filter: /^node:crypto$/ }, () => ({ path: CRYPTO_SHIM }));
      build.onResolve({ filter: /[\\/]precompile\.ts$/ }, (args) => ({ path: path.resolve(args.resolveDir, args.path), sideEffects: false }));
    },
  };
}
