/**
 * Helpers shared by the chapter test files (chapter-*.test.mjs): opening a
 * chapter once per file, waiting for its widgets, reading and checking its
 * theory checks, editing a cell and waiting for the checks it re-runs, and
 * making sure its canvases have drawn and that no NaN is shown.
 *
 * What each chapter asserts about its own physics (formulas, tolerances)
 * stays in its test file; only the page plumbing lives here.
 */
import assert from 'node:assert/strict';
import { after, before } from 'node:test';
import { cell, openChapter, openSite, typeIntoCell } from './fixture.mjs';

/** Selector of every theory-check widget. */
export const THEORY_CHECK = '[data-widget="theory-check"]';

/**
 * Registers `before`/`after` hooks that open `path` on a fresh site, wait
 * until its widgets are ready (see {@link widgetsReady}), and close it all
 * afterwards. `opened` receives `{ site, page, problems }` once it is open.
 * @param {string} path e.g. '/kepler/'
 * @param {(chapter: { site: Awaited<ReturnType<typeof openSite>>, page: import('playwright-core').Page, problems: string[] }) => void} opened
 * @param {{ widgets?: Record<string, number> }} [options] passed on to widgetsReady
 */
export function useChapter(path, opened, { widgets } = {}) {
  /** @type {Awaited<ReturnType<typeof openSite>> | undefined} */
  let site;
  /** @type {import('playwright-core').Page | undefined} */
  let page;
  before(async () => {
    site = await openSite();
    const chapter = await openChapter(site, path);
    page = chapter.page;
    opened({ site, page, problems: chapter.problems });
    await widgetsReady(page, widgets);
  });
  after(async () => {
    await page?.close();
    await site?.close();
  });
}

/**
 * Waits (up to 30 s) until every `[data-widget]` on the page has `data-ready`,
 * and, when `expected` is given, until there are at least `expected[kind]`
 * widgets of each kind named in it.
 * @param {import('playwright-core').Page} page
 * @param {Record<string, number>} [expected] e.g. { simulator: 2, 'theory-check': 2 }
 */
export async function widgetsReady(page, expected = {}) {
  await page.waitForFunction(
    (expected) => {
      const all = [...document.querySelectorAll('[data-widget]')];
      const count = (kind) => all.filter((w) => w.dataset.widget === kind).length;
      return Object.entries(expected).every(([kind, n]) => count(kind) >= n) && all.every((w) => w.hasAttribute('data-ready'));
    },
    expected,
  );
}

/**
 * The theory checks `all`, each as its data attributes with the numeric ones
 * as numbers (NaN when absent) and its text; with `method`, also the text of
 * its `.pb-measured` line. Runs in the page, so it refers to nothing outside.
 * @param {HTMLElement[]} all
 * @param {boolean} method
 */
function readChecks(all, method) {
  const numeric = ['measured', 'predicted', 'tolerance', 'allowed', 'error', 'errorFormula', 'errorIntegration', 'errorMeasurement'];
  return all.map((w) => {
    const check = { ...w.dataset, text: w.textContent ?? '' };
    for (const name of numeric) check[name] = name in w.dataset ? Number(w.dataset[name]) : NaN;
    if (method) check.method = w.querySelector('.pb-measured')?.textContent ?? '';
    return check;
  });
}

/**
 * Every theory check on the page, in page order: its data attributes (see
 * widgets/chapter/theory-check/theory-check.ts), with the numbers (measured, predicted,
 * tolerance = the sum of the errors allowed, error = the difference as
 * compared, errorFormula, errorIntegration, errorMeasurement) as numbers,
 * NaN when absent, and its text. With `method`, each also carries the text
 * of its `.pb-measured` line (how it measured).
 * @param {import('playwright-core').Page} page
 * @param {{ method?: boolean }} [options]
 */
export function theoryChecks(page, { method = false } = {}) {
  return page.$$eval(THEORY_CHECK, readChecks, method);
}

/**
 * The theory check in cell `id`, parsed like {@link theoryChecks}. With
 * `wait`, first waits (up to 30 s) for the check to appear.
 * @param {import('playwright-core').Page} page
 * @param {string} id
 * @param {{ wait?: boolean }} [options]
 */
