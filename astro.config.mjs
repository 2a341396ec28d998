// @ts-check
import { defineConfig } from 'astro/config';
import mdx from '@astrojs/mdx';
import remarkMath from 'remark-math';
import rehypeKatex from 'rehype-katex';
import { remarkCells, CELL_CODE_LANGUAGE } from './src/lib/remark-cells.mjs';

/**
 * Names the lazily loaded chunks so the first page load can be checked for
 * their absence (tests/e2e/lazy.test.mjs): CodeMirror and its Lezer parsers
 * go to `editor`, the Observable parser and acorn go to `parser`.
 *
 * Only modules with no dependency shared with the page's boot code may be
 * listed: Rollup pulls a manual chunk's unassigned dependencies into it, so
 * listing widgets/cells/parse.ts would drag spec.ts (used at boot) into
 * `parser` and make every page load it.
 * @param {string} id
 * @returns {string | undefined}
 */
function lazyChunk(id) {
  if (/[\\/]node_modules[\\/](@codemirror|@lezer|style-mod|w3c-keyname|crelt)[\\/]/.test(id)) return 'editor';
  if (/[\\/]widgets[\\/]cells[\\/]editor\.ts$/.test(id)) return 'editor';
  if (/[\\/]node_modules[\\/](@observablehq[\\/]parser|acorn|acorn-walk)[\\/]/.test(id)) return 'parser';
  return undefined;
}

/**
 * KaTeX declares its fonts `font-display: block`: when one arrives after the
 * first layout, every line holding inline math reflows, which on a slow
 * connection was most of a chapter's layout shift. `optional` (as for the
 * text fonts, src/lib/fonts.ts) keeps the first layout: a math font that is
 * late is used from the next page on. The main two are preloaded.
 * @returns {import('vite').Plugin}
 */
function katexFontDisplay() {
  return {
    name: 'phasebook:katex-font-display',
    transform(code, id) {
      if (!/[\\/]katex[\\/]dist[\\/]katex(\.min)?\.css$/.test(id)) return null;
      const changed = code.replaceAll('font-display:block', 'font-display:optional');
      if (changed === code) this.error('katex.min.css no longer says font-display:block; check how it declares its fonts');
      return { code: changed, map: null };
    },
  };
}

/**
 * PHASEBOOK_OUT_DIR lets several builds run side by side (each with its own
 * output and caches) without wiping each other's dist/.
 */
const outDir = process.env.PHASEBOOK_OUT_DIR;

/**
 * PHASEBOOK_BASE serves the book under a sub-path, e.g. `/phasebook/` for a
 * GitHub project site; unset, the book lives at the root of its host. Links
 * in src/ are built on import.meta.env.BASE_URL so that they follow it.
 */
const base = process.env.PHASEBOOK_BASE || undefined;

export default defineConfig({
  site: 'http://localhost:4321',
  ...(outDir ? { outDir } : {}),
  ...(base ? { base } : {}),
  output: 'static',
  trailingSlash: 'always',
  build: { format: 'directory' },
  markdown: {
    remarkPlugins: [remarkMath, remarkCells],
    rehypePlugins: [rehypeKatex],
    syntaxHighlight: { type: 'shiki', excludeLangs: [CELL_CODE_LANGUAGE] },
    shikiConfig: {
      themes: { light: 'github-light', dark: 'github-dark' },
      defaultColor: false,
    },
  },
  integrations: [mdx()],
  vite: {
    ...(outDir ? { cacheDir: `${outDir}/.vite-cache` } : {}),
    // Workers (the stability chart's) load mathjs lazily, so they need ES modules to split chunks.
    worker: { format: 'es' },
    plugins: [katexFontDisplay()],
    build: {
      rollupOptions: { output: { manualChunks: lazyChunk } },
    },
  },
});
