/**
 * /for-teachers/: the page renders the chapter template (templates/chapter.mdx)
 * live, so a teacher's copy is known to run: its cells run without errors, its
 * simulator draws, and its theory check agrees with the pendulum's period
 * computed here; an edit of the amplitude re-runs the check.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { cell, errorOf, openChapter, openSite, typeIntoCell } from './fixture.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

const TEMPLATE_CELLS = ['pendulum', 'pendulumH', 'pendulumStart', 'pendulumModel', 'pendulumEquations', 'pendulumSimulator', 'periodCheck'];

async function widgetsReady() {
  await page.waitForFunction(
    () => {
      const all = [...document.querySelectorAll('[data-widget]')];
      const kinds = new Set(all.map((w) => w.dataset.widget));
      return ['simulator', 'equations', 'theory-check'].every((k) => kinds.has(k)) && all.every((w) => w.hasAttribute('data-ready'));
    },
    null,
    { timeout: 30_000 },
  );
}

before(async () => {
  site = await openSite();
  ({ page, problems } = await openChapter(site, '/for-teachers/'));
  await widgetsReady();
});
after(async () => {
  await page?.close();
  await site?.close();
});

/** The period check, its numbers parsed. */
const periodCheck = () =>
  cell(page, 'periodCheck')
    .locator('[data-widget="theory-check"]')
    .evaluate((w) => ({ ...w.dataset, measured: Number(w.dataset.measured), predicted: Number(w.dataset.predicted), tolerance: Number(w.dataset.tolerance) }));

function assertPeriod(check, omega0, theta0) {
  assert.equal(check.agrees, 'true', JSON.stringify(check));
  assert.equal(check.relative, 'true');
  assert.ok(Math.abs(check.measured - check.predicted) / check.predicted <= check.tolerance, JSON.stringify(check));
  const predicted = ((2 * Math.PI) / omega0) * (1 + theta0 ** 2 / 16);
  assert.ok(Math.abs(check.predicted - predicted) < 1e-12, `page ${check.predicted}, test ${predicted}`);
  assert.ok(Math.abs(check.tolerance - (2 * 11 * theta0 ** 4) / 3072) < 1e-15);
}

test('the template runs live on the page: every cell, the simulator and the period check', async () => {
  for (const id of TEMPLATE_CELLS) assert.equal(await errorOf(page, id), '', `cell ${id}`);
  assertPeriod(await periodCheck(), 2, 0.5);
  const pixels = await page.$eval('[data-widget="simulator"]', (simulator) =>
    Math.max(
      0,
      ...[...simulator.querySelectorAll('canvas')].map((canvas) => {
        if (!canvas.width || !canvas.height) return 0;
        const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
        let differ = 0;
        for (let i = 0; i < data.length; i += 4) {
          if (data[i + 3] > 0 && (data[i] !== data[0] || data[i + 1] !== data[1] || data[i + 2] !== data[2] || data[i + 3] !== data[3])) differ++;
        }
        return differ;
      }),
    ),
  );
  assert.ok(pixels > 500, `the simulator drew ${pixels} pixels`);
  assert.ok((await page.locator('[data-widget="equations"] .katex').count()) > 0);
  assert.deepEqual(problems, []);
});

test('editing the amplitude re-runs the period check, which still agrees', async () => {
  await typeIntoCell(page, 'pendulumStart', 'pendulumStart = [1.5, 0]');
  await page.waitForFunction(
    () => {
      const w = document.querySelector('[data-cell="periodCheck"] [data-widget="theory-check"]');
      return w && Number(w.dataset.tolerance) > 0.01;
    },
    null,
    { timeout: 20_000 },
  );
  assertPeriod(await periodCheck(), 2, 1.5);
  assert.deepEqual(problems, []);
  await cell(page, 'pendulumStart').locator('[data-cell-reset]').click();
});
