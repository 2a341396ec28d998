import { describe, expect, it } from 'vitest';
import { contentSecurityPolicy, scriptHash } from '../../../../site/lib/csp.ts';
import { PACKAGE_BASE as B } from '../../../../site/scorm/chapter-files.ts';
import { inlineScripts, prunePage, relativeUrls, withAdapter, withScriptHashes } from '../../../../site/scorm/relative-urls.ts';

describe('site/scorm/relative-urls.ts: addresses that work under any path an LMS chooses', () => {
  it('makes the book’s addresses relative to the package’s root from the file’s own folder', () => {
    expect(relativeUrls(`url(${B}_astro/a.woff2)`, '_astro/page.css', 1)).toBe('url(../_astro/a.woff2)');
    expect(relativeUrls(`<script src="${B}_astro/b.js">`, 'introduction/index.html', 1)).toBe('<script src="../_astro/b.js">');
    expect(relativeUrls(`href="${B}x.svg"`, 'top.html', 1)).toBe('href="./x.svg"');
    expect(relativeUrls('nothing to change', 'deep/er/file.js', 1)).toBe('nothing to change');
  });

  it('read against the page and against the script, one relative address finds the same file', () => {
    const script = relativeUrls(`new URL("${B}_astro/w.js", import.meta.url); preload("${B}" + "_astro/c.js")`, '_astro/core.js', 1);
    const root = 'https://lms.example/lms/course-7/sco-3/';
    const [workerUrl, preloadBase] = [...script.matchAll(/"([^"]*)"/g)].map((m) => m[1]);
    expect(new URL(workerUrl, `${root}_astro/core.js`).href).toBe(`${root}_astro/w.js`);
    expect(new URL(preloadBase + '_astro/c.js', `${root}introduction/index.html`).href).toBe(`${root}_astro/c.js`);
  });

  it('refuses a script whose addresses would resolve one way against the page and another against itself', () => {
    expect(() => relativeUrls(`"${B}_astro/w.js"`, '_astro/deeper/chunk.js', 1)).toThrow(/not as deep as the page/);
  });

  it('takes the search box out, points links to other pages at the published book or keeps them as text, and links the page to itself', () => {
    const page = [
      `<form class="site-search" data-search data-search-module="${B}_astro/s.js"><input></form>`,
      `<a class="wordmark" href="${B}">Phasebook</a>`,
      `<a href="${B}kepler/#orbit">Kepler</a>`,
      `<a href="${B}introduction/#cell-sim">sim</a>`,
      `<link rel="preload" href="${B}_astro/font.woff2">`,
    ].join('\n');
    const published = prunePage(page, { slug: 'introduction', site: 'https://you.github.io/course/' });
    expect(published).not.toContain('site-search');
    expect(published).toContain('<a class="wordmark" href="https://you.github.io/course/">');
    expect(published).toContain('<a href="https://you.github.io/course/kepler/#orbit">');
    expect(published).toContain(`<a href="${B}introduction/index.html#cell-sim">`);
    expect(published).toContain(`<link rel="preload" href="${B}_astro/font.woff2">`);
    const alone = prunePage(page, { slug: 'introduction', site: null });
    expect(alone).toContain('<a class="wordmark" data-book-page="">Phasebook</a>');
    expect(alone).toContain('<a data-book-page="kepler/#orbit">Kepler</a>');
  });

  it('gives the policy the hashes of the inline scripts as they read now, the same the build gives them', () => {
    const scripts = ['(() => { const f = "/fonts/a.woff2"; })();', 'const form = document.querySelector("form");'];
    const page = (texts: string[]) => `<html><head><meta http-equiv="Content-Security-Policy" content="${contentSecurityPolicy(texts).replaceAll('"', '&quot;')}">`
      + `<script>${texts[0]}</script><script type="application/json">{"data":1}</script><script type="module" src="/x.js"></script>`
      + `<script type="module">${texts[1]}</script></head><body></body></html>`;
    expect(inlineScripts(page(scripts))).toEqual(scripts);
    // The build's own page keeps its policy; an edited script gets its new hash, and the old one goes.
    expect(withScriptHashes(page(scripts))).toBe(page(scripts));
    const edited = page(scripts).replace('/fonts/a.woff2', '../fonts/a.woff2');
    const policy = withScriptHashes(edited);
    expect(policy).toContain(scriptHash(scripts[0].replace('/fonts/', '../fonts/')));
    expect(policy).not.toContain(scriptHash(scripts[0]));
    expect(policy).toContain(scriptHash(scripts[1]));
    expect(() => withScriptHashes('<html><head></head></html>')).toThrow(/no Content-Security-Policy/);
  });

  it('adds the adapter’s script to the head, after the page is parsed', () => {
    expect(withAdapter('<head><title>t</title></head><body>', '../phasebook-scorm.js')).toBe('<head><title>t</title><script defer src="../phasebook-scorm.js"></script></head><body>');
  });
});
