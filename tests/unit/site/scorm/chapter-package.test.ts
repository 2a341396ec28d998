import { describe, expect, it } from 'vitest';
import { PACKAGE_BASE } from '../../../../site/scorm/chapter-files.ts';
import { ADAPTER_PATH, chapterPackage, pageTitle } from '../../../../site/scorm/chapter-package.ts';
import { BOOK, builtSite } from '../../support/scorm-book.ts';

const decoder = new TextDecoder();

describe('site/scorm/chapter-package.ts: a chapter’s package', () => {
  const adapter = new TextEncoder().encode('/* adapter */');
  const files = chapterPackage(builtSite(BOOK), 'introduction', { site: null, adapter });
  const byPath = new Map(files.map((f) => [f.path, decoder.decode(f.bytes)]));
  const manifest = byPath.get('imsmanifest.xml')!;

  it('lists in its manifest every file it holds but the manifest, and no other', () => {
    const listed = [...manifest.matchAll(/<file href="([^"]*)"\/>/g)].map((m) => decodeURIComponent(m[1]));
    expect(listed.sort()).toEqual(files.map((f) => f.path).filter((p) => p !== 'imsmanifest.xml').sort());
    expect(files.at(-1)!.path).toBe('imsmanifest.xml');
  });

  it('holds the chapter, the files it needs and the adapter, and not the search code the package cannot serve', () => {
    expect(byPath.get(ADAPTER_PATH)).toBe('/* adapter */');
    expect(byPath.has('_astro/core.D1.js')).toBe(true);
    expect(byPath.has('_astro/search.S1.js')).toBe(false);
    expect(byPath.has('kepler/index.html')).toBe(false);
  });

  it('leaves no address under the package base, and loads the adapter from the page', () => {
    for (const [path, text] of byPath) expect(text, path).not.toContain(PACKAGE_BASE);
    const page = byPath.get('introduction/index.html')!;
    expect(page).toContain('<script type="module" src="../_astro/boot.C1.js">');
    expect(page).toContain(`<script defer src="../${ADAPTER_PATH}"></script></head>`);
    expect(byPath.get('_astro/core.D1.js')).toContain('new URL("../_astro/sim-worker.W1.js",import.meta.url)');
  });

  it('titles the item with the chapter’s title, its references read', () => {
    expect(manifest).toContain('<title>Introduction — Phasebook</title>');
    expect(pageTitle('<title>Lagrange &amp; Hamilton &#8212; &#x3c9;</title>', 'x')).toBe('Lagrange & Hamilton — ω');
    expect(pageTitle('<p>untitled</p>', 'slug')).toBe('slug');
  });
});
