/**
 * A reader adds cells of their own below any cell: they run, are saved with
 * the reader's edits, can be renamed by editing and deleted, and a data
 * export records them.
 */
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { after, before, test } from 'node:test';
import { addedCells, cellsReady, openChapter, openSite, typeIntoAddedCell } from './fixture.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());


const outputOfLast = (page) => addedCells(page).last().locator('[data-cell-output]').textContent();

test('a reader adds a cell below any cell, runs it, renames it by editing, and deletes it; reloads keep it', async () => {
  const { page, problems } = await openChapter(site, '/adiabatic-invariants/');
  await page.locator('[data-cell="params"] [data-cell-add]').click();
  // The code that builds a cell of the reader's comes with the first one (cells/chapter.ts).
  await addedCells(page).first().waitFor();
  assert.equal(await addedCells(page).count(), 1);
  // It sits right below the cell it was added to, with the cursor in it.
  assert.equal(await page.evaluate(() => document.querySelector('[data-cell="params"]').nextElementSibling?.hasAttribute('data-cell-added')), true);
  await page.waitForFunction(() => document.querySelector('[data-cell-added] .cm-content')?.contains(document.activeElement));
  await typeIntoAddedCell(page, 'lambda = 2 * params.omega0');
  await page.waitForFunction(() => document.querySelector('[data-cell-added] [data-cell-output]')?.textContent === 'lambda = 8');

  // Another cell can read it.
  await page.locator('[data-cell-added] [data-cell-add]').click();
  await typeIntoAddedCell(page, 'twice = lambda * 2');
  await page.waitForFunction(() => [...document.querySelectorAll('[data-cell-added] [data-cell-output]')].some((o) => o.textContent === 'twice = 16'));

  await page.reload();
  await cellsReady(page);
  assert.equal(await addedCells(page).count(), 2);
  assert.deepEqual(await addedCells(page).locator('[data-cell-output]').allTextContents(), ['lambda = 8', 'twice = 16']);

  // Renaming is editing: the reader's second cell follows (and fails, naming the old name).
  await addedCells(page).first().locator('.cell-editor').click();
  // After the reload the editor loads on this click: type once it has the focus, as a reader sees it appear.
  await page.waitForFunction(() => document.querySelector('[data-cell-added] .cm-content')?.contains(document.activeElement));
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.insertText('mu = 3');
  await page.keyboard.press('Shift+Enter');
  await page.waitForFunction(() => document.querySelector('[data-cell-added] [data-cell-output]')?.textContent === 'mu = 3');
  await page.waitForFunction(() => /lambda is not defined/.test(document.querySelectorAll('[data-cell-added] [data-cell-error]')[1]?.textContent ?? ''));

  // Its Reset deletes it, and the deletion is kept.
  while ((await addedCells(page).count()) > 0) await addedCells(page).first().locator('[data-cell-reset]').click();
  assert.equal(await addedCells(page).count(), 0);
  await page.reload();
  await cellsReady(page);
  assert.equal(await addedCells(page).count(), 0);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a data export records the cells the reader changed or added', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  await page.locator('[data-cell="params"] [data-cell-add]').click();
  await typeIntoAddedCell(page, 'mine = 42');
  await page.waitForFunction(() => document.querySelector('[data-cell-added] [data-cell-output]')?.textContent === 'mine = 42');
  const id = await addedCells(page).first().getAttribute('data-cell');
  await page.waitForSelector('[data-cell="sim"] [data-widget="simulator"][data-ready]');
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.locator('[data-cell="sim"] button', { hasText: 'Download JSON' }).click(),
  ]);
  const file = JSON.parse(await readFile(await download.path(), 'utf8'));
  assert.deepEqual(file.meta.provenance, { page: '/playground/', cells: [{ cell: id, source: 'mine = 42', added: true }] });
  assert.deepEqual(problems, []);
  await page.close();
});
