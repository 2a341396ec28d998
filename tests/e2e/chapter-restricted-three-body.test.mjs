/**
 * /restricted-three-body/: the Jacobi constant's conservation and the small
 * oscillations about L4, measured in the page, swept across their regimes
 * against references this file computes itself, independently of the book:
 * the Jacobi constant C = −2H of the start and the drift of C under this
 * suite's own classical RK4 (sweep-physics.mjs) at the page's step; the
 * roots of λ⁴ + λ² + (27/4)μ(1 − μ) = 0 in closed form (Murray & Dermott
 * §3.8) below and above Routh's μ = (1 − √(23/27))/2; the collinear points
 * from the force balance on the axis by this file's own bisection. And the
 * chapter's exercises, answered in the page.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertDrawn, assertLoadsClean, assertNoCellErrors, assertNoNaNShown, chartIn, editAndReadChecks, theoryChecks, useChapter } from './chapter-checks.mjs';
import { answer, answerCode } from './exercise-answers.mjs';
import { rk4 } from './sweep-physics.mjs';

const CHECKS = ['jacobiCheck', 'l4Checks'];
const ROUTH = (1 - Math.sqrt(23 / 27)) / 2;

/** Hamilton's equations of the rotating-frame H, written out here. */
const rate = (mu) => (t, [x, y, px, py]) => {
  const r1 = Math.hypot(x + mu, y);
  const r2 = Math.hypot(x - 1 + mu, y);
  const a = (1 - mu) / r1 ** 3;
  const b = mu / r2 ** 3;
  return [px + y, py - x, py - a * (x + mu) - b * (x - 1 + mu), -px - a * y - b * y];
};

/** C = −2H = 2Ω − v², with v = (px + y, py − x) (Murray & Dermott ch. 3). */
function jacobi(mu, [x, y, px, py]) {
  const r1 = Math.hypot(x + mu, y);
  const r2 = Math.hypot(x - 1 + mu, y);
  return x * x + y * y + (2 * (1 - mu)) / r1 + (2 * mu) / r2 - (px + y) ** 2 - (py - x) ** 2;
}

/** The start at rest 0.01 + dx from L4 that the page's cells make. */
function startNearL4(mu, [dx, dy]) {
  const [x, y] = [0.5 - mu + dx, Math.sqrt(3) / 2 + dy];
  return [x, y, -y, x];
}

/** This file's RK4 over 40 time units: the drift of C, and the closest approach as r^{3/2}/√m. */
function reference(mu, initial, dt) {
  let tau = Infinity;
  const end = rk4(rate(mu), initial, 0, dt, Math.ceil(40 / dt), (t, [x, y]) => {
    tau = Math.min(tau, Math.hypot(x + mu, y) ** 1.5 / Math.sqrt(1 - mu), Math.hypot(x - 1 + mu, y) ** 1.5 / Math.sqrt(mu));
  });
  return { C0: jacobi(mu, initial), drift: Math.abs(jacobi(mu, end) - jacobi(mu, initial)), tau };
}

/** The roots about L4 in closed form: λ² = (−1 ± √(1 − 27μ(1 − μ)))/2. */
function roots(mu) {
  const k = (27 / 4) * mu * (1 - mu);
  if (1 - 4 * k >= 0) {
    const r = Math.sqrt(1 - 4 * k);
    return { stable: true, libration: Math.sqrt((1 - r) / 2), epicycle: Math.sqrt((1 + r) / 2) };
  }
  // λ² = (−1 + i√(4k − 1))/2; Re √ of it
  const re = -0.5;
  const im = Math.sqrt(4 * k - 1) / 2;
  return { stable: false, growth: Math.sqrt((Math.hypot(re, im) + re) / 2) };
}

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

useChapter('/restricted-three-body/', (opened) => ({ page, problems } = opened));

