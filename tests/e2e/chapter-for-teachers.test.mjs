/**
 * /for-teachers/: the page renders the chapter template (templates/chapter.mdx)
 * live, so a teacher's copy is known to run: its cells run without errors, its
 * simulator draws, and its theory check agrees with the pendulum's period
 * computed here; an edit of the amplitude re-runs the check.
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { assertAgrees, drawnPixels, resetCell, theoryCheckIn, useChapter } from './chapter-checks.mjs';
import { errorOf, typeIntoCell } from './fixture.mjs';

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

const TEMPLATE_CELLS = ['pendulum', 'pendulumH', 'pendulumStart', 'pendulumModel', 'pendulumEquations', 'pendulumSimulator', 'periodCheck'];

/** The page is open once these widgets are there (and every widget is ready). */
const EXPECTED = { simulator: 1, equations: 1, 'theory-check': 1 };

useChapter('/for-teachers/', (opened) => ({ page, problems } = opened), { widgets: EXPECTED });

/** The period check, its numbers parsed. */
const periodCheck = () => theoryCheckIn(page, 'periodCheck');

function assertPeriod(check, omega0, theta0) {
  assertAgrees(check, { relative: true });
  const predicted = ((2 * Math.PI) / omega0) * (1 + theta0 ** 2 / 16);
  assert.ok(Math.abs(check.predicted - predicted) < 1e-12, `page ${check.predicted}, test ${predicted}`);
  // The formula's error: 11θ0⁴/3072 and the terms after it, each smaller by at most (θ0/π)², relative to the prediction.
  const left = (11 * theta0 ** 4) / 3072 / (1 - (theta0 / Math.PI) ** 2) / (1 + theta0 ** 2 / 16);
  assert.ok(Math.abs(check.errorFormula - left) < 1e-15, `page ${check.errorFormula}, test ${left}`);
}

test('the template runs live on the page: every cell, the simulator and the period check', async () => {
  for (const id of TEMPLATE_CELLS) assert.equal(await errorOf(page, id), '', `cell ${id}`);
  assertPeriod(await periodCheck(), 2, 0.5);
  const [{ pixels }] = await drawnPixels(page, '[data-widget="simulator"]');
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
  );
  assertPeriod(await periodCheck(), 2, 1.5);
  assert.deepEqual(problems, []);
  await resetCell(page, 'pendulumStart');
});

test('the table of reserved names is the list the compiler refuses (core/expression/names.ts), each with its meaning', async () => {
  const root = fileURLToPath(new URL('../../', import.meta.url));
  // The core's list, read by the core itself (TypeScript, so through tsx).
  const source = JSON.parse(
    execFileSync(process.execPath, ['--import', 'tsx', '--eval', "import('./core/index.ts').then((c) => console.log(JSON.stringify(c.RESERVED_NAMES)))"], { cwd: root, encoding: 'utf8' }),
  );
  const rows = await page.locator('[data-reserved-names] tbody tr').evaluateAll((trs) =>
    trs.map((tr) => ({ names: [...tr.querySelectorAll('[data-reserved-name]')].map((c) => c.textContent), meaning: tr.cells[1].textContent })),
  );
  assert.deepEqual(rows.flatMap(({ names, meaning }) => names.map((name) => ({ name, meaning }))), source);
  assert.ok(source.some(({ name, meaning }) => name === 'E' && meaning.startsWith("Euler's number")));
});
