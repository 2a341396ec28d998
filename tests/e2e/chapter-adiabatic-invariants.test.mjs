/**
 * /adiabatic-invariants/: the two theory checks (the first-order wobble of I
 * under the paper's slow ramp, and the sudden limit of a fast ramp) against
 * formulas evaluated here; the simulators draw; the ramp-rate sweep fills its
 * figure; editing the ramp rate updates the first check, which still agrees.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertDrawn, chartIn, resetCell, theoryCheckIn, useChapter, widgetsReady } from './chapter-checks.mjs';
import { answer, answerCode } from './exercise-answers.mjs';
import { typeIntoCell } from './fixture.mjs';

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

/** Widgets the page makes: two simulators (each with its views), equations, two theory checks. */
const EXPECTED = { simulator: 2, equations: 1, 'theory-check': 2 };

useChapter('/adiabatic-invariants/', (opened) => ({ page, problems } = opened), { widgets: EXPECTED });

/** The theory check in cell `id`, its numbers parsed, once it is there. */
const checkIn = (id) => theoryCheckIn(page, id, { wait: true });

/**
 * First-order adiabatic theory for ω = ω0 + εt from (q0, p0): the largest relative departure of I
 * from I0 is (|ε|/2)(1/ω_min² + |q0 p0|/(I0 ω0²)), with I0 = H/ω0.
 */
function wobble({ omega0, epsilon, q0, p0, T = 60 }) {
  const I0 = (p0 ** 2 / 2 + (omega0 ** 2 * q0 ** 2) / 2) / omega0;
  const omegaMin = Math.min(omega0, omega0 + epsilon * T);
  return {
    predicted: (Math.abs(epsilon) / 2) * (1 / omegaMin ** 2 + Math.abs(q0 * p0) / (I0 * omega0 ** 2)),
    neglected: ((2 * Math.PI + 2) * Math.abs(epsilon)) / omegaMin ** 2,
  };
}

test('both theory checks agree with formulas computed here, and the plots are drawn', async () => {
  const slow = await checkIn('slowCheck');
  assertAgrees(slow);
  assert.equal(slow.relative, 'true');
  const expected = wobble({ omega0: 4, epsilon: 0.05, q0: 1, p0: 0 });
  assert.ok(Math.abs(slow.predicted - expected.predicted) < 1e-15, `page ${slow.predicted}, test ${expected.predicted}`);
  assert.ok(Math.abs(slow.errorFormula - expected.neglected) < 1e-15);
  // The first-order formula is far better than its allowance: within 0.1 % of the measured wobble.
  assert.ok(Math.abs(slow.measured / slow.predicted - 1) < 1e-3, JSON.stringify(slow));

  const fast = await checkIn('fastCheck');
  assertAgrees(fast);
  assert.equal(fast.relative, 'false');
  const [w0, w1, tau] = [4, 8, 0.05];
  assert.equal(fast.predicted, (w1 / w0 + w0 / w1) / 2 - 1); // the sudden limit, 1/4
  const tauSquared = (((w1 - w0) ** 2 * (w0 ** 2 + 4 * w0 * w1 + w1 ** 2)) / (36 * w0 * w1)) * tau ** 2;
  // The formula's error: the τ² term and those beyond it, smaller by (ω_max τ)² each.
  assert.ok(Math.abs(fast.errorFormula - tauSquared * (1 + (w1 * tau) ** 2)) < 1e-15);
  // The departure from the sudden limit is the τ² term, to within a few per cent of it.
  assert.ok(Math.abs(fast.predicted - fast.measured - tauSquared) < 0.05 * tauSquared, JSON.stringify(fast));

  await assertDrawn(page, '[data-widget="simulator"]', 2);

  const equations = await page.locator('[data-widget="equations"] .katex').count();
  assert.ok(equations > 0, 'H is typeset');
  assert.deepEqual(problems, []);
});