export async function theoryCheckIn(page, id, { wait = false } = {}) {
  const widget = cell(page, id).locator(THEORY_CHECK);
  if (wait) await widget.waitFor();
  const [check] = await widget.evaluateAll(readChecks, false);
  return check;
}

/**
 * Asserts that a check's allowance is the sum of the error terms it names
 * (absent terms count as 0), so that its verdict is exactly "the difference
 * is inside the errors named".
 */
export function assertSumOfTerms(check) {
  const terms = ['errorFormula', 'errorIntegration', 'errorMeasurement'].map((name) => check[name]).filter((v) => !Number.isNaN(v));
  assert.ok(terms.length > 0, `no error terms: ${JSON.stringify(check)}`);
  const sum = terms.reduce((a, b) => a + b, 0);
  assert.ok(Math.abs(check.tolerance - sum) <= 1e-12 * Math.max(1, sum), `tolerance ${check.tolerance} is not the sum ${sum} of ${terms}`);
}

/**
 * The agreement a theory check claims, recomputed here from its own numbers:
 * its verdict is 'agrees', its allowance is the sum of the errors it names,
 * and |measured − predicted| (divided by |predicted| when the check is
 * relative) is within it. With `relative`, also asserts that the check is
 * (true) or is not (false) relative.
 * @param {{ agrees: string, verdict: string, relative: string, measured: number, predicted: number, tolerance: number }} check
 * @param {{ relative?: boolean }} [options]
 */
export function assertAgrees(check, { relative } = {}) {
  assert.equal(check.verdict, 'agrees', JSON.stringify(check));
  assert.equal(check.agrees, 'true', JSON.stringify(check));
  if (relative !== undefined) assert.equal(check.relative, String(relative));
  assertSumOfTerms(check);
  const difference = Math.abs(check.measured - check.predicted);
  const error = check.relative === 'true' ? difference / Math.abs(check.predicted) : difference;
  assert.ok(error <= check.tolerance, JSON.stringify(check));
}

/**
 * For each element matching `selector`, in page order, its widget kind and
 * how many pixels of its most-drawn canvas differ from that canvas's first
 * pixel (the background), counting only pixels that are not transparent.
 * @param {import('playwright-core').Page} page
 * @param {string} selector
 * @returns {Promise<{ kind: string, pixels: number }[]>}
 */
export function drawnPixels(page, selector) {
  return page.$$eval(selector, (plots) =>
    plots.map((plot) => {
      const counts = [...plot.querySelectorAll('canvas')].map((canvas) => {
        if (!canvas.width || !canvas.height) return 0;
        const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
        let differ = 0;
        for (let i = 0; i < data.length; i += 4) {
          if (data[i + 3] > 0 && (data[i] !== data[0] || data[i + 1] !== data[1] || data[i + 2] !== data[2] || data[i + 3] !== data[3])) differ++;
        }
        return differ;
      });
      return { kind: plot.dataset.widget, pixels: Math.max(0, ...counts) };
    }),
  );
}

/**
 * The series of the chart whose label is `label` (widgets/chapter/chart/chart.ts),
 * once it has drawn: each with its label, kind ('line', 'dots', 'band'),
 * number of curves, number of points and its values ({x, y} of each curve);
 * and the chart's text description.
 * @param {import('playwright-core').Page} page
 * @param {string} label
 */
export async function chartIn(page, label) {
  const figure = page.locator(`[data-widget="chart"][data-label="${label}"][data-ready]`);
  await figure.waitFor();
  return figure.evaluate((f) => ({
    description: f.querySelector('.pb-chart-description')?.textContent ?? '',
    series: f.chart.series.map((s) => ({
      label: s.label,
      kind: s.kind,
      curves: s.curves.length,
      points: s.curves.reduce((n, c) => n + c.x.length, 0),
      values: s.curves.map((c) => ({ x: Array.from(c.x), y: Array.from(c.y) })),
    })),
  }));
}

