/**
 * /scattering/: the deflection of one particle of the paper's beam against
 * the exact finite-start orbit (recomputed here from the Laplace–Runge–Lenz
 * vector) and against Rutherford's formula; the beam's trajectory view draws;
 * the envelope and deflection figures are made; editing the field strength
 * re-runs both checks, which still agree.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, chartIn, drawnPixels, resetCell, theoryChecks, useChapter, widgetsReady } from './chapter-checks.mjs';
import { answer, answerCode } from './exercise-answers.mjs';
import { typeIntoCell } from './fixture.mjs';

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

const EXPECTED = { simulator: 1, trajectory: 1, equations: 1, 'theory-check': 2 };

useChapter('/scattering/', (opened) => ({ page, problems } = opened), { widgets: EXPECTED });

const checks = () => theoryChecks(page);

/**
 * The exact deflection of a particle of mass m started at (x, y) with momentum (px, py) in
 * U = α/r, written out here independently of the page: the orbit's axis lies along the
 * Laplace–Runge–Lenz vector A = p × L + mα r̂, the asymptotes at arccos(1/e) from it, e = |A|/mα.
 */
function exactDeflection(x, y, px, py, alpha, m) {
  const r = Math.hypot(x, y);
  const L = x * py - y * px;
  const ax = py * L + (m * alpha * x) / r;
  const ay = -px * L + (m * alpha * y) / r;
  const e = Math.hypot(ax, ay) / (m * alpha);
  const out = Math.atan2(ay, ax) + Math.sign(L) * Math.acos(1 / e);
  const turn = Math.atan2(px * Math.sin(out) - py * Math.cos(out), px * Math.cos(out) + py * Math.sin(out));
  return Math.abs(turn);
}

/** Rutherford: tan(θ/2) = |α|/(2 E b), E = p²/2m. */
const rutherford = (b, p, alpha, m) => 2 * Math.atan(Math.abs(alpha) / (2 * (p * p) / (2 * m) * b));

/** The first-order shortfall of a start at x0 against Rutherford (the chapter's estimate). */
function shortfall(x0, b, p, alpha, m) {
  const E0 = (p * p) / (2 * m);
  const theta = rutherford(b, p, alpha, m);
  return (Math.sin(theta) / 2) * Math.log(1 + alpha / (Math.hypot(x0, b) * E0)) + (Math.abs(alpha) * b) / (4 * x0 * x0 * E0);
}

function assertChecks([orbit, formula], alpha) {
  const [x0, b, p, m] = [-20, 1.5, 4, 0.5];
  assertAgrees(orbit, { relative: false });
  const exact = exactDeflection(x0, b, p, 0, alpha, m);
  assert.ok(Math.abs(orbit.predicted - exact) < 1e-12, `exact orbit: page ${orbit.predicted}, test ${exact}`);
  // The run ends ~300 units out; what is left of the turn there is of order 1e-5 rad.
  assert.ok(orbit.tolerance > 0 && orbit.tolerance < 1e-4, JSON.stringify(orbit));
  assert.ok(orbit.measured < orbit.predicted, 'the simulated particle has not quite finished turning');

  assertAgrees(formula, { relative: false });
  const theta = rutherford(b, p, alpha, m);
  assert.ok(Math.abs(formula.predicted - theta) < 1e-12, `Rutherford: page ${formula.predicted}, test ${theta}`);
  // The formula's error: the first-order shortfall of a start at x0, and the next order, smaller by
  // |α|/r0E0 + |b/x0|.
  const first = Math.abs(shortfall(x0, b, p, alpha, m));
  const expected = first * (1 + Math.abs(alpha) / (Math.hypot(x0, b) * ((p * p) / (2 * m))) + Math.abs(b / x0));
  assert.ok(Math.abs(formula.errorFormula - expected) < 1e-12, `formula error: page ${formula.errorFormula}, test ${expected}`);
  // the difference is real, not noise: the start at x0 = −20 costs most of the first-order estimate
  assert.ok(Math.abs(formula.measured - formula.predicted) > 0.5 * first);
}