test('the sweep over ramp rates fills its figure: linear ramp ∝ ε, smooth ramp exponentially small', async () => {
  // 17 linear-ramp points and 16 smooth-ramp points, drawn as the sweep proceeds
  const label = 'Change of the action against the ramp rate';
  await page.waitForFunction(
    (label) => {
      const series = document.querySelector(`[data-widget="chart"][data-label="${label}"]`)?.chart?.series ?? [];
      return series.filter((s) => s.kind === 'dots').reduce((n, s) => n + s.curves[0].x.length, 0) === 17 + 16;
    },
    label,
  );
  const { series } = await chartIn(page, label);
  const points = (name) => {
    const { x, y } = series.find((s) => s.label === name).values[0];
    return x.map((e, i) => [e, y[i]]);
  };
  // The linear ramp's change grows with ε, by more than two decades over the sweep (the slope-1 law and
  // the sudden limit: from about 3·10⁻⁴ to about 0.3) ...
  const linear = points('linear ramp');
  assert.equal(linear.length, 17);
  assert.ok(linear[16][1] > 100 * linear[0][1], JSON.stringify(linear));
  // ... and the smooth ramp's first point lies more than five decades below the linear ramp's at a similar rate
  const smooth = points('smooth (tanh) ramp');
  assert.equal(smooth.length, 16);
  assert.ok(Math.abs(Math.log10(smooth[0][0] / linear[9][0])) < 0.2, `rates ${smooth[0][0]}, ${linear[9][0]}`);
  assert.ok(smooth[0][1] < 1e-5 * linear[9][1], `smooth ${smooth[0]}, linear ${linear[9]}`);
  assert.deepEqual(problems, []);
});

test('editing the ramp rate re-runs the first check, which still agrees', async () => {
  const before = await checkIn('slowCheck');
  await typeIntoCell(page, 'params', 'params = ({omega0: 4, epsilon: 0.2})');
  await page.waitForFunction(
    (old) => {
      const w = document.querySelector('[data-cell="slowCheck"] [data-widget="theory-check"]');
      return w && w.dataset.predicted !== old;
    },
    before.predicted.toString(),
  );
  const after = await checkIn('slowCheck');
  assertAgrees(after);
  const expected = wobble({ omega0: 4, epsilon: 0.2, q0: 1, p0: 0 });
  assert.ok(Math.abs(after.predicted - expected.predicted) < 1e-15, `page ${after.predicted}, test ${expected.predicted}`);
  assert.ok(after.measured > 3.5 * before.measured, 'the wobble grows with ε');
  await widgetsReady(page, EXPECTED);
  assert.deepEqual(problems, []);
  await resetCell(page, 'params');
});

test('the exercises, answered in the page: right answers computed here pass, plausible wrong ones fail and say why', async () => {
  // I = E/ω is the adiabatic invariant (Landau & Lifshitz §49): E₀ = 8 at ω = 4 becomes 8 · 7/4 at ω = 7.
  let v = await answer(page, 'energy-after-ramp', String((8 * 7) / 4));
  assert.equal(v.result, 'passed', v.text);
  v = await answer(page, 'energy-after-ramp', '8');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /energy is not conserved/);
  v = await answer(page, 'energy-after-ramp', String((8 * 49) / 16));
  assert.equal(v.result, 'failed');
  assert.match(v.text, /keeps the amplitude of q/);
  // The sudden limit: q and p do not move, so at p = 0 the action goes as H/ω = ωq²/2, by ω₁/ω₀ (Landau & Lifshitz §49–50).
  assert.equal((await answer(page, 'jump-at-turning-point', String(8 / 4))).result, 'passed');
  v = await answer(page, 'jump-at-turning-point', '1');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /adiabatic invariant, kept under a slow change/);
  v = await answer(page, 'jump-at-turning-point', String((8 / 4) ** 2));
  assert.match(v.text, /ratio of the energies/);
  // Parametric resonance is strongest at twice the frequency, γ = 2ω₀ (Landau & Lifshitz §27).
  assert.equal((await answer(page, 'fastest-modulation', String(2 * 4))).result, 'passed');
  v = await answer(page, 'fastest-modulation', '4');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /second, narrower resonance/);
  v = await answer(page, 'fastest-modulation', (8 / (2 * Math.PI)).toFixed(4));
  assert.match(v.text, /cycles per unit time/);
  // ω(t) = 6 − t/20, the same ramp written otherwise, passes; a frozen frequency and a rising one fail.
  v = await answerCode(page, 'falling-frequency', 'myRamp', 'myRamp = "(6 - t/20)^2*q^2/2 + p^2/2"');
  assert.equal(v.result, 'passed', v.text);
  v = await answerCode(page, 'falling-frequency', 'myRamp', 'myRamp = "p^2/2 + 18*q^2"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /Hamilton’s equations differ at t = [\d.]+, \(q, p\)/);
  v = await answerCode(page, 'falling-frequency', 'myRamp', 'myRamp = "p^2/2 + (6 + 0.05*t)^2*q^2/2"');
  assert.equal(v.result, 'failed');
  assert.deepEqual(problems, []);
});
