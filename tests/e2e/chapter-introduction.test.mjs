/**
 * /introduction/: the paper's default model in a simulator with every widget
 * kind, its two theory checks, Space on a focused simulator, and a CSV
 * download that matches `phasebook simulate` for the same model.
 */
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
import { before, test } from 'node:test';
import { assertAgrees, assertDrawn, theoryChecks, useChapter } from './chapter-checks.mjs';
import { cell, typeIntoCell } from './fixture.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const H = 'p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t+beta)';
const PARAMS = { u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 10, f: 20 };
const DT = 5e-4;
const EVERY = 1;
/** The interval typed into the data panel. */
const T0 = 0;
const T1 = 1;
/** Rows with T0 ≤ t ≤ T1, each at t = steps·dt as the core computes it, and the last of their times. */
const rowTimes = [];
for (let i = 0; i * EVERY * DT <= T1; i++) if (i * EVERY * DT >= T0) rowTimes.push(i * EVERY * DT);
const LAST_T = rowTimes[rowTimes.length - 1];

const WIDGETS = '[data-widget]';
const simulatorIn = (page, id) => cell(page, id).locator('[data-widget="simulator"]');

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;
/** The CLI's output for the same model and interval, started at once: it takes seconds to start. */
let cli;

before(async () => {
  const args = ['bin/phasebook.mjs', 'simulate', '--hamiltonian', H, '--dof', '1', '--initial', '2,0'];
  for (const [name, value] of Object.entries(PARAMS)) args.push('--param', `${name}=${value}`);
  args.push('--dt', String(DT), '--t-end', String(LAST_T), '--every', String(EVERY));
  cli = promisify(execFile)(process.execPath, args, { cwd: ROOT, maxBuffer: 1 << 26 });
  cli.catch(() => {}); // awaited in its test
});
useChapter('/introduction/', (opened) => ({ page, problems } = opened));

test('every widget kind is on the page, ready, and has drawn', async () => {
  const kinds = await page.$$eval(WIDGETS, (all) => all.map((w) => w.dataset.widget));
  for (const kind of ['simulator', 'time-plot', 'phase-portrait', 'spectrum', 'trajectory', 'theory-check', 'equations']) {
    assert.ok(kinds.includes(kind), `no ${kind} widget; found ${kinds.join(', ')}`);
  }
  // Three simulators: the default model, the Lissajous figure, the batch; each with controls and a data panel.
  for (const id of ['sim', 'lissajous', 'batch']) {
    const root = simulatorIn(page, id);
    assert.equal(await root.count(), 1, `simulator in ${id}`);
    assert.ok(await root.locator('.pb-transport button').first().isVisible());
    assert.ok(await root.locator('.pb-data').getByRole('button', { name: 'Download CSV' }).isVisible());
  }
  assert.equal(await simulatorIn(page, 'batch').evaluate((el) => el.simulator.simulation.count), 9);
  assert.deepEqual(await simulatorIn(page, 'sim').evaluate((el) => el.simulator.simulation.record.columns), ['t', 'q', 'p', 'H']);
  // The spectrum compares its strongest peak with the drive frequency it marks once a peak completes 1.5 periods
  // in its window. A simulator out of view pauses, and the reading through the chapter passed this one by in
  // moments (less simulated time the busier the machine): the reader looks at it, and it runs until it has one.
  await simulatorIn(page, 'sim').scrollIntoViewIfNeeded();
  await simulatorIn(page, 'sim').locator('[data-widget="spectrum"]', { hasText: /drive κ\/2π/ }).waitFor();
  // H typeset from the model.
  assert.ok((await page.locator('[data-widget="equations"] .katex').count()) > 0);

  // Every plot canvas has drawn something besides its background.
  await assertDrawn(page, '[data-widget="time-plot"], [data-widget="phase-portrait"], [data-widget="spectrum"], [data-widget="trajectory"]', 7);
  assert.deepEqual(problems, []);
});

test('the theory checks agree: the drive line at κ/2π, and the 16× error ratio of RK 3/8', async () => {
  const [line, order] = await theoryChecks(page);
  assertAgrees(line, { relative: false });
  assert.ok(Math.abs(line.predicted - 8 / (2 * Math.PI)) < 1e-12);
  // The forced response of a linear equation is at κ exactly, and the integrator keeps it there:
  // only the measurement's error is allowed, the other lines' leakage, a small part of the resolution 1/T.
  assert.equal(line.errorFormula, 0);
  assert.equal(line.errorIntegration, 0);
  assert.ok(line.errorMeasurement > 0 && line.errorMeasurement < 0.1 / 40, String(line.errorMeasurement));
  assertAgrees(order, { relative: false });
  assert.equal(order.predicted, 16);
  // The next order of the error series: 8ΩΔt with Ω = γ = 21.7, the fastest rate in H.
  assert.ok(Math.abs(order.errorFormula - 8 * 21.7 * DT) < 1e-12, String(order.errorFormula));
  assert.ok(order.tolerance < 1, String(order.tolerance));
});

