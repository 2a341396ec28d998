/**
 * /standard-map/: the portrait, its K and the orbits a reader launches, and
 * the two theory checks swept across their regimes against references this
 * file holds or computes itself, independently of the book: Greene's K_c =
 * 0.971635406 as MacKay (1983) gives it; the diffusion of p from this
 * file's own iteration of the map from its own random starts (mulberry32),
 * and Rechester and White's formula (PRL 44, 1586, 1980) from this file's
 * own Bessel functions (Abramowitz & Stegun 9.1.10 and 9.2.5);
 * the accelerator bands 2πm ≤ K ≤ √((2πm)² + 16) (Chirikov 1979). And the
 * chapter's exercises, answered in the page.
 */
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { test } from 'node:test';
import { assertAgrees, assertLoadsClean, assertNoCellErrors, assertNoNaNShown, assertSumOfTerms, chartIn, editAndReadChecks, theoryChecks, useChapter } from './chapter-checks.mjs';
import { answer, answerCode } from './exercise-answers.mjs';
import { cell, typeIntoCell, waitForOutput } from './fixture.mjs';
import { seededUniform } from './sweep-physics.mjs';

const MACKAY_K = 0.971635406;
const TWO_PI = 2 * Math.PI;

/**
 * J_n(x) written out here: by its power series Σ (−1)^k (x/2)^{2k+n} / (k! (k+n)!) (A&S 9.1.10) up to
 * x = 20, where its cancellation still leaves 10⁻⁹; beyond, by Hankel's asymptotic expansion (A&S 9.2.5),
 * whose terms at x ≥ 20 fall below 10⁻¹² within a dozen.
 */
function besselJ(n, x) {
  if (x <= 20) {
    let term = (x / 2) ** n;
    for (let j = 1; j <= n; j++) term /= j;
    let sum = term;
    for (let k = 1; k < 200; k++) {
      term *= -((x / 2) ** 2) / (k * (k + n));
      sum += term;
    }
    return sum;
  }
  const mu = 4 * n * n;
  let [P, Q, a] = [1, 0, 1];
  for (let k = 1; k <= 24; k++) {
    a *= (mu - (2 * k - 1) ** 2) / (k * 8 * x);
    if (k % 2 === 1) Q += (k % 4 === 1 ? 1 : -1) * a;
    else P += (k % 4 === 2 ? -1 : 1) * a;
  }
  const chi = x - (n * Math.PI) / 2 - Math.PI / 4;
  return Math.sqrt(2 / (Math.PI * x)) * (P * Math.cos(chi) - Q * Math.sin(chi));
}

/** Rechester and White's D, written out here. */
function rechesterWhite(K) {
  const [J1, J2, J3] = [1, 2, 3].map((n) => besselJ(n, K));
  return ((K * K) / 2) * (1 - 2 * J2 - 2 * J1 * J1 + 2 * J2 * J2 + 2 * J3 * J3);
}

/** ⟨(p_n − p_0)²⟩/n and its standard error, from this file's own iteration of p' = p + K sin q, q' = q + p'. */
function diffusionHere(K, orbits = 4000, n = 400) {
  // independent of the book's Philox
  const random = seededUniform(20261202);
  const values = [];
  for (let j = 0; j < orbits; j++) {
    let q = TWO_PI * random();
    let p = TWO_PI * random();
    const p0 = p;
    for (let i = 0; i < n; i++) {
      p += K * Math.sin(q);
      q = (q + p) % TWO_PI;
    }
    values.push((p - p0) ** 2 / n);
  }
  const mean = values.reduce((a, b) => a + b, 0) / orbits;
  const variance = values.reduce((a, v) => a + (v - mean) ** 2, 0) / (orbits - 1);
  return { D: mean, standardError: Math.sqrt(variance / orbits) };
}

const inAcceleratorBand = (K) => [1, 2, 3, 4, 5, 6].some((m) => K >= TWO_PI * m - 0.2 && K <= Math.sqrt((TWO_PI * m) ** 2 + 16) + 0.7);

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

useChapter('/standard-map/', (opened) => ({ page, problems } = opened));

