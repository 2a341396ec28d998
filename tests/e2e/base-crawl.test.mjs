/**
 * Every page of the book built for a base path (base-build.mjs's BASE),
 * crawled: each page's links (a, area), assets (script, link, img, source,
 * iframe, the fonts its stylesheets declare), the requests it makes once
 * every cell has run (workers, chunks, fonts, the search index), its share
 * link and its downloads must all resolve with 200 from under the base, and
 * none may leave it. Served from a host whose root holds nothing (server.mjs
 * answers 404 outside the base), as a GitHub project site is.
 */
import assert from 'node:assert/strict';
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative, sep } from 'node:path';
import { after, before, test } from 'node:test';
import { cellsReady, firstViewReady, HANG_MS, watchPage } from './browser.mjs';
import { BASE, BASE_DIST, openBaseSite } from './base-build.mjs';
import { cell, typeIntoCell } from './fixture.mjs';
import { search } from './search-helpers.mjs';

/** @type {Awaited<ReturnType<typeof openBaseSite>>} */
let site;
/** @type {Awaited<ReturnType<typeof openBaseSite>>['server']} */
let server;
/** @type {Awaited<ReturnType<typeof openBaseSite>>['browser']} */
let browser;
before(async () => {
  site = await openBaseSite('base-crawl.test');
  ({ server, browser } = site);
});
after(() => site?.close());

/** Every page of the built site: each index.html (the book's own folders, not _astro/ or pagefind/), as its path under the base. */
function pagesUnder(dir) {
  const found = [];
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) {
      if (dir === BASE_DIST && (name.startsWith('_') || name === 'pagefind')) continue;
      found.push(...pagesUnder(path));
    } else if (name === 'index.html') {
      const folder = relative(BASE_DIST, dir).split(sep).join('/');
      found.push(`${BASE}${folder ? `${folder}/` : ''}`);
    }
  }
  return found;
}

/** In the page: every URL its markup and stylesheets name, by where it was found. */
function namedUrls() {
  const urls = [];
  const add = (kind, value, base = document.baseURI) => {
    if (value) urls.push({ kind, url: new URL(value, base).href });
  };
  const srcset = (kind, value) => (value ?? '').split(',').map((c) => c.trim().split(/\s+/)[0]).filter(Boolean).forEach((u) => add(kind, u));
  document.querySelectorAll('a[href], area[href]').forEach((el) => add('link', el.getAttribute('href')));
  document.querySelectorAll('script[src], img[src], source[src], iframe[src], video[src], audio[src], embed[src]').forEach((el) => add(el.tagName.toLowerCase(), el.getAttribute('src')));
  document.querySelectorAll('img[srcset], source[srcset]').forEach((el) => srcset(el.tagName.toLowerCase(), el.getAttribute('srcset')));
  document.querySelectorAll('link[href]').forEach((el) => add(`link[rel=${el.getAttribute('rel')}]`, el.getAttribute('href')));
  document.querySelectorAll('[style*="url("]').forEach((el) => {
    for (const m of el.getAttribute('style').matchAll(/url\(\s*["']?([^"')]+)["']?\s*\)/g)) add('style', m[1]);
  });
  const rulesOf = (sheet) => {
    try {
      return [...sheet.cssRules];
    } catch {
      return [];
    }
  };
  const walk = (rules, base) => {
    for (const rule of rules) {
      if (rule instanceof CSSFontFaceRule) {
        for (const m of rule.style.getPropertyValue('src').matchAll(/url\(\s*["']?([^"')]+)["']?\s*\)/g)) add('font', m[1], base);
      } else if (rule instanceof CSSImportRule) {
        add('css-import', rule.href, base);
      } else if ('cssRules' in rule) {
        walk([...rule.cssRules], base);
      }
    }
  };
  for (const sheet of document.styleSheets) walk(rulesOf(sheet), sheet.href ?? document.baseURI);
  return urls;
}

/**
 * Found URLs on this host: each must lie under the base and answer 200.
 * A link to another host is not the site's to check; an asset from one is
 * already a problem watchPage reports.
 */
async function assertAllResolve(found, origin) {
  const local = new Map();
  for (const { where, kind, url } of found) {
    const parsed = new URL(url);
    if (parsed.origin !== origin) continue;
    parsed.hash = '';
    if (!local.has(parsed.href)) local.set(parsed.href, `${kind} on ${where}`);
  }
  const escaped = [...local].filter(([url]) => !new URL(url).pathname.startsWith(BASE)).map(([url, from]) => `${url} (${from})`);
  assert.deepEqual(escaped, [], 'URLs outside the base path');
  const failed = [];
  for (const [url, from] of local) {
    const response = await fetch(url, { redirect: 'manual' });
    await response.arrayBuffer();
    if (response.status !== 200) failed.push(`${response.status} ${url} (${from})`);
  }
  assert.deepEqual(failed, [], 'URLs that do not answer 200');
  return local;
}