test('Space plays and pauses the simulator that has focus', async () => {
  const sim = simulatorIn(page, 'sim');
  const playing = () => sim.evaluate((el) => el.simulator.driver.playing);
  assert.equal(await playing(), true);
  await sim.focus();
  await page.keyboard.press('Space');
  assert.equal(await playing(), false);
  await page.keyboard.press('Space');
  assert.equal(await playing(), true);
  assert.equal(await sim.getByRole('button', { name: 'Pause' }).count(), 1);
});

test('the CSV download has the header, the rows of the interval, and the CLI’s numbers', async (t) => {
  const sim = simulatorIn(page, 'sim');
  // Out of view it would pause: the reader looks at it while it runs past the interval.
  await sim.scrollIntoViewIfNeeded();
  await page.waitForFunction((el) => el.simulator.simulation.t > 1.2, await sim.elementHandle());
  await sim.locator('input[aria-label^="Export from time t0"]').fill(String(T0));
  await sim.locator('input[aria-label^="Export to time t1"]').fill(String(T1));
  const [download] = await Promise.all([page.waitForEvent('download'), sim.getByRole('button', { name: 'Download CSV' }).click()]);
  const csv = await readFile(await download.path(), 'utf8');
  const lines = csv.trimEnd().split('\n');
  assert.equal(lines[0], 't,q,p,H');
  assert.equal(lines.length - 1, rowTimes.length);
  assert.equal(Number(lines[1].split(',')[0]), T0);
  assert.equal(Number(lines.at(-1).split(',')[0]), LAST_T);
  // The same core, dt and every give the same numbers. They are not always bit-identical: the
  // browser's Math.cos (and exp, log, …) may round differently from Node's in the last bit, so the
  // comparison allows a few units in the last place of each column's scale; times are exact.
  const { stdout } = await cli;
  const reference = stdout.trimEnd().split('\n');
  assert.equal(reference[0], lines[0]);
  assert.equal(reference.length, lines.length);
  const rows = (text) => text.slice(1).map((line) => line.split(',').map(Number));
  const [mine, theirs] = [rows(lines), rows(reference)];
  const scale = [0, 1, 2, 3].map((c) => Math.max(...mine.map((r) => Math.abs(r[c]))));
  let identical = 0;
  mine.forEach((row, i) => {
    assert.equal(row[0], theirs[i][0], `t of row ${i + 1}`);
    row.forEach((value, c) => {
      if (value === theirs[i][c]) identical++;
      else assert.ok(Math.abs(value - theirs[i][c]) <= 4 * Number.EPSILON * scale[c], `row ${i + 1} column ${c}: ${value} vs ${theirs[i][c]}`);
    });
  });
  t.diagnostic(`${identical} of ${4 * mine.length} values bit-identical to the CLI's`);
  assert.ok(identical >= 0.9 * 4 * mine.length, `only ${identical} of ${4 * mine.length} values identical`);
  assert.deepEqual(problems, []);
});

test('editing a parameter re-runs the checks; the drive line follows κ', async () => {
  await typeIntoCell(page, 'params', 'params = ({u: 0.3, gamma: 21.7, beta: 0.2, kappa: 5, omega: 10, f: 20})');
  const expected = 5 / (2 * Math.PI);
  await page.waitForFunction(
    (f) => Math.abs(Number(document.querySelector('[data-widget="theory-check"]')?.dataset.predicted) - f) < 1e-12,
    expected,
  );
  await page.waitForFunction(() => document.querySelectorAll('[data-widget="theory-check"]').length === 2, null);
  const [line, order] = await theoryChecks(page);
  assertAgrees(line, { relative: false });
  assert.ok(Math.abs(line.predicted - expected) < 1e-12);
  assertAgrees(order, { relative: false });
  await page.waitForFunction(() => document.querySelector('[data-cell="sim"] [data-widget="simulator"]')?.hasAttribute('data-ready'), null);
  assert.equal(await simulatorIn(page, 'sim').evaluate((el) => el.simulator.model.params[3]), 5);
  assert.deepEqual(problems, []);
});
