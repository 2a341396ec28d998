/**
 * /how-the-simulator-integrates/: the method comparison runs the pendulum
 * p²/2 − cos q from q = 2 under RK 3/8, Störmer–Verlet, Yoshida 4, the
 * implicit midpoint rule and Dormand–Prince in a worker, and the chapter's
 * theory checks agree with the theory: the measured orders 4, 2, 4, 2
 * against the exact period 4K(sin 1) (Landau & Lifshitz §11), RK 3/8's
 * energy error growing like t¹, Verlet's bounded at the size its modified
 * Hamiltonian gives (Hairer, Lubich & Wanner, Geometric Numerical
 * Integration, ch. IX). The figures carry data; editing dt or the order
 * study's steps updates them, and the checks say "outside validity" where
 * the theory's premise fails.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertLoadsClean, assertNoNaNShown, chartIn, editAndReadChecks, theoryChecks, useChapter } from './chapter-checks.mjs';
import { answer, answerCode } from './exercise-answers.mjs';

const COMPARISON = '[data-widget="method-comparison"]';
const ENERGY = 'Relative energy error against time';
const PORTRAITS = 'Phase portraits of the long run';
/** The exact period of the pendulum from q = 2: 4K(sin 1), K by the AGM. */
const PERIOD = (() => {
  let [a, b] = [1, Math.sqrt(1 - Math.sin(1) ** 2)];
  for (let i = 0; i < 10; i++) [a, b] = [(a + b) / 2, Math.sqrt(a * b)];
  return (4 * Math.PI) / (2 * a);
})();
const ORDER = `Global error at T = ${Number(PERIOD.toPrecision(6))} against the step`;

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

useChapter('/how-the-simulator-integrates/', (opened) => ({ page, problems } = opened), { widgets: { 'theory-check': 7, 'method-comparison': 1, chart: 3 } });

test('the page loads clean: the comparison and seven checks get ready, nothing leaves localhost', async () => {
  await assertLoadsClean(page, problems, { [COMPARISON]: 1, '[data-widget="theory-check"]': 7 });
  assert.equal(await page.locator(`${COMPARISON} [data-widget="chart"]`).count(), 3);
  assert.equal(await page.locator(`${COMPARISON} [data-widget="table"]`).count(), 2);
});

test('every theory check agrees: orders 4, 2, 4, 2; drift exponent 1; Verlet bounded at its modified-Hamiltonian size', async () => {
  const checks = await theoryChecks(page);
  assert.equal(checks.length, 7);
  for (const check of checks) assertAgrees(check);
  const [rk38, verlet, yoshida4, midpoint, drift, bounded, size] = checks;
  assert.deepEqual([rk38, verlet, yoshida4, midpoint].map((c) => c.predicted), [4, 2, 4, 2]);
  for (const c of [rk38, verlet, yoshida4, midpoint]) assert.ok(c.tolerance < 0.3, JSON.stringify(c));
  assert.equal(drift.predicted, 1);
  assert.ok(Math.abs(drift.measured - 1) < 0.05, String(drift.measured));
  assert.equal(bounded.predicted, 1);
  assert.ok(Math.abs(bounded.measured - 1) < 0.01, String(bounded.measured));
  // (ωh)²-sized: the largest energy error of Verlet at h = 0.1 on this swing is a few 10⁻³ of H₀.
  assert.ok(size.measured > 1e-3 && size.measured < 1e-2, String(size.measured));
});

