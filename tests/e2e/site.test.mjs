/**
 * The site as a reader meets it: contents, chapter pages, math, links, and
 * the book without JavaScript. (That nothing goes wrong on any page's load,
 * no console or page error, no failed or foreign request, is checked in the
 * sweep of every page, every-page.mjs, at three widths.)
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { openSite, watchPage } from './fixture.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

/** Paths of the chapters, in the order the contents page lists them. */
async function chapterPaths() {
  const page = await site.context.newPage();
  await page.goto(`${site.origin}/`);
  const hrefs = await page.locator('.toc a').evaluateAll((links) => links.map((a) => a.getAttribute('href')));
  await page.close();
  return hrefs;
}

test('contents page lists the chapters in declared order, with descriptions', async () => {
  const page = await site.context.newPage();
  await page.goto(`${site.origin}/`);
  const titles = await page.locator('.toc li > a').allTextContents();
  assert.deepEqual(titles.slice(0, 1), ['Introduction']);
  assert.equal(titles.at(-1), 'How to use this book');
  const descriptions = await page.locator('.toc li > p').allTextContents();
  assert.equal(descriptions.length, titles.length);
  assert.ok(descriptions.every((text) => text.trim().length > 0));
  await page.close();
});

test('KaTeX renders inline and display math on the introduction', async () => {
  const page = await site.context.newPage();
  await page.goto(`${site.origin}/introduction/`);
  assert.ok((await page.locator('.katex').count()) >= 5);
  assert.ok((await page.locator('.katex-display').count()) >= 2);
  // Hamilton's equations: the MathML copy KaTeX emits carries the source.
  const annotations = await page.locator('.katex annotation').allTextContents();
  assert.ok(annotations.some((tex) => tex.includes('\\frac{\\partial H}{\\partial p_i}')));
  // KaTeX fonts load from the site itself.
  const fontsLoaded = await page.evaluate(async () => {
    await document.fonts.ready;
    return [...document.fonts].filter((font) => font.family.startsWith('KaTeX') && font.status === 'loaded').length;
  });
  assert.ok(fontsLoaded > 0, 'no KaTeX font loaded');
  await page.close();
});

test('chapters link to previous and next in declared order, at their top and their bottom, and to the contents at the bottom', async () => {
  const paths = await chapterPaths();
  for (const [i, path] of paths.entries()) {
    const page = await site.context.newPage();
    await page.goto(site.origin + path);
    for (const place of ['top', 'bottom']) {
      const nav = page.locator(`nav.chapter-nav-${place}`);
      assert.equal(await nav.count(), 1, `one ${place} navigation on ${path}`);
      const hrefOf = async (selector) => {
        const links = nav.locator(selector);
        return (await links.count()) > 0 ? links.getAttribute('href') : null;
      };
      assert.equal(await hrefOf('a[rel=prev]'), i > 0 ? paths[i - 1] : null, `previous of ${path}, ${place}`);
      assert.equal(await hrefOf('a[rel=next]'), i < paths.length - 1 ? paths[i + 1] : null, `next of ${path}, ${place}`);
      assert.equal(await hrefOf('a.contents'), place === 'bottom' ? '/' : null, `contents from ${path}, ${place}`);
    }
    // The top's links come before the chapter's title, the bottom's after its text.
    const order = await page.evaluate(() => {
      const title = document.querySelector('article h1');
      const follows = (a, b) => Boolean(a && b && a.compareDocumentPosition(b) & Node.DOCUMENT_POSITION_FOLLOWING);
      return [follows(document.querySelector('.chapter-nav-top'), title), follows(document.querySelector('article'), document.querySelector('.chapter-nav-bottom'))];
    });
    assert.deepEqual(order, [true, true], path);
    await page.close();
  }
});

test('without JavaScript, text, math and cell sources still read', async () => {
  const noScript = await openSite({ javaScriptEnabled: false });
  try {
    const page = await noScript.context.newPage();
    const { problems } = watchPage(page);
    await page.goto(`${noScript.origin}/introduction/`);
    assert.match((await page.locator('article').textContent()) ?? '', /Hamilton.s equations/);
    assert.ok((await page.locator('.katex-display').count()) >= 2);
    assert.ok(await page.locator('.katex-display').first().isVisible());
    const omega = page.locator('[data-cell="omega"]');
    assert.equal(await omega.locator('pre.cell-code').textContent(), 'omega = 10');
    assert.ok(await omega.locator('pre.cell-code').isVisible());
    assert.ok(await omega.locator('.cell-noscript').isVisible());
    assert.equal(await omega.locator('.cell-toolbar').isVisible(), false);
    assert.equal(await page.locator('.theme-toggle').isVisible(), false);
    assert.deepEqual(problems, []);
  } finally {
    await noScript.close();
  }
});

test('the theme toggle switches and remembers the theme', async () => {
  const page = await site.context.newPage();
  await page.emulateMedia({ colorScheme: 'light' });
  await page.goto(`${site.origin}/introduction/`);
  const background = () => page.evaluate(() => getComputedStyle(document.documentElement).backgroundColor);
  const light = await background();
  const label = () => page.locator('[data-theme-toggle]').innerText();
  assert.equal(await label(), 'Dark theme');
  await page.locator('[data-theme-toggle]').click();
  assert.equal(await page.evaluate(() => document.documentElement.dataset.theme), 'dark');
  assert.equal(await label(), 'Light theme');
  const dark = await background();
  assert.notEqual(dark, light);
  await page.reload();
  assert.equal(await background(), dark);
  await page.locator('[data-theme-toggle]').click();
  assert.equal(await background(), light);
  await page.evaluate(() => localStorage.removeItem('phasebook:theme'));
  // With nothing pinned the page follows the system, and the label offers the other theme.
  await page.emulateMedia({ colorScheme: 'dark' });
  await page.reload();
  assert.equal(await background(), dark);
  assert.equal(await label(), 'Light theme');
  await page.locator('[data-theme-toggle]').click();
  assert.equal(await background(), light);
  assert.equal(await label(), 'Dark theme');
  await page.evaluate(() => localStorage.removeItem('phasebook:theme'));
  await page.close();
});
