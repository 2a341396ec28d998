/**
 * The book's chart() and table() as a reader meets them (widgets/chapter/chart/chart.ts,
 * table.ts): a chart's text description and its data-table view reached by
 * keyboard, its CSV holding every point drawn and its PNG the figure with its
 * legend, a redraw when the theme changes; Kepler's live table updating in
 * place, so that a phone reader who scrolled to the "change" column keeps it
 * in view.
 */
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { after, before, test } from 'node:test';
import { chartIn, widgetsReady } from './chapter-checks.mjs';
import { cellsReady, openChapter, openSite } from './fixture.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite({ acceptDownloads: true })));
after(() => site?.close());

const DEFLECTION = 'Deflection angle against impact parameter';

test('a chart says what it shows, opens its data by keyboard, and downloads every point as CSV and the figure as PNG', async () => {
  const { page, problems } = await openChapter(site, '/scattering/');
  await widgetsReady(page);
  const { series, description } = await chartIn(page, DEFLECTION);
  const figure = page.locator(`[data-widget="chart"][data-label="${DEFLECTION}"]`);
  const canvas = figure.locator('canvas');
  assert.equal(await canvas.getAttribute('role'), 'img');
  assert.equal(await canvas.getAttribute('aria-label'), DEFLECTION);
  const described = await canvas.getAttribute('aria-describedby');
  assert.equal(await page.locator(`#${described}`).textContent(), description);
  assert.match(description, /simulated beam: 29 points, x from 0\.3 to 4\.5/);

  // The data table, by keyboard: focus its summary, Enter opens it; a table per curve, with every point of the beam.
  const summary = figure.locator('.pb-chart-data > summary');
  await summary.focus();
  await page.keyboard.press('Enter');
  const tables = figure.locator('.pb-chart-data table');
  await tables.first().waitFor();
  assert.equal(await tables.count(), series.length);
  const beam = tables.filter({ has: page.locator('caption', { hasText: /^simulated beam$/ }) });
  const rows = await beam.locator('tbody tr').evaluateAll((trs) => trs.map((tr) => [...tr.cells].map((c) => Number(c.textContent))));
  const drawn = series.find((s) => s.label === 'simulated beam').values[0];
  assert.equal(rows.length, 29);
  rows.forEach(([x, y], i) => {
    assert.ok(Math.abs(x - drawn.x[i]) <= 1e-11 * Math.abs(drawn.x[i]));
    assert.ok(Math.abs(y - drawn.y[i]) <= 1e-11 * Math.abs(drawn.y[i]));
  });

  // CSV: a row a point of every curve drawn, each number the same double.
  const [csv] = await Promise.all([page.waitForEvent('download'), figure.getByRole('button', { name: 'CSV' }).click()]);
  assert.equal(csv.suggestedFilename(), 'deflection-angle-against-impact-parameter.csv');
  const lines = (await readFile(await csv.path(), 'utf8')).trim().split('\n');
  assert.equal(lines[0], 'series,impact parameter |b|,deflection θ (degrees)');
  assert.equal(lines.length - 1, series.reduce((n, s) => n + s.points, 0));
  const beamRows = lines.filter((l) => l.startsWith('simulated beam,')).map((l) => l.split(',').slice(1).map(Number));
  assert.deepEqual(beamRows, drawn.x.map((x, i) => [x, drawn.y[i]]));

  // PNG: the canvas's device pixels across, and taller than the canvas by the legend drawn under it.
  const [png] = await Promise.all([page.waitForEvent('download'), figure.getByRole('button', { name: 'PNG' }).click()]);
  const bytes = await readFile(await png.path());
  assert.deepEqual([...bytes.subarray(1, 4)], [...Buffer.from('PNG')]);
  const [width, height] = [bytes.readUInt32BE(16), bytes.readUInt32BE(20)];
  const size = await canvas.evaluate((c) => [c.width, c.height]);
  assert.equal(width, size[0]);
  assert.ok(height > size[1], `PNG ${width}×${height}, canvas ${size}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a chart redraws in the colours of the theme the reader picks', async () => {
  const { page } = await openChapter(site, '/scattering/');
  await chartIn(page, DEFLECTION);
  const canvas = page.locator(`[data-widget="chart"][data-label="${DEFLECTION}"] canvas`);
  // The tick labels are drawn in the theme's muted text colour: count the pixels of each theme's.
  const inColour = (rgb) =>
    canvas.evaluate((c, rgb) => {
      const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 0; i < data.length; i += 4) if (data[i + 3] === 255 && Math.abs(data[i] - rgb[0]) + Math.abs(data[i + 1] - rgb[1]) + Math.abs(data[i + 2] - rgb[2]) < 6) n++;
      return n;
    }, rgb);
  const LIGHT_MUTED = [0x5e, 0x5b, 0x55];
  const DARK_MUTED = [0x9d, 0x9b, 0xa3];
  await page.evaluate(() => (document.documentElement.dataset.theme = 'light'));
  await page.waitForTimeout(200);
  const light = [await inColour(LIGHT_MUTED), await inColour(DARK_MUTED)];
  await page.evaluate(() => (document.documentElement.dataset.theme = 'dark'));
  await page.waitForTimeout(200);
  const dark = [await inColour(LIGHT_MUTED), await inColour(DARK_MUTED)];
  assert.ok(light[0] > 20 && light[1] === 0, `light theme: ${light}`);
  assert.ok(dark[1] > 20 && dark[0] === 0, `dark theme: ${dark}`);
  await page.close();
});

test('a chart a generator updates every frame is drawn while near the view only, and drawn again on its return', async () => {
  const PHASE = "The oscillator's state in phase space";
  const page = await site.context.newPage();
  // Counts each canvas's clearings: the chart clears its canvas once a drawing.
  await page.addInitScript(() => {
    const clear = CanvasRenderingContext2D.prototype.clearRect;
    CanvasRenderingContext2D.prototype.clearRect = function (...args) {
      this.canvas.pbPaints = (this.canvas.pbPaints ?? 0) + 1;
      return clear.apply(this, args);
    };
  });
  await page.goto(`${site.origin}/introduction/`);
  await cellsReady(page);
  const figure = page.locator(`[data-widget="chart"][data-label="${PHASE}"]`);
  await figure.scrollIntoViewIfNeeded();
  await figure.locator('canvas').waitFor();
  const paints = () => figure.locator('canvas').evaluate((c) => c.pbPaints ?? 0);
  const statePoint = () => figure.evaluate((el) => JSON.stringify(el.chart.series.find((s) => s.label === 'state now').curves));
  // Near the view: drawn frame after frame (a few at least, however few frames a busy machine gives).
  const before = await paints();
  await page.waitForFunction((n) => (document.querySelector('[data-widget="chart"][data-label="The oscillator\'s state in phase space"] canvas').pbPaints ?? 0) >= n + 5, before);
  // Far from it: the chart keeps changing (its description and .chart follow), but nothing is drawn.
  await page.evaluate(() => window.scrollTo(0, document.documentElement.scrollHeight));
  await page.waitForTimeout(500);
  const away = await paints();
  const point = await statePoint();
  await page.waitForFunction((p) => JSON.stringify(document.querySelector('[data-widget="chart"][data-label="The oscillator\'s state in phase space"]').chart.series.find((s) => s.label === 'state now').curves) !== p, point);
  await page.waitForTimeout(1000);
  assert.equal(await paints(), away, 'drawings while far from the view');
  // Back: drawn again.
  await figure.scrollIntoViewIfNeeded();
  await page.waitForFunction((n) => (document.querySelector('[data-widget="chart"][data-label="The oscillator\'s state in phase space"] canvas').pbPaints ?? 0) > n, away);
  await page.close();
});

test('Kepler’s live table updates in place: a phone reader scrolled to the "change" column keeps it in view', async () => {
  const { page, problems } = await openChapter(site, '/kepler/');
  // A tall phone, so that the stars (which pause off screen) and the table are in view together.
  await page.setViewportSize({ width: 360, height: 7000 });
  const box = page.locator('[data-widget="table"]');
  await box.evaluate((b) => b.scrollIntoView({ block: 'end' }));
  await page.waitForFunction(() => {
    const [sim, table] = ['[data-widget="simulator"]', '[data-widget="table"]'].map((s) => document.querySelector(s).getBoundingClientRect());
    // scrollIntoView aligns to whole pixels; a box's edges may not be.
    return sim.top >= 0 && table.bottom <= innerHeight + 1;
  });
  // A box that scrolls is marked as one (named, focusable) by an idle pass (cells/scrollables.ts), which on a
  // busy machine may come after the table is in view.
  await page.waitForFunction((b) => b.hasAttribute('role'), await box.elementHandle());
  assert.equal(await box.getAttribute('role'), 'region');
  assert.equal(await box.getAttribute('tabindex'), '0');
  const change = box.locator('thead th', { hasText: 'change' });
  assert.match((await change.getAttribute('class')) ?? '', /pb-highlight/);
  // The table is rewritten four times a second, and its numbers change width as they change (5e-14, then
  // 4.7e-12): each rewrite must leave the reader where they were. Watched over several rewrites, since any one
  // may happen to keep the width.
  const rewrites = (count) =>
    box.evaluate(
      (b, count) =>
        new Promise((done) => {
          const caption = b.querySelector('caption');
          const seen = [];
          const observer = new MutationObserver(() => {
            // After the rewrite is laid out: the next frame.
            requestAnimationFrame(() => {
              seen.push({ left: b.scrollLeft, max: b.scrollWidth - b.clientWidth });
              if (seen.length === count) {
                observer.disconnect();
                done(seen);
              }
            });
          });
          observer.observe(caption, { childList: true, characterData: true, subtree: true });
        }),
      count,
    );
  // A reader halfway along keeps their place exactly.
  const middle = await box.evaluate((b) => (b.scrollLeft = Math.round((b.scrollWidth - b.clientWidth) / 2)));
  assert.ok(middle > 0);
  for (const seen of await rewrites(6)) assert.equal(seen.left, middle, `scrolled to ${middle}, then ${seen.left}`);
  // A reader at the end, where the "change" column is, stays at the end.
  await box.evaluate((b) => (b.scrollLeft = b.scrollWidth));
  for (const seen of await rewrites(6)) assert.ok(seen.left > 0 && seen.left >= seen.max - 1, `at ${seen.left} of ${seen.max}`);
  const [th, vw] = await Promise.all([change.boundingBox(), page.evaluate(() => document.documentElement.clientWidth)]);
  assert.ok(th && th.x >= 0 && th.x + th.width <= vw, `the change column at ${th?.x}…${(th?.x ?? 0) + (th?.width ?? 0)} of ${vw}`);
  assert.deepEqual(problems, []);
  await page.close();
});
