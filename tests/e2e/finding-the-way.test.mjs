/**
 * Finding one's way in a long chapter and in the book: the "On this page"
 * column that follows the reading position on a wide screen, and its menu on
 * a phone; the links of section headings; and search — the `/` shortcut,
 * results that land on their section, formulas found by their TeX, search
 * with the connection cut, and search after a reader's edit has run and the
 * sandbox has taken WebAssembly from the page. (Previous and next at the top
 * and the bottom: site.test.mjs. What loads when: lazy.test.mjs. Under a
 * base path: base-path.test.mjs.)
 */
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { cell, firstViewReady, landedOn, openChapter, openSite, typeIntoCell, waitForOutput, watchPage } from './fixture.mjs';
import { search, searchInput, shownResults } from './search-helpers.mjs';
import { DIST } from './server.mjs';

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
const WIDE = { width: 1280, height: 900 };
const PHONE = { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true };

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite({ viewport: WIDE })));
after(() => site?.close());

const column = (page) => page.locator('nav.on-this-page-column');
const menu = (page) => page.locator('nav.on-this-page-menu');
/** The section a list marks as being read ('' when none). */
const current = (list) => list.locator('a[aria-current="location"]').evaluateAll((links) => links.map((a) => a.dataset.sectionLink).join(' '));

async function axeViolations(page) {
  await page.evaluate(AXE);
  return page.evaluate(async () =>
    (await window.axe.run(document, { resultTypes: ['violations'] })).violations.map((v) => `${v.id} (${v.nodes.length}): ${v.nodes[0]?.target.join(' ')}`),
  );
}

test('on a wide screen, "On this page" stays beside the chapter and marks the section being read as the reader scrolls', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  assert.ok(await column(page).isVisible());
  assert.equal(await menu(page).isVisible(), false, 'the menu is for narrower screens');
  const ids = await column(page).locator('a[data-section-link]').evaluateAll((links) => links.map((a) => a.dataset.sectionLink));
  assert.deepEqual(ids, await page.locator('article .heading > h2').evaluateAll((hs) => hs.map((h) => h.id)), 'every section, in order');
  assert.ok(ids.length >= 8);

  // At the top, above the first section, none is marked.
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.waitForFunction(() => !document.querySelector('.on-this-page-column a[aria-current]'));

  // Forwards a section at a time, a jump across several, and back.
  for (const id of [ids[0], ids[1], ids[2], ids[6], ids[3]]) {
    await page.locator(`[id="${id}"]`).evaluate((heading) => heading.scrollIntoView({ block: 'start' }));
    await page.waitForFunction((want) => document.querySelector('.on-this-page-column a[aria-current]')?.dataset.sectionLink === want, id);
    assert.equal(await current(column(page)), id, 'one section marked at a time');
    // The column stays in view, wherever the reader is.
    const box = await column(page).boundingBox();
    assert.ok(box && box.y >= 0 && box.y < 40, `column at ${box?.y}`);
  }
  // At the very bottom the last section counts, even one too short to reach the reading line.
  await page.evaluate(() => window.scrollTo(0, document.documentElement.scrollHeight));
  await page.waitForFunction((want) => document.querySelector('.on-this-page-column a[aria-current]')?.dataset.sectionLink === want, ids.at(-1));

  // A click in the column goes to the section.
  await column(page).locator(`a[data-section-link="${ids[4]}"]`).click();
  await landedOn(page, ids[4]);
  await page.waitForFunction((want) => document.querySelector('.on-this-page-column a[aria-current]')?.dataset.sectionLink === want, ids[4]);
  assert.deepEqual(problems, []);
  await page.close();
});

test('on a phone (390 px, touch), "On this page" is a menu at the top of the chapter that opens and jumps to a section', async () => {
  const phone = await openSite(PHONE);
  try {
    const page = await phone.context.newPage();
    const { problems } = watchPage(page);
    await page.goto(`${phone.origin}/kepler/`);
    await firstViewReady(page);
    assert.equal(await column(page).isVisible(), false);
    assert.ok(await menu(page).isVisible());
    // At the top of the chapter: under its title, above its text.
    const [menuBox, titleBox] = [await menu(page).boundingBox(), await page.locator('article h1').boundingBox()];
    assert.ok(menuBox && titleBox && menuBox.y > titleBox.y && menuBox.y < 700, `menu at ${menuBox?.y}`);
    const summary = menu(page).locator('summary');
    assert.ok((await summary.boundingBox()).height >= 44, 'the summary is a 44 px target');
    assert.equal(await menu(page).locator('a').first().isVisible(), false, 'closed at first');

    await summary.tap();
    const links = menu(page).locator('a[data-section-link]');
    await links.first().waitFor();
    const heights = await links.evaluateAll((all) => all.map((a) => a.getBoundingClientRect().height));
    assert.ok(heights.every((h) => h >= 44), `link heights ${heights}`);
    const target = await links.nth(2).getAttribute('data-section-link');
    await links.nth(2).tap();
    await landedOn(page, target);
    assert.equal(await menu(page).locator('details').evaluate((d) => d.open), false, 'the menu closes once a section is chosen');
    await page.waitForFunction((want) => document.querySelector('.on-this-page-menu a[aria-current]')?.dataset.sectionLink === want, target);
    assert.deepEqual(problems, []);
    await page.close();
  } finally {
    await phone.close();
  }
});

