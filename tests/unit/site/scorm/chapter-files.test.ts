import { describe, expect, it } from 'vitest';
import { chapterFiles } from '../../../../site/scorm/chapter-files.ts';
import { BOOK, builtSite } from '../../support/scorm-book.ts';

describe('site/scorm/chapter-files.ts: the files a chapter needs', () => {
  it('follows the page’s addresses, chunk imports, the preload list and workers, to the end', () => {
    const files = chapterFiles(builtSite(BOOK), 'introduction');
    expect(files[0]).toBe('introduction/index.html');
    expect(new Set(files)).toEqual(new Set([
      'introduction/index.html',
      '_astro/serif.A1.woff2',
      '_astro/search.S1.js',
      '_astro/search-worker.SW1.js',
      '_astro/boot.C1.js',
      '_astro/core.D1.js',
      '_astro/exercise.E1.js',
      '_astro/plots.P1.js',
      '_astro/sim-worker.W1.js',
    ]));
  });

  it('leaves out what nothing it needs names: other pages and their scripts, unused chunks, the search index', () => {
    const files = chapterFiles(builtSite(BOOK), 'introduction');
    for (const left of ['index.html', 'kepler/index.html', '_astro/kepler-only.K1.js', '_astro/unused.U1.js', 'pagefind/pagefind.js', 'pagefind/index/en.pf_index']) {
      expect(files).not.toContain(left);
    }
  });

  it('refuses a chapter the build does not have', () => {
    expect(() => chapterFiles(builtSite(BOOK), 'lagrange')).toThrow(/no chapter “lagrange”/);
  });
});
