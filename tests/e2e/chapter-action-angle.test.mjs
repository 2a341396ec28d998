/**
 * /action-angle/: the symplectic condition of the simulated flow map, the
 * pendulum's action and its frequency, measured in the page and swept
 * across their regimes against references this file computes itself,
 * independently of the book: the action (1/2π)∮p dq by this file's own
 * quadrature of the loop, with sin(q/2) = k sin φ, so that
 * J = (4ωk²/π)∫ cos²φ / √(1 − k² sin²φ) dφ over a period of a smooth
 * integrand, summed by the trapezoid rule; the frequency 2π/T with
 * T = 4K(k)/ω by the same quadrature of K (Landau & Lifshitz §11, §50);
 * the flow's Jacobian from this suite's own RK4 (sweep-physics.mjs). And
 * the chapter's exercises, answered in the page.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertLoadsClean, assertNoCellErrors, assertNoNaNShown, assertSumOfTerms, chartIn, editAndReadChecks, theoryChecks, useChapter } from './chapter-checks.mjs';
import { answer, answerCode } from './exercise-answers.mjs';
import { rk4 } from './sweep-physics.mjs';

const CHECKS = ['symplecticCheckCell', 'actionCheck', 'frequencyCheck'];

/** The trapezoid rule over one period [−π/2, π/2) of a smooth periodic integrand: exact to rounding with 400 points. */
const periodic = (f, n = 400) => (Math.PI / n) * Array.from({ length: n }, (_, i) => f(-Math.PI / 2 + (Math.PI * i) / n)).reduce((a, b) => a + b, 0);

/** The pendulum H = p²/2 − ω² cos q released at rest from q0: its action and its frequency, by this file's quadrature. */
function pendulumHere(q0, omega = 1) {
  const k = Math.sin(Math.abs(q0) / 2);
  const root = (phi) => Math.sqrt(1 - k * k * Math.sin(phi) ** 2);
  const action = ((4 * omega * k * k) / Math.PI) * periodic((phi) => Math.cos(phi) ** 2 / root(phi));
  // K(k) = ∫₀^{π/2} dφ/√(1 − k² sin²φ), half the integral over the period
  const K = periodic((phi) => 1 / root(phi)) / 2;
  return { action, frequency: (Math.PI * omega) / (2 * K) };
}

/** This file's flow map of the pendulum over T by RK4 at step h, and the defect det M − 1 of its Jacobian by central differences. */
function defectHere(x0, { T = 10, h = 0.005, epsilon = 1e-4, omega = 1 } = {}) {
  const rate = (t, [q, p]) => [p, -omega * omega * Math.sin(q)];
  const flow = (x) => rk4(rate, x, 0, h, Math.round(T / h));
  const column = (j) => {
    const plus = [...x0];
    const minus = [...x0];
    plus[j] += epsilon;
    minus[j] -= epsilon;
    const [a, b] = [flow(plus), flow(minus)];
    return [(a[0] - b[0]) / (2 * epsilon), (a[1] - b[1]) / (2 * epsilon)];
  };
  const [c0, c1] = [column(0), column(1)];
  return Math.abs(c0[0] * c1[1] - c1[0] * c0[1] - 1);
}

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

useChapter('/action-angle/', (opened) => ({ page, problems } = opened));

test('the page loads clean: every cell runs, the simulator, the chart and three checks get ready', async () => {
  await assertLoadsClean(page, problems, {
    '[data-widget="theory-check"]': 3,
    '[data-widget="simulator"]': 1,
    '[data-widget="chart"]': 1,
  });
  await assertNoNaNShown(page);
});

/** The three checks at a start against this file's references; `libration` whether it swings. */
function assertSweepPoint(checks, { q0, libration, hamiltonian = true }) {
  const [symplectic] = checks.symplecticCheckCell;
  const [action] = checks.actionCheck;
  const [frequency] = checks.frequencyCheck;
  // every Hamiltonian flow is canonical, whatever the start and whether H depends on t
  assertAgrees(symplectic);
  assertSumOfTerms(symplectic);
  assert.equal(symplectic.predicted, 0);
  if (!libration) {
    for (const check of [action, frequency]) {
      assert.equal(check.verdict, 'outside', JSON.stringify(check));
      assert.match(check.reason, /over the top/);
    }
    return;
  }
  const here = pendulumHere(q0);
  if (!hamiltonian) {
    // a driven pendulum's loop is not the closed form's: the action check must see it
    assert.equal(action.verdict, 'disagrees', JSON.stringify(action));
    return;
  }
  for (const [check, value] of [[action, here.action], [frequency, here.frequency]]) {
    assertAgrees(check);
    assertSumOfTerms(check);
    assert.ok(Math.abs(check.predicted - value) < 1e-10 * value, `${check.predicted} vs ${value}`);
    // the allowance is a small part of the value: the check would tell the harmonic estimate apart
    assert.ok(check.tolerance < 1e-3 * value, JSON.stringify(check));
  }
}

