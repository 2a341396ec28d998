/**
 * /liouville/: the area a flow keeps or shrinks, measured in the page by
 * the ensemble's tracked boundary, and the returns of a section against
 * Kac's lemma, swept across their regimes against references this file
 * computes itself, independently of the book: the area πr² a Hamiltonian
 * flow keeps (Liouville 1838) and πr²e^(−γT) a damping leaves (Liouville's
 * formula), the mean return 1/ε (Kac 1947), the Fibonacci numbers at which
 * the golden rotation comes closest, worked out here; the boundary's
 * vertices against this suite's own RK4 from their points on the circle
 * (sweep-physics.mjs). And the chapter's exercises, answered in the page.
 */
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { assertAgrees, assertLoadsClean, assertNoCellErrors, assertNoNaNShown, assertSumOfTerms, editAndReadChecks, theoryCheckIn, useChapter } from './chapter-checks.mjs';
import { typeIntoCell } from './fixture.mjs';
import { answer, answerCode } from './exercise-answers.mjs';
import { rk4 } from './sweep-physics.mjs';

const CHECKS = ['areaCheck', 'splittingCheck', 'dampedCheck', 'kacCheck'];
const GOLDEN = (1 + Math.sqrt(5)) / 2;
const DISC = Math.PI * 0.6 * 0.6;
const DAMPED_DISC = Math.PI * 0.5 * 0.5;

/** The Fibonacci numbers up to `limit`, 1, 2, 3, 5, … (the first 1 once). */
function fibonacciUpTo(limit) {
  const out = [1];
  for (let [a, b] = [1, 2]; b <= limit; [a, b] = [b, a + b]) out.push(b);
  return out;
}

/** @type {import('playwright-core').Page} */
let page;
/** @type {string[]} */
let problems;

useChapter('/liouville/', (opened) => ({ page, problems } = opened));

/** Reads the checks by cell, scrolled to so that the cells far from the first view run. */
async function checksNow() {
  const all = {};
  for (const id of CHECKS) {
    await page.locator(`[data-cell="${id}"]`).scrollIntoViewIfNeeded();
    await page.waitForSelector(`[data-cell="${id}"] [data-widget="theory-check"][data-ready]`);
    all[id] = [await theoryCheckIn(page, id)];
  }
  return all;
}

test('the page loads clean: every cell runs, the two ensembles draw their clouds, and the four checks get ready', async () => {
  await checksNow();
  await assertLoadsClean(page, problems, { '[data-widget="theory-check"]': 4, '[data-widget="ensemble"]': 2, '[data-widget="table"]': 1 });
  for (const ensemble of await page.locator('[data-widget="ensemble"]').all()) {
    await ensemble.scrollIntoViewIfNeeded();
    assert.ok(Number(await ensemble.getAttribute('data-points')) > 15_000, 'the cloud is drawn');
  }
  await assertNoNaNShown(page);
});

test('at the defaults every check agrees with this file’s formulas: πr², Verlet’s πr², e^(−γT), 1/ε', async () => {
  const { areaCheck: [area], splittingCheck: [splitting], dampedCheck: [damped], kacCheck: [kac] } = await checksNow();
  for (const check of [area, splitting, damped, kac]) {
    assertAgrees(check);
    assertSumOfTerms(check);
  }
  assert.ok(Math.abs(area.predicted - DISC) < 1e-12 * DISC);
  assert.ok(Math.abs(splitting.predicted - DISC) < 1e-12 * DISC);
  assert.ok(Math.abs(damped.predicted - Math.exp(-0.1 * 20)) < 1e-12);
  assert.ok(Math.abs(kac.predicted - 10) < 1e-12);
  // the allowances are small parts of the values: a blob that lost a thousandth of its area would be told
  assert.ok(area.tolerance < 1e-3 * DISC, JSON.stringify(area));
  assert.ok(damped.tolerance < 1e-3 * damped.predicted, JSON.stringify(damped));
  assert.ok(kac.tolerance < 0.1 * kac.predicted, JSON.stringify(kac));
  // RK 3/8 at Verlet's step loses area beyond Verlet's allowance: the splitting check shows a real difference
  const times = Number(/(\d+) times this allowance/.exec(splitting.text)?.[1]);
  assert.ok(times > 1, splitting.text);
});

