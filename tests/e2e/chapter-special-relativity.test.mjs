/**
 * /special-relativity/: the simulated position against the closed-form
 * hyperbolic motion q(t) = q0 + (√(p² + m²) − √(p0² + m²))/F, evaluated
 * here, and the speed that stays below c; the Newtonian comparison; an edit
 * of the force.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertDrawn, chartIn, assertLoadsClean, assertNoCellErrors, theoryChecks, useChapter, widgetsReady } from './chapter-checks.mjs';
import { answer, answerCode } from './exercise-answers.mjs';
import { typeIntoCell } from './fixture.mjs';

const [Q0, P0] = [-10, -10];

/** Landau & Lifshitz, Fields §20: p = p0 + Ft, q = q0 + (E − E0)/F, v = p/E. */
function exact({ m, F }, t) {
  const p = P0 + F * t;
  const E = Math.sqrt(p ** 2 + m ** 2);
  const E0 = Math.sqrt(P0 ** 2 + m ** 2);
  return { q: Q0 + (E - E0) / F, v: p / E };
}

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

async function assertChecks(params) {
  const [position, speed] = await theoryChecks(page, { method: true });
  assertAgrees(position, { relative: false });
  assertAgrees(speed, { relative: false });
  // The closed form is exact: what is allowed is the integrator's rounding (and Simpson's error), under 1e-9.
  assert.equal(position.errorFormula, 0);
  assert.equal(speed.errorFormula, 0);
  assert.ok(position.tolerance > 0 && position.tolerance < 1e-9, String(position.tolerance));
  assert.ok(speed.tolerance > 0 && speed.tolerance < 1e-9, String(speed.tolerance));
  // The position check compares at the time of the largest difference, which it names (to 1e-3, the step).
  const at = Number(/at t = ([\d.]+)/.exec(position.method)?.[1]);
  assert.ok(at >= 0 && at <= 40, position.method);
  assert.ok(Math.abs(position.predicted - exact(params, at).q) < 1e-11, `${position.predicted} vs ${exact(params, at).q}`);
  // The largest speed over [0, 40] is at one of the ends, and it is below c = 1.
  const fastest = Math.max(Math.abs(exact(params, 0).v), Math.abs(exact(params, 40).v));
  assert.ok(Math.abs(speed.predicted - fastest) < 1e-14, `${speed.predicted} vs ${fastest}`);
  assert.ok(speed.measured < 1 && fastest < 1);
}

useChapter('/special-relativity/', (opened) => ({ page, problems } = opened));

test('the page loads clean: every cell runs, every widget gets ready, nothing leaves localhost', async () => {
  await assertLoadsClean(page, problems, {
    '[data-widget="theory-check"]': 2,
    '[data-widget="equations"] .katex': 1,
  });
});

test('the simulation follows the closed form within its rounding error, and its speed stays below c', async () => {
  const params = { m: Math.sqrt(10), F: 0.8 };
  await assertChecks(params);
  // The paper's numbers: at t = 40, p = 22 and v = 22/√494 = 0.98983.
  assert.ok(Math.abs(exact(params, 40).v - 22 / Math.sqrt(494)) < 1e-15);
  assert.ok(Math.abs(exact(params, 40).q - (-10 + (Math.sqrt(494) - Math.sqrt(110)) / 0.8)) < 1e-12);
});

test('the views and the comparison plots have drawn; the Newtonian speed crosses c at t = 16.45', async () => {
  await assertDrawn(page, '[data-widget="time-plot"], [data-widget="phase-portrait"]', 2);

  const lines = (figure) => figure.series.filter((s) => s.kind === 'line').reduce((n, s) => n + s.curves, 0);
  const velocity = await chartIn(page, 'Velocity against time, relativistic and Newtonian');
  assert.equal(lines(velocity), 2);
  // The Newtonian speed p/m reaches c where |p| = m: t = (±m − p0)/F.
  const crossing = (Math.sqrt(10) - P0) / 0.8;
  assert.match(velocity.description, new RegExp(`t = ${crossing.toFixed(2)}`));
  assert.equal(lines(await chartIn(page, 'Worldlines: position against time')), 4);
});

