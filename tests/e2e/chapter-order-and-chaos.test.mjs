/**
 * /order-and-chaos/: the chaotic share of Hénon & Heiles's section measured
 * in the page against their Fig. 6 (Astron. J. 69, 73, 1964) at E = 1/12,
 * 1/8 and 1/6; the surface of section draws its orbits in a worker; a click
 * (or Enter) launches an orbit from the clicked point, regular inside a
 * curve at E = 1/12 and chaotic in the sea at E = 1/6, as the paper's
 * sections show. The anisotropic Kepler problem of the paper's chaotic
 * two-body variant (section "Kepler's broken symmetry, again"): its section
 * scatters at the paper's factor 1.5 (μ = 1.625, above Devaney's 9/8), its
 * energy check agrees through the close approaches while the isotropy checks
 * are outside validity; at the isotropic factor every orbit closes (the
 * Poincaré map is the identity) and the period agrees with Kepler's third
 * law and the exponent with zero; a factor that unbinds the orbit is refused
 * in words.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertDrawn, assertLoadsClean, assertNoNaNShown, assertSumOfTerms, editAndReadChecks, resetCell, theoryChecks, useChapter } from './chapter-checks.mjs';
import { errorOf, typeIntoCell } from './fixture.mjs';
import { answer, answerCode } from './exercise-answers.mjs';

const SECTION = '[data-widget="poincare-section"][data-system="henon-heiles"]';
const KEPLER = '[data-widget="poincare-section"][data-system="anisotropic-kepler"]';
/** The three checks of the Kepler problem, by their labels, in page order. */
const KEPLER_CHECKS = ['Energy through the close approaches', 'Period at isotropy', 'Largest Lyapunov exponent at isotropy'];

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

useChapter('/order-and-chaos/', (opened) => ({ page, problems } = opened), { widgets: { 'theory-check': 6, 'poincare-section': 2 } });

test('the page loads clean: every cell runs, the two sections and six checks get ready, nothing leaves localhost', async () => {
  await assertLoadsClean(page, problems, { '[data-widget="theory-check"]': 6, [SECTION]: 1, [KEPLER]: 1 });
});

