/**
 * The first load ships neither the editor (CodeMirror) nor the parser
 * (acorn): the editor comes on the first interaction with a cell, the
 * parser on the first Run of changed source. Reports
 * the JavaScript bytes (gzip) at each stage as test diagnostics.
 */
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { gzipSync } from 'node:zlib';
import { cell, cellsReady, openSite, typeIntoCell, waitForOutput, watchPage } from './fixture.mjs';
import { pages } from './every-page.mjs';
import { DIST } from './server.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

const EDITOR_CHUNK = /\/_astro\/editor\.[\w-]+\.js$/;
const PARSER_CHUNK = /\/_astro\/parser\.[\w-]+\.js$/;
/** Strings only CodeMirror's or acorn's code contains, to catch them in any chunk. */
const EDITOR_MARKERS = ['cm-content', 'cm-scroller'];
const PARSER_MARKERS = ['allowHashBang', 'Unterminated string constant'];

const scripts = (requests) => requests.filter((url) => url.endsWith('.js'));
const fileOf = (url) => join(DIST, new URL(url).pathname);
const gzipBytes = (urls) => urls.reduce((sum, url) => sum + gzipSync(readFileSync(fileOf(url)), { level: 9 }).length, 0);
const containsAny = (url, markers) => {
  const text = readFileSync(fileOf(url), 'utf8');
  return markers.some((marker) => text.includes(marker));
};

test('first load fetches no editor or parser code; focus loads the editor, Run of an edit the parser', async (t) => {
  const page = await site.context.newPage();
  const { problems, requests } = watchPage(page);
  await page.goto(`${site.origin}/introduction/`);
  await cellsReady(page);
  await page.waitForTimeout(300);

  const initial = scripts(requests);
  assert.ok(initial.length > 0);
  assert.deepEqual(initial.filter((url) => EDITOR_CHUNK.test(url) || PARSER_CHUNK.test(url)), []);
  assert.deepEqual(initial.filter((url) => containsAny(url, [...EDITOR_MARKERS, ...PARSER_MARKERS])), []);
  const initialBytes = gzipBytes(initial);
  t.diagnostic(`initial JS: ${initial.length} file(s), ${initialBytes} B gzip`);

  // The editor replaces the static code without moving anything or changing colours.
  const box = cell(page, 'phase').locator('.cell-box');
  const heightBefore = (await box.boundingBox())?.height ?? 0;
  const tokens = () =>
    cell(page, 'phase').locator('.cell-editor').evaluate((host) =>
      [...host.querySelectorAll('[class*="tok-"]')].map((span) => `${span.className}:${span.textContent}`),
    );
  const tokensBefore = await tokens();
  assert.ok(tokensBefore.includes('tok-keyword:while'));
  await cell(page, 'phase').locator('pre.cell-code').focus();
  await cell(page, 'phase').locator('.cm-editor').waitFor();
  const heightAfter = (await box.boundingBox())?.height ?? 0;
  assert.ok(Math.abs(heightAfter - heightBefore) <= 1, `cell height ${heightBefore} → ${heightAfter}`);
  assert.deepEqual(await tokens(), tokensBefore);
  assert.ok(await cell(page, 'phase').locator('.cm-content').evaluate((node) => node.contains(document.activeElement)));

  const withEditor = scripts(requests);
  const editorChunks = withEditor.filter((url) => EDITOR_CHUNK.test(url));
  assert.equal(editorChunks.length, 1);
  assert.ok(containsAny(editorChunks[0], EDITOR_MARKERS));
  assert.deepEqual(withEditor.filter((url) => PARSER_CHUNK.test(url)), []);
  t.diagnostic(`after the editor loads: ${withEditor.length} file(s), ${gzipBytes(withEditor)} B gzip`);

  // Running the unchanged original needs no parser: the build parsed it.
  await page.keyboard.press('Shift+Enter');
  await page.waitForTimeout(200);
  assert.deepEqual(scripts(requests).filter((url) => PARSER_CHUNK.test(url)), []);

  await typeIntoCell(page, 'omega', 'omega = 5');
  await waitForOutput(page, 'omega', (text) => text === 'omega = 5');
  const withParser = scripts(requests);
  const parserChunks = withParser.filter((url) => PARSER_CHUNK.test(url));
  assert.equal(parserChunks.length, 1);
  assert.ok(containsAny(parserChunks[0], PARSER_MARKERS));
  t.diagnostic(`after the parser loads: ${withParser.length} file(s), ${gzipBytes(withParser)} B gzip`);

  assert.deepEqual(problems, []);
  await page.evaluate(() => localStorage.clear());
  await page.close();
});