test('the menu opens from the keyboard and is one named landmark, where the column is hidden', async () => {
  const page = await site.context.newPage();
  await page.setViewportSize({ width: 1000, height: 800 });
  await page.goto(`${site.origin}/order-and-chaos/`);
  await firstViewReady(page);
  const nav = page.getByRole('navigation', { name: 'On this page' });
  assert.equal(await nav.count(), 1, 'one "On this page" for screen readers: the hidden one is not counted');
  await menu(page).locator('summary').focus();
  await page.keyboard.press('Enter');
  assert.equal(await menu(page).locator('details').evaluate((d) => d.open), true);
  await page.keyboard.press('Tab');
  const focused = await page.evaluate(() => document.activeElement?.getAttribute('data-section-link'));
  assert.equal(focused, 'the-surface-of-section');
  await page.keyboard.press('Enter');
  await landedOn(page, 'the-surface-of-section');
  await page.close();
});

test('every section heading of every chapter has a link to itself beside it', () => {
  let headings = 0;
  for (const entry of readdirSync(DIST, { withFileTypes: true })) {
    if (!entry.isDirectory() || entry.name.startsWith('_') || entry.name === 'pagefind') continue;
    let html;
    try {
      html = readFileSync(join(DIST, entry.name, 'index.html'), 'utf8');
    } catch {
      continue;
    }
    const article = html.slice(html.indexOf('<article'), html.indexOf('</article>'));
    for (const [, level, id] of article.matchAll(/<h([2-4]) id="([^"]+)"/g)) {
      headings++;
      const wrapped = new RegExp(`<div class="heading heading-h${level}"><h${level} id="${id}">[\\s\\S]*?</h${level}><a class="heading-anchor" href="#${id}">`);
      assert.match(article, wrapped, `/${entry.name}/#${id}`);
    }
  }
  assert.ok(headings >= 80, `${headings} headings`);
});

test('a heading\'s link shows on hover and on focus, says where it leads, and lands there', async () => {
  const page = await site.context.newPage();
  await page.goto(`${site.origin}/introduction/`);
  await firstViewReady(page);
  const link = page.getByRole('link', { name: 'Link to the section “Live cells”' });
  assert.equal(await link.count(), 1);
  const opacity = () => link.evaluate((a) => Number(getComputedStyle(a).opacity));
  assert.equal(await opacity(), 0, 'out of the way while reading');
  await link.evaluate((a) => a.closest('.heading').scrollIntoView({ block: 'center' }));
  await page.locator('#live-cells').hover();
  assert.equal(await opacity(), 1, 'shown on hover');
  await page.mouse.move(0, 0);
  assert.equal(await opacity(), 0);
  // The keyboard reaches it: from the last thing before it that takes focus, one Tab.
  await link.evaluate((target) => {
    const focusable = [...document.querySelectorAll('a[href], button, input, select, textarea, summary, [tabindex]:not([tabindex="-1"])')]
      .filter((element) => element.checkVisibility() && element.compareDocumentPosition(target) & Node.DOCUMENT_POSITION_FOLLOWING);
    focusable.at(-1).focus();
  });
  await page.keyboard.press('Tab');
  assert.ok(await link.evaluate((a) => a === document.activeElement), 'reached by Tab');
  assert.equal(await opacity(), 1, 'shown on focus');
  const box = await link.boundingBox();
  assert.ok(box.width >= 24 && box.height >= 24, `${box.width}×${box.height}`);
  await page.keyboard.press('Enter');
  await landedOn(page, 'live-cells');
  await page.close();
});

