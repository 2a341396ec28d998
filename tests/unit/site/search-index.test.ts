import { mkdtempSync, readdirSync, readFileSync, mkdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { gunzipSync } from 'node:zlib';
import katex from 'katex';
import { describe, expect, it } from 'vitest';
import { indexFileList, runtimeFiles, withSearchModule, writeSearchIndex } from '../../../site/lib/search-index.mjs';
import { INDEX_FILES } from '../../../site/search/held-index.ts';
import { SEARCH_MODULE_PLACEHOLDER } from '../../../site/lib/search-box.ts';

const TEX = '\\dot q = \\frac{\\partial H}{\\partial p}';

/** A built chapter as the site writes one: the frame, and the article Pagefind reads. */
function chapter(title: string, body: string): string {
  return `<!doctype html><html lang="en"><head><title>${title}</title></head><body>
    <header><form role="search"><input type="search" placeholder="Search"></form></header>
    <nav class="on-this-page"><a href="#motion">Hamilton frame words</a></nav>
    <article data-pagefind-body><h1>${title}</h1>${body}</article>
    <footer>Footer words</footer></body></html>`;
}

/** The text Pagefind keeps of each page of the index in `site`, by URL. */
function indexedText(site: string): Map<string, string> {
  const folder = join(site, 'pagefind', 'fragment');
  const pages = new Map<string, string>();
  for (const file of readdirSync(folder)) {
    const fragment = JSON.parse(gunzipSync(readFileSync(join(folder, file))).subarray('pagefind_dcd'.length).toString('utf8'));
    pages.set(fragment.url, fragment.content);
  }
  return pages;
}

describe('site/lib/search-index.mjs: the search index built with the site', () => {
  it('indexes each chapter\'s article, a formula by its TeX once, and none of the controls', async () => {
    const site = mkdtempSync(join(tmpdir(), 'search-index-'));
    const formula = katex.renderToString(TEX, { displayMode: true });
    mkdirSync(join(site, 'motion'));
    writeFileSync(
      join(site, 'motion', 'index.html'),
      chapter(
        'Motion',
        `<div class="heading heading-h2"><h2 id="equations">Equations</h2><a class="heading-anchor" href="#equations"><span aria-hidden="true">§</span><span class="visually-hidden">Link to the section “Equations”</span></a></div>
         <p>Hamilton's equations read</p>${formula}
         <figure class="cell"><pre class="cell-code">omega = 10</pre><div class="cell-toolbar"><span>Shift+Enter runs</span><button>Reset</button></div></figure>`,
      ),
    );
    writeFileSync(join(site, 'index.html'), '<!doctype html><html lang="en"><body><h1>Contents</h1><p>Contents words</p></body></html>');

    const written = await writeSearchIndex(site);

    expect(written.pages).toBe(1);
    const pages = indexedText(site);
    expect([...pages.keys()]).toEqual(['/motion/']);
    const text = pages.get('/motion/') ?? '';
    expect(text).toContain(TEX);
    expect(text.split('\\partial H').length - 1).toBe(1);
    // The typeset letters, from KaTeX's HTML or from its MathML: q̇, ∂, and a fraction's pieces run together.
    expect(text).not.toMatch(/[˙∂]|∂H∂p/);
    expect(text).toContain('omega = 10');
    for (const control of ['Shift+Enter', 'Reset', 'Link to the section', '§', 'frame words', 'Footer', 'Search']) expect(text).not.toContain(control);

    const files = readdirSync(join(site, 'pagefind'), { recursive: true }).map(String);
    expect(files).toContain('pagefind.js');
    expect(files).toContain(INDEX_FILES);
    expect(files.filter((file) => /ui|highlight|pagefind-worker|unknown/.test(file))).toEqual([]);
    const listed = JSON.parse(readFileSync(join(site, 'pagefind', INDEX_FILES), 'utf8')).files as string[];
    expect(listed).toContain('pagefind-entry.json');
    expect(listed).toContain('wasm.en.pagefind');
    expect(listed.some((file) => file.startsWith('index/'))).toBe(true);
    expect(listed.some((file) => file.startsWith('fragment/'))).toBe(true);
    expect(listed).not.toContain('pagefind.js');
    expect(written.bytes).toBeGreaterThan(0);
  });

  it('keeps of Pagefind\'s output only what the worker uses, and refuses an index without pages', () => {
    const file = (path: string, content = '') => ({ path, content: new TextEncoder().encode(content) });
    const entry = file('pagefind-entry.json', JSON.stringify({ languages: { en: { hash: 'en_1', wasm: 'en', page_count: 2 } } }));
    const kept = runtimeFiles([
      entry,
      file('pagefind.js'),
      file('pagefind.en_1.pf_meta'),
      file('wasm.en.pagefind'),
      file('wasm.unknown.pagefind'),
      file('index/en_2.pf_index'),
      file('fragment/en_3.pf_fragment'),
      file('pagefind-ui.js'),
      file('pagefind-worker.js'),
      file('pagefind-highlight.js'),
    ]).map(({ path }) => path);
    expect(kept).toEqual(['pagefind-entry.json', 'pagefind.js', 'pagefind.en_1.pf_meta', 'wasm.en.pagefind', 'index/en_2.pf_index', 'fragment/en_3.pf_fragment']);
    expect(indexFileList(kept.map((path) => ({ path })))).toEqual({
      files: ['fragment/en_3.pf_fragment', 'index/en_2.pf_index', 'pagefind-entry.json', 'pagefind.en_1.pf_meta', 'wasm.en.pagefind'],
    });
    expect(() => runtimeFiles([file('pagefind-entry.json', '{"languages":{}}')])).toThrow(/no page/);
    expect(() => runtimeFiles([])).toThrow(/pagefind-entry/);
  });

  it('puts the search module\'s address in place of its placeholder', () => {
    const html = `<form data-search-module="${SEARCH_MODULE_PLACEHOLDER}">`;
    expect(withSearchModule(html, '/phasebook/_astro/search.abc.js')).toBe('<form data-search-module="/phasebook/_astro/search.abc.js">');
    expect(withSearchModule('<p>none</p>', '/x.js')).toBe('<p>none</p>');
  });
});
