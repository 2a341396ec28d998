/**
 * Embeds (`/embed/<chapter>/<cell>/`, cells/embed.ts), driven from a page of
 * another origin: a second local server on another port serves a teacher's
 * page holding the iframe, as another site would. The embed shows its
 * widget with the cells it reads folded, reports its height whenever it
 * changes, takes a cell's code from the host and answers with the state; the
 * Embed button's snippet works pasted into such a page; axe finds nothing
 * on the embed page; and its JavaScript stays within a live simulator's
 * budget (80 KB gzip).
 */
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { after, before, test } from 'node:test';
import { cell, firstViewReady, openSite, typeIntoCell, watchPage } from './fixture.mjs';
import { DIST } from './server.mjs';

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
const EMBED = '/embed/introduction/sim/';
/** A live simulator's JavaScript budget, 80 KB gzip (the project's decided budgets; a KB is 1024 bytes, as bench/browser.mjs counts). */
const SIMULATOR_BUDGET = 80 * 1024;

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
/** The teacher's page: what it serves, set by each test, on an origin of its own. */
let hostHtml = '';
/** @type {{ origin: string, close: () => Promise<void> }} */
let host;

before(async () => {
  site = await openSite({ viewport: { width: 1100, height: 900 } });
  const server = createServer((request, response) => response.writeHead(200, { 'Content-Type': 'text/html; charset=utf-8', 'Cache-Control': 'no-store' }).end(hostHtml));
  await new Promise((ready) => server.listen(0, 'localhost', ready));
  const address = server.address();
  // `localhost` on a port of its own: another origin than the book's 127.0.0.1:port.
  host = { origin: `http://localhost:${typeof address === 'object' && address ? address.port : 0}`, close: () => new Promise((done) => server.close(() => done())) };
});
after(async () => {
  await site?.close();
  await host?.close();
});

