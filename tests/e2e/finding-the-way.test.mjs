/**
 * Finding one's way in a long chapter: the "On this page" column that
 * follows the reading position on a wide screen, and its menu on a phone;
 * the links of section headings. (Previous and next at the top and the
 * bottom: site.test.mjs.)
 */
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { firstViewReady, landedOn, openChapter, openSite, watchPage } from './fixture.mjs';
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

test('axe finds no violation with "On this page" marking a section at 1280 px, nor on a phone with its menu open', async () => {
  const page = await site.context.newPage();
  await page.goto(`${site.origin}/order-and-chaos/`);
  await firstViewReady(page);
  await page.locator('#the-lyapunov-exponent').evaluate((heading) => heading.scrollIntoView());
  await page.waitForSelector('.on-this-page-column a[aria-current]');
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
  } finally {
    await phone.close();
  }
});