test('a reader who only reads loads neither the editor nor the parser, however long they stay', async () => {
  const page = await site.context.newPage();
  const { problems, requests } = watchPage(page);
  await page.goto(`${site.origin}/introduction/`);
  await cellsReady(page);
  // Idle time is no reason to fetch 170 kB the reader may never use: only a touch on a cell is.
  await page.waitForTimeout(3000);
  assert.equal(await page.locator('[data-cell] .cm-editor').count(), 0);
  assert.deepEqual(scripts(requests).filter((url) => EDITOR_CHUNK.test(url) || PARSER_CHUNK.test(url)), []);
  assert.deepEqual(problems, []);
  await page.close();
});

test('search loads nothing with a page, however long the reader stays; focusing the box loads its module, its worker and the index', async (t) => {
  const page = await site.context.newPage();
  const { problems, requests } = watchPage(page);
  await page.goto(`${site.origin}/introduction/`);
  await cellsReady(page);
  await page.waitForTimeout(1500);
  const isSearch = (url) => /\/_astro\/search[.-][\w-]+\.js$|\/pagefind\//.test(new URL(url).pathname);
  assert.deepEqual(requests.filter(isSearch), []);
  assert.deepEqual(scripts(requests).filter((url) => containsAny(url, ['searchHeld', 'phasebook-search'])), []);

  await page.locator('#site-search-input').focus();
  await page.waitForSelector('form[data-search-held]', { state: 'attached' });
  const searchScripts = scripts(requests).filter(isSearch);
  assert.equal(searchScripts.filter((url) => /\/search\.[\w-]+\.js$/.test(url)).length, 1, 'the search module');
  assert.equal(searchScripts.filter((url) => /\/search-worker-[\w-]+\.js$/.test(url)).length, 1, 'its worker');
  const index = requests.filter((url) => new URL(url).pathname.startsWith('/pagefind/'));
  t.diagnostic(`search: ${gzipBytes(searchScripts)} B gzip of script, then ${index.length} file(s) of the index, ${gzipBytes(index)} B gzip`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a chapter without cells loads no cell code', async () => {
  const page = await site.context.newPage();
  const { requests } = watchPage(page);
  await page.goto(`${site.origin}/`);
  await page.waitForLoadState('load');
  assert.deepEqual(scripts(requests), []);
  await page.close();
});

/** The chunk a script URL names (site/lib/chunks.mjs groups the book's code by what loads it together). */
const chunkOf = (url) => new URL(url).pathname.split('/').pop().split('.')[0];

test('the boot chunk imports no other chunk: everything a widget needs comes when a cell asks for it', () => {
  const html = readFileSync(join(DIST, 'kepler', 'index.html'), 'utf8');
  const entries = [...html.matchAll(/<script type="module" src="([^"]+)"/g)].map((m) => m[1]);
  assert.equal(entries.length, 1, `one script per chapter page, found ${entries.join(', ')}`);
  const boot = readFileSync(join(DIST, entries[0]), 'utf8');
  assert.deepEqual([...boot.matchAll(/(?:^|[;}\n])\s*import\s*(?:[\w${},\s*]+from\s*)?["']([^"']+)["']/g)].map((m) => m[1]), []);
  assert.ok(/import\(["']\.\/simulator\.[\w-]+\.js["']\)/.test(boot) || /["']\.\/simulator\.[\w-]+\.js["']/.test(boot), 'the simulator loads on demand');
});

test('a link to a simulator fetches the simulator and its views, and no other widget, the compiler, or the share code', async () => {
  const page = await site.context.newPage();
  const { problems, requests } = watchPage(page);
  await page.goto(`${site.origin}/kepler/#cell-stars`);
  await page.locator('#cell-stars [data-widget="simulator"][data-ready]').waitFor();
  await page.waitForTimeout(500);
  const chunks = scripts(requests).map(chunkOf);
  for (const wanted of ['simulator', 'plots', 'time-plot', 'plane-views', 'model']) assert.ok(chunks.includes(wanted), `${wanted} in ${chunks.join(', ')}`);
  const unwanted = ['chart', 'table', 'theory-check', 'poincare-section', 'stability-chart', 'point-panel', 'method-comparison', 'analysis', 'compiler', 'share-ui', 'mathjs-instance', 'katex', 'editor', 'parser'];
  assert.deepEqual(chunks.filter((name) => unwanted.includes(name)), []);
  assert.deepEqual(problems, []);
  await page.close();
});

/**
 * The decided budgets of JavaScript a reader's first view costs (gzip, level 9, as bench/cold-load.mjs counts):
 * a chapter opened at its top, and opened by a link to its first simulator, the widget a reader comes for.
 * Counted once the first view has run and the network has gone quiet, before any interaction.
 */
// The top was 29.0 KB on the heaviest chapter (parametric resonance) before Liouville's chapter; its names in the
// catalogue and a model's non-Hamiltonian terms (their key, and the check of stored data) added 0.4 KB to every page's
// boot and model chunks. The catalogue grows with each chapter: split by chapter, it would stop growing.
const TOP_BUDGET = 30 * 1024;
const SIMULATOR_LINK_BUDGET = 80 * 1024;

/** The chapters with cells, each with the id of the cell holding its first simulator (null for none), from the built HTML. */
function chaptersWithCells() {
  return pages()
    .map((path) => ({ path, html: readFileSync(join(DIST, path, 'index.html'), 'utf8') }))
    .filter(({ html }) => html.includes('data-cell-spec'))
    .map(({ path, html }) => {
      const reserve = html.indexOf('data-reserve="simulator"');
      const cellIds = reserve < 0 ? [] : [...html.slice(0, reserve).matchAll(/<figure class="cell" id="([^"]+)"/g)];
      return { path, simulator: cellIds.at(-1)?.[1] ?? null };
    });
}

/** The scripts `page` has asked for and not yet received, as a live set. */
function pendingScripts(page) {
  const pending = new Set();
  page.on('request', (request) => request.resourceType() === 'script' && pending.add(request));
  page.on('requestfinished', (request) => pending.delete(request));
  page.on('requestfailed', (request) => pending.delete(request));
  return pending;
}

/**
 * Waits until no script is in flight and none has been asked for during a quiet second. Only scripts count:
 * Playwright's 'networkidle' also waits on every font, image and fetch, and on a machine under a load of 15 one
 * chapter's page never gave it its 500 ms without a request in 180 s, though every script had long arrived.
 */
async function scriptsSettled(page, pending) {
  for (;;) {
    const before = pending.size;
    let asked = 0;
    const count = (request) => request.resourceType() === 'script' && (asked += 1);
    page.on('request', count);
    await page.waitForTimeout(1000);
    page.off('request', count);
    if (before === 0 && asked === 0 && pending.size === 0) return;
  }
}

/** The gzip bytes of the scripts `url` loads before any interaction; `simulator`: the cell id whose simulator must have drawn. */
async function firstViewScripts(url, simulator) {
  const page = await site.context.newPage();
  const { problems, requests } = watchPage(page);
  const pending = pendingScripts(page);
  await page.goto(url);
  await page.waitForSelector('body[data-cells-ready]', { state: 'attached' });
  if (simulator) await page.locator(`#${simulator} [data-widget="simulator"][data-ready]`).waitFor();
  await scriptsSettled(page, pending);
  const loaded = scripts(requests);
  // Read before closing: closing aborts what is still in flight, which is no problem of the page's.
  const seen = [...problems];
  await page.close();
  return { bytes: gzipBytes(loaded), names: loaded.map(chunkOf), problems: seen };
}

test('every chapter stays within the JavaScript budgets: its top ≤ 30 KB, a link to its first simulator ≤ 80 KB (gzip)', async (t) => {
  const chapters = chaptersWithCells();
  assert.ok(chapters.length >= 10, `chapters with cells: ${chapters.map((c) => c.path).join(', ')}`);
  assert.ok(chapters.filter((c) => c.simulator).length >= 8, 'most chapters have a simulator');
  const over = [];
  for (const { path, simulator } of chapters) {
    const top = await firstViewScripts(site.origin + path);
    assert.deepEqual(top.problems, [], path);
    t.diagnostic(`${path} top: ${(top.bytes / 1024).toFixed(1)} KB (${top.names.join(', ')})`);
    if (top.bytes > TOP_BUDGET) over.push(`${path} top ${(top.bytes / 1024).toFixed(1)} KB`);
    if (!simulator) continue;
    const link = await firstViewScripts(`${site.origin}${path}#${simulator}`, simulator);
    assert.deepEqual(link.problems, [], `${path}#${simulator}`);
    t.diagnostic(`${path}#${simulator}: ${(link.bytes / 1024).toFixed(1)} KB (${link.names.join(', ')})`);
    if (link.bytes > SIMULATOR_LINK_BUDGET) over.push(`${path}#${simulator} ${(link.bytes / 1024).toFixed(1)} KB`);
  }
  assert.deepEqual(over, []);
});

/**
 * The page itself, gzip level 9: a phone on Slow 4G (50 KB/s) takes a second per 50 KB of it before the page is
 * whole. The prose, its typeset math and the cells' data make 50–60 KB of a chapter; exercises' sealed parts,
 * scrambled bytes that gzip cannot shrink, made 40–60 % more (175 KB on /order-and-chaos/) until they were
 * deflated before sealing (widgets/chapter/exercise/seal.ts).
 */
const PAGE_BUDGET = 90 * 1024;

test('every page stays within the page budget: its HTML ≤ 90 KB gzip', (t) => {
  const over = [];
  for (const path of pages()) {
    const bytes = gzipSync(readFileSync(join(DIST, path, 'index.html')), { level: 9 }).length;
    t.diagnostic(`${path}: ${(bytes / 1024).toFixed(1)} KB`);
    if (bytes > PAGE_BUDGET) over.push(`${path} ${(bytes / 1024).toFixed(1)} KB`);
  }
  assert.ok(pages().length >= 12);
  assert.deepEqual(over, []);
});
