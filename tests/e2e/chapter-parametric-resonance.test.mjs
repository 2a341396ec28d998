/**
 * /parametric-resonance/: the growth rate measured in the page against the
 * first-order formula and against a Floquet multiplier this test computes
 * itself; the stability chart, whose click sets γ and u in its simulator;
 * the chapter's exercises, answered.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertDrawn, theoryChecks, useChapter, widgetsReady } from './chapter-checks.mjs';
import { answer, answerCode } from './exercise-answers.mjs';
import { cell, typeIntoCell } from './fixture.mjs';

const WIDGETS = '[data-widget]';

/** Landau & Lifshitz §27: s = ½√((uω/2)² − (γ − 2ω)²) inside the band, 0 outside. */
function firstOrder({ u, gamma, omega }) {
  const half = (u * omega) / 2;
  const epsilon = gamma - 2 * omega;
  return Math.abs(epsilon) < half ? 0.5 * Math.sqrt(half * half - epsilon * epsilon) : 0;
}

/**
 * The trace of the monodromy matrix of q̈ + ω²(1 + u cos γt) q = 0 over one drive period,
 * computed here independently of the page, by the classical Runge–Kutta method.
 */
function monodromyTrace({ u, gamma, omega }, steps = 4000) {
  const T = (2 * Math.PI) / gamma;
  const h = T / steps;
  const rate = (t, q, p) => [p, -omega * omega * (1 + u * Math.cos(gamma * t)) * q];
  const advance = ([q, p]) => {
    for (let i = 0; i < steps; i++) {
      const t = i * h;
      const k1 = rate(t, q, p);
      const k2 = rate(t + h / 2, q + (h / 2) * k1[0], p + (h / 2) * k1[1]);
      const k3 = rate(t + h / 2, q + (h / 2) * k2[0], p + (h / 2) * k2[1]);
      const k4 = rate(t + h, q + h * k3[0], p + h * k3[1]);
      q += (h / 6) * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
      p += (h / 6) * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
    }
    return [q, p];
  };
  return advance([1, 0])[0] + advance([0, 1])[1];
}

/** The larger Floquet multiplier, a root of λ² − (tr M)λ + 1 = 0 (det M = 1); 1 when stable. */
function floquetMultiplier(params) {
  const half = monodromyTrace(params) / 2;
  return Math.abs(half) > 1 ? half + Math.sign(half) * Math.sqrt(half * half - 1) : 1;
}

/** The Floquet growth rate s = ln|λ_max|/T. */
const floquetGrowth = (params) => (Math.log(Math.abs(floquetMultiplier(params))) * params.gamma) / (2 * Math.PI);

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

useChapter('/parametric-resonance/', (opened) => ({ page, problems } = opened));

/**
 * The first-order formula's stated error: the next order moves the band down by δ = u²ω/32
 * (Landau & Lifshitz §27, problem 1), the order after by uδ; the largest change of s over that
 * move, plus uδ.
 */
function neglected({ u, gamma, omega }) {
  const half = (u * omega) / 2;
  const rate = (e) => (Math.abs(e) < half ? 0.5 * Math.sqrt(half * half - e * e) : 0);
  const epsilon = gamma - 2 * omega;
  const shift = (u * u * omega) / 32;
  const ends = [epsilon + shift * (1 - u), epsilon + shift * (1 + u)];
  const moved = [...ends, ...(ends[0] < 0 && ends[1] > 0 ? [0] : [])].map(rate);
  return Math.max(...moved.map((r) => Math.abs(r - rate(epsilon)))) + u * shift;
}

function assertChecks([formula, exact], params) {
  const s = firstOrder(params);
  assertAgrees(formula, { relative: false });
  assert.ok(Math.abs(formula.predicted - s) < 1e-12, `first-order s: page ${formula.predicted}, test ${s}`);
  assert.ok(Math.abs(formula.errorFormula - neglected(params)) < 1e-12, `formula error: page ${formula.errorFormula}, test ${neglected(params)}`);
  assertAgrees(exact, { relative: false });
  const floquet = floquetGrowth(params);
  assert.ok(Math.abs(exact.predicted - floquet) < 1e-6 * floquet, `Floquet s: page ${exact.predicted}, test ${floquet}`);
  assert.equal(exact.errorFormula, 0);
  // The fit is within its own stated errors of the exact growth rate.
  assert.ok(Math.abs(exact.measured - floquet) <= exact.errorIntegration + exact.errorMeasurement, JSON.stringify(exact));
}

test('the page loads with its widgets ready and drawn, and both growth-rate checks agree', async () => {
  const kinds = await page.$$eval(WIDGETS, (all) => all.map((w) => w.dataset.widget));
  for (const kind of ['simulator', 'time-plot', 'phase-portrait', 'theory-check', 'stability-chart']) {
    assert.ok(kinds.includes(kind), `no ${kind} widget; found ${kinds.join(', ')}`);
  }
  const params = { u: 0.3, gamma: 21.3, omega: 10 };
  assertChecks(await theoryChecks(page), params);
  // the paper's example: inside the band, s ≈ 0.374 to first order, 0.346 exactly
  assert.ok(Math.abs(firstOrder(params) - 0.3741657) < 1e-6);

  await assertDrawn(page, '[data-widget="time-plot"], [data-widget="phase-portrait"], [data-widget="stability-chart"]', 4);
  // The chart found the tongue: between the first-order boundaries, whose width uω grows from 0 to 10
  // across the chart's 10 units of γ, lies half of the chart.
  const unstable = Number(await page.locator('[data-widget="stability-chart"]').getAttribute('data-unstable'));
  assert.ok(unstable > 0.45 * 7200 && unstable < 0.55 * 7200, `unstable points: ${unstable}`);
  assert.deepEqual(problems, []);
});