/** Checks the four checks against this file's physics for mass ratio mu, start and step. */
function assertSweepPoint(checks, { mu, initial, dt }) {
  const [jacobiCheck] = checks.jacobiCheck;
  const [libration, epicycle, growth] = checks.l4Checks;
  const ref = reference(mu, initial, dt);
  const modes = roots(mu);

  // Jacobi: valid while Δt ≤ τ/3 at the closest approach
  if (dt <= ref.tau / 3) {
    assertAgrees(jacobiCheck);
    assert.ok(Math.abs(jacobiCheck.predicted - ref.C0) < 1e-13, `${jacobiCheck.predicted} vs ${ref.C0}`);
    assert.equal(jacobiCheck.errorFormula, 0);
    // The page's allowance is its integrator's error estimated for this step; this file's RK4,
    // a different fourth-order rule, drifts by the same order of magnitude (or both are at rounding).
    const floor = 1e-12;
    assert.ok(jacobiCheck.tolerance >= Math.max(ref.drift, floor) / 30, `allowed ${jacobiCheck.tolerance}, RK4 drift ${ref.drift}`);
    assert.ok(jacobiCheck.tolerance <= Math.max(ref.drift, floor) * 30, `allowed ${jacobiCheck.tolerance}, RK4 drift ${ref.drift}`);
  } else {
    assert.equal(jacobiCheck.verdict, 'outside', JSON.stringify(jacobiCheck));
    assert.match(jacobiCheck.reason, /resolve the closest/);
  }

  // near L4: within 0.05 and within √μ/3, where the libration swings through at most a third of a radian
  const start = [0.5 - mu, Math.sqrt(3) / 2, -Math.sqrt(3) / 2, 0.5 - mu];
  const near = Math.hypot(...initial.map((v, i) => v - start[i])) <= Math.min(0.05, Math.sqrt(mu) / 3);
  if (modes.stable && !near) {
    for (const check of [libration, epicycle]) {
      assert.equal(check.verdict, 'outside');
      assert.match(check.reason, /near L4/);
    }
  } else if (modes.stable) {
    for (const [check, omega] of [[libration, modes.libration], [epicycle, modes.epicycle]]) {
      assertAgrees(check);
      assert.ok(Math.abs(check.predicted - omega) < 1e-12, `${check.predicted} vs ${omega}`);
      // the allowance is a small part of the frequency: the check tells a wrong root, or the small-μ form's factor 2
      assert.ok(check.tolerance < 0.05 * omega, JSON.stringify(check));
    }
    // below Routh's value nothing grows, and the growth check is not shown
    assert.equal(growth, undefined);
  } else {
    for (const check of [libration, epicycle]) {
      assert.equal(check.verdict, 'outside');
      assert.match(check.reason, /above Routh/);
    }
    assertAgrees(growth);
    assert.ok(Math.abs(growth.predicted - modes.growth) < 1e-12, `${growth.predicted} vs ${modes.growth}`);
    assert.ok(growth.tolerance < 0.3 * modes.growth, JSON.stringify(growth));
  }
}

test('the page loads clean: every cell runs, every widget gets ready, nothing leaves localhost', async () => {
  await assertLoadsClean(page, problems, {
    '[data-widget="theory-check"]': 3,
    '[data-widget="equations"] .katex': 1,
    '[data-widget="chart"]': 1,
  });
  await assertNoNaNShown(page);
});

test('at μ = 0.01 the Jacobi constant is kept and the frequencies about L4 are the quartic’s roots', async () => {
  const [jacobiCheck, ...l4Checks] = await theoryChecks(page);
  const checks = { jacobiCheck: [jacobiCheck], l4Checks };
  assertSweepPoint(checks, { mu: 0.01, initial: startNearL4(0.01, [0.01, 0]), dt: 0.01 });
});

test('the zero-velocity chart and the simulator have drawn; the Lagrange points are the force balance’s roots', async () => {
  await assertDrawn(page, '[data-widget="trajectory"], [data-widget="time-plot"]', 2);
  const chart = await chartIn(page, (await page.locator('[data-widget="chart"]').getAttribute('data-label')) ?? '');
  const points = chart.series.find((s) => s.label === 'Lagrange points').values[0];
  const mu = 0.01;
  const force = (x) => x - ((1 - mu) * (x + mu)) / Math.abs(x + mu) ** 3 - (mu * (x - 1 + mu)) / Math.abs(x - 1 + mu) ** 3;
  const bisect = (a, b) => {
    for (let i = 0; i < 200; i++) {
      const m = (a + b) / 2;
      if (Math.sign(force(m)) === Math.sign(force(a))) a = m;
      else b = m;
    }
    return (a + b) / 2;
  };
  const expected = [bisect(-mu + 1e-9, 1 - mu - 1e-9), bisect(1 - mu + 1e-9, 3), bisect(-3, -mu - 1e-9), 0.5 - mu, 0.5 - mu];
  expected.forEach((x, i) => assert.ok(Math.abs(points.x[i] - x) < 1e-12, `L${i + 1}: ${points.x[i]} vs ${x}`));
  assert.ok(Math.abs(points.y[3] - Math.sqrt(3) / 2) < 1e-15);
  // every point of the zero-velocity curve lies on 2Ω = C of the start, to the grid's interpolation error
  const C = jacobi(mu, startNearL4(mu, [0.01, 0]));
  const curve = chart.series.find((s) => s.label.startsWith('zero-velocity')).values[0];
  assert.ok(curve.x.length > 10);
  curve.x.forEach((x, i) => {
    const y = curve.y[i];
    const twoOmega = x * x + y * y + (2 * (1 - mu)) / Math.hypot(x + mu, y) + (2 * mu) / Math.hypot(x - 1 + mu, y);
    assert.ok(Math.abs(twoOmega - C) < 1e-3, `(${x}, ${y}): 2Ω = ${twoOmega}, C = ${C}`);
  });
});