test('the figures have data: five methods over 10⁵ steps, five portraits, four order studies with fitted lines', async () => {
  const energy = await chartIn(page, ENERGY);
  assert.deepEqual(energy.series.map((s) => s.label), ['RK 3/8', 'Störmer–Verlet', 'Yoshida 4', 'implicit midpoint', 'Dormand–Prince']);
  for (const s of energy.series) {
    assert.ok(s.points > 300, `${s.label}: ${s.points} points`);
    const t = s.values[0].x;
    assert.ok(Math.abs(t[t.length - 1] - 10000) < 30, `${s.label} ends at ${t[t.length - 1]}`);
  }
  // From a twentieth of the run to its end, RK 3/8's error grows as t does (linearly); Verlet's band is flat.
  const growth = (s) => {
    const { x, y } = s.values[0];
    return { error: y[y.length - 1] / y[20], time: x[x.length - 1] / x[20] };
  };
  const rk = growth(energy.series[0]);
  assert.ok(rk.error / rk.time > 0.7 && rk.error / rk.time < 1.3, JSON.stringify(rk));
  assert.ok(growth(energy.series[1]).error < 1.5, JSON.stringify(growth(energy.series[1])));
  const portraits = await chartIn(page, PORTRAITS);
  assert.equal(portraits.series.length, 5);
  for (const s of portraits.series) {
    const q = s.values[0].x;
    assert.ok(q.length > 1000 && Math.max(...q) <= 2.01 && Math.min(...q) >= -2.01, s.label);
  }
  const order = await chartIn(page, ORDER);
  const dots = order.series.filter((s) => s.kind === 'dots');
  assert.deepEqual(dots.map((s) => s.label), ['RK 3/8', 'Störmer–Verlet', 'Yoshida 4', 'implicit midpoint']);
  for (const s of dots) assert.equal(s.points, 4);
  assert.equal(order.series.filter((s) => s.kind === 'line').length, 4);
  await assertNoNaNShown(page);
});

test('a larger dt updates the run: RK 3/8’s error is no longer small, Verlet stays bounded but its h² term no longer leads', async () => {
  const { driftChecks } = await editAndReadChecks(page, 'dt', 'dt = 0.5', ['driftChecks']);
  const [drift, bounded, size] = driftChecks;
  assert.equal(drift.verdict, 'outside');
  assert.match(drift.reason, /must stay small/);
  assertAgrees(bounded);
  assert.equal(size.verdict, 'outside');
  assert.match(size.reason, /Ω·h = 0\.5/);
  assert.equal(await page.locator(COMPARISON).getAttribute('data-steps'), '20000');
  const energy = await chartIn(page, ENERGY);
  assert.ok(energy.series[0].values[0].x.length > 300);
  assert.deepEqual(problems, []);
});

test('order-study steps too large for the asymptotic regime are outside validity, and the figure follows', async () => {
  const { orderChecks } = await editAndReadChecks(page, 'steps', 'steps = [0.8, 0.4, 0.2]', ['orderChecks']);
  assert.deepEqual(orderChecks.map((c) => c.verdict), ['outside', 'outside', 'outside', 'outside']);
  for (const c of orderChecks) assert.match(c.reason, /Ω·h/);
  const order = await chartIn(page, ORDER);
  for (const s of order.series.filter((s) => s.kind === 'dots')) assert.equal(s.points, 3);
  await assertNoNaNShown(page);
  assert.deepEqual(problems, []);
});

test('an H that does not separate: Verlet and Yoshida cannot run and their checks are outside validity; the midpoint rule still has order 2', async () => {
  await editAndReadChecks(page, 'steps', 'steps = [0.05, 0.025, 0.0125, 0.00625]', ['orderChecks']);
  await editAndReadChecks(page, 'dt', 'dt = 0.1', ['driftChecks']);
  const { orderChecks, driftChecks } = await editAndReadChecks(page, 'H', 'H = "(1 + 0.2*cos(q))*p^2/2 - omega^2*cos(q)"', ['orderChecks', 'driftChecks']);
  const [rk38, verlet, yoshida4, midpoint] = orderChecks;
  assertAgrees(midpoint);
  // RK 3/8 on this H is still short of its asymptotic regime at these steps (its local slopes climb from
  // about 3.4 to 3.9), which its check may say; it must never claim a wrong order.
  assert.ok(['agrees', 'outside'].includes(rk38.verdict), JSON.stringify(rk38));
  // Not the pendulum any more: measured against a finer run of another method.
  assert.match(rk38.text, /Dormand–Prince/);
  for (const c of [verlet, yoshida4]) {
    assert.equal(c.verdict, 'outside');
    assert.match(c.reason, /T\(p\) \+ V\(q, t\)/);
  }
  const [drift, bounded, size] = driftChecks;
  assertAgrees(drift);
  assert.equal(bounded.verdict, 'outside');
  assert.match(bounded.reason, /T\(p\) \+ V\(q, t\)/);
  assert.equal(size.verdict, 'outside');
  assert.match(await page.locator(`${COMPARISON} > figcaption`).textContent(), /Not run — Störmer–Verlet: .*Yoshida 4: /);
  const energy = await chartIn(page, ENERGY);
  assert.deepEqual(energy.series.map((s) => s.label), ['RK 3/8', 'implicit midpoint', 'Dormand–Prince']);
  await assertNoNaNShown(page);
  assert.deepEqual(problems, []);
});