test('clicking the stability chart sets γ and u in the simulator under it', async () => {
  const canvas = page.locator('[data-widget="stability-chart"] canvas');
  const box = await canvas.boundingBox();
  const explorer = cell(page, 'explorer').locator('[data-widget="simulator"]');
  const params = () =>
    explorer.evaluate((el) => {
      const { paramNames, params } = el.simulator.model;
      return Object.fromEntries(paramNames.map((name, i) => [name, params[i]]));
    });
  assert.deepEqual(await params(), { u: 0.3, gamma: 21.3, beta: 0.2, kappa: 8, omega: 10, f: 0 });
  // The plot area is inset by the axes' margins: 50 px left, 12 right, 24 top, 38 bottom.
  const at = (x, y) => ({ gamma: 15 + (10 * (x - 50)) / (box.width - 62), u: (24 + (box.height - 62) - y) / (box.height - 62) });
  for (const [x, y] of [
    [50 + 0.5 * (box.width - 62), 24 + 0.2 * (box.height - 62)],
    [50 + 0.9 * (box.width - 62), 24 + 0.7 * (box.height - 62)],
  ]) {
    await canvas.click({ position: { x, y } });
    const chosen = await params();
    const expected = at(x, y);
    assert.ok(Math.abs(chosen.gamma - expected.gamma) < 0.05, `γ ${chosen.gamma}, expected ${expected.gamma}`);
    assert.ok(Math.abs(chosen.u - expected.u) < 0.01, `u ${chosen.u}, expected ${expected.u}`);
    assert.match((await cell(page, 'chosen').locator('[data-cell-output]').textContent()) ?? '', new RegExp(`γ = ${chosen.gamma.toFixed(2)}, u = ${chosen.u.toFixed(2)}`));
  }
  // The last point, γ ≈ 24, u ≈ 0.3, is far outside the tongue: the explorer restarted there.
  assert.ok(await explorer.evaluate((el) => el.simulator.simulation.t < 5));
  assert.deepEqual(problems, []);
});

test('editing u re-runs both checks, which still agree', async () => {
  await typeIntoCell(page, 'params', 'params = ({u: 0.4, gamma: 21.3, beta: 0.2, kappa: 8, omega: 10, f: 0})');
  const params = { u: 0.4, gamma: 21.3, omega: 10 };
  await page.waitForFunction(
    (s) => {
      const all = document.querySelectorAll('[data-widget="theory-check"]');
      return all.length === 2 && Math.abs(Number(all[0].dataset.predicted) - s) < 1e-12 && Math.abs(Number(all[1].dataset.predicted) - 0.7338) < 1e-3;
    },
    firstOrder(params),
  );
  assertChecks(await theoryChecks(page), params);
  await widgetsReady(page);
  assert.deepEqual(problems, []);
});

test('the exercises: right answers pass, plausible wrong ones fail and say why', async () => {
  // The growth rate from this file's own RK4 monodromy matrix.
  assert.equal((await answer(page, 'growth-at-u-04', floquetGrowth({ u: 0.4, gamma: 21.3, omega: 10 }).toFixed(4))).result, 'passed');
  // The first-order formula, rightly applied, is within its stated error (Landau & Lifshitz §27).
  assert.equal((await answer(page, 'growth-at-u-04', String(firstOrder({ u: 0.4, gamma: 21.3, omega: 10 })))).result, 'passed');
  let v = await answer(page, 'growth-at-u-04', '1');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /the rate at the band’s centre/);
  v = await answer(page, 'growth-at-u-04', String(2 * firstOrder({ u: 0.4, gamma: 21.3, omega: 10 })));
  assert.match(v.text, /leaves out the ½/);

  const lambda = floquetMultiplier({ u: 0.3, gamma: 20, omega: 10 });
  assert.equal((await answer(page, 'multiplier-at-centre', lambda.toFixed(4))).result, 'passed');
  v = await answer(page, 'multiplier-at-centre', (-lambda).toFixed(4));
  assert.equal(v.result, 'failed');
  assert.match(v.text, /the sign is not/);
  v = await answer(page, 'multiplier-at-centre', (1 / lambda).toFixed(4));
  assert.match(v.text, /the other multiplier, 1\/λ/);

  // The upper edge to second order, 2ω + uω/2 − u²ω/32 (Landau & Lifshitz §27, problem 1), within ±0.01 of the true edge.
  assert.equal((await answer(page, 'tongue-edge-at-u-03', String(20 + 1.5 - (0.09 * 10) / 32))).result, 'passed');
  v = await answer(page, 'tongue-edge-at-u-03', '21.5');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /the first-order edge/);
  v = await answer(page, 'tongue-edge-at-u-03', '18.47');
  assert.match(v.text, /That is the lower edge/);

  // The slow equations' H, written otherwise: ȧ = ∂H/∂b, ḃ = −∂H/∂a.
  v = await answerCode(page, 'slow-hamiltonian', 'slowH', 'slowH = "-(epsilon + u*omega/2)*p^2/4 - (epsilon - u*omega/2)*q^2/4"');
  assert.equal(v.result, 'passed', v.text);
  for (const wrong of ['(epsilon/2 + u*omega/4)*p^2/2 + (epsilon/2 - u*omega/4)*q^2/2', '-(epsilon/2 - u*omega/4)*p^2/2 - (epsilon/2 + u*omega/4)*q^2/2']) {
    v = await answerCode(page, 'slow-hamiltonian', 'slowH', `slowH = "${wrong}"`);
    assert.equal(v.result, 'failed');
    assert.match(v.text, /1 of 2 checks failed/);
    assert.match(v.text, /Failed: Hamilton’s equations differ at \(q, p\)/);
  }
  assert.deepEqual(problems, []);
});