const portrait = () => page.locator('[data-widget="standard-map"]');
const datum = async (name) => portrait().getAttribute(`data-${name}`);

test('the page loads clean: every cell runs, the portrait, two tables, the chart and both checks get ready', async () => {
  await assertLoadsClean(page, problems, {
    '[data-widget="standard-map"]': 1,
    '[data-widget="theory-check"]': 2,
    '[data-widget="chart"]': 1,
  });
  await assertNoNaNShown(page);
});

test('at the defaults both checks agree: Greene’s levels close in on MacKay’s K_c, and D on Rechester and White’s', async () => {
  const [greene, diffusion] = await theoryChecks(page);
  assertAgrees(greene);
  assertSumOfTerms(greene);
  assert.ok(Math.abs(greene.predicted - MACKAY_K) < 1e-12, `${greene.predicted}`);
  // the deepest level of 12 is within 10⁻⁵ of MacKay’s value, and the allowance is no looser than that
  assert.ok(Math.abs(greene.measured - MACKAY_K) < 1e-5, `${greene.measured}`);
  assert.ok(greene.tolerance < 1e-4, `${greene.tolerance}`);
  assertDiffusionPoint(diffusion, 10);
});

/** The diffusion check at K against this file's own measurement and formula. */
function assertDiffusionPoint(check, K) {
  if (K < 4.5 || inAcceleratorBand(K)) {
    assert.equal(check.verdict, 'outside', JSON.stringify(check));
    assert.match(check.reason, K < 4.5 ? /too small/ : /accelerator/);
    return;
  }
  assertAgrees(check);
  assertSumOfTerms(check);
  const expected = rechesterWhite(K);
  assert.ok(Math.abs(check.predicted - expected) < 1e-6 * expected, `${check.predicted} vs ${expected}`);
  // the page's D and this file's, from other random starts, differ by no more than their combined statistics allow
  const here = diffusionHere(K);
  const spread = 4 * Math.hypot(here.standardError, check.errorMeasurement / 3);
  assert.ok(Math.abs(check.measured - here.D) < spread, `page ${check.measured}, here ${here.D} ± ${spread}`);
  // and the allowance is small enough to tell Rechester and White from the quasilinear K²/2 where they differ by a third
  if (Math.abs(expected - (K * K) / 2) > 0.3 * expected) assert.ok(check.tolerance < Math.abs(expected - (K * K) / 2), JSON.stringify(check));
}

test('sweep of K in the diffusion check: agrees at 10, 20 and 30, outside at 3 (too small) and at 6.5 and 13 (accelerator modes)', async () => {
  for (const K of [3, 6.5, 13, 20, 30]) {
    const checks = await editAndReadChecks(page, 'diffusionK', `diffusionK = ${K}`, ['diffusionCheck']);
    assertDiffusionPoint(checks.diffusionCheck[0], K);
  }
  await editAndReadChecks(page, 'diffusionK', 'diffusionK = 10', ['diffusionCheck']);
});

test('sweep of the depth in Greene’s check: 2 levels are outside validity, 8 and 10 agree, closer to MacKay’s K_c the deeper', async () => {
  const distances = [];
  for (const depth of [6, 12, 14]) {
    const { greeneCheck: [check] } = await editAndReadChecks(page, 'depth', `depth = ${depth}`, ['greeneCheck']);
    // levels 5 to depth
    if (depth - 5 + 1 < 8) {
      assert.equal(check.verdict, 'outside', JSON.stringify(check));
      assert.match(check.reason, /too few/);
      continue;
    }
    assertAgrees(check);
    // the truth is inside the allowance the check names, as it claims
    assert.ok(Math.abs(check.measured - MACKAY_K) <= check.tolerance, JSON.stringify(check));
    distances.push(Math.abs(check.measured - MACKAY_K));
  }
  assert.ok(distances[1] < distances[0], `${distances}`);
  await editAndReadChecks(page, 'depth', 'depth = 12', ['greeneCheck']);
});

