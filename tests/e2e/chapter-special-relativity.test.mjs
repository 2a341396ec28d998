/**
 * /special-relativity/: the simulated position against the closed-form
 * hyperbolic motion q(t) = q0 + (√(p² + m²) − √(p0² + m²))/F, evaluated
 * here, and the speed that stays below c; the Newtonian comparison; an edit
 * of the force.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { openChapter, openSite, typeIntoCell } from './fixture.mjs';

const [Q0, P0] = [-10, -10];

/** Landau & Lifshitz, Fields §20: p = p0 + Ft, q = q0 + (E − E0)/F, v = p/E. */
function exact({ m, F }, t) {
  const p = P0 + F * t;
  const E = Math.sqrt(p ** 2 + m ** 2);
  const E0 = Math.sqrt(P0 ** 2 + m ** 2);
  return { q: Q0 + (E - E0) / F, v: p / E };
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
    all.map((w) => ({
      ...w.dataset,
      measured: +w.dataset.measured,
      predicted: +w.dataset.predicted,
      tolerance: +w.dataset.tolerance,
      method: w.querySelector('.pb-measured')?.textContent ?? '',
    })),
  );

function assertAgrees(check) {
  assert.equal(check.agrees, 'true', JSON.stringify(check));
  assert.equal(check.relative, 'false');
  assert.ok(Math.abs(check.measured - check.predicted) <= check.tolerance, JSON.stringify(check));
}

async function assertChecks(params) {
  const [position, speed] = await checks();
  assertAgrees(position);
  assertAgrees(speed);
  assert.equal(position.tolerance, 1e-9);
  assert.equal(speed.tolerance, 1e-9);
  // The position check compares at the time of the largest difference, which it names (to 1e-3, the step).
  const at = Number(/at t = ([\d.]+)/.exec(position.method)?.[1]);
  assert.ok(at >= 0 && at <= 40, position.method);
  assert.ok(Math.abs(position.predicted - exact(params, at).q) < 1e-11, `${position.predicted} vs ${exact(params, at).q}`);
  // The largest speed over [0, 40] is at one of the ends, and it is below c = 1.
  const fastest = Math.max(Math.abs(exact(params, 0).v), Math.abs(exact(params, 40).v));
  assert.ok(Math.abs(speed.predicted - fastest) < 1e-14, `${speed.predicted} vs ${fastest}`);
  assert.ok(speed.measured < 1 && fastest < 1);
}

before(async () => {
  site = await openSite();
  ({ page, problems } = await openChapter(site, '/special-relativity/'));
  await allReady();
});
after(async () => {
  await page?.close();
  await site?.close();
});

test('the page loads clean: every cell runs, every widget gets ready, nothing leaves localhost', async () => {
  assert.equal(await page.locator('[data-cell-error]:visible').count(), 0);
  assert.equal(await page.locator('[data-widget="theory-check"]').count(), 2);
  assert.equal(await page.locator('[data-widget="equations"] .katex').count(), 1);
  assert.deepEqual(problems, []);
});

test('the simulation follows the closed form to 1e-9, and its speed stays below c', async () => {
  const params = { m: Math.sqrt(10), F: 0.8 };
  await assertChecks(params);
  // The paper's numbers: at t = 40, p = 22 and v = 22/√494 = 0.98983.
  assert.ok(Math.abs(exact(params, 40).v - 22 / Math.sqrt(494)) < 1e-15);
  assert.ok(Math.abs(exact(params, 40).q - (-10 + (Math.sqrt(494) - Math.sqrt(110)) / 0.8)) < 1e-12);
});

test('the views and the comparison plots have drawn; the Newtonian speed crosses c at t = 16.45', async () => {
  const drawn = await page.$$eval('[data-widget="time-plot"], [data-widget="phase-portrait"]', (plots) =>
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
  assert.equal(drawn.length, 2, JSON.stringify(drawn));
  for (const { kind, pixels } of drawn) assert.ok(pixels > 500, `${kind} drew ${pixels} pixels`);

  const velocity = page.locator('svg[aria-label^="Velocity against time"]');
  assert.equal(await velocity.locator('path').count(), 2);
  // The Newtonian speed p/m reaches c where |p| = m: t = (±m − p0)/F.
  const crossing = (Math.sqrt(10) - P0) / 0.8;
  assert.match((await velocity.textContent()) ?? '', new RegExp(`t = ${crossing.toFixed(2)}`));
  const worldlines = page.locator('svg[aria-label^="Worldlines"]');
  assert.equal(await worldlines.locator('path').count(), 4);
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
  await allReady();
  await assertChecks(params);
  assert.equal(await page.locator('[data-cell-error]:visible').count(), 0);
  assert.deepEqual(problems, []);
});
