// @ts-check
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'astro/config';
import mdx from '@astrojs/mdx';
import { rehypeHeadingIds } from '@astrojs/markdown-remark';
import remarkMath from 'remark-math';
import rehypeKatex from 'rehype-katex';
import { remarkBaseLinks } from './site/lib/remark-base-links.mjs';
import { remarkCells, CELL_CODE_LANGUAGE } from './site/lib/remark-cells.mjs';
import { remarkExercises } from './site/lib/remark-exercises.mjs';
import { bookChunks } from './site/lib/chunks.mjs';
import { linkedPreloads } from './site/lib/linked-preloads.mjs';
import { rehypeHeadingAnchors } from './site/lib/rehype-heading-anchors.mjs';
import { searchIndex } from './site/lib/search-index.mjs';
import { failLoudly } from './site/lib/fail-loudly.mjs';
import { staticOnly } from './site/lib/static-only.mjs';
import { recordFingerprint } from './site/lib/build-fingerprint.mjs';

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
 * declares the same faces with the book's loading rules (in the page's own
 * head, preloaded where a chapter's first view draws them).
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
 * The book's chunks (site/lib/chunks.mjs), for the browser's build only. The
 * build that renders the pages on the server runs the same modules; grouped
 * there, the groups it tree-shakes away became empty chunks (a warning each)
 * and its `boot` group a chunk written among the pages.
 * @returns {import('vite').Plugin}
 */
function clientChunks() {
  return {
    name: 'phasebook:client-chunks',
    config(_config, { isSsrBuild }) {
      if (isSsrBuild) return null;
      return {
        build: {
          rollupOptions: {
            output: {
              manualChunks: bookChunks(),
              // The book's modules are all grouped; this merges the small pieces Rollup cuts from
              // third-party code loaded on demand, each of which would cost a round trip.
              experimentalMinChunkSize: 20_000,
            },
          },
        },
      };
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
 * in site/ are built on import.meta.env.BASE_URL so that they follow it, and
 * the chapters' root-relative links are put under it by remarkBaseLinks.
 */
const base = process.env.PHASEBOOK_BASE || undefined;

export default defineConfig({
  // The site's pages, layouts and build-time code; the book's browser code is in cells/ and widgets/.
  srcDir: './site',
  site: 'http://localhost:4321',
  // Astro's own cache (the content store) goes beside the output too: in node_modules/ it would be shared.
  ...(outDir ? { outDir, cacheDir: `${outDir}.astro-cache` } : {}),
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
    remarkPlugins: [remarkMath, remarkCells, remarkExercises, [remarkBaseLinks, { base }]],
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
  // staticOnly after the others: it takes Astro's server code out of what they wrote; the fingerprint is recorded last, once all went well.
  integrations: [mdx(), failLoudly(), linkedPreloads(), searchIndex(), staticOnly(), recordFingerprint()],
  vite: {
    ...(outDir ? { cacheDir: `${outDir}/.vite-cache` } : {}),
    // Workers (the stability chart's) load mathjs lazily, so they need ES modules to split chunks.
    worker: { format: 'es', rollupOptions: { treeshake: { moduleSideEffects: coreIsPure } } },
    plugins: [katexWithoutFontFaces(), clientChunks()],
    build: {
      // PHASEBOOK_SOURCEMAP=1 writes source maps, to see which modules make up each chunk's bytes.
      sourcemap: !!process.env.PHASEBOOK_SOURCEMAP,
      rollupOptions: {
        treeshake: { moduleSideEffects: coreIsPure },
      },
    },
  },
});