test('`/` focuses the search box from the page, but is typed as a character in a field or a cell\'s editor', async () => {
  const page = await site.context.newPage();
  const { problems, requests } = watchPage(page);
  await page.goto(`${site.origin}/introduction/`);
  await firstViewReady(page);
  const searchRequests = () => requests.filter((url) => /\/_astro\/search[.-]|\/pagefind\//.test(url));
  assert.deepEqual(searchRequests(), []);

  await page.keyboard.press('/');
  assert.ok(await searchInput(page).evaluate((input) => input === document.activeElement), '/ focused the box');
  assert.equal(await searchInput(page).inputValue(), '', 'the / itself is not typed');
  await page.waitForFunction(() => document.querySelector('[data-search-status]')?.textContent?.startsWith('Search the text'));
  assert.ok(searchRequests().length > 0, 'search loads once asked for');
  await page.keyboard.type('1/2');
  assert.equal(await searchInput(page).inputValue(), '1/2', 'in the box, / is a character');

  // In a cell's editor too.
  await page.keyboard.press('Escape');
  await cell(page, 'omega').locator('.cell-editor').click();
  await cell(page, 'omega').locator('.cm-content').waitFor();
  await page.keyboard.press('End');
  await page.keyboard.type('/');
  assert.equal(await cell(page, 'omega').locator('.cm-content').textContent(), 'omega = 10/');
  assert.equal(await searchInput(page).evaluate((input) => input === document.activeElement), false);
  await page.keyboard.press('ControlOrMeta+Z');
  assert.deepEqual(problems, []);
  await page.evaluate(() => localStorage.clear());
  await page.close();
});

test('search finds "Lyapunov" in Order and chaos and "adiabatic" in its chapter, with marked excerpts, and its results land on their section', async () => {
  const page = await site.context.newPage();
  const { problems } = watchPage(page);
  await page.goto(`${site.origin}/kepler/`);
  await firstViewReady(page);

  assert.match(await search(page, 'Lyapunov'), /chapters? match/);
  let results = await shownResults(page);
  assert.equal(results[0].title, 'Order and chaos');
  assert.equal(results[0].href, '/order-and-chaos/');
  const lyapunov = results[0].sections.find((section) => section.title === 'The Lyapunov exponent');
  assert.ok(lyapunov, JSON.stringify(results[0].sections));
  assert.equal(lyapunov.href, '/order-and-chaos/#the-lyapunov-exponent');
  assert.ok(lyapunov.marked.includes('Lyapunov'), `marked: ${lyapunov.marked}`);
  assert.ok(lyapunov.excerpt.includes('Lyapunov'));

  await search(page, 'adiabatic');
  results = await shownResults(page);
  assert.equal(results[0].href, '/adiabatic-invariants/');
  assert.ok(results[0].sections.every((section) => section.href.startsWith('/adiabatic-invariants/')));
  assert.ok(results[0].sections.some((section) => section.marked.some((word) => /^adiabatic$/i.test(word))));

  // By keyboard: ↓ into the results, ↑ back to the box, Escape closes them.
  const panel = page.locator('[data-search-panel]');
  await page.keyboard.press('ArrowDown');
  assert.equal(await page.evaluate(() => document.activeElement?.getAttribute('href')), '/adiabatic-invariants/');
  await page.keyboard.press('ArrowUp');
  assert.ok(await searchInput(page).evaluate((input) => input === document.activeElement));
  await page.keyboard.press('Escape');
  assert.equal(await panel.isVisible(), false);
  await page.keyboard.press('ArrowDown');
  assert.ok(await panel.isVisible(), '↓ opens them again');

  // A section's link lands on its heading, on another page.
  await search(page, 'Lyapunov');
  await page.locator('.search-section[href="/order-and-chaos/#the-lyapunov-exponent"]').click();
  await landedOn(page, 'the-lyapunov-exponent');
  assert.equal(new URL(page.url()).pathname, '/order-and-chaos/');

  // Enter in the box opens the first chapter's best section; a result on this page moves the view and closes the results.
  await search(page, 'surface of section');
  const first = await page.locator('[data-search-results] a.search-section').first().getAttribute('href');
  assert.ok(first?.startsWith('/order-and-chaos/'), first);
  await searchInput(page).press('Enter');
  await page.waitForFunction((href) => location.pathname + location.hash === href, first);
  assert.equal(await panel.isVisible(), false);
  assert.deepEqual(problems, []);
  await page.close();
});

test('search finds a formula by its TeX, and shows it as TeX, not as the letters KaTeX draws it with', async () => {
  const page = await site.context.newPage();
  const { problems } = watchPage(page);
  await page.goto(`${site.origin}/`);
  await search(page, '\\dot q_i = \\frac{\\partial H}{\\partial p_i}');
  const results = await shownResults(page);
  // The introduction, which holds the formula, is among the first results (the action–angle chapter, dense with
  // ∂H/∂p-like formulas, may rank above it), and its excerpt shows the formula as TeX, its words marked.
  const introduction = results.slice(0, 3).find((result) => result.href === '/introduction/');
  assert.ok(introduction, JSON.stringify(results.map((r) => r.href)));
  const excerpts = results.flatMap((result) => result.sections.map((section) => section.excerpt));
  assert.ok(introduction.sections.some((section) => section.excerpt.includes('\\dot q_i = \\frac{\\partial H}{\\partial p_i}')), excerpts.join('\n'));
  assert.ok(introduction.sections.some((section) => section.marked.some((word) => word.includes('\\partial'))), 'its words are marked');
  // KaTeX's HTML and MathML set the same formula as q˙ᵢ = ∂H∂pᵢ: neither is in the index, so no excerpt shows it.
  assert.ok(excerpts.every((text) => !/q˙|∂H∂p/.test(text)), excerpts.join('\n'));

  // A fragment of TeX finds the formulas that hold it, in several chapters.
  await search(page, '\\partial H');
  const found = await shownResults(page);
  assert.ok(found.length >= 3, `${found.length} chapters`);
  assert.ok(found.flatMap((result) => result.sections).some((section) => section.excerpt.includes('{\\partial H}')));
  assert.deepEqual(problems, []);
  await page.close();
});

test('search works with the network cut once the box has opened, and says so when it cannot load at all', async () => {
  const page = await site.context.newPage();
  const { problems } = watchPage(page);
  await page.goto(`${site.origin}/introduction/`);
  await firstViewReady(page);
  await searchInput(page).focus();
  await page.waitForSelector('form[data-search-held]', { state: 'attached' });
  await site.context.setOffline(true);
  try {
    for (const [query, chapter] of [['Lyapunov', '/order-and-chaos/'], ['adiabatic', '/adiabatic-invariants/'], ['Kepler', '/kepler/']]) {
      await search(page, query);
      assert.equal((await shownResults(page))[0]?.href, chapter, query);
    }
    assert.deepEqual(problems, []);

    // A page that never opened search before the connection went cannot load it, and says why.
    const cold = await site.context.newPage();
    await site.context.setOffline(false);
    await cold.goto(`${site.origin}/introduction/`);
    await firstViewReady(cold);
    await site.context.setOffline(true);
    await searchInput(cold).focus();
    await cold.waitForFunction(() => /connection .* seems to be lost/.test(document.querySelector('[data-search-status]')?.textContent ?? ''));
    assert.ok(await cold.locator('[data-search-panel]').isVisible());
    // Back online, the next focus loads it.
    await site.context.setOffline(false);
    await cold.locator('article h1').click();
    await search(cold, 'Lyapunov');
    assert.equal((await shownResults(cold))[0]?.href, '/order-and-chaos/');
    await cold.close();
  } finally {
    await site.context.setOffline(false);
  }
  await page.close();
});

test('search still works after a reader\'s edit has run and the sandbox has taken WebAssembly from the page', async () => {
  const page = await site.context.newPage();
  const { problems } = watchPage(page);
  await page.goto(`${site.origin}/introduction/`);
  await firstViewReady(page);
  assert.equal(await page.evaluate(() => typeof WebAssembly), 'object');
  await typeIntoCell(page, 'omega', 'omega = 5');
  await waitForOutput(page, 'omega', (text) => text === 'omega = 5');
  await page.waitForFunction(() => typeof WebAssembly === 'undefined', null);

  await search(page, 'Lyapunov');
  assert.equal((await shownResults(page))[0]?.href, '/order-and-chaos/');
  assert.deepEqual(problems, []);
  await page.evaluate(() => localStorage.clear());
  await page.close();
});

test('axe finds no violation with search results shown, at 1280 px and on a phone with the menu open and with results shown', async () => {
  const page = await site.context.newPage();
  await page.goto(`${site.origin}/order-and-chaos/`);
  await firstViewReady(page);
  await page.locator('#the-lyapunov-exponent').evaluate((heading) => heading.scrollIntoView());
  await page.waitForSelector('.on-this-page-column a[aria-current]');
  await search(page, 'Lyapunov');
  assert.deepEqual(await axeViolations(page), []);
  await page.close();

  const phone = await openSite(PHONE);
  try {
    const small = await phone.context.newPage();
    await small.goto(`${phone.origin}/order-and-chaos/`);
    await firstViewReady(small);
    await menu(small).locator('summary').tap();
    await menu(small).locator('a').first().waitFor();
    assert.deepEqual(await axeViolations(small), [], 'menu open');
    await search(small, 'Lyapunov');
    // The results fit the phone's width.
    const box = await small.locator('[data-search-panel]').boundingBox();
    assert.ok(box && box.x >= 0 && box.x + box.width <= 390, `panel ${box?.x}–${box && box.x + box.width}`);
    const heights = await small.locator('[data-search-results] a').evaluateAll((links) => links.map((a) => a.getBoundingClientRect().height));
    assert.ok(heights.every((h) => h >= 44), `result heights ${heights}`);
    assert.ok((await searchInput(small).boundingBox()).height >= 44);
    assert.deepEqual(await axeViolations(small), [], 'results shown');
  } finally {
    await phone.close();
  }
});
