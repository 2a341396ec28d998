/**
 * /order-and-chaos/: the chaotic share of Hénon & Heiles's section measured
 * in the page against their Fig. 6 (Astron. J. 69, 73, 1964) at E = 1/12,
 * 1/8 and 1/6; the surface of section draws its orbits in a worker; a click
 * (or Enter) launches an orbit from the clicked point, regular inside a
 * curve at E = 1/12 and chaotic in the sea at E = 1/6, as the paper's
 * sections show.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertDrawn, assertLoadsClean, assertNoNaNShown, assertSumOfTerms, editAndReadChecks, theoryChecks, useChapter } from './chapter-checks.mjs';

const SECTION = '[data-widget="poincare-section"]';

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

useChapter('/order-and-chaos/', (opened) => ({ page, problems } = opened), { widgets: { 'theory-check': 3, 'poincare-section': 1 } });

test('the page loads clean: every cell runs, the section and three checks get ready, nothing leaves localhost', async () => {
  await assertLoadsClean(page, problems, { '[data-widget="theory-check"]': 3, [SECTION]: 1 });
});

test('the chaotic share agrees with Hénon & Heiles Fig. 6 at each energy, within its three named errors', async () => {
  const checks = await theoryChecks(page);
  assert.equal(checks.length, 3);
  // Read off the figure: no chaos at 1/12, a little under half at 1/8, almost all at 1/6.
  assert.deepEqual(checks.map((c) => c.predicted), [0, 0.45, 0.9]);
  for (const check of checks) {
    assertAgrees(check);
    assertSumOfTerms(check);
    assert.ok(check.errorFormula >= 0.05 && check.errorMeasurement > 0, JSON.stringify(check));
  }
  // The measured shares rise with the energy, as the figure's ordered area falls.
  assert.ok(checks[0].measured < 0.1 && checks[1].measured > 0.25 && checks[2].measured > 0.75, checks.map((c) => c.measured).join(', '));
});

/** Pixel position in the section's canvas of the point (u, p) at energy E, plane y = 0: the disk of radius √(2E). */
async function pointAt(E, u, p) {
  const box = await page.locator(`${SECTION} canvas`).boundingBox();
  const r = Math.sqrt(2 * E) * 1.08;
  // The plot is inset by the axes' margins: 50 px left, 12 right, 24 top, 38 bottom.
  return { x: 50 + ((u + r) / (2 * r)) * (box.width - 62), y: 24 + ((r - p) / (2 * r)) * (box.height - 62) };
}

test('the section draws thousands of crossings inside the allowed disk', async () => {
  const section = page.locator(SECTION);
  assert.equal(await section.getAttribute('data-energy'), String(1 / 12));
  assert.ok(Number(await section.getAttribute('data-points')) > 3000);
  await assertDrawn(page, SECTION, 1, 2000);
  assert.match(await section.locator('.pb-poincare-summary').textContent(), /orbits, \d+ crossings of y = 0/);
});

test('a click launches an orbit: regular on a curve at E = 1/12, chaotic in the sea at E = 1/6', async () => {
  const section = page.locator(SECTION);
  const canvas = section.locator('canvas');
  await section.scrollIntoViewIfNeeded();
  await canvas.click({ position: await pointAt(1 / 12, 0.1, 0) });
  await page.waitForFunction((s) => document.querySelector(s).dataset.launched === '1', SECTION, { timeout: 30_000 });
  const regular = Number(await section.getAttribute('data-exponent'));
  assert.ok(regular >= 0 && regular < 0.02, String(regular));
  assert.match(await section.locator('.pb-stability-reading').textContent(), /regular/);

  await section.getByLabel('1/6').check();
  await page.waitForFunction((s) => document.querySelector(s).hasAttribute('data-ready') && document.querySelector(s).dataset.energy === String(1 / 6), SECTION, { timeout: 30_000 });
  await canvas.click({ position: await pointAt(1 / 6, 0.1, 0.1) });
  await page.waitForFunction((s) => document.querySelector(s).dataset.launched === '1', SECTION, { timeout: 30_000 });
  const chaotic = Number(await section.getAttribute('data-exponent'));
  assert.ok(chaotic > 0.05, String(chaotic));

  // Outside the disk: nothing is launched, and the reader is told why.
  await canvas.click({ position: await pointAt(1 / 6, 0.6, 0.6) });
  assert.match(await section.locator('.pb-stability-reading').textContent(), /outside the region/);
  assert.equal(await section.getAttribute('data-launched'), '1');
});

test('the keyboard launches an orbit too: arrows move the point, Enter launches', async () => {
  const section = page.locator(SECTION);
  const canvas = section.locator('canvas');
  await canvas.focus();
  // From the last click, (0.6, 0.6), outside the disk: Shift+arrows move a tenth of its width each.
  await canvas.press('Enter');
  assert.match(await section.locator('.pb-stability-reading').textContent(), /outside the region/);
  for (let i = 0; i < 5; i++) await canvas.press('Shift+ArrowLeft');
  for (let i = 0; i < 5; i++) await canvas.press('Shift+ArrowDown');
  assert.doesNotMatch(await section.locator('.pb-stability-reading').textContent(), /outside/);
  await canvas.press('Enter');
  await page.waitForFunction((s) => document.querySelector(s).dataset.launched === '2', SECTION, { timeout: 30_000 });
  assert.deepEqual(problems, []);
});

test('an energy the figure is not read at gets no verdict, and one above the escape energy is outside validity', async () => {
  const { areaChecks } = await editAndReadChecks(page, 'energies', 'energies = [0.1, 0.2]', ['areaChecks']);
  assert.deepEqual(areaChecks.map((c) => c.verdict), ['undefined', 'outside']);
  assert.match(areaChecks[0].reason, /only at E = 1\/12, 1\/8 and 1\/6/);
  assert.match(areaChecks[1].reason, /above the escape energy/);
  await assertNoNaNShown(page);
  assert.deepEqual(problems, []);
});
