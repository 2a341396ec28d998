/**
 * The reader's edits survive reloads, Reset brings the book's original back,
 * and an edit made from an older version of a cell is offered, not applied.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { cell, cellsReady, errorOf, openChapter, openSite, outputOf, typeIntoCell, waitForOutput } from './fixture.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

/** The inspector shows numbers to 12 significant digits (cells/inspect.ts). */
const PERIOD_OF = (omega) => `period = ${Number(((2 * Math.PI) / omega).toPrecision(12))}`;

/** The storage key of a cell's edit on this page (cells/storage.ts): the browser's secret, the page's path, the cell. */
const editKey = (page, id) =>
  page.evaluate((id) => `phasebook:v2:${localStorage.getItem('phasebook:v2:secret')}:${location.pathname}:edit:${id}`, id);

const readSaved = async (page, id = 'omega') => {
  const key = await editKey(page, id);
  return page.evaluate((key) => JSON.parse(localStorage.getItem(key) ?? 'null'), key);
};

/** Stores an edit as this book would have (with the secret), e.g. one made from an older version of the chapter. */
const plant = async (page, id, edit) => {
  const key = await editKey(page, id);
  await page.evaluate(([key, edit]) => localStorage.setItem(key, JSON.stringify({ savedAt: Date.now(), tab: 'an-earlier-visit', ...edit })), [key, edit]);
};

async function reload(page) {
  await page.reload();
  await cellsReady(page);
}

test('a reload keeps an edit, and the edited cell runs with it', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  const hash = await cell(page, 'omega').getAttribute('data-cell-hash');
  await typeIntoCell(page, 'omega', 'omega = 5');
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(5));
  const saved = await readSaved(page);
  assert.equal(saved.ran, 'omega = 5');
  assert.equal(saved.draft, 'omega = 5');
  assert.equal(saved.base, hash);

  await reload(page);
  assert.equal(await outputOf(page, 'omega'), 'omega = 5');
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(5));
  assert.equal(await cell(page, 'omega').locator('.cell-editor').textContent(), 'omega = 5');
  assert.equal(await cell(page, 'omega').getAttribute('data-cell-edited'), '');
  assert.equal(await cell(page, 'omega').locator('[data-cell-reset]').isEnabled(), true);
  assert.deepEqual(problems, []);
  await page.close();
});

test('typing saves a draft without running it; after a reload the draft is back, shown but not run', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'omega', 'omega = 7', { run: false });
  const key = await editKey(page, 'omega');
  await page.waitForFunction((key) => localStorage.getItem(key) !== null, key);
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  await reload(page);
  assert.equal(await cell(page, 'omega').locator('.cell-editor').textContent(), 'omega = 7');
  // Only code the reader ran runs again: a draft could be the half-typed loop that froze the page.
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.equal(await cell(page, 'omega').locator('[data-cell-status]').textContent(), 'not run yet');
  assert.deepEqual(problems, []);
  await page.close();
});

test('keys typed just before leaving the page are kept (saved when the page is hidden, not only after a pause)', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'omega', 'omega = 8', { run: false });
  // No wait for the draft's delayed save: reload at once.
  await reload(page);
  assert.equal(await cell(page, 'omega').locator('.cell-editor').textContent(), 'omega = 8');
  assert.deepEqual(problems, []);
  await page.close();
});

test('Reset restores the original source and value and forgets the edit', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'omega', 'omega = 5');
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(5));
  await cell(page, 'omega').locator('[data-cell-reset]').click();
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(10));
  assert.equal(await cell(page, 'omega').locator('.cm-content').textContent(), 'omega = 10');
  assert.equal(await readSaved(page), null);
  assert.equal(await cell(page, 'omega').locator('[data-cell-reset]').isEnabled(), false);

  // Reset before the editor exists (a reload with an edit, no click into the cell).
  await typeIntoCell(page, 'omega', 'omega = 5');
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(5));
  await reload(page);
  await cell(page, 'omega').locator('[data-cell-reset]').click();
  await waitForOutput(page, 'omega', (text) => text === 'omega = 10');
  assert.equal(await cell(page, 'omega').locator('.cell-editor').textContent(), 'omega = 10');
  await reload(page);
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.deepEqual(problems, []);
  await page.close();
});

test('an edit made from an older original is offered, not applied: Restore my edit', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  const hash = await cell(page, 'omega').getAttribute('data-cell-hash');
  await plant(page, 'omega', { draft: 'omega = 3', ran: 'omega = 3', base: 'an-old-hash' });
  await reload(page);
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.equal(await cell(page, 'omega').locator('.cell-editor').textContent(), 'omega = 10');
  const notice = cell(page, 'omega').locator('[data-cell-notice]');
  assert.ok(await notice.isVisible());
  assert.match((await notice.textContent()) ?? '', /changed since your edit/);

  await notice.getByRole('button', { name: 'Restore my edit' }).click();
  await waitForOutput(page, 'period', (text) => text === PERIOD_OF(3));
  assert.equal(await notice.isVisible(), false);
  const saved = await readSaved(page);
  assert.equal(saved.ran, 'omega = 3');
  assert.equal(saved.base, hash);
  assert.deepEqual(problems, []);
  await page.close();
});

test('an edit made from an older original is offered, not applied: Discard', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await plant(page, 'omega', { draft: 'omega = 3', ran: 'omega = 3', base: 'an-old-hash' });
  await reload(page);
  const notice = cell(page, 'omega').locator('[data-cell-notice]');
  await notice.getByRole('button', { name: 'Discard' }).click();
  assert.equal(await notice.isVisible(), false);
  assert.equal(await readSaved(page), null);
  await reload(page);
  assert.equal(await notice.isVisible(), false);
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a saved edit that does not parse keeps its text, shows the error, and runs the original', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  const hash = await cell(page, 'omega').getAttribute('data-cell-hash');
  await plant(page, 'omega', { draft: 'omega = (', ran: 'omega = (', base: hash });
  const periodKey = await editKey(page, 'period');
  await page.evaluate((key) => localStorage.setItem(key, '{not json'), periodKey);
  await reload(page);
  assert.match(await errorOf(page, 'omega'), /^SyntaxError: .*\(1:\d+\)$/);
  assert.equal(await cell(page, 'omega').locator('.cell-editor').textContent(), 'omega = (');
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.equal(await outputOf(page, 'period'), PERIOD_OF(10));
  assert.deepEqual(problems, []);
  await page.close();
});