test('the portrait draws its orbits; the slider and the field set K; a K out of range is refused under the field', async () => {
  await portrait().scrollIntoViewIfNeeded();
  assert.ok(Number(await datum('points')) > 100_000, await datum('points'));
  assert.equal(Number(await datum('k')), 0.9716);
  await portrait().locator('input[type="range"]').evaluate((slider) => {
    slider.value = '0.5';
    slider.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await page.waitForFunction(() => document.querySelector('[data-widget="standard-map"]')?.getAttribute('data-k') === '0.5');
  assert.equal(await portrait().getByLabel('K', { exact: true }).inputValue(), '0.5');
  const field = portrait().getByLabel('K', { exact: true });
  await field.fill('7');
  await field.press('Enter');
  assert.match((await portrait().locator('.pb-field-message').textContent()) ?? '', /from 0 to 3/);
  assert.equal(await datum('k'), '0.5');
  await field.fill('1.5');
  await field.press('Enter');
  await page.waitForFunction(() => document.querySelector('[data-widget="standard-map"]')?.getAttribute('data-k') === '1.5');
  assert.equal((await portrait().locator('.pb-field-message').textContent()) ?? '', '');
});

/** This file's reading of the orbit from (q, p): the mean advance of the lifted q per kick over 2π, and whether p moved by over 2π. */
function orbitHere(K, q, p, n = 5000) {
  let lifted = q;
  let most = 0;
  const p0 = p;
  for (let i = 0; i < n; i++) {
    p += K * Math.sin(lifted);
    lifted += p;
    most = Math.max(most, Math.abs(p - p0));
  }
  return { rotation: (lifted - q) / (TWO_PI * n), crossed: most > TWO_PI };
}

test('the keyboard launches orbits: the main island’s centre is regular, with no rotation; the layer below K_c stays within 2π, above it crosses', async () => {
  const canvas = portrait().locator('canvas');
  await canvas.focus();
  await canvas.press('Enter');
  assert.equal(await datum('launched'), '1');
  // at the elliptic fixed point (π, 0) the orbit stays put: rotation 0, exponent that of an elliptic point, ≈ 0
  assert.ok(Math.abs(Number(await datum('rotation'))) < 1e-12, await datum('rotation'));
  assert.ok(Number(await datum('exponent')) < 0.01, await datum('exponent'));

  // five steps up: (π, 0.628), inside the island at K = 1.5, which librates: its rotation number is the fixed point's, 0
  for (let i = 0; i < 5; i++) await canvas.press('ArrowUp');
  await canvas.press('Enter');
  const inside = orbitHere(1.5, Math.PI, (5 * TWO_PI) / 50);
  assert.ok(Math.abs(Number(await datum('rotation')) - inside.rotation) < 1e-9, `${await datum('rotation')} vs ${inside.rotation}`);
  assert.equal(await datum('crossed'), String(inside.crossed));

  // near the saddle (0, 0), in the chaotic layer: bounded below K_c, crossing above, as this file's own iteration says
  for (const [K, crossed] of [[0.9, false], [2, true]]) {
    const field = portrait().getByLabel('K', { exact: true });
    await field.fill(String(K));
    await field.press('Enter');
    await page.waitForFunction((k) => document.querySelector('[data-widget="standard-map"]')?.getAttribute('data-k') === k, String(K));
    await portrait().evaluate((root) => delete root.dataset.crossed);
    // the cursor to (≈0.13, ≈0.13): from (π, 0.628), left 24 steps of 2π/50 wraps to q = π − 24·2π/50 …
    await canvas.evaluate((c) => c.focus());
    for (let i = 0; i < 24; i++) await canvas.press('ArrowLeft');
    for (let i = 0; i < 4; i++) await canvas.press('ArrowDown');
    await canvas.press('Enter');
    const q = Math.PI - (24 * TWO_PI) / 50;
    const here = orbitHere(K, q, (1 * TWO_PI) / 50);
    assert.equal(here.crossed, crossed, `this file's orbit at K = ${K}`);
    assert.equal(await datum('crossed'), String(crossed), `K = ${K}`);
    if (crossed) assert.ok(Number(await datum('exponent')) > 0.01, await datum('exponent'));
    // back to the island's column for the next K
    for (let i = 0; i < 24; i++) await canvas.press('ArrowRight');
    for (let i = 0; i < 4; i++) await canvas.press('ArrowUp');
  }
});

test('the last launched orbit downloads as CSV: n, q, p, each row the map of the one before', async () => {
  const [download] = await Promise.all([page.waitForEvent('download'), portrait().getByRole('button', { name: /Download orbit/ }).click()]);
  const rows = (await readFile(await download.path(), 'utf8')).trim().split('\n');
  assert.equal(rows[0], 't,q,p');
  assert.equal(rows.length, 5002);
  const K = Number(await datum('k'));
  const values = rows.slice(1).map((r) => r.split(',').map(Number));
  for (let i = 0; i + 1 < values.length; i++) {
    const [n, q, p] = values[i];
    const [n1, q1, p1] = values[i + 1];
    assert.equal(n1, n + 1);
    assert.ok(Math.abs(p1 - (p + K * Math.sin(q))) < 1e-9 * Math.max(1, Math.abs(p1)), `row ${i}`);
    const dq = (((q1 - (q + p1)) % TWO_PI) + TWO_PI + Math.PI) % TWO_PI - Math.PI;
    assert.ok(Math.abs(dq) < 1e-9 * Math.max(1, Math.abs(p1)), `row ${i}: q`);
  }
});

test('the chart measures D across K: outside the accelerator bands each point lies near Rechester and White’s curve', async () => {
  const chart = await chartIn(page, (await page.locator('[data-widget="chart"]').getAttribute('data-label')) ?? '');
  const measured = chart.series.find((s) => s.label.startsWith('measured')).values[0];
  assert.equal(measured.x.length, 73);
  let near = 0;
  let valid = 0;
  measured.x.forEach((K, i) => {
    if (K < 4.5 || inAcceleratorBand(K)) return;
    valid++;
    const ratio = rechesterWhite(K) / ((K * K) / 2);
    // 400 orbits: a standard error of √2/20 ≈ 0.07 of the ratio; the terms left out, 6(2/πK)^{3/2}
    if (Math.abs(measured.y[i] - ratio) < 4 * 0.071 + 6 * (2 / (Math.PI * K)) ** 1.5) near++;
  });
  assert.ok(valid >= 30, `${valid}`);
  assert.ok(near >= valid - 1, `${near} of ${valid}`);
});

test('a bad option is reported under its cell; the rest of the page keeps working; fixing it recovers', async () => {
  await typeIntoCell(page, 'portrait', 'portrait = standardMap({K: -1})');
  await page.waitForSelector('[data-cell="portrait"] [data-cell-error]:visible');
  assert.match((await cell(page, 'portrait').locator('[data-cell-error]').textContent()) ?? '', /K must be a number/);
  const [greene] = await theoryChecks(page);
  assert.equal(greene.verdict, 'agrees');
  await typeIntoCell(page, 'portrait', 'portrait = standardMap({K})');
  await page.waitForSelector('[data-cell="portrait"] [data-widget="standard-map"][data-ready]');
  await waitForOutput(page, 'K', (out) => out.includes('0.9716'));
  await assertNoCellErrors(page);
});

test('the exercises, answered in the page: right answers from closed forms pass, the known slips fail with their reason', async () => {
  // tr M(π) = 2 − K reaches −2 at K = 4; tr M(π)M(0) = 2 − K² at K = 2
  assert.equal((await answer(page, 'main-island-stability', '4')).result, 'passed');
  let v = await answer(page, 'main-island-stability', '2');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /trace/);
  assert.equal((await answer(page, 'half-resonance-stability', '2')).result, 'passed');
  v = await answer(page, 'half-resonance-stability', '4');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /period-1/);
  assert.equal((await answer(page, 'primary-overlap', ((Math.PI * Math.PI) / 4).toFixed(3))).result, 'passed');
  v = await answer(page, 'primary-overlap', '9.8696');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /π²/);
  assert.equal((await answerCode(page, 'resonance-pendulum', 'myH', 'myH = "p0^2/2 + 0.5*cos(q0)"')).result, 'passed');
  assert.equal((await answerCode(page, 'resonance-pendulum', 'myH', 'myH = "p0^2/2 - 0.5*cos(q0)"')).result, 'failed');
  assert.deepEqual(problems, []);
});
