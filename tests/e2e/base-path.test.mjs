/**
 * The book served under a base path, as a GitHub project site is
 * (`PHASEBOOK_BASE=<base> npm run build`, then the site at
 * that base, base-build.mjs's BASE): its pages, their links and search all stay under it, and
 * nothing is asked of the host's root. The site is built for this by
 * base-build.mjs when the one at hand is older than the site under test.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { firstViewReady, watchPage } from './browser.mjs';
import { BASE, openBaseSite } from './base-build.mjs';
import { landedOn } from './fixture.mjs';
import { search, shownResults } from './search-helpers.mjs';

/** @type {Awaited<ReturnType<typeof openBaseSite>>} */
let site;
/** @type {Awaited<ReturnType<typeof openBaseSite>>['server']} */
let server;
/** @type {Awaited<ReturnType<typeof openBaseSite>>['browser']} */
let browser;
before(async () => {
  site = await openBaseSite('base-path.test');
  ({ server, browser } = site);
});
after(() => site?.close());

test('under a base path, a chapter loads whole from under it, and its navigation stays there', async () => {
  const page = await browser.context.newPage();
  const { problems, requests } = watchPage(page);
  await page.goto(`${server.origin}${BASE}order-and-chaos/`);
  await firstViewReady(page);
  assert.deepEqual(problems, []);
  const outside = requests.filter((url) => url.startsWith(server.origin) && !new URL(url).pathname.startsWith(BASE));
  assert.deepEqual(outside, []);
  for (const selector of ['.chapter-nav-top a[rel=prev]', '.chapter-nav-top a[rel=next]', '.chapter-nav-bottom a.contents', '.wordmark']) {
    const href = (await page.locator(selector).getAttribute('href')) ?? '';
    assert.ok(href.startsWith(BASE), `${selector} links to ${href}, outside ${BASE}`);
  }
  await page.locator('.on-this-page-column a[data-section-link="the-lyapunov-exponent"]').click();
  await landedOn(page, 'the-lyapunov-exponent');
  assert.equal(new URL(page.url()).pathname, `${BASE}order-and-chaos/`);
  await page.close();
});

test('under a base path, search finds "Lyapunov" in Order and chaos and "adiabatic" in its chapter, and lands on the section', async () => {
  const page = await browser.context.newPage();
  const { problems, requests } = watchPage(page);
  await page.goto(`${server.origin}${BASE}kepler/`);
  await firstViewReady(page);

  await search(page, 'adiabatic');
  assert.equal((await shownResults(page))[0]?.href, `${BASE}adiabatic-invariants/`);

  await search(page, 'Lyapunov');
  const [first] = await shownResults(page);
  assert.equal(first?.href, `${BASE}order-and-chaos/`);
  assert.ok(first.sections.some((section) => section.href === `${BASE}order-and-chaos/#the-lyapunov-exponent`), JSON.stringify(first.sections));
  const index = requests.filter((url) => /\/pagefind\//.test(url));
  assert.ok(index.length > 0 && index.every((url) => new URL(url).pathname.startsWith(`${BASE}pagefind/`)), index.join('\n'));

  await page.locator(`.search-section[href="${BASE}order-and-chaos/#the-lyapunov-exponent"]`).click();
  await landedOn(page, 'the-lyapunov-exponent');
  assert.deepEqual(problems, []);
  await page.close();
});