test('the chaotic share agrees with Hénon & Heiles Fig. 6 at each energy, within its three named errors', async () => {
  const checks = (await theoryChecks(page)).filter((c) => c.text.includes('Chaotic share'));
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

/**
 * Pixel position in a section's canvas of the point (u, p) when the allowed region is a disk of radius
 * `radius` about the origin: √(2E) for Hénon–Heiles at energy E on the plane y = 0, 1 for the Kepler problem.
 */
async function pointIn(selector, radius, u, p) {
  const box = await page.locator(`${selector} canvas`).boundingBox();
  const r = radius * 1.08;
  // The plot is inset by the axes' margins: 50 px left, 12 right, 24 top, 38 bottom; the disk is drawn round,
  // at one scale on both axes, centred in the plot.
  const [width, height] = [box.width - 62, box.height - 62];
  const scale = Math.min(width, height) / (2 * r);
  return { x: 50 + width / 2 + u * scale, y: 24 + height / 2 - p * scale };
}

/** Pixel position in the Hénon–Heiles section of the point (u, p) at energy E. */
const pointAt = (E, u, p) => pointIn(SECTION, Math.sqrt(2 * E), u, p);

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
  await page.waitForFunction((s) => document.querySelector(s).dataset.launched === '1', SECTION);
  const regular = Number(await section.getAttribute('data-exponent'));
  assert.ok(regular >= 0 && regular < 0.02, String(regular));
  assert.match(await section.locator('.pb-stability-reading').textContent(), /regular/);

  await section.getByLabel('1/6').check();
  await page.waitForFunction((s) => document.querySelector(s).hasAttribute('data-ready') && document.querySelector(s).dataset.energy === String(1 / 6), SECTION);
  await canvas.click({ position: await pointAt(1 / 6, 0.1, 0.1) });
  await page.waitForFunction((s) => document.querySelector(s).dataset.launched === '1', SECTION);
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
  await page.waitForFunction((s) => document.querySelector(s).dataset.launched === '2', SECTION);
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

/** The Kepler problem's three checks now on the page, in page order. */
async function keplerChecks() {
  const all = await theoryChecks(page);
  return KEPLER_CHECKS.map((label) => all.find((c) => c.text.includes(label)));
}

/** Waits (up to 2 min, the section is thousands of adaptive steps per orbit) until the Kepler section for `factor` is complete. */
async function keplerSectionFor(factor) {
  await page.waitForFunction(
    ([s, f]) => {
      const root = document.querySelector(s);
      return root?.dataset.factor === f && root.hasAttribute('data-ready');
    },
    [KEPLER, String(factor)],
  );
  return page.locator(KEPLER).evaluate((root) => ({ ...root.dataset, summary: root.querySelector('.pb-poincare-summary')?.textContent ?? '' }));
}

test('the anisotropic Kepler section at the paper’s factor 1.5: μ = 1.625, the crossings scattered over the whole disk', async () => {
  const section = await keplerSectionFor(1.5);
  assert.equal(Number(section.mu), 1.625);
  assert.ok(Number(section.points) > 3000, section.points);
  // Orbits wander across the section: some orbit's crossings lie farther apart than the disk's radius.
  assert.ok(Number(section.spread) > 1, section.spread);
  assert.match(section.summary, /At μ = 1\.625: \d+ orbits, \d+ crossings of v = 0 with p_v > 0/);
  await assertDrawn(page, KEPLER, 1, 2000);
});

test('its checks: the energy agrees through the close approaches; period and exponent are outside validity, the exponent positive', async () => {
  const [energy, period, exponent] = await keplerChecks();
  assertAgrees(energy);
  // The regularised integration keeps the energy to 1e−8, through approaches far closer than the orbit's size.
  assert.ok(energy.measured < 1e-8 && energy.measured <= energy.errorIntegration, JSON.stringify(energy));
  assert.match(energy.text, /after \d+ close approaches/);
  assert.equal(period.verdict, 'outside');
  assert.match(period.reason, /μ = 1\.625: the mass is anisotropic/);
  assert.equal(exponent.verdict, 'outside');
  assert.match(exponent.reason, /above μ = 9\/8/);
  // Chaotic, as Devaney's μ > 9/8 allows: far above a regular orbit's ln T / T ≈ 0.01 at T = 600.
  assert.ok(exponent.measured > 0.1, String(exponent.measured));
});

test('a click in the Kepler section launches a chaotic orbit; a click outside the disk is refused', async () => {
  const section = page.locator(KEPLER);
  const canvas = section.locator('canvas');
  await section.scrollIntoViewIfNeeded();
  await canvas.click({ position: await pointIn(KEPLER, 1, 0.7, 0.1) });
  await page.waitForFunction((s) => document.querySelector(s).dataset.launched === '1', KEPLER);
  assert.ok(Number(await section.getAttribute('data-exponent')) > 0.1);
  assert.match(await section.locator('.pb-stability-reading').textContent(), /chaotic/);
  await canvas.click({ position: await pointIn(KEPLER, 1, 0.8, 0.8) });
  assert.match(await section.locator('.pb-stability-reading').textContent(), /outside the region/);
  assert.equal(await section.getAttribute('data-launched'), '1');
});

test('editing the factor to isotropy closes every orbit, and the period and exponent checks agree', async () => {
  const before = await page.locator(`${KEPLER} canvas`).evaluate((c) => c.toDataURL());
  const { keplerChecks: checks } = await editAndReadChecks(page, 'factor', 'factor = 1', ['keplerChecks']);
  const [energy, period, exponent] = KEPLER_CHECKS.map((label) => checks.find((c) => c.text.includes(label)));
  assertAgrees(energy);
  // Kepler's third law T = 2π√(m A³/k) with m = 1/(2a) = 1/4, A = k/(2|E|): the paper's own orbit, whose period is 2.9395.
  assertAgrees(period);
  assert.ok(Math.abs(period.predicted - 2.93951) < 1e-4, String(period.predicted));
  assert.ok(Math.abs(period.measured - period.predicted) / period.predicted < 1e-8, JSON.stringify(period));
  // λ = 0 within ln κ / T: a tangent vector that only turns.
  assertAgrees(exponent);
  assert.ok(Math.abs(exponent.measured) < 0.005, String(exponent.measured));

  const section = await keplerSectionFor(1);
  assert.equal(Number(section.mu), 1);
  // Every Kepler ellipse closes: each orbit's crossings fall on one point, to the integration's accuracy.
  assert.ok(Number(section.spread) < 1e-6, section.spread);
  assert.match(section.summary, /each orbit's crossings fall on one point/);
  const after = await page.locator(`${KEPLER} canvas`).evaluate((c) => c.toDataURL());
  assert.notEqual(after, before);
  await assertDrawn(page, KEPLER, 1, 100);
  assert.deepEqual(problems, []);
});

test('the other isotropic factor makes the paper’s orbit a collision orbit: the period check says so; an unbound factor is refused in words', async () => {
  const { keplerChecks: checks } = await editAndReadChecks(page, 'factor', 'factor = -1', ['keplerChecks']);
  const period = checks.find((c) => c.text.includes(KEPLER_CHECKS[1]));
  assert.equal(period.verdict, 'outside');
  assert.match(period.reason, /L = 0/);

  // With factor 10 the paper's initial state has E > 0: the section and the run refuse it, in words under their cells.
  await typeIntoCell(page, 'factor', 'factor = 10');
  await page.waitForFunction(() => {
    const shown = (id) => document.querySelector(`[data-cell="${id}"] [data-cell-error]`)?.textContent ?? '';
    return /unbound/.test(shown('keplerSection')) && /unbound/.test(shown('keplerRun'));
  }, null);
  assert.match(await errorOf(page, 'keplerSection'), /E = .* ≥ 0/);
  await resetCell(page, 'factor');
  await keplerSectionFor(1.5);
  await assertNoNaNShown(page);
  assert.deepEqual(problems, []);
});

/** The root of `f` between `low` and `high` (f changing sign there), by bisection. */
function bisect(f, low, high) {
  for (let i = 0; i < 60; i++) {
    const mid = (low + high) / 2;
    if (Math.sign(f(mid)) === Math.sign(f(low))) low = mid;
    else high = mid;
  }
  return (low + high) / 2;
}

test('the exercises, answered in the page: right answers from independent sources pass, plausible wrong ones fail and say why', async () => {
  // The section's edge at E = 1/12: the largest x on y = 0 where Hénon & Heiles's H (1964), all momenta zero, reaches E.
  const henonHeiles = (x, y) => (x * x + y * y) / 2 + x * x * y - y ** 3 / 3;
  assert.equal((await answer(page, 'section-radius', bisect((x) => henonHeiles(x, 0) - 1 / 12, 0, 1).toFixed(4))).result, 'passed');
  let v = await answer(page, 'section-radius', '0.2887');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /both carry a factor ½/);
  v = await answer(page, 'section-radius', '0.1667');
  assert.match(v.text, /the bound on x²/);

  // The relative motion's coefficient along u = c·x1 − x2 of Σp² is |∇u|² = c² + 1, along v = y1 − y2 it is 2:
  // Devaney's μ = 9/8 (Invent. Math. 45, 1978) for c > 1, and isotropy, μ = 1, for c < 0.
  const ratio = (c) => (c * c + 1) / 2;
  assert.equal((await answer(page, 'devaney-factor', bisect((c) => ratio(c) - 9 / 8, 1, 2).toFixed(4))).result, 'passed');
  v = await answer(page, 'devaney-factor', '1.125');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /That is μ itself/);
  v = await answer(page, 'devaney-factor', '0.8819');
  assert.match(v.text, /v is the heavy direction/);
  assert.equal((await answer(page, 'isotropic-factor', bisect((c) => ratio(c) - 1, -2, 0).toFixed(3))).result, 'passed');
  v = await answer(page, 'isotropic-factor', '1');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /the ordinary two-body problem/);
  v = await answer(page, 'isotropic-factor', '0.6667');
  assert.match(v.text, /does not balance the masses/);

  // A circular orbit of H = 2p² − 1/r at E = −1/2: radius R = k/(2|E|) = 1, speed from mv²/R = k/R² with m = 1/4, T = 2πR/v.
  const [m, R] = [1 / 4, 1];
  assert.equal((await answer(page, 'isotropic-kepler-period', ((2 * Math.PI * R) / Math.sqrt(1 / (m * R))).toFixed(4))).result, 'passed');
  v = await answer(page, 'isotropic-kepler-period', '6.2832');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /the mass is not 1/);
  v = await answer(page, 'isotropic-kepler-period', '8.8858');
  assert.match(v.text, /semi-major axis/);

  // At c = 2, w = x1 + 2x2 is orthogonal to u, and p_x1² + p_x2² = 5(p_u² + p_w²): written otherwise, reordered.
  v = await answerCode(page, 'relative-hamiltonian', 'myRelativeH', 'myRelativeH = "2*p1^2 - k/sqrt(q1^2 + q0^2) + 5*p0^2"');
  assert.equal(v.result, 'passed', v.text);
  v = await answerCode(page, 'relative-hamiltonian', 'myRelativeH', 'myRelativeH = "3.25*p0^2 + 2*p1^2 - k/sqrt(q0^2 + q1^2)"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /Hamilton’s equations differ at \(q0, q1, p0, p1\)/);
  v = await answerCode(page, 'relative-hamiltonian', 'myRelativeH', 'myRelativeH = "2*p0^2 + 5*p1^2 - k/sqrt(q0^2 + q1^2)"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /Hamilton’s equations differ/);
  assert.deepEqual(problems, []);
});
