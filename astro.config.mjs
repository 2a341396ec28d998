// @ts-check
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'astro/config';
import mdx from '@astrojs/mdx';
import { rehypeHeadingIds } from '@astrojs/markdown-remark';
import remarkMath from 'remark-math';
import rehypeKatex from 'rehype-katex';
import { remarkCells, CELL_CODE_LANGUAGE } from './site/lib/remark-cells.mjs';
import { remarkExercises } from './site/lib/remark-exercises.mjs';
import { bookChunks } from './site/lib/chunks.mjs';
import { linkedPreloads } from './site/lib/linked-preloads.mjs';
import { rehypeHeadingAnchors } from './site/lib/rehype-heading-anchors.mjs';
import { searchIndex } from './site/lib/search-index.mjs';

const CORE = fileURLToPath(new URL('./core/', import.meta.url));

/**
 * Rollup's `moduleSideEffects`: false for the core's modules, which are pure.
 * A module of the core that nothing uses is then dropped even when it is
 * reached through the core's front door (core/index.ts), so that
 * importing one name from the index never brings the rest of the core into a
 * page's first load or a worker.
 * @param {string} id
 */
function coreIsPure(id) {
  return !id.startsWith(CORE);
}

/**
 * Takes KaTeX's @font-face rules out of its stylesheet: site/lib/fonts.ts
 * declares the same faces with the book's loading rules (font-display
 * optional, nothing on a slow connection) instead of KaTeX's `block`, which
 * reflowed every line holding inline math when a math font arrived late.
 * @returns {import('vite').Plugin}
 */
function katexWithoutFontFaces() {
  return {
    name: 'phasebook:katex-without-font-faces',
    transform(code, id) {
      if (!/[\\/]katex[\\/]dist[\\/]katex(\.min)?\.css$/.test(id)) return null;
      const changed = code.replace(/@font-face\s*\{[^}]*\}/g, '');
      if (changed === code) this.error('katex.min.css declares no @font-face any more; check site/lib/fonts.ts');
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
 * in site/ are built on import.meta.env.BASE_URL so that they follow it.
 */
const base = process.env.PHASEBOOK_BASE || undefined;

export default defineConfig({
  // The site's pages, layouts and build-time code; the book's browser code is in cells/ and widgets/.
  srcDir: './site',
  site: 'http://localhost:4321',
  ...(outDir ? { outDir } : {}),
  ...(base ? { base } : {}),
  output: 'static',
  trailingSlash: 'always',
  build: {
    format: 'directory',
    // The stylesheet (8 KB gzip) comes inside each page: fetched apart, over a slow network it arrived a second
    // after the text, on a connection of its own, and held the first paint until then.
    inlineStylesheets: 'always',
  },
  markdown: {
    remarkPlugins: [remarkMath, remarkCells, remarkExercises],
    // Headings get their ids here, before their links are made; Astro's own pass later keeps them.
    rehypePlugins: [rehypeKatex, rehypeHeadingIds, rehypeHeadingAnchors],
    syntaxHighlight: { type: 'shiki', excludeLangs: [CELL_CODE_LANGUAGE] },
    shikiConfig: {
      // github-dark's comments read at 3.4:1 on the dark page; the default variant's at 5.9:1.
      themes: { light: 'github-light', dark: 'github-dark-default' },
      defaultColor: false,
    },
  },
  // searchIndex after linkedPreloads: the index is built from the pages as they are served.
  integrations: [mdx(), linkedPreloads(), searchIndex()],
  vite: {
    ...(outDir ? { cacheDir: `${outDir}/.vite-cache` } : {}),
    // Workers (the stability chart's) load mathjs lazily, so they need ES modules to split chunks.
    worker: { format: 'es', rollupOptions: { treeshake: { moduleSideEffects: coreIsPure } } },
    plugins: [katexWithoutFontFaces()],
    build: {
      // PHASEBOOK_SOURCEMAP=1 writes source maps, to see which modules make up each chunk's bytes.
      sourcemap: !!process.env.PHASEBOOK_SOURCEMAP,
      rollupOptions: {
        treeshake: { moduleSideEffects: coreIsPure },
        output: {
          manualChunks: bookChunks(),
          // The book's modules are all grouped (site/lib/chunks.mjs); this merges the small pieces Rollup
          // cuts from third-party code loaded on demand, each of which would cost a round trip.
          experimentalMinChunkSize: 20_000,
        },
      },
    },
  },
});