test('the closest returns come at the Fibonacci numbers, each closer by the golden ratio', async () => {
  const table = page.locator('[data-widget="table"]');
  await table.scrollIntoViewIfNeeded();
  const rows = await table.locator('tbody tr').evaluateAll((trs) => trs.map((tr) => [...tr.querySelectorAll('td')].map((td) => Number(td.textContent.replace('−', '-').replace(/[\s,]/g, '')))));
  assert.deepEqual(rows.map((r) => r[0]), fibonacciUpTo(2000));
  // ‖F_k φ‖ = φ^(−k) (Binet), F_k the k-th row's n (the row of n = 1 is k = 2), as the simulation sees it: its phase
  // lags by RK 3/8's (ωΔt)⁵/120 a step, 2π/Δt steps a crossing, twice over for the start's own error in the bound
  const lagPerCrossing = ((GOLDEN * 0.02) ** 5 / 120) * (2 * Math.PI / 0.02) / (2 * Math.PI);
  rows.forEach(([n, distance], i) => {
    const exact = GOLDEN ** -(i + 2);
    assert.ok(Math.abs(distance - exact) <= 2 * lagPerCrossing * n + 5e-3 * exact, `n = ${n}: ${distance} vs φ^(−${i + 2}) = ${exact}`);
  });
});

test('sweep of the step: at Δt = 0.05 the RK 3/8 and damped checks agree with larger allowances', async () => {
  const { areaCheck: [before] } = await checksNow();
  const checks = await editAndReadChecks(page, 'dt', 'dt = 0.05', ['areaCheck', 'dampedCheck']);
  for (const [check] of Object.values(checks)) {
    assertAgrees(check);
    assertSumOfTerms(check);
  }
  assert.ok(checks.areaCheck[0].errorIntegration > before.errorIntegration, `${checks.areaCheck[0].errorIntegration} vs ${before.errorIntegration}`);
  await editAndReadChecks(page, 'dt', 'dt = 0.01', ['areaCheck', 'dampedCheck']);
});

test('sweep of the damping: γ = 0.3 and anti-damping γ = −0.05 agree with e^(−γT); a term of −2γp disagrees', async () => {
  for (const gamma of [0.3, -0.05]) {
    const { dampedCheck: [check] } = await editAndReadChecks(page, 'gamma', `gamma = ${gamma}`, ['dampedCheck']);
    assertAgrees(check);
    assert.ok(Math.abs(check.predicted - Math.exp(-gamma * 20)) < 1e-12 * Math.exp(-gamma * 20), `${check.predicted}`);
  }
  await editAndReadChecks(page, 'gamma', 'gamma = 0.1', ['dampedCheck']);
  // the area then falls as e^(−2γT): the check must see that the divergence is not −γ
  const { dampedCheck: [wrong] } = await editAndReadChecks(page, 'dampedModel', 'dampedModel = canonicalEquations({dof: 1, hamiltonian: "p^2/2 + q^2/2", nonHamiltonian: {p: "-2*gamma*p"}, params: {gamma}})', ['dampedCheck']);
  assert.equal(wrong.verdict, 'disagrees', JSON.stringify(wrong));
  assert.ok(Math.abs(wrong.measured - Math.exp(-0.2 * 20)) < 1e-3 * Math.exp(-4), `${wrong.measured}`);
  await editAndReadChecks(page, 'dampedModel', 'dampedModel = canonicalEquations({dof: 1, hamiltonian: "p^2/2 + q^2/2", nonHamiltonian: {p: "-gamma*p"}, params: {gamma}})', ['dampedCheck']);
});

