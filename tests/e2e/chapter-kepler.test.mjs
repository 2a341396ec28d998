/**
 * /kepler/: the period measured in the page against Kepler's third law and
 * the conservation of L and of the direction of the Laplace–Runge–Lenz
 * vector, with the orbit's elements computed here from the initial state;
 * the live readouts; an edit of k; the chapter's exercises, answered.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertDrawn, assertLoadsClean, assertNoCellErrors, theoryChecks, useChapter, widgetsReady } from './chapter-checks.mjs';
import { answer, answerCode } from './exercise-answers.mjs';
import { typeIntoCell } from './fixture.mjs';
// The orbit's elements (Landau & Lifshitz §15), written out once for the e2e suite.
import { keplerElements as elements } from './sweep-physics.mjs';

const INITIAL = [-3, -3, 3, 3, 2, -3, -2, 3];

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

async function assertChecks(k) {
  const orbit = elements(INITIAL, k);
  const [period, momentum, lenz] = await theoryChecks(page);
  for (const check of [period, momentum, lenz]) assertAgrees(check);
  assert.equal(period.relative, 'true');
  assert.ok(Math.abs(period.predicted - orbit.T) < 1e-12 * orbit.T, `${period.predicted} vs ${orbit.T}`);
  // Kepler's third law and the conservation laws are exact: only the integrator's and the
  // measurement's errors are allowed, (Δt/τp)⁴ per revolution and rounding, below 1e-9 for these orbits.
  for (const check of [period, momentum, lenz]) assert.equal(check.errorFormula, 0);
  assert.ok(period.tolerance > 1e-12 && period.tolerance < 1e-9, String(period.tolerance));
  assert.ok(Math.abs(momentum.predicted - orbit.L) < 1e-12, `${momentum.predicted} vs ${orbit.L}`);
  assert.equal(lenz.relative, 'false');
  assert.ok(Math.abs(lenz.predicted - orbit.angle) < 1e-12, `${lenz.predicted} vs ${orbit.angle}`);
  return orbit;
}

useChapter('/kepler/', (opened) => ({ page, problems } = opened));

test('the page loads clean: every cell runs, every widget gets ready, nothing leaves localhost', async () => {
  await assertLoadsClean(page, problems, {
    '[data-widget="theory-check"]': 3,
    '[data-widget="equations"] .katex': 1,
  });
});

test('the period agrees with Kepler’s third law, T = 2.9395, and L and the direction of A are kept', async () => {
  const orbit = await assertChecks(500);
  assert.ok(Math.abs(orbit.T - 2.93951) < 1e-5);
  assert.ok(Math.abs(orbit.a - 7.5929) < 1e-4);
  assert.equal(orbit.L, 30);
});

test('the stars have drawn their orbits and the readouts follow the simulation', async () => {
  await assertDrawn(page, '[data-widget="trajectory"], [data-widget="time-plot"]', 2);

  // The readout table: its time advances, and the energy and L stay at their initial values.
  // Widgets out of view pause, so the reader's view goes to the stars first.
  await page.locator('[data-widget="simulator"]').first().scrollIntoViewIfNeeded();
  const table = page.locator('table:has(caption)');
  const first = await table.locator('caption').textContent();
  await page.waitForFunction((before) => document.querySelector('table caption')?.textContent !== before, first);
  const rows = await table.locator('tr').evaluateAll((trs) => trs.slice(1).map((tr) => [...tr.cells].map((c) => c.textContent.trim())));
  const byName = Object.fromEntries(rows.map(([name, ...values]) => [name, values.map(Number)]));
  const orbit = elements(INITIAL, 500);
  assert.ok(Math.abs(byName['energy H'][0] - orbit.E) < 1e-8);
  assert.ok(Math.abs(byName['energy H'][1] - orbit.E) < 1e-6);
  assert.ok(Math.abs(byName['angular momentum L'][1] - 30) < 1e-6);
  assert.ok(Math.abs(byName['Px = px1 + px2'][1]) < 1e-9);
});

test('editing k re-runs the checks, which still agree (k = 400)', async () => {
  await typeIntoCell(page, 'k', 'k = 400');
  const { T } = elements(INITIAL, 400);
  await page.waitForFunction(
    (expected) => {
      const check = document.querySelector('[data-widget="theory-check"]');
      return check && Math.abs(Number(check.getAttribute('data-predicted')) - expected) < 1e-9;
    },
    T,
  );
  await widgetsReady(page);
  const orbit = await assertChecks(400);
  assert.ok(Math.abs(orbit.T - 4.5708) < 1e-4);
  await assertNoCellErrors(page);
  assert.deepEqual(problems, []);
});

test('the exercises: right answers pass, plausible wrong ones fail and say why', async () => {
  // Kepler's third law from the orbit's elements at k = 400 (Landau & Lifshitz §15).
  assert.equal((await answer(page, 'period-at-k-400', elements(INITIAL, 400).T.toFixed(4))).result, 'passed');
  let v = await answer(page, 'period-at-k-400', '2.9395');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /the period at k = 500/);
  v = await answer(page, 'period-at-k-400', String(elements(INITIAL, 500).T * Math.sqrt(500 / 400)));
  assert.match(v.text, /the orbit grows too/);

  // |A| = μke, from A = p × L − μk r/r at the start (Goldstein §3.9).
  const { e } = elements(INITIAL, 500);
  assert.equal((await answer(page, 'lenz-length', String(0.25 * 500 * e))).result, 'passed');
  v = await answer(page, 'lenz-length', '232');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /One sign is flipped/);
  v = await answer(page, 'lenz-length', '145.5');
  assert.match(v.text, /reduced mass μ = 1\/4/);

  // E = p²/2μ − k/r = 0 with p² = 13, μ = 1/4, r = 6√2 (Landau & Lifshitz §15).
  const unbinding = (13 / (2 * 0.25)) * 6 * Math.SQRT2;
  assert.equal((await answer(page, 'unbinding-strength', unbinding.toFixed(1))).result, 'passed');
  v = await answer(page, 'unbinding-strength', String(unbinding / 2));
  assert.equal(v.result, 'failed');
  assert.match(v.text, /That is half of it/);
  v = await answer(page, 'unbinding-strength', String(2 * unbinding));
  assert.match(v.text, /balances a circular orbit/);

  // The relative motion's H, p²/2μ − k/r with μ = 1/4, written otherwise and plus a constant.
  v = await answerCode(page, 'relative-hamiltonian', 'relativeH', 'relativeH = "2*p1^2 + 2*p0^2 - k/sqrt(q1^2 + q0^2) + 3"');
  assert.equal(v.result, 'passed', v.text);
  v = await answerCode(page, 'relative-hamiltonian', 'relativeH', 'relativeH = "p0^2 + p1^2 - k/sqrt(q0^2 + q1^2)"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /2 of 2 checks failed/);
  assert.match(v.text, /Hamilton’s equations differ at \(q0, q1, p0, p1\)/);
  assert.match(v.text, /not back where it began/);
  v = await answerCode(page, 'relative-hamiltonian', 'relativeH', 'relativeH = "2*(p0^2 + p1^2) + k/sqrt(q0^2 + q1^2)"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /Hamilton’s equations differ/);
  assert.deepEqual(problems, []);
});
