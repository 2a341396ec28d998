/**
 * /nonlinear-oscillator/: the frequency measured in the page against the
 * second-order formula of Landau & Lifshitz §28 and against the exact
 * frequency this test computes itself from the period integral; the
 * frequency–amplitude plot; an edit of the amplitude b.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertDrawn, chartIn, assertLoadsClean, assertNoCellErrors, theoryChecks, useChapter, widgetsReady } from './chapter-checks.mjs';
import { cell, typeIntoCell } from './fixture.mjs';

const PARAMS = { omega0: 10, alpha: -2, beta: -3 };

/** ω = ω0 + (3β/2ω0 − 15α²/4ω0³) b², and the check's formula error: the b³ term and an estimate of the b⁴ term. */
function formula({ omega0, alpha, beta }, b) {
  const omega2 = (3 * beta) / (2 * omega0) - (15 * alpha ** 2) / (4 * omega0 ** 3);
  const neglected = Math.abs(((2 * alpha * omega2) / omega0 ** 2) * b ** 3) + (omega2 * b ** 2) ** 2 / omega0;
  return { omega: omega0 + omega2 * b ** 2, neglected };
}

/**
 * The exact angular frequency of the motion released at rest from q = b > 0:
 * T = 2∫ dq / √(2(E − V)) between the turning points, with q = c + d sin θ
 * taking out the endpoint singularities (midpoint rule, spectrally accurate).
 */
function exactOmega({ omega0, alpha, beta }, b) {
  const V = (q) => (omega0 ** 2 * q ** 2) / 2 + alpha * q ** 3 + beta * q ** 4;
  const E = V(b);
  let lo = -b;
  while (V(lo) < E) lo *= 1.1;
  let hi = 0;
  for (let i = 0; i < 200; i++) {
    const mid = (lo + hi) / 2;
    if (V(mid) < E) hi = mid;
    else lo = mid;
  }
  const c = (b + lo) / 2;
  const d = (b - lo) / 2;
  const n = 20000;
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const theta = -Math.PI / 2 + ((i + 0.5) * Math.PI) / n;
    const q = c + d * Math.sin(theta);
    sum += (d * Math.cos(theta)) / Math.sqrt(2 * (E - V(q)));
  }
  const period = (2 * sum * Math.PI) / n;
  return (2 * Math.PI) / period;
}

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

function assertChecks(b) {
  return theoryChecks(page).then(([frequency, peakVsCrossings]) => {
    const { omega, neglected } = formula(PARAMS, b);
    const exact = exactOmega(PARAMS, b);
    assertAgrees(frequency);
    assert.equal(frequency.relative, 'false');
    assert.ok(Math.abs(frequency.predicted - omega) < 1e-12, `${frequency.predicted} vs ${omega}`);
    assert.ok(Math.abs(frequency.errorFormula - neglected) < 1e-12);
    // The spectral peak is within its own stated errors (leakage, integration) of the exact frequency.
    assert.ok(Math.abs(frequency.measured - exact) <= frequency.errorMeasurement + frequency.errorIntegration, `${frequency.measured} vs exact ${exact}`);
    assertAgrees(peakVsCrossings);
    assert.equal(peakVsCrossings.relative, 'true');
    // Two measurements of one frequency: no formula, no integrator error, only the measurements' own.
    assert.equal(peakVsCrossings.errorFormula, 0);
    assert.ok(peakVsCrossings.errorMeasurement > 0 && peakVsCrossings.errorMeasurement < 1e-4, String(peakVsCrossings.errorMeasurement));
    // The zero-crossing frequency is the exact one to about 1e-7.
    assert.ok(Math.abs(peakVsCrossings.predicted - exact) < 1e-6 * exact, `${peakVsCrossings.predicted} vs exact ${exact}`);
    return { frequency, exact };
  });
}

useChapter('/nonlinear-oscillator/', (opened) => ({ page, problems } = opened));

test('the page loads clean: every cell runs, every widget gets ready, nothing leaves localhost', async () => {
  await assertLoadsClean(page, problems, {
    '[data-widget="theory-check"]': 2,
    '[data-widget="simulator"]': 1,
    '[data-widget="equations"] .katex': 1,
  });
});

test('the frequency agrees with ω0 + (3β/2ω0 − 15α²/4ω0³)b² = 9.535, and with the exact 9.5389', async () => {
  const { frequency, exact } = await assertChecks(1);
  assert.ok(Math.abs(frequency.predicted - 9.535) < 1e-12);
  assert.ok(Math.abs(exact - 9.538923) < 1e-6, `exact ${exact}`);
  // The residual is 0.0039, ten times inside the formula's error of 0.040.
  assert.ok(Math.abs(frequency.measured - frequency.predicted - 0.0039) < 1e-4);
});

test('the views have drawn, with the measured peak near the theory marker', async () => {
  // Once the record holds a few periods, the spectrum's strongest peak sits at the theory marker.
  const expected = formula(PARAMS, 1).omega / (2 * Math.PI);
  // Widgets out of view pause: the reader looks at the oscillator while its record fills.
  await page.locator('[data-widget="simulator"]').first().scrollIntoViewIfNeeded();
  await page.waitForFunction(
    (f) => Math.abs((document.querySelector('[data-widget="spectrum"]')?.peaks?.[0]?.frequency ?? 0) - f) < 0.05,
    expected,
  );
  // Every plot has drawn something besides its background (on one of its layers).
  await assertDrawn(page, '[data-widget="time-plot"], [data-widget="phase-portrait"], [data-widget="spectrum"]', 3);
  const peak = await page.$eval('[data-widget="spectrum"]', (v) => v.peaks[0].frequency);
  assert.ok(Math.abs(peak - expected) < 0.05, `peak ${peak}`);
  // The frequency–amplitude plot: a formula curve and measured points up to the escape at b = 2.648.
  const figure = await chartIn(page, 'Frequency against amplitude: simulation and formula');
  assert.equal(figure.series.filter((s) => s.kind === 'line').reduce((n, s) => n + s.curves, 0), 1);
  assert.ok(figure.series.filter((s) => s.kind === 'dots').reduce((n, s) => n + s.points, 0) >= 25);
  assert.match(figure.description, /escape at b = 2\.648/);
});

test('editing b re-runs the checks, which still agree (b = 0.5)', async () => {
  await typeIntoCell(page, 'b', 'b = 0.5');
  const { omega } = formula(PARAMS, 0.5);
  const exact = exactOmega(PARAMS, 0.5);
  await page.waitForFunction(
    ([formulaValue, exactValue]) => {
      const [first, second] = [...document.querySelectorAll('[data-widget="theory-check"]')].map((w) => Number(w.getAttribute('data-predicted')));
      return Math.abs(first - formulaValue) < 1e-12 && Math.abs(second - exactValue) < 1e-5;
    },
    [omega, exact],
  );
  await widgetsReady(page);
  await assertChecks(0.5);
  assert.equal(await cell(page, 'initial').locator('[data-cell-output]').textContent(), 'initial = [0.5, 0]');
  await assertNoCellErrors(page);
  assert.deepEqual(problems, []);
});