test('a model with a non-Hamiltonian term is outside the area check’s validity', async () => {
  const { areaCheck: [check] } = await editAndReadChecks(page, 'model', 'model = canonicalEquations({dof: 1, hamiltonian: H, params: {omega}, nonHamiltonian: {p: "-0.01*p"}})', ['areaCheck']);
  assert.equal(check.verdict, 'outside', JSON.stringify(check));
  assert.match(check.reason, /non-Hamiltonian/);
  await editAndReadChecks(page, 'model', 'model = canonicalEquations({dof: 1, hamiltonian: H, params: {omega}})', ['areaCheck']);
});

test('sweep of the section: √2 and a wider arc agree with 1/ε; a rational ratio and coupled oscillators are outside', async () => {
  let { kacCheck: [check] } = await editAndReadChecks(page, 'ratio', 'ratio = sqrt(2)', ['kacCheck']);
  assertAgrees(check);
  assert.ok(Math.abs(check.predicted - 10) < 1e-12);
  ({ kacCheck: [check] } = await editAndReadChecks(page, 'arc', 'arc = 0.05', ['kacCheck']));
  assertAgrees(check);
  assert.ok(Math.abs(check.predicted - 20) < 1e-12);
  await editAndReadChecks(page, 'arc', 'arc = 0.1', ['kacCheck']);
  ({ kacCheck: [check] } = await editAndReadChecks(page, 'ratio', 'ratio = 1.5', ['kacCheck']));
  assert.equal(check.verdict, 'outside', JSON.stringify(check));
  assert.match(check.reason, /periodic/);
  await editAndReadChecks(page, 'ratio', 'ratio = (1 + sqrt(5)) / 2', ['kacCheck']);
  ({ kacCheck: [check] } = await editAndReadChecks(page, 'pair', 'pair = canonicalEquations({dof: 2, hamiltonian: "(p1^2 + q1^2)/2 + (p2^2 + ratio^2*q2^2)/2 + 0.1*q1^2*q2^2", params: {ratio}, coordinates: [\'q1\', \'q2\'], momenta: [\'p1\', \'p2\']})', ['kacCheck']));
  assert.equal(check.verdict, 'outside', JSON.stringify(check));
  assert.match(check.reason, /no rotation/);
  await editAndReadChecks(page, 'pair', 'pair = canonicalEquations({dof: 2, hamiltonian: "(p1^2 + q1^2)/2 + (p2^2 + ratio^2*q2^2)/2", params: {ratio}, coordinates: [\'q1\', \'q2\'], momenta: [\'p1\', \'p2\']})', ['kacCheck']);
  await assertNoCellErrors(page);
});

test('the pendulum’s ensemble plays and keeps its area; its boundary’s vertices are this file’s RK4 images of their points on the circle', async () => {
  const blob = page.locator('[data-cell="blob"] [data-widget="ensemble"]');
  await blob.scrollIntoViewIfNeeded();
  await page.waitForFunction(() => Number(document.querySelector('[data-cell="blob"] [data-widget="ensemble"]')?.dataset.t) >= 5);
  const read = async () => blob.evaluate((root) => ({ ...root.dataset }));
  const now = await read();
  assert.ok(Number(now.vertices) > 256, 'the boundary was refined as it stretched');
  assert.ok(Math.abs(Number(now.area) - DISC) <= Number(now.areaError), `${now.area} ± ${now.areaError} vs ${DISC}`);
  // pause, then download the boundary and follow three of its vertices from the circle with this file's RK4
  await blob.getByRole('button', { name: /Pause/ }).click();
  const paused = await read();
  const [download] = await Promise.all([page.waitForEvent('download'), blob.getByRole('button', { name: /Download boundary/ }).click()]);
  const text = await (await download.createReadStream()).toArray().then((chunks) => Buffer.concat(chunks).toString('utf8'));
  const lines = text.trim().split('\n');
  assert.equal(lines[0], 's,q,p');
  assert.equal(lines.length - 1, Number(paused.vertices));
  const t = Number(paused.t);
  const rate = (_, [q, p]) => [p, -Math.sin(q)];
  for (const line of [lines[1], lines[Math.floor(lines.length / 3)], lines[lines.length - 1]]) {
    const [s, q, p] = line.split(',').map(Number);
    const start = [0.6 * Math.cos(2 * Math.PI * s), 1.2 + 0.6 * Math.sin(2 * Math.PI * s)];
    const steps = Math.round(t / 0.0025);
    const [qr, pr] = rk4(rate, start, 0, t / steps, steps);
    assert.ok(Math.hypot(q - qr, p - pr) < 1e-6, `s = ${s}: (${q}, ${p}) vs (${qr}, ${pr})`);
  }
});