/** A host page: `body` as given, and a script that records the book's messages and asks the iframe by message. */
function hostPage(body) {
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>A teacher's page</title></head><body><main><h1>A teacher's page</h1>${body}</main>
<script>
  const BOOK = ${JSON.stringify(site.origin)};
  window.fromBook = [];
  addEventListener('message', (event) => { if (event.origin === BOOK) window.fromBook.push(event.data); });
  window.ask = (message) => new Promise((resolve) => {
    const id = String(Math.random());
    const frame = document.querySelector('iframe');
    addEventListener('message', function reply(event) {
      if (event.source !== frame.contentWindow || event.data?.id !== id) return;
      removeEventListener('message', reply);
      resolve({ origin: event.origin, data: event.data });
    });
    frame.contentWindow.postMessage({ ...message, id }, BOOK);
  });
</script></body></html>`;
}

/** The book's messages of a type the host page has received. */
const received = (page, type) => page.evaluate((t) => window.fromBook.filter((m) => m.type === t), type);

test('from another origin: the embed loads its widget with its cells folded, reports its height, follows a cell the host sets and reports the state', async () => {
  hostHtml = hostPage(`<iframe src="${site.origin}${EMBED}" title="The simulator" style="width: 100%; height: 150px; border: 0"></iframe>
<script>addEventListener('message', (e) => { if (e.origin === BOOK && e.data.type === 'phasebook:height') document.querySelector('iframe').style.height = e.data.height + 'px'; });</script>`);
  const page = await site.context.newPage();
  const { problems } = watchPage(page);
  await page.goto(`${host.origin}/`);
  await page.waitForFunction(() => window.fromBook.some((m) => m.type === 'phasebook:ready'), null);
  const frame = page.frames().find((f) => f.url().startsWith(`${site.origin}${EMBED}`));
  assert.ok(frame, 'the iframe holds the embed page');
  await frame.locator('[data-cell="sim"] [data-widget="simulator"][data-ready]').waitFor();

  // One widget, the cells it reads present but folded, nothing else of the chapter.
  const [ready] = await received(page, 'phasebook:ready');
  assert.equal(ready.chapter, 'introduction');
  assert.equal(ready.cell, 'sim');
  for (const used of ['params', 'H', 'model', 'initial']) assert.ok(ready.cells.includes(used), `${used} in ${ready.cells}`);
  for (const unused of ['omega', 'period', 'lissajous']) assert.ok(!ready.cells.includes(unused), `${unused} not in ${ready.cells}`);
  assert.equal(await frame.locator('[data-cell]').count(), ready.cells.length);
  assert.equal(await frame.locator('details[data-embed-uses]').getAttribute('open'), null);
  assert.equal(await frame.locator('[data-cell="params"]').isVisible(), false);
  assert.equal(await frame.locator('h2').count(), 0, 'no section of the chapter');

  // Sized to its content: the iframe is as tall as the page says, and the page fits it without scrolling.
  const fits = () =>
    page.waitForFunction(
      async () => {
        const heights = window.fromBook.filter((m) => m.type === 'phasebook:height').map((m) => m.height);
        const frame = document.querySelector('iframe');
        return heights.length > 0 && frame.style.height === `${heights.at(-1)}px` && heights.at(-1);
      },
      null,
    );
  await fits();
  const closedHeight = await frame.evaluate(() => document.documentElement.scrollHeight);
  const frameHeight = await page.evaluate(() => document.querySelector('iframe').getBoundingClientRect().height);
  assert.ok(closedHeight > 300, `the simulator is shown (${closedHeight} px)`);
  assert.ok(Math.abs(frameHeight - closedHeight) <= 1, `the iframe (${frameHeight} px) is as tall as the embed (${closedHeight} px)`);

  // Unfolded, the cells are there to read and edit, and the height follows.
  await frame.locator('details[data-embed-uses] > summary').click();
  await frame.locator('[data-cell="params"] .cell-code').waitFor();
  await page.waitForFunction((before) => window.fromBook.filter((m) => m.type === 'phasebook:height').at(-1).height > before + 100, closedHeight);
  await fits();

  // The host sets the parameters: the simulator follows. With u = 0 and f = 0 the model is a harmonic
  // oscillator of frequency omega, q = 2 cos(omega t), p = -2 omega sin(omega t) from (2, 0), and H = 2 omega² stays
  // (closed form; Landau & Lifshitz, Mechanics §21).
  const set = await page.evaluate(() => window.ask({ type: 'phasebook:set', cell: 'params', source: 'params = ({u: 0, gamma: 21.7, beta: 0.2, kappa: 8, omega: 5, f: 0})' }));
  assert.equal(set.origin, site.origin);
  assert.equal(set.data.ok, true, JSON.stringify(set.data));
  // Told by the simulator itself: the one running omega = 5 has run past t = 0.5.
  await frame.waitForFunction(
    () => {
      const sim = document.querySelector('[data-cell="sim"] [data-widget="simulator"][data-ready]')?.simulator;
      return sim && sim.model.params[sim.model.paramNames.indexOf('omega')] === 5 && sim.simulation.t > 0.5;
    },
    null,
  );
  const { data: state } = await page.evaluate(() => window.ask({ type: 'phasebook:get' }));
  assert.equal(state.type, 'phasebook:state');
  assert.deepEqual(state.cells.params.value, { u: 0, gamma: 21.7, beta: 0.2, kappa: 8, omega: 5, f: 0 });
  assert.equal(typeof state.cells.H.value, 'string');
  const [sim] = state.simulators;
  assert.equal(sim.cell, 'sim');
  assert.equal(sim.params.omega, 5);
  assert.equal(sim.params.f, 0);
  const [q, p] = sim.state;
  assert.ok(sim.t > 0.5, `t = ${sim.t}`);
  assert.ok(Math.abs(q - 2 * Math.cos(5 * sim.t)) < 1e-4, `q(${sim.t}) = ${q}, closed form ${2 * Math.cos(5 * sim.t)}`);
  assert.ok(Math.abs(p + 10 * Math.sin(5 * sim.t)) < 1e-3, `p(${sim.t}) = ${p}, closed form ${-10 * Math.sin(5 * sim.t)}`);
  assert.ok(Math.abs((p * p) / 2 + (25 * q * q) / 2 - 50) < 1e-4 * 50, 'H = 50 is conserved');

  // A cell the embed does not hold, or a message that is not one, is answered in words; nothing else breaks.
  const wrong = await page.evaluate(() => window.ask({ type: 'phasebook:set', cell: 'omega', source: 'omega = 1' }));
  assert.equal(wrong.data.ok, false);
  assert.match(wrong.data.error, /no cell “omega”/);
  const malformed = await page.evaluate(() => window.ask({ type: 'phasebook:set', cell: 'params' }));
  assert.equal(malformed.data.ok, false);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the Embed button gives a snippet that, pasted into another site’s page, shows the widget with the reader’s edits and sizes itself', async () => {
  const page = await site.context.newPage();
  const { problems } = watchPage(page);
  await page.goto(`${site.origin}/`);
  await page.evaluate(() => localStorage.clear());
  await page.goto(`${site.origin}/introduction/`);
  await firstViewReady(page);
  await typeIntoCell(page, 'initial', 'initial = [1.5, 0]');
  await cell(page, 'initial').locator('[data-cell-output]').filter({ hasText: '1.5' }).waitFor();
  await page.locator('[data-embed-button]').click();
  await page.locator('[data-embed-choice]').selectOption('sim');
  const snippet = page.locator('[data-embed-snippet]');
  await page.waitForFunction(() => document.querySelector('[data-embed-snippet]')?.value.includes('/embed/introduction/sim/'));
  const html = await snippet.inputValue();
  const src = /<iframe src="([^"]+)"/.exec(html)?.[1].replace(/&amp;/g, '&') ?? '';
  assert.ok(src.startsWith(`${site.origin}/embed/introduction/sim/#share=`), src);
  assert.match(await page.locator('[data-embed-panel] .share-status').textContent(), /with your edits of 1 cell/);

  hostHtml = hostPage(html);
  const teacher = await site.context.newPage();
  const teacherWatch = watchPage(teacher);
  await teacher.goto(`${host.origin}/`);
  // The snippet's own script sizes the iframe (from 480 px) to the height the embed reports.
  await teacher.waitForFunction(() => {
    const last = window.fromBook.filter((m) => m.type === 'phasebook:height').at(-1);
    return last && document.querySelector('iframe').style.height === `${last.height}px`;
  }, null);
  const frame = teacher.frames().find((f) => f.url().startsWith(`${site.origin}/embed/`));
  await frame.locator('[data-cell="sim"] [data-widget="simulator"][data-ready]').waitFor();
  // The reader's edit runs in the embed: the simulator starts from (1.5, 0).
  const { data: state } = await teacher.evaluate(() => window.ask({ type: 'phasebook:get' }));
  assert.deepEqual(state.cells.initial.value, [1.5, 0]);
  assert.equal(state.cells.initial.source, 'initial = [1.5, 0]');
  assert.deepEqual([...problems, ...teacherWatch.problems], []);
  await teacher.close();
  await page.close();
});