test('at q₀ = 2 the flow map is canonical, and the action and frequency are the closed forms’', async () => {
  const [symplecticCheckCell, actionCheck, frequencyCheck] = await theoryChecks(page);
  assertSweepPoint({ symplecticCheckCell: [symplecticCheckCell], actionCheck: [actionCheck], frequencyCheck: [frequencyCheck] }, { q0: 2, libration: true });
  // this file's RK4 at half the page's step has a defect of the same small size as the page measures
  const reference = defectHere([2, 0]);
  assert.ok(symplecticCheckCell.measured < 1e-5 && reference < 1e-5, `page ${symplecticCheckCell.measured}, here ${reference}`);
});

test('sweep of the amplitude: small, wide and near the separatrix agree; a rotation is outside the action and frequency checks', async () => {
  for (const q0 of [0.5, 3]) {
    const checks = await editAndReadChecks(page, 'q0', `q0 = ${q0}`, CHECKS);
    assertSweepPoint(checks, { q0, libration: true });
  }
  await editAndReadChecks(page, 'q0', 'q0 = 2', CHECKS);
  const rotating = await editAndReadChecks(page, 'initial', 'initial = [0, 2.5]', CHECKS);
  assertSweepPoint(rotating, { q0: NaN, libration: false });
  await editAndReadChecks(page, 'initial', 'initial = [q0, 0]', CHECKS);
});

test('a driven pendulum: its flow is still canonical, and the action check sees that the loop is not the free pendulum’s', async () => {
  const checks = await editAndReadChecks(page, 'H', 'H = "p^2/2 - omega^2*cos(q) + 0.1*q*cos(0.8*t)"', CHECKS);
  assertSweepPoint(checks, { q0: 2, libration: true, hamiltonian: false });
  await editAndReadChecks(page, 'H', 'H = "p^2/2 - omega^2*cos(q)"', CHECKS);
});

test('sweep of the step: at Δt = 0.05 every check still agrees, with a symplectic allowance grown with RK 3/8’s defect', async () => {
  const [before] = (await theoryChecks(page)).filter((c) => c.text.includes('canonical'));
  const checks = await editAndReadChecks(page, 'dt', 'dt = 0.05', CHECKS);
  assertSweepPoint(checks, { q0: 2, libration: true });
  assert.ok(checks.symplecticCheckCell[0].errorIntegration > before.errorIntegration, `${checks.symplecticCheckCell[0].errorIntegration} vs ${before.errorIntegration}`);
  await editAndReadChecks(page, 'dt', 'dt = 0.01', CHECKS);
  await assertNoCellErrors(page);
});

test('the frequency chart: the simulation’s points lie on the exact curve, which tends to ω as J → 0 and falls toward the separatrix', async () => {
  const chart = await chartIn(page, (await page.locator('[data-widget="chart"]').getAttribute('data-label')) ?? '');
  const measured = chart.series.find((s) => s.label.startsWith('simulation')).values[0];
  assert.equal(measured.x.length, 8);
  const amplitudes = [0.5, 1, 1.5, 2, 2.5, 2.8, 3, 3.1];
  amplitudes.forEach((a, i) => {
    const here = pendulumHere(a);
    assert.ok(Math.abs(measured.x[i] - here.action) < 1e-9, `J at ${a}: ${measured.x[i]} vs ${here.action}`);
    // four periods' crossings at Δt = 0.01, interpolated: the period to 10⁻⁴ of itself
    assert.ok(Math.abs(measured.y[i] - here.frequency) < 1e-3 * here.frequency, `ω at ${a}: ${measured.y[i]} vs ${here.frequency}`);
  });
});

test('the exercises, answered in the page: right answers from this file’s quadrature pass, the known slips fail with their reason', async () => {
  assert.equal((await answer(page, 'oscillator-action', '0.5')).result, 'passed');
  let v = await answer(page, 'oscillator-action', '3.1416');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /over 2π/);
  assert.equal((await answer(page, 'wide-swing-frequency', pendulumHere(2).frequency.toFixed(4))).result, 'passed');
  v = await answer(page, 'wide-swing-frequency', '0.75');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /by luck/);
  assert.equal((await answer(page, 'pendulum-action', pendulumHere(1).action.toFixed(5))).result, 'passed');
  v = await answer(page, 'pendulum-action', '0.4597');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /harmonic/);
  assert.equal((await answerCode(page, 'action-angle-oscillator', 'myH', 'myH = "2*p0"')).result, 'passed');
  assert.equal((await answerCode(page, 'action-angle-oscillator', 'myH', 'myH = "p0/2"')).result, 'failed');
  assert.deepEqual(problems, []);
});