test('a click moves the disc and starts again; the damped ensemble shrinks as e^(−γt)', async () => {
  const blob = page.locator('[data-cell="blob"] [data-widget="ensemble"]');
  await blob.scrollIntoViewIfNeeded();
  const box = await blob.locator('canvas').boundingBox();
  await blob.locator('canvas').click({ position: { x: box.width / 2, y: box.height / 2 } });
  await page.waitForFunction(() => Number(document.querySelector('[data-cell="blob"] [data-widget="ensemble"]')?.dataset.t) < 1);
  const damped = page.locator('[data-cell="dampedBlob"] [data-widget="ensemble"]');
  await damped.scrollIntoViewIfNeeded();
  await page.waitForFunction(() => Number(document.querySelector('[data-cell="dampedBlob"] [data-widget="ensemble"]')?.dataset.t) >= 5);
  await damped.getByRole('button', { name: /Pause/ }).click();
  const now = await damped.evaluate((root) => ({ ...root.dataset }));
  const expected = DAMPED_DISC * Math.exp(-0.1 * Number(now.t));
  assert.ok(Math.abs(Number(now.area) - expected) <= Number(now.areaError) + 1e-6 * expected, `${now.area} ± ${now.areaError} vs ${expected}`);
  assert.equal(now.state, 'paused');
});

test('a bad option is reported under its cell; the rest keeps working; fixing it recovers', async () => {
  await page.locator('[data-cell="blob"]').scrollIntoViewIfNeeded();
  await typeIntoCell(page, 'radius', 'radius = -1');
  await page.waitForFunction(() => /radius must be positive/.test(document.querySelector('[data-cell="blob"] [data-cell-error]')?.textContent ?? ''));
  assert.equal(await page.locator('[data-cell="dampedBlob"] [data-cell-error]:visible').count(), 0);
  await typeIntoCell(page, 'radius', 'radius = 0.6');
  await page.waitForSelector('[data-cell="blob"] [data-widget="ensemble"][data-ready]');
  await assertNoCellErrors(page);
});

test('the exercises, answered in the page: right answers from closed forms computed here pass, the known slips fail with their reason', async () => {
  assert.equal((await answer(page, 'damped-area', (0.25 * Math.PI * Math.exp(-1)).toFixed(4))).result, 'passed');
  let v = await answer(page, 'damped-area', '0.4764');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /amplitude/);
  assert.equal((await answer(page, 'area-halving', (Math.LN2 / 0.1).toFixed(3))).result, 'passed');
  assert.equal((await answer(page, 'kac-return', '20')).result, 'passed');
  v = await answer(page, 'kac-return', '10');
  assert.equal(v.result, 'failed');
  // the first n with nφ within 0.001 of a whole number, searched here
  let n = 1;
  while (Math.abs(n * GOLDEN - Math.round(n * GOLDEN)) >= 0.001) n++;
  assert.equal((await answer(page, 'first-close-return', String(n))).result, 'passed');
  v = await answer(page, 'first-close-return', '377');
  assert.equal(v.result, 'failed');
  // frequencies 1 and 3/2: ω² = 9/4 on the second oscillator's spring
  assert.equal((await answerCode(page, 'exact-recurrence', 'myPair', 'myPair = "(p0^2 + q0^2)/2 + (p1^2 + 2.25*q1^2)/2"')).result, 'passed');
  assert.equal((await answerCode(page, 'exact-recurrence', 'myPair', 'myPair = "(p0^2 + q0^2)/2 + (p1^2 + 1.5*q1^2)/2"')).result, 'failed');
  assert.deepEqual(problems, []);
});