test('the embed page: axe finds no violation, folded and unfolded, at 1100 and 390 px, and its JavaScript is within a simulator link’s budget', async (t) => {
  const page = await site.context.newPage();
  const { problems, requests } = watchPage(page);
  await page.goto(`${site.origin}${EMBED}`);
  await firstViewReady(page);
  await page.locator('[data-cell="sim"] [data-widget="simulator"][data-ready]').waitFor();
  const scripts = requests.filter((url) => url.endsWith('.js'));
  const bytes = scripts.reduce((sum, url) => sum + gzipSync(readFileSync(join(DIST, new URL(url).pathname)), { level: 9 }).length, 0);
  t.diagnostic(`embed page JS: ${scripts.length} file(s), ${bytes} B gzip`);
  assert.ok(bytes <= SIMULATOR_BUDGET, `${bytes} B gzip of JavaScript`);

  await page.evaluate(AXE);
  const axe = () => page.evaluate(async () => (await window.axe.run(document, { resultTypes: ['violations'] })).violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target).join(' ')}`));
  assert.deepEqual(await axe(), []);
  const summary = page.locator('details[data-embed-uses] > summary');
  assert.ok((await summary.boundingBox()).height >= 24, 'the fold is a target of 24 px or more');
  await summary.click();
  await page.locator('[data-cell="params"] .cell-code').waitFor();
  assert.deepEqual(await axe(), []);
  // In a narrow iframe, as a phone shows one.
  await page.setViewportSize({ width: 390, height: 800 });
  assert.deepEqual(await axe(), []);
  assert.deepEqual(problems, []);
  await page.close();
});