/** Largest |H − H₀|/H₀ of a plain kick–drift–kick loop on p²/2 + ω²q²/2 from (1, 0), written here; Infinity once it overflows. */
function leapfrogEnergyError(omega, h, steps) {
  let [q, p, worst] = [1, 0, 0];
  for (let n = 0; n < steps; n++) {
    p -= (h / 2) * omega * omega * q;
    q += h * p;
    p -= (h / 2) * omega * omega * q;
    const error = Math.abs((p * p + omega * omega * q * q) / (omega * omega) - 1);
    if (!Number.isFinite(error)) return Infinity;
    worst = Math.max(worst, error);
  }
  return worst;
}

test('the exercises, answered in the page: right answers from independent sources pass, plausible wrong ones fail and say why', async () => {
  // Σbᵢcᵢ⁴ of the 3/8 rule is Simpson's 3/8 quadrature of x⁴ on [0, 1]: 1/5 plus its error (3/80)h⁵·4! with h = 1/3 (Abramowitz & Stegun 25.4.13).
  assert.equal((await answer(page, 'order-five-moment', (1 / 5 + (3 / 80) * (1 / 3) ** 5 * 24).toFixed(4))).result, 'passed');
  let v = await answer(page, 'order-five-moment', '0.2');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /what order 5 would need/);
  v = await answer(page, 'order-five-moment', '0.0787');
  assert.match(v.text, /leaves out the last stage/);

  // Verlet's band on the oscillator ω = 2 at h = 0.1, measured by this file's own leapfrog loop.
  assert.equal((await answer(page, 'verlet-energy-band', leapfrogEnergyError(2, 0.1, 20_000).toPrecision(4))).result, 'passed');
  v = await answer(page, 'verlet-energy-band', '0.0025');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /for ω = 1/);
  v = await answer(page, 'verlet-energy-band', '0.02');
  assert.match(v.text, /H only falls/);

  // The stability limit at ω = 1.25, bracketed by the same loop: bounded below it, overflowing above it.
  let [stable, unstable] = [1, 2];
  while (unstable - stable > 1e-3) {
    const mid = (stable + unstable) / 2;
    if (leapfrogEnergyError(1.25, mid, 5_000) < 1e3) stable = mid;
    else unstable = mid;
  }
  assert.equal((await answer(page, 'verlet-stable-step', stable.toFixed(3))).result, 'passed');
  v = await answer(page, 'verlet-stable-step', '2');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /divided by ω = 1\.25/);
  v = await answer(page, 'verlet-stable-step', '2.263');
  assert.match(v.text, /four-stage Runge–Kutta/);

  // H + h²H₂ from the symmetric BCH formula (Hairer, Lubich & Wanner §III.4), written otherwise: terms reordered, a constant added.
  v = await answerCode(page, 'pendulum-modified-hamiltonian', 'myModifiedH', 'myModifiedH = "h^2*omega^2*cos(q)*p^2/12 - h^2*omega^4*sin(q)^2/24 + p^2/2 - omega^2*cos(q) + 1"');
  assert.equal(v.result, 'passed', v.text);
  v = await answerCode(page, 'pendulum-modified-hamiltonian', 'myModifiedH', 'myModifiedH = "p^2/2 - omega^2*cos(q)"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /Hamilton’s equations differ at \(q, p\)/);
  v = await answerCode(page, 'pendulum-modified-hamiltonian', 'myModifiedH', 'myModifiedH = "p^2/2 - omega^2*cos(q) - h^2*(omega^2*cos(q)*p^2/12 - omega^4*sin(q)^2/24)"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /Hamilton’s equations differ/);
  assert.deepEqual(problems, []);
});
