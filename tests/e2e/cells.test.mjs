/**
 * Live cells on /introduction/: reactivity, generators, and errors that stay
 * under the cell that caused them while the rest of the page keeps running.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { cell, errorOf, openChapter, openSite, outputOf, typeIntoCell, waitForOutput } from './fixture.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

/** The inspector shows numbers to 12 significant digits (cells/inspect.ts). */
const PERIOD_OF = (omega) => `period = ${Number(((2 * Math.PI) / omega).toPrecision(12))}`;

test('cells show their first values: numbers inspected, html as DOM', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.equal(await outputOf(page, 'period'), PERIOD_OF(10));
  assert.equal(await cell(page, 'periodText').locator('[data-cell-output] > p strong').textContent(), '0.628');
  // The phase-space figure is the book's chart: the orbit and the state now, on the unit circle.
  const figure = cell(page, 'phasePortrait').locator('[data-cell-output] > [data-widget="chart"][data-ready]');
  await figure.waitFor();
  const drawn = await figure.evaluate((f) => ({
    role: f.querySelector('canvas').getAttribute('role'),
    name: f.querySelector('canvas').getAttribute('aria-label'),
    series: f.chart.series.map((s) => ({ label: s.label, source: s.source, kind: s.kind, x: Array.from(s.curves[0].x), y: Array.from(s.curves[0].y) })),
  }));
  assert.equal(drawn.role, 'img');
  assert.equal(drawn.name, "The oscillator's state in phase space");
  const [orbit, now] = drawn.series;
  assert.equal(orbit.source, 'curve');
  assert.equal(orbit.kind, 'line');
  // The orbit over one period: q² + (p/mω)² = 1, the oscillator's level curve of H at unit amplitude, closed.
  assert.ok(orbit.x.every((q, i) => Math.abs(q * q + orbit.y[i] * orbit.y[i] - 1) < 1e-12), orbit.label);
  assert.ok(Math.abs(orbit.x.at(-1) - orbit.x[0]) < 1e-12 && Math.abs(orbit.y.at(-1) - orbit.y[0]) < 1e-12, 'the orbit closes');
  assert.equal(now.kind, 'dots');
  assert.equal(now.x.length, 1);
  assert.ok(Math.abs(now.x[0] ** 2 + now.y[0] ** 2 - 1) < 1e-12, `the state (${now.x[0]}, ${now.y[0]}) lies on the orbit`);
  assert.deepEqual(problems, []);
  await page.close();
});

/** The state the phase-space chart shows now, and the figure showing it (marked, so a new figure would be seen). */
const stateShown = (page) =>
  page.evaluate(() => {
    const f = document.querySelector('[data-cell="phasePortrait"] [data-widget="chart"]');
    const c = f?.chart.series[1].curves[0];
    return { q: c?.x[0], p: c?.y[0], same: f?.dataset.marked === '', count: document.querySelectorAll('[data-cell="phasePortrait"] [data-cell-output] > *').length };
  });

test('generator cells animate: the chart fed by one is updated in place, frame after frame', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  const first = await outputOf(page, 'phase');
  assert.match(first, /^phase = \{t: /);
  await waitForOutput(page, 'phase', (text) => text !== first);
  await cell(page, 'phasePortrait').locator('[data-widget="chart"][data-ready]').evaluate((f) => (f.dataset.marked = ''));
  const start = await stateShown(page);
  // Some frames later the point has moved along the circle, in the same figure (no figure rebuilt per frame).
  await page.waitForFunction(
    (before) => {
      const c = document.querySelector('[data-cell="phasePortrait"] [data-widget="chart"]')?.chart.series[1].curves[0];
      return c && c.x[0] !== before.q && c.y[0] !== before.p;
    },
    start,
  );
  await page.waitForTimeout(500);
  const later = await stateShown(page);
  assert.equal(later.same, true, 'the same figure, updated in place');
  assert.equal(later.count, 1);
  assert.ok(Math.abs(later.q ** 2 + later.p ** 2 - 1) < 1e-12);
  assert.deepEqual(problems, []);
  await page.close();
});

