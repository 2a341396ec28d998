/**
 * /special-relativity/: the simulated position against the closed-form
 * hyperbolic motion q(t) = q0 + (√(p² + m²) − √(p0² + m²))/F, evaluated
 * here, and the speed that stays below c; the Newtonian comparison; an edit
 * of the force.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertDrawn, chartIn, assertLoadsClean, assertNoCellErrors, theoryChecks, useChapter, widgetsReady } from './chapter-checks.mjs';
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
    { timeout: 20_000 },
  );
  await widgetsReady(page);
  await assertChecks(params);
  await assertNoCellErrors(page);
  assert.deepEqual(problems, []);
});
