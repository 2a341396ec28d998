/**
 * /nonlinear-oscillator/: the frequency measured in the page against the
 * second-order formula of Landau & Lifshitz §28 and against the exact
 * frequency this test computes itself from the period integral; the
 * frequency–amplitude plot; an edit of the amplitude b.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { cell, openChapter, openSite, typeIntoCell } from './fixture.mjs';

const PARAMS = { omega0: 10, alpha: -2, beta: -3 };

/** ω = ω0 + (3β/2ω0 − 15α²/4ω0³) b², and the check's allowance for the terms it leaves out. */
function formula({ omega0, alpha, beta }, b) {
  const omega2 = (3 * beta) / (2 * omega0) - (15 * alpha ** 2) / (4 * omega0 ** 3);
  const tolerance = Math.abs(((2 * alpha * omega2) / omega0 ** 2) * b ** 3) + (omega2 * b ** 2) ** 2 / omega0;
  return { omega: omega0 + omega2 * b ** 2, tolerance };
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

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

const allReady = () =>
  page.waitForFunction(() => [...document.querySelectorAll('[data-widget]')].every((w) => w.hasAttribute('data-ready')), null, {
    timeout: 30_000,
  });

const checks = () =>
  page.$$eval('[data-widget="theory-check"]', (all) =>
    all.map((w) => ({ ...w.dataset, measured: +w.dataset.measured, predicted: +w.dataset.predicted, tolerance: +w.dataset.tolerance })),
  );

/** The check agrees, and the agreement holds when recomputed here from its numbers. */
function assertAgrees(check) {
  assert.equal(check.agrees, 'true', JSON.stringify(check));
  const difference = Math.abs(check.measured - check.predicted);
  const error = check.relative === 'true' ? difference / Math.abs(check.predicted) : difference;
  assert.ok(error <= check.tolerance, JSON.stringify(check));
}

function assertChecks(b) {
  return checks().then(([frequency, peakVsCrossings]) => {
    const { omega, tolerance } = formula(PARAMS, b);
    const exact = exactOmega(PARAMS, b);
    assertAgrees(frequency);
    assert.equal(frequency.relative, 'false');
    assert.ok(Math.abs(frequency.predicted - omega) < 1e-12, `${frequency.predicted} vs ${omega}`);
    assert.ok(Math.abs(frequency.tolerance - tolerance) < 1e-12);
    // The spectral peak is within 5e-5 of the exact frequency, far inside the formula's allowance.
    assert.ok(Math.abs(frequency.measured - exact) < 5e-5 * exact, `${frequency.measured} vs exact ${exact}`);
    assertAgrees(peakVsCrossings);
    assert.equal(peakVsCrossings.relative, 'true');
    assert.equal(peakVsCrossings.tolerance, 1e-4);
    // The zero-crossing frequency is the exact one to about 1e-7.
    assert.ok(Math.abs(peakVsCrossings.predicted - exact) < 1e-6 * exact, `${peakVsCrossings.predicted} vs exact ${exact}`);
    return { frequency, exact };
  });
}

before(async () => {
  site = await openSite();
  ({ page, problems } = await openChapter(site, '/nonlinear-oscillator/'));
  await allReady();
});
after(async () => {
  await page?.close();
  await site?.close();
});

test('the page loads clean: every cell runs, every widget gets ready, nothing leaves localhost', async () => {
  assert.equal(await page.locator('[data-cell-error]:visible').count(), 0);
  assert.equal(await page.locator('[data-widget="theory-check"]').count(), 2);
  assert.equal(await page.locator('[data-widget="simulator"]').count(), 1);
  assert.equal(await page.locator('[data-widget="equations"] .katex').count(), 1);
  assert.deepEqual(problems, []);
});

test('the frequency agrees with ω0 + (3β/2ω0 − 15α²/4ω0³)b² = 9.535, and with the exact 9.5389', async () => {
  const { frequency, exact } = await assertChecks(1);
  assert.ok(Math.abs(frequency.predicted - 9.535) < 1e-12);
  assert.ok(Math.abs(exact - 9.538923) < 1e-6, `exact ${exact}`);
  // The residual is 0.0039, ten times inside the allowance of 0.040.
  assert.ok(Math.abs(frequency.measured - frequency.predicted - 0.0039) < 1e-4);
});

test('the views have drawn, with the measured peak near the theory marker', async () => {
  // Once the record holds a few periods, the spectrum's strongest peak sits at the theory marker.
  const expected = formula(PARAMS, 1).omega / (2 * Math.PI);
  await page.waitForFunction(
    (f) => Math.abs((document.querySelector('[data-widget="spectrum"]')?.peaks?.[0]?.frequency ?? 0) - f) < 0.05,
    expected,
    { timeout: 20_000 },
  );
  // Every plot has drawn something besides its background (on one of its layers).
  const drawn = await page.$$eval('[data-widget="time-plot"], [data-widget="phase-portrait"], [data-widget="spectrum"]', (plots) =>
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
  assert.equal(drawn.length, 3, JSON.stringify(drawn));
  for (const { kind, pixels } of drawn) assert.ok(pixels > 500, `${kind} drew ${pixels} pixels`);
  const peak = await page.$eval('[data-widget="spectrum"]', (v) => v.peaks[0].frequency);
  assert.ok(Math.abs(peak - expected) < 0.05, `peak ${peak}`);
  // The frequency–amplitude plot: a formula curve and measured points up to the escape at b = 2.648.
  const svg = page.locator('svg[aria-label^="Frequency against amplitude"]');
  assert.equal(await svg.locator('path').count(), 1);
  assert.ok((await svg.locator('circle').count()) >= 25);
  assert.match((await svg.textContent()) ?? '', /escape at b = 2\.648/);
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
    { timeout: 15_000 },
  );
  await allReady();
  await assertChecks(0.5);
  assert.equal(await cell(page, 'initial').locator('[data-cell-output]').textContent(), 'initial = [0.5, 0]');
  assert.equal(await page.locator('[data-cell-error]:visible').count(), 0);
  assert.deepEqual(problems, []);
});