test('an animated chart offers Pause: paused, it holds its picture while the cell runs on; Play resumes', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  const toggle = cell(page, 'phasePortrait').locator('.pb-chart-tools button[data-motion]');
  await toggle.waitFor();
  assert.equal(await toggle.textContent(), 'Pause');
  await toggle.click();
  assert.equal(await toggle.textContent(), 'Play');
  const held = await stateShown(page);
  const phase = await outputOf(page, 'phase');
  await waitForOutput(page, 'phase', (text) => text !== phase);
  await page.waitForTimeout(300);
  assert.deepEqual(await stateShown(page), held);
  await toggle.click();
  assert.equal(await toggle.textContent(), 'Pause');
  await page.waitForFunction((before) => document.querySelector('[data-cell="phasePortrait"] [data-widget="chart"]')?.chart.series[1].curves[0].x[0] !== before, held.q);
  assert.deepEqual(problems, []);
  await page.close();
});

test('editing a cell re-runs the cells that use it (Shift+Enter and Run)', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'omega', 'omega = 5', { run: 'keys' });
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(5));
  assert.equal(await outputOf(page, 'omega'), 'omega = 5');
  assert.equal(await cell(page, 'periodText').locator('strong').textContent(), '1.257');

  await typeIntoCell(page, 'omega', 'omega = 2 * 10', { run: 'button' });
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(20));
  assert.equal(await cell(page, 'periodText').locator('strong').textContent(), '0.314');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a syntax error shows under its cell with line:column; the old definition and other cells keep running', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'omega', 'omega = = 3');
  await page.waitForFunction(() => document.querySelector('[data-cell="omega"] [data-cell-error]')?.textContent?.includes('SyntaxError'));
  assert.equal(await errorOf(page, 'omega'), 'SyntaxError: Unexpected token (1:8)');
  // The editor keeps the reader's text; the old definition keeps its value.
  assert.equal(await cell(page, 'omega').locator('.cm-content').textContent(), 'omega = = 3');
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.equal(await outputOf(page, 'period'), PERIOD_OF(10));
  assert.equal(await errorOf(page, 'period'), '');
  const phase = await outputOf(page, 'phase');
  await waitForOutput(page, 'phase', (text) => text !== phase);

  // A multi-line block reports the line the error is on.
  await typeIntoCell(page, 'period', 'period = {\n  const x = 1;\n  return x +;\n}');
  await page.waitForFunction(() => document.querySelector('[data-cell="period"] [data-cell-error]')?.textContent?.includes('SyntaxError'));
  assert.match(await errorOf(page, 'period'), /^SyntaxError: Unexpected token \(3:\d+\)$/);

  // Fixing the text clears the error.
  await typeIntoCell(page, 'omega', 'omega = 4');
  await waitForOutput(page, 'omega', (text) => text === 'omega = 4');
  assert.equal(await errorOf(page, 'omega'), '');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a name that exists on window but not in the book is "not defined"', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'omega', 'omega = status');
  await page.waitForFunction(() => document.querySelector('[data-cell="omega"] [data-cell-error]')?.textContent?.includes('not defined'));
  assert.equal(await errorOf(page, 'omega'), 'RuntimeError: status is not defined');
  // Dependents say which input failed; unrelated cells keep running.
  await page.waitForFunction(() => document.querySelector('[data-cell="period"] [data-cell-error]')?.textContent?.includes('omega'));
  assert.equal(await errorOf(page, 'period'), 'RuntimeError: input omega failed: status is not defined');
  assert.equal(await outputOf(page, 'period'), '');

  await typeIntoCell(page, 'omega', 'omega = name');
  await page.waitForFunction(() => document.querySelector('[data-cell="omega"] [data-cell-error]')?.textContent?.includes('name is not defined'));

  // Builtins do resolve: Math by bare name, html, width.
  await typeIntoCell(page, 'omega', 'omega = hypot(3, 4) + width * 0');
  await waitForOutput(page, 'omega', (text) => text === 'omega = 5');
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(5));
  assert.equal(await errorOf(page, 'period'), '');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a runtime error stays under its cell; promises are awaited', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'omega', 'omega = { throw new TypeError("no frequency") }');
  await page.waitForFunction(() => document.querySelector('[data-cell="omega"] [data-cell-error]')?.textContent?.includes('TypeError'));
  assert.equal(await errorOf(page, 'omega'), 'TypeError: no frequency');
  assert.match(await errorOf(page, 'period'), /input omega failed: no frequency/);

  await typeIntoCell(page, 'omega', 'omega = new Promise((resolve) => setTimeout(() => resolve(8), 50))');
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(8));
  assert.equal(await errorOf(page, 'omega'), '');
  assert.deepEqual(problems, []);
  await page.close();
});