test('both deflection checks agree with formulas computed here; the beam and the figures are drawn', async () => {
  assertChecks(await checks(), 30);
  // the paper's particle at b = 1.5: Rutherford's 64.0°, 2.4° more than the simulation
  const [orbit, formula] = await checks();
  assert.ok(Math.abs(formula.predicted - 1.117199) < 1e-6);
  assert.ok(Math.abs(formula.predicted - orbit.measured - 0.0414) < 0.001);

  const [{ pixels }] = await drawnPixels(page, '[data-widget="trajectory"]');
  assert.ok(pixels > 2000, `the trajectory view drew ${pixels} pixels`);

  // The envelope figure: 30 trajectories, the parabola, 30 points where y = 2b, the centre.
  const envelope = await chartIn(page, 'Trajectories of the beam and the parabola that bounds them');
  const lines = envelope.series.filter((s) => s.kind === 'line').reduce((n, s) => n + s.curves, 0);
  const dots = (series) => series.filter((s) => s.kind === 'dots').reduce((n, s) => n + s.points, 0);
  assert.equal(lines, 31);
  assert.equal(dots(envelope.series), 31);
  // The deflection figures: a dot per particle off the axis.
  assert.equal(dots((await chartIn(page, 'Deflection angle against impact parameter')).series), 29);
  assert.ok((await page.locator('[data-widget="equations"] .katex').count()) > 0, 'H is typeset');
  assert.deepEqual(problems, []);
});

test('editing the field strength re-runs both checks, which still agree', async () => {
  const [before] = await checks();
  await typeIntoCell(page, 'params', 'params = ({alpha: 20})');
  await page.waitForFunction(
    (old) => {
      const all = document.querySelectorAll('[data-widget="theory-check"]');
      return all.length === 2 && [...all].every((w) => w.hasAttribute('data-ready')) && all[0].dataset.predicted !== old && all[1].dataset.predicted !== String(2 * Math.atan(30 / 48));
    },
    String(before.predicted),
  );
  const after = await checks();
  assertChecks(after, 20);
  assert.ok(after[0].measured < before.measured, 'a weaker field bends less');
  await widgetsReady(page, EXPECTED);
  assert.deepEqual(problems, []);
  await resetCell(page, 'params');
});

test('the exercises, answered in the page: right answers computed here pass, plausible wrong ones fail and say why', async () => {
  // Rutherford, tan(θ/2) = α/2Eb with E = p₀²/2m = 16 (Landau & Lifshitz §19).
  let v = await answer(page, 'rutherford-angle', String(2 * Math.atan(30 / (2 * 16 * 1.5))));
  assert.equal(v.result, 'passed', v.text);
  v = await answer(page, 'rutherford-angle', String(Math.atan(30 / (2 * 16 * 1.5))));
  assert.equal(v.result, 'failed');
  assert.match(v.text, /That is θ\/2/);
  v = await answer(page, 'rutherford-angle', String((2 * Math.atan(30 / 48) * 180) / Math.PI));
  assert.match(v.text, /in degrees/);
  // Head-on, the particle stops where α/r = E = p₀²/2m + α/|x₀| (energy conservation, Landau & Lifshitz §18).
  assert.equal((await answer(page, 'slower-beam-turning-point', String(-30 / (9 + 30 / 20)))).result, 'passed');
  v = await answer(page, 'slower-beam-turning-point', String(-30 / 9));
  assert.equal(v.result, 'failed');
  assert.match(v.text, /already holds at x₀ = −20/);
  v = await answer(page, 'slower-beam-turning-point', String(30 / 10.5));
  assert.match(v.text, /x is negative/);
  // The right angle on the exact orbit from x₀ = −20 (exactDeflection above), by bisection here.
  let [low, high] = [0.1, 5];
  for (let k = 0; k < 60; k++) {
    const mid = (low + high) / 2;
    [low, high] = exactDeflection(-20, mid, 4, 0, 30, 0.5) > Math.PI / 2 ? [mid, high] : [low, mid];
  }
  assert.equal((await answer(page, 'right-angle-impact', low.toFixed(4))).result, 'passed');
  v = await answer(page, 'right-angle-impact', String(30 / 32));
  assert.equal(v.result, 'failed');
  assert.match(v.text, /Rutherford’s α\/2E₀, for a particle from infinity/);
  v = await answer(page, 'right-angle-impact', String(30 / 16));
  assert.match(v.text, /That is α\/E₀/);
  // H = |p|²/2m + α/r with m = 2, α = 10, written otherwise, passes; the paper's mass and an attracting centre fail.
  v = await answerCode(page, 'heavier-particle-hamiltonian', 'myBeamH', 'myBeamH = "10/sqrt(q1^2 + q0^2) + p0^2/4 + p1^2/4"');
  assert.equal(v.result, 'passed', v.text);
  v = await answerCode(page, 'heavier-particle-hamiltonian', 'myBeamH', 'myBeamH = "p0^2 + p1^2 + 10/sqrt(q0^2 + q1^2)"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /Hamilton’s equations differ at \(q0, q1, p0, p1\)/);
  v = await answerCode(page, 'heavier-particle-hamiltonian', 'myBeamH', 'myBeamH = "(p0^2 + p1^2)/4 - 10/sqrt(q0^2 + q1^2)"');
  assert.equal(v.result, 'failed');
  assert.deepEqual(problems, []);
});
