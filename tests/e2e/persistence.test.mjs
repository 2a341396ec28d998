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

const KEY = 'phasebook:v1:edit:introduction:omega';
const PERIOD_OF = (omega) => `period = ${(2 * Math.PI) / omega}`;

const readSaved = (page) => page.evaluate((key) => JSON.parse(localStorage.getItem(key) ?? 'null'), KEY);

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
  assert.equal(saved.source, 'omega = 5');
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

test('typing saves a draft without running it; the draft is back after a reload', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'omega', 'omega = 7', { run: false });
  await page.waitForFunction((key) => localStorage.getItem(key) !== null, KEY);
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  await reload(page);
  assert.equal(await cell(page, 'omega').locator('.cell-editor').textContent(), 'omega = 7');
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
  await page.evaluate((key) => {
    localStorage.setItem(key, JSON.stringify({ source: 'omega = 3', base: 'an-old-hash', savedAt: Date.now() }));
  }, KEY);
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
  assert.equal(saved.source, 'omega = 3');
  assert.equal(saved.base, hash);
  assert.deepEqual(problems, []);
  await page.close();
});

test('an edit made from an older original is offered, not applied: Discard', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  await page.evaluate((key) => {
    localStorage.setItem(key, JSON.stringify({ source: 'omega = 3', base: 'an-old-hash', savedAt: Date.now() }));
  }, KEY);
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
  await page.evaluate(([key, base]) => {
    localStorage.setItem(key, JSON.stringify({ source: 'omega = (', base, savedAt: Date.now() }));
    localStorage.setItem('phasebook:v1:edit:introduction:period', '{not json');
  }, [KEY, hash]);
  await reload(page);
  assert.match(await errorOf(page, 'omega'), /^SyntaxError: .*\(1:\d+\)$/);
  assert.equal(await cell(page, 'omega').locator('.cell-editor').textContent(), 'omega = (');
  assert.equal(await outputOf(page, 'omega'), 'omega = 10');
  assert.equal(await outputOf(page, 'period'), PERIOD_OF(10));
  assert.deepEqual(problems, []);
  await page.close();
});