test('editing the force re-runs the checks, which still agree (F = 2)', async () => {
  await typeIntoCell(page, 'params', 'params = ({m: sqrt(10), F: 2})');
  const params = { m: Math.sqrt(10), F: 2 };
  const fastest = Math.max(Math.abs(exact(params, 0).v), Math.abs(exact(params, 40).v));
  await page.waitForFunction(
    (expected) => {
      const check = document.querySelectorAll('[data-widget="theory-check"]')[1];
      return check && Math.abs(Number(check.getAttribute('data-predicted')) - expected) < 1e-12;
    },
    fastest,
  );
  await widgetsReady(page);
  await assertChecks(params);
  await assertNoCellErrors(page);
  assert.deepEqual(problems, []);
});

test('the exercises, answered in the page: right answers computed here pass, plausible wrong ones fail and say why', async () => {
  const m = Math.sqrt(10);
  // Energy conservation, √(p² + m²) − Fq constant (Landau & Lifshitz, Fields §20), at p = 0: q = q₀ + (m − √(p₀² + m²))/F.
  let v = await answer(page, 'turning-point-stronger-force', String(Q0 + (m - Math.hypot(P0, m)) / 2));
  assert.equal(v.result, 'passed', v.text);
  v = await answer(page, 'turning-point-stronger-force', String(Q0 - P0 ** 2 / (2 * m * 2)));
  assert.equal(v.result, 'failed');
  assert.match(v.text, /That is Newton’s particle/);
  v = await answer(page, 'turning-point-stronger-force', String(Q0 - (m - Math.hypot(P0, m)) / 2));
  assert.match(v.text, /to the left of the start/);
  // The same, read backwards: √(p₀² + m²) = m + F · 10, against the force.
  assert.equal((await answer(page, 'start-to-turn-at-minus-20', String(-Math.sqrt((m + 0.8 * 10) ** 2 - m * m)))).result, 'passed');
  v = await answer(page, 'start-to-turn-at-minus-20', String(-Math.sqrt(2 * m * 0.8 * 10)));
  assert.equal(v.result, 'failed');
  assert.match(v.text, /That is Newton’s particle/);
  v = await answer(page, 'start-to-turn-at-minus-20', String(-Math.sqrt((10 + 8) ** 2 - 100)));
  assert.match(v.text, /m² = 10, so m = √10/);
  // v = p/√(p² + m²) at |p| = m (Landau & Lifshitz, Fields §9).
  assert.equal((await answer(page, 'speed-when-newton-reaches-c', String(m / Math.hypot(m, m)))).result, 'passed');
  v = await answer(page, 'speed-when-newton-reaches-c', '1');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /always below 1/);
  v = await answer(page, 'speed-when-newton-reaches-c', '0.5');
  assert.match(v.text, /√2·m, not 2m/);
  // H = √(p² + 1) + q²/2 written otherwise passes; Newton's spring and a wrong sign fail both checks.
  v = await answerCode(page, 'relativistic-spring', 'mySpringH', 'mySpringH = "q^2/2 + sqrt(1 + p^2)"');
  assert.equal(v.result, 'passed', v.text);
  assert.match(v.text, /All 2 checks passed/);
  v = await answerCode(page, 'relativistic-spring', 'mySpringH', 'mySpringH = "p^2/2 + q^2/2"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /2 of 2 checks failed/);
  assert.match(v.text, /not back where it began/);
  v = await answerCode(page, 'relativistic-spring', 'mySpringH', 'mySpringH = "sqrt(p^2 + 1) - q^2/2"');
  assert.equal(v.result, 'failed');
  assert.deepEqual(problems, []);
});
