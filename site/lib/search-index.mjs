/**
 * Search, built with the site (an Astro integration, in astro.config.mjs):
 *
 * 1. The search box's module (site/search/search-ui.ts) is a chunk of the
 *    client bundle that no page imports: the box's inline script imports it
 *    when the reader asks (site/lib/search-box.ts). Its file name, hash
 *    included, is known once the bundle is written, and is then put in
 *    place of the placeholder in every page.
 * 2. Pagefind indexes the built chapters, the `data-pagefind-body` of each
 *    (the article: not the header, the navigation or the footer), and only
 *    what a reader reads there. A formula is indexed by its TeX source:
 *    KaTeX sets each one as HTML for the eye and as MathML for screen
 *    readers, which holds the TeX in an <annotation>; the HTML and the
 *    MathML's own text are left out, so the index sees `\dot q`, once, and
 *    not the letters of the typeset formula. The buttons of cells and the
 *    links of headings are left out too.
 * 3. Of Pagefind's output, only what the search worker uses is written into
 *    `pagefind/` (not Pagefind's own interfaces), with the list of the
 *    index's files the worker fetches when the box opens
 *    (site/search/held-index.ts).
 */
import { mkdir, readdir, readFile, rm, writeFile } from 'node:fs/promises';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { createIndex, close as closePagefind } from 'pagefind';
import { INDEX_FILES } from '../search/held-index.ts';
import { SEARCH_MODULE_PLACEHOLDER } from './search-box.ts';

const SEARCH_UI = fileURLToPath(new URL('../search/search-ui.ts', import.meta.url));

/** The folder of the index in the built site (site/components/SearchBox.astro points there). */
export const INDEX_FOLDER = 'pagefind';

/** What of a chapter's text is not indexed. */
export const NOT_INDEXED = [
  // KaTeX's HTML, and its MathML but for the <annotation> that holds the TeX source.
  '.katex-html',
  '.katex-mathml semantics > :not(annotation)',
  // The words of controls, not of the book.
  '.heading-anchor',
  '.on-this-page',
  '.share-edits',
  '.cell-toolbar',
];

/**
 * The files of Pagefind's output the search worker needs: its script, the
 * entry, and the index (meta, WebAssembly of each language, index, filter
 * and fragment chunks). Pagefind's interfaces, its own worker and its
 * highlighter are left out; so is a language no page is in.
 * @param {readonly { path: string, content: Uint8Array }[]} files
 */
export function runtimeFiles(files) {
  const entry = files.find((file) => file.path === 'pagefind-entry.json');
  if (!entry) throw new Error('search-index: Pagefind wrote no pagefind-entry.json');
  const languages = Object.values(JSON.parse(Buffer.from(entry.content).toString('utf8')).languages ?? {});
  if (!languages.length) throw new Error('search-index: Pagefind indexed no page (no data-pagefind-body in the built chapters?)');
  const wasm = new Set(languages.map((language) => `wasm.${language.wasm}.pagefind`));
  return files.filter(
    ({ path }) =>
      path === 'pagefind.js' ||
      path === 'pagefind-entry.json' ||
      path.endsWith('.pf_meta') ||
      wasm.has(path) ||
      /^(index|fragment|filter)\//.test(path),
  );
}

/** The list the worker reads: every file it holds in memory (pagefind.js, a module it imports, is not one). */
export function indexFileList(files) {
  return { files: files.map(({ path }) => path).filter((path) => path !== 'pagefind.js').sort() };
}

/**
 * Indexes the built site in `siteDir` and writes the index into its
 * `pagefind/` folder: how many files, their bytes (as written: Pagefind
 * compresses the index itself) and how many pages it holds.
 * @returns {Promise<{ files: number, bytes: number, pages: number }>}
 */
export async function writeSearchIndex(siteDir) {
  try {
    const { index, errors } = await createIndex({ excludeSelectors: NOT_INDEXED, forceLanguage: 'en' });
    if (!index) throw new Error(`search-index: ${errors.join('; ')}`);
    const added = await index.addDirectory({ path: siteDir });
    if (added.errors.length) throw new Error(`search-index: ${added.errors.join('; ')}`);
    const output = await index.getFiles();
    if (output.errors.length) throw new Error(`search-index: ${output.errors.join('; ')}`);
    const files = runtimeFiles(output.files);
    const folder = join(siteDir, INDEX_FOLDER);
    await rm(folder, { recursive: true, force: true });
    for (const { path, content } of files) {
      await mkdir(dirname(join(folder, path)), { recursive: true });
      await writeFile(join(folder, path), content);
    }
    await writeFile(join(folder, INDEX_FILES), JSON.stringify(indexFileList(files)));
    const entry = JSON.parse(Buffer.from(files.find(({ path }) => path === 'pagefind-entry.json').content).toString('utf8'));
    const pages = Object.values(entry.languages).reduce((sum, language) => sum + (language.page_count ?? 0), 0);
    return { files: files.length, bytes: files.reduce((sum, { content }) => sum + content.length, 0), pages };
  } finally {
    await closePagefind();
  }
}

/** `html` with the search module's address in place of the placeholder (unchanged when it has none). */
export function withSearchModule(html, moduleUrl) {
  return html.replaceAll(SEARCH_MODULE_PLACEHOLDER, moduleUrl);
}

async function* htmlFiles(dir) {
  for (const entry of await readdir(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) yield* htmlFiles(path);
    else if (entry.name.endsWith('.html')) yield path;
  }
}

/** The Astro integration: the search module's chunk in the client build, then the pages' placeholders and the index. */
export function searchIndex() {
  let base = '/';
  let client = false;
  let reference = null;
  let moduleFile = null;
  return {
    name: 'phasebook:search-index',
    hooks: {
      'astro:config:setup': ({ updateConfig }) => {
        updateConfig({
          vite: {
            plugins: [
              {
                name: 'phasebook:search-module',
                apply: 'build',
                configResolved(config) {
                  client = !config.build.ssr;
                },
                buildStart() {
                  reference = client ? this.emitFile({ type: 'chunk', id: SEARCH_UI, name: 'search' }) : null;
                },
                generateBundle() {
                  if (reference) moduleFile = this.getFileName(reference);
                },
              },
            ],
          },
        });
      },
      'astro:config:done': ({ config }) => {
        base = config.base.endsWith('/') ? config.base : `${config.base}/`;
      },
      'astro:build:done': async ({ dir, logger }) => {
        if (!moduleFile) throw new Error('search-index: the client bundle has no search module');
        const siteDir = fileURLToPath(dir);
        let pages = 0;
        for await (const file of htmlFiles(siteDir)) {
          const html = await readFile(file, 'utf8');
          const filled = withSearchModule(html, `${base}${moduleFile}`);
          if (filled !== html) {
            await writeFile(file, filled);
            pages++;
          }
        }
        if (!pages) throw new Error(`search-index: no page holds the search box's placeholder ${SEARCH_MODULE_PLACEHOLDER}`);
        const index = await writeSearchIndex(siteDir);
        logger.info(`${index.pages} chapters indexed; ${index.files} files, ${(index.bytes / 1024).toFixed(0)} KB in ${INDEX_FOLDER}/`);
      },
    },
  };
}
