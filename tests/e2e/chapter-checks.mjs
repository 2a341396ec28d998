/**
 * Helpers shared by the chapter test files (chapter-*.test.mjs): opening a
 * chapter once per file, waiting for its widgets, reading and checking its
 * theory checks, and making sure its canvases have drawn.
 *
 * What each chapter asserts about its own physics (formulas, tolerances)
 * stays in its test file; only the page plumbing lives here.
 */
import assert from 'node:assert/strict';
import { after, before } from 'node:test';
import { cell, openChapter, openSite } from './fixture.mjs';

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
    { timeout: 30_000 },
  );
}

/**
 * Every theory check on the page, in page order: its data attributes, with
 * `measured`, `predicted` and `tolerance` as numbers. With `method`, each also
 * carries the text of its `.pb-measured` line (how it measured).
 * @param {import('playwright-core').Page} page
 * @param {{ method?: boolean }} [options]
 */
export function theoryChecks(page, { method = false } = {}) {
  return page.$$eval(
    THEORY_CHECK,
    (all, method) =>
      all.map((w) => ({
        ...w.dataset,
        measured: Number(w.dataset.measured),
        predicted: Number(w.dataset.predicted),
        tolerance: Number(w.dataset.tolerance),
        ...(method ? { method: w.querySelector('.pb-measured')?.textContent ?? '' } : {}),
      })),
    method,
  );
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
  if (wait) await widget.waitFor({ timeout: 30_000 });
  return widget.evaluate((w) => ({
    ...w.dataset,
    measured: Number(w.dataset.measured),
    predicted: Number(w.dataset.predicted),
    tolerance: Number(w.dataset.tolerance),
  }));
}

/**
 * The agreement a theory check claims, recomputed here from its own numbers:
 * `data-agrees` is 'true' and |measured − predicted| (divided by |predicted|
 * when the check is relative) is within its tolerance. With `relative`, also
 * asserts that the check is (true) or is not (false) relative.
 * @param {{ agrees: string, relative: string, measured: number, predicted: number, tolerance: number }} check
 * @param {{ relative?: boolean }} [options]
 */
export function assertAgrees(check, { relative } = {}) {
  assert.equal(check.agrees, 'true', JSON.stringify(check));
  if (relative !== undefined) assert.equal(check.relative, String(relative));
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