test('builtins: now ticks, width follows the text column, invalidation resolves on redefinition', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'omega', 'omega = Math.round(now)');
  const first = await waitForOutput(page, 'omega', (text) => /^omega = \d+$/.test(text));
  await waitForOutput(page, 'omega', (text) => text !== first);

  const column = await page.locator('[data-chapter]').evaluate((node) => Math.floor(node.getBoundingClientRect().width));
  await typeIntoCell(page, 'omega', 'omega = width');
  await waitForOutput(page, 'omega', (text) => text === `omega = ${column}`);
  await page.setViewportSize({ width: 500, height: 900 });
  const narrow = await page.locator('[data-chapter]').evaluate((node) => Math.floor(node.getBoundingClientRect().width));
  assert.ok(narrow < column);
  await waitForOutput(page, 'omega', (text) => text === `omega = ${narrow}`);
  await page.setViewportSize({ width: 1100, height: 900 });

  await typeIntoCell(page, 'omega', 'omega = { invalidation.then(() => (document.body.dataset.invalidated = "yes")); return 10; }');
  await waitForOutput(page, 'omega', (text) => text === 'omega = 10');
  assert.equal(await page.evaluate(() => document.body.dataset.invalidated), undefined);
  await typeIntoCell(page, 'omega', 'omega = 11');
  await page.waitForFunction(() => document.body.dataset.invalidated === 'yes');
  assert.deepEqual(problems, []);
  await page.close();
});

test('the inspector is compact: a model in one line, numbers rounded for reading, long lists open on demand', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  assert.match(await outputOf(page, 'model'), /^model = Model: 1 DOF, exact derivatives, H = p\^2\/2 \+ omega\^2\*\(1 \+ u\*cos\(gamma\*t\)\)/);
  await typeIntoCell(page, 'omega', 'omega = 0.1 + 0.2 - 3.9');
  await waitForOutput(page, 'omega', (text) => text === 'omega = -3.6');
  await typeIntoCell(page, 'omega', 'omega = Array.from({length: 100}, (_, i) => i)');
  await waitForOutput(page, 'omega', (text) => text.startsWith('omega = [0, 1, 2'));
  const list = cell(page, 'omega').locator('details.inspect-list');
  assert.match((await list.locator('summary').textContent()) ?? '', /… 80 more\]$/);
  await list.locator('summary').click();
  assert.match((await list.locator('.inspect-all').textContent()) ?? '', /, 98, 99$/);
  // A typed array inside another value is named, not listed.
  await typeIntoCell(page, 'omega', 'omega = ({x: new Float64Array(351), y: [new Float64Array(4)]})');
  await waitForOutput(page, 'omega', (text) => text === 'omega = {x: Float64Array(351), y: [Float64Array(4)]}');
  assert.deepEqual(problems, []);
  await page.close();
});

test('the simulator’s dt field and the chapter’s dt cell are one value: the checks follow the field', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  const field = cell(page, 'sim').locator('input[aria-label="Time step dt"]');
  await field.fill('0.001');
  await field.press('Enter');
  await waitForOutput(page, 'dt', (text) => text === 'dt = 0.001');
  assert.equal(await cell(page, 'dt').locator('.cell-editor').textContent(), 'dt = 0.001');
  assert.equal(await cell(page, 'dt').getAttribute('data-cell-edited'), '');
  // The widget was rebuilt from the cell, and the step-halving check uses the new dt.
  await page.waitForFunction(() => document.querySelector('[data-cell="sim"] [data-widget="simulator"]')?.simulator?.simulation?.dt === 0.001);
  await page.waitForFunction(
    () => [...document.querySelectorAll('[data-widget="theory-check"]')].some((check) => /dt = 0\.001\b/.test(check.textContent ?? '')),
    null,
  );
  assert.deepEqual(problems, []);
  await page.close();
});
