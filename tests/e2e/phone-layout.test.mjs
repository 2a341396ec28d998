/**
 * The phone audit (phone-audit.mjs), which the sweep of every page runs at
 * 360 and 390 px (every-page.mjs), finds what it looks for: a clipped
 * column, a box with no cue, and shrunken figure text.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { widgetsReady } from './chapter-checks.mjs';
import { cellsReady, openSite } from './fixture.mjs';
import { audit, settle, SMALLEST_TEXT } from './phone-audit.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

test('the audit finds what it looks for: a clipped column, a box with no cue, and shrunken figure text', async () => {
  const page = await site.context.newPage();
  await page.setViewportSize({ width: 360, height: 800 });
  await page.goto(`${site.origin}/kepler/`);
  await cellsReady(page);
  await widgetsReady(page);
  await settle(page);
  assert.deepEqual(await page.evaluate(audit, SMALLEST_TEXT), []);
  // Kepler's table, as it was before: its box hides what overflows it.
  await page.evaluate(() => {
    const box = document.querySelector('[data-widget="table"]');
    box.style.overflowX = 'hidden';
    box.closest('.cell-output').style.overflowX = 'hidden';
  });
  const clipped = await page.evaluate(audit, SMALLEST_TEXT);
  assert.ok(clipped.some((p) => /column "change" of table .* is cut off/.test(p)), clipped.join('\n'));
  // A box that scrolls but says nothing about it.
  await page.evaluate(() => {
    const box = document.querySelector('[data-widget="table"]');
    box.style.overflowX = 'auto';
    box.style.background = 'none';
  });
  const silent = await page.evaluate(audit, SMALLEST_TEXT);
  assert.ok(silent.some((p) => /scrolls without a cue/.test(p)), silent.join('\n'));
  // A figure drawn for 640 px and shrunk to the column, as the old SVG charts were: 12 px text becomes 6.
  await page.evaluate(() => {
    const figure = document.createElement('div');
    figure.innerHTML = '<svg viewBox="0 0 640 380" style="width: 320px"><text x="10" y="20" font-size="12">10⁻⁸</text></svg>';
    document.querySelector('main.page').append(figure);
  });
  const small = await page.evaluate(audit, SMALLEST_TEXT);
  assert.ok(small.some((p) => /text "10⁻⁸" in svg is 6\.0 px/.test(p)), small.join('\n'));
  await page.close();
});