/**
 * Asserts that exactly `count` elements match `selector` and that each has
 * drawn more than `min` pixels besides its background (see {@link drawnPixels}).
 * @param {import('playwright-core').Page} page
 * @param {string} selector
 * @param {number} count
 * @param {number} [min]
 */
export async function assertDrawn(page, selector, count, min = 500) {
  const drawn = await drawnPixels(page, selector);
  assert.equal(drawn.length, count, JSON.stringify(drawn));
  for (const { kind, pixels } of drawn) assert.ok(pixels > min, `${kind} drew ${pixels} pixels`);
}

/** Clicks the reset button of cell `id`, restoring its original text. */
export async function resetCell(page, id) {
  await cell(page, id).locator('[data-cell-reset]').click();
}

/** Asserts that no cell on the page shows an error line. */
export async function assertNoCellErrors(page) {
  assert.equal(await page.locator('[data-cell-error]:visible').count(), 0);
}

/**
 * The "page loads clean" check: no cell shows an error, each selector in
 * `counts` matches exactly that many elements, and the page has reported no
 * problems (console errors, failed or off-site requests).
 * @param {import('playwright-core').Page} page
 * @param {string[]} problems
 * @param {Record<string, number>} counts e.g. { '[data-widget="theory-check"]': 2 }
 */
export async function assertLoadsClean(page, problems, counts) {
  await assertNoCellErrors(page);
  for (const [selector, n] of Object.entries(counts)) assert.equal(await page.locator(selector).count(), n, selector);
  assert.deepEqual(problems, []);
}

/**
 * Replaces cell `id`'s text with `source` and runs it, as a reader does, then
 * waits until each cell in `checks` shows a theory check
 * made after the edit, and returns those checks by cell, parsed like
 * {@link theoryChecks}. A check cell that fails instead makes this throw with
 * its error line, so a sweep point that breaks a cell says so.
 * @param {import('playwright-core').Page} page
 * @param {string} id
 * @param {string} source
 * @param {string[]} checks ids of the cells whose theory checks to wait for
 */
export async function editAndReadChecks(page, id, source, checks) {
  const selector = checks.map((c) => `[data-cell="${c}"] ${THEORY_CHECK}`).join(', ');
  // Mark the checks on the page now; the ones made after the edit lack the mark.
  await page.$$eval(selector, (all) => all.forEach((w) => (w.dataset.stale = '')));
  await typeIntoCell(page, id, source);
  const failed = await page.waitForFunction(
    ([ids, kind]) => {
      const states = ids.map((c) => {
        const root = document.querySelector(`[data-cell="${c}"]`);
        const error = root?.querySelector('[data-cell-error]');
        if (error && error.offsetParent !== null && error.textContent) return `${c}: ${error.textContent}`;
        const fresh = [...(root?.querySelectorAll(kind) ?? [])].filter((w) => !('stale' in w.dataset) && 'ready' in w.dataset);
        return fresh.length > 0 && root.dataset.cellState !== 'pending' ? 'ok' : null;
      });
      if (states.some((s) => s === null)) return false;
      return states.filter((s) => s !== 'ok').join('; ') || 'none';
    },
    [checks, THEORY_CHECK],
  );
  const errors = await failed.jsonValue();
  if (errors !== 'none') throw new Error(`after ${id} = ${source}: ${errors}`);
  const result = {};
  for (const c of checks) result[c] = await cell(page, c).locator(THEORY_CHECK).evaluateAll(readChecks, false);
  return result;
}

/**
 * Asserts that no text a reader sees outside code says NaN or Infinity: an
 * undefined value must say why instead.
 * @param {import('playwright-core').Page} page
 */
export async function assertNoNaNShown(page) {
  const shown = await page.evaluate(() => {
    const hits = [];
    const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      const parent = node.parentElement;
      if (!parent || parent.closest('pre, code, .cm-editor, script, style') || parent.offsetParent === null) continue;
      if (/\bNaN\b|\bInfinity\b/.test(node.textContent ?? '')) hits.push(`${parent.closest('[data-cell]')?.getAttribute('data-cell') ?? '(text)'}: ${node.textContent}`);
    }
    return hits;
  });
  assert.deepEqual(shown, [], 'NaN or Infinity shown to the reader');
}