test('sweep of the step: Δt = 0.2 agrees with a larger allowance, Δt = 0.5 does not resolve the orbit', async () => {
  for (const dt of [0.2, 0.5]) {
    const checks = await editAndReadChecks(page, 'dt', `dt = ${dt}`, CHECKS);
    assertSweepPoint(checks, { mu: 0.01, initial: startNearL4(0.01, [0.01, 0]), dt });
  }
  await editAndReadChecks(page, 'dt', 'dt = 0.01', CHECKS);
});

test('a Hamiltonian that depends on time does not conserve C, and the Jacobi check says so', async () => {
  const forced = 'H = "(px^2 + py^2)/2 + y*px - x*py - (1 - mu)/sqrt((x + mu)^2 + y^2) - mu/sqrt((x - 1 + mu)^2 + y^2) + 0.001*x*cos(t)"';
  const checks = await editAndReadChecks(page, 'H', forced, CHECKS);
  assert.equal(checks.jacobiCheck[0].verdict, 'disagrees', JSON.stringify(checks.jacobiCheck[0]));
  await editAndReadChecks(page, 'H', 'H = "(px^2 + py^2)/2 + y*px - x*py - (1 - mu)/sqrt((x + mu)^2 + y^2) - mu/sqrt((x - 1 + mu)^2 + y^2)"', CHECKS);
});

test('sweep of μ below and above Routh’s value: the frequencies below (outside at μ = 0.001, where the start is too far for the narrow libration), the growth rate above', async () => {
  for (const mu of [0.001, 0.003, 0.02, 0.05, 0.2]) {
    assert.equal(mu < ROUTH, roots(mu).stable);
    const checks = await editAndReadChecks(page, 'mu', `mu = ${mu}`, CHECKS);
    assertSweepPoint(checks, { mu, initial: startNearL4(mu, [0.01, 0]), dt: 0.01 });
  }
  await editAndReadChecks(page, 'mu', 'mu = 0.01', CHECKS);
  await assertNoCellErrors(page);
});

test('a start far from L4 is outside the frequency checks’ validity', async () => {
  const checks = await editAndReadChecks(page, 'displacement', 'displacement = [0.04, 0]', CHECKS);
  for (const check of checks.l4Checks.slice(0, 2)) {
    assert.equal(check.verdict, 'outside');
    assert.match(check.reason, /near L4/);
  }
  await editAndReadChecks(page, 'displacement', 'displacement = [0.01, 0]', CHECKS);
});

test('the exercises, answered in the page: right answers pass, the known slips fail with their reason', async () => {
  const libration = 2 * Math.PI / roots(0.000954).libration;
  assert.equal((await answer(page, 'trojan-libration', libration.toFixed(3))).result, 'passed');
  let v = await answer(page, 'trojan-libration', '6.3036');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /epicyclic/);

  assert.equal((await answer(page, 'routh-value', ROUTH.toFixed(5))).result, 'passed');
  v = await answer(page, 'routh-value', String(1 / 27));
  assert.equal(v.result, 'failed');
  assert.match(v.text, /1 − μ/);

  // L1 of the Earth–Moon system, from the force balance by this file's bisection
  const mu = 0.012150585;
  const force = (x) => x - ((1 - mu) * (x + mu)) / Math.abs(x + mu) ** 3 - (mu * (x - 1 + mu)) / Math.abs(x - 1 + mu) ** 3;
  let [a, b] = [-mu + 1e-9, 1 - mu - 1e-9];
  for (let i = 0; i < 200; i++) [a, b] = Math.sign(force((a + b) / 2)) === Math.sign(force(a)) ? [(a + b) / 2, b] : [a, (a + b) / 2];
  assert.equal((await answer(page, 'earth-moon-l1', a.toFixed(4))).result, 'passed');
  v = await answer(page, 'earth-moon-l1', '0.82847');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /Hill/);

  const right = 'myH = "(p0^2 + p1^2)/2 + q1*p0 - q0*p1 - 0.99/sqrt((q0 + 0.01)^2 + q1^2) - 0.01/sqrt((q0 - 0.99)^2 + q1^2)"';
  assert.equal((await answerCode(page, 'rotating-hamiltonian', 'myH', right)).result, 'passed');
  const backwards = 'myH = "(p0^2 + p1^2)/2 - q1*p0 + q0*p1 - 0.99/sqrt((q0 + 0.01)^2 + q1^2) - 0.01/sqrt((q0 - 0.99)^2 + q1^2)"';
  assert.equal((await answerCode(page, 'rotating-hamiltonian', 'myH', backwards)).result, 'failed');
  assert.deepEqual(problems, []);
});