test('under a base path, every page: each link, asset, font, worker and request resolves with 200 under the base, and none leaves it', async (t) => {
  const pages = pagesUnder(BASE_DIST);
  const found = [];
  const problemsSeen = [];
  for (const path of pages) {
    const page = await browser.context.newPage();
    const { problems, requests } = watchPage(page);
    // Some steps (evaluate, count, close) have no wait limit of their own: once, a page here sat idle for
    // 20 minutes with none of them returning. The guard names the page and the step instead.
    let step = 'open';
    const crawl = async () => {
      await page.goto(`${server.origin}${path}`);
      step = 'load';
      await page.waitForLoadState('load');
      step = 'run its cells';
      // Every cell run, so that every widget has asked for its chunks and workers; an embed's cells are all in view.
      if (path.includes('/embed/')) await firstViewReady(page);
      else if (await page.locator('[data-cell]').count()) await cellsReady(page);
      step = 'read its URLs';
      found.push(...(await page.evaluate(namedUrls)).map((u) => ({ where: path, ...u })));
      found.push(...requests.filter((url) => !url.startsWith('data:') && !url.startsWith('blob:')).map((url) => ({ where: path, kind: 'request', url })));
      problemsSeen.push(...problems.map((p) => `${path}: ${p}`));
      step = 'close';
      await page.close();
    };
    let timer;
    const hang = new Promise((_, reject) => (timer = setTimeout(() => reject(new Error(`${path} hung at “${step}” for ${2 * HANG_MS / 1000} s`)), 2 * HANG_MS)));
    try {
      await Promise.race([crawl(), hang]);
    } finally {
      clearTimeout(timer);
    }
  }
  // Search: its module, its worker and the index, asked for from a chapter.
  {
    const page = await browser.context.newPage();
    const { problems, requests } = watchPage(page);
    await page.goto(`${server.origin}${BASE}kepler/`);
    await search(page, 'Lyapunov');
    found.push(...requests.map((url) => ({ where: 'search', kind: 'request', url })));
    problemsSeen.push(...problems.map((p) => `search: ${p}`));
    await page.close();
  }
  assert.deepEqual(problemsSeen, []);
  const local = await assertAllResolve(found, server.origin);
  // What the crawl covered: had a kind of URL gone unseen, the test above would prove nothing of it.
  const paths = [...local.keys()].map((url) => new URL(url).pathname);
  const count = (pattern) => paths.filter((p) => pattern.test(p)).length;
  t.diagnostic(`${pages.length} pages, ${local.size} distinct URLs: ${count(/\.woff2$/)} fonts, ${count(/-worker-[\w-]+\.js$/)} workers, ${count(/\/_astro\/.*\.js$/)} scripts, ${count(/\/pagefind\//)} search files`);
  assert.ok(pages.length >= 13, `${pages.length} pages`);
  assert.ok(pages.some((path) => path === `${BASE}embed/introduction/sim/`), 'the embed pages');
  for (const chapter of ['introduction', 'kepler', 'order-and-chaos', 'for-teachers']) assert.ok(paths.includes(`${BASE}${chapter}/`), `a link to ${chapter}`);
  assert.ok(count(/\.woff2$/) >= 4, 'fonts');
  assert.ok(count(/-worker-[\w-]+\.js$/) >= 3, 'workers: search, and the widgets that compute in one');
  assert.ok(count(/\/pagefind\//) >= 2, 'the search index');
});

test('under a base path, the chapters link to each other under it: the links that once pointed at the host root', () => {
  // Written as `[Introduction](/introduction/)` in content/; built for a base path they must carry it.
  for (const [chapter, target] of [['introduction', 'parametric-resonance'], ['order-and-chaos', 'kepler'], ['how-the-simulator-integrates', 'introduction']]) {
    const html = readFileSync(join(BASE_DIST, chapter, 'index.html'), 'utf8');
    const hrefs = [...html.matchAll(/<a [^>]*href="([^"]*)"/g)].map((m) => m[1]);
    assert.ok(hrefs.includes(`${BASE}${target}/`), `${chapter} links to ${BASE}${target}/`);
    assert.deepEqual(hrefs.filter((href) => href.startsWith('/') && !href.startsWith(BASE)), [], `${chapter}: links from the host root`);
  }
});

test('under a base path, a share link and the downloads stay under the base', async () => {
  const page = await browser.context.newPage();
  const { problems } = watchPage(page);
  await page.goto(`${server.origin}${BASE}introduction/`);
  await cellsReady(page);

  // Downloads are made in the page (blob: URLs), never fetched from a path of the host.
  const sim = page.locator('[data-cell="sim"] [data-widget="simulator"]');
  await sim.scrollIntoViewIfNeeded();
  await page.waitForFunction((el) => el.simulator?.simulation.t > 0.2, await sim.elementHandle());
  const [csv] = await Promise.all([page.waitForEvent('download'), sim.getByRole('button', { name: 'Download CSV' }).click()]);
  assert.match(csv.url(), /^(blob|data):/);
  assert.match(readFileSync(await csv.path(), 'utf8'), /^t,q,p,H\n/);

  // The share link names the chapter under the base, and opens there with its edits.
  await typeIntoCell(page, 'omega', 'omega = 9');
  await cell(page, 'period').locator('[data-cell-output]').filter({ hasText: (2 * Math.PI / 9).toFixed(3).slice(0, 4) }).waitFor();
  await page.locator('[data-share-button]').click();
  const link = await page.locator('[data-share-link]').inputValue();
  assert.ok(link.startsWith(`${server.origin}${BASE}introduction/#`), link);
  const shared = await browser.context.newPage();
  const sharedWatch = watchPage(shared);
  await shared.goto(link);
  await shared.locator('[data-share-banner] [data-share-run]').waitFor();
  assert.equal(new URL(shared.url()).pathname, `${BASE}introduction/`);
  assert.deepEqual([...problems, ...sharedWatch.problems], []);
  await shared.close();
  await page.close();
});
