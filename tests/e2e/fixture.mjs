/**
 * Shared set-up for the e2e test files: the built site on a local server and
 * a fresh headless Chromium, plus helpers that drive cells like a reader.
 */
import { HANG_MS, launchBrowser, watchPage, cellsReady, firstViewReady } from './browser.mjs';
import { startServer } from './server.mjs';

export { cellsReady, firstViewReady, watchPage };

/** @param {import('playwright-core').BrowserContextOptions} [options] */
export async function openSite(options) {
  const server = await startServer();
  try {
    const browser = await launchBrowser(options);
    return {
      origin: server.origin,
      context: browser.context,
      async close() {
        await browser.close();
        await server.close();
      },
    };
  } catch (error) {
    await server.close();
    throw error;
  }
}

/**
 * Opens a chapter with no saved edits and reads it through, so that every
 * cell has run (see cellsReady).
 * @param {{ origin: string, context: import('playwright-core').BrowserContext }} site
 * @param {string} path e.g. '/introduction/'
 */
export async function openChapter(site, path) {
  const page = await site.context.newPage();
  // Clear saved edits from the contents page, which runs no cells: reloading a chapter instead
  // would abort the requests its widgets had in flight, and those would count as problems.
  await page.goto(site.origin + '/');
  await page.evaluate(() => localStorage.clear());
  const watch = watchPage(page);
  await page.goto(site.origin + path);
  await cellsReady(page);
  return { page, ...watch };
}

/** The `[data-cell]` root of the cell named or numbered `id`. */
export function cell(page, id) {
  return page.locator(`[data-cell="${id}"]`);
}

/** Text of a cell's output. */
export async function outputOf(page, id) {
  return (await cell(page, id).locator('[data-cell-output]').textContent()) ?? '';
}

/** Text of a cell's error line ('' when there is none). */
export async function errorOf(page, id) {
  const error = cell(page, id).locator('[data-cell-error]');
  return (await error.isVisible()) ? ((await error.textContent()) ?? '') : '';
}

/** Waits until the output of cell `id` satisfies `predicate`. */
export async function waitForOutput(page, id, predicate) {
  const deadline = Date.now() + HANG_MS;
  let last = '';
  while (Date.now() < deadline) {
    last = await outputOf(page, id);
    if (predicate(last)) return last;
    await page.waitForTimeout(50);
  }
  throw new Error(`output of ${id} never matched; last: ${JSON.stringify(last)}`);
}

/**
 * Replaces a cell's text the way a reader does: click into it (which loads
 * the editor), select all, type, then Shift+Enter (or the Run button).
 * @param {import('playwright-core').Page} page
 * @param {string} id
 * @param {string} source
 * @param {{ run?: 'keys' | 'button' | false }} [options]
 */
export async function typeIntoCell(page, id, source, { run = 'keys' } = {}) {
  const root = cell(page, id);
  await root.locator('.cell-editor').click();
  const content = root.locator('.cm-content');
  await content.waitFor();
  await content.click();
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.insertText(source);
  if (run === 'keys') await page.keyboard.press('Shift+Enter');
  if (run === 'button') await root.locator('[data-cell-run]').click();
}

/** The cells a reader added, in page order. */
export const addedCells = (page) => page.locator('[data-cell-added]');

/** Types `source` into the newest added cell's editor, replacing what it holds, and runs it. */
export async function typeIntoAddedCell(page, source) {
  const content = addedCells(page).last().locator('.cm-content');
  await content.waitFor();
  await content.click();
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.insertText(source);
  await page.keyboard.press('Shift+Enter');
}

/** Waits until the place `id` (a heading) is at the top of the view, within its top third, with the address naming it: where a link to it lands. */
export async function landedOn(page, id) {
  await page.waitForFunction(
    (target) => {
      const heading = document.getElementById(target);
      if (!heading || decodeURIComponent(location.hash.slice(1)) !== target) return false;
      const top = heading.getBoundingClientRect().top;
      return top >= -1 && top < innerHeight / 3;
    },
    id,
  );
}
