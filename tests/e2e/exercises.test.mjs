/**
 * The exercises (issue 22), answered in the page as a reader answers them:
 * for each, the right answer passes and plausible wrong ones fail with the
 * sentence that explains them. The right numbers are computed here from
 * closed forms (named at each), not read from the page; the frequencies of
 * the nonlinear oscillator come from this file's own RK4 integration, an
 * independent method. Then hints one at a time, the solution's confirmation,
 * "show me in the simulator" and its undo, a throwing and a runaway answer,
 * progress over a reload and through export, reset and import, a storage
 * failure said aloud, the keyboard, axe at 1280 and 390 px, and that no
 * exercise code loads with a chapter's first view.
 */
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { after, before, test } from 'node:test';
import { launchBrowser } from './browser.mjs';
import { cell, errorOf, firstViewReady, openSite, typeIntoCell, waitForOutput, watchPage } from './fixture.mjs';
import { answer, answerCode, exercise, reach, verdictAfter } from './exercise-answers.mjs';

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite({ viewport: { width: 1280, height: 900 } })));
after(() => site?.close());

const EXERCISE_CHUNK = /\/_astro\/exercises?\.[\w-]+\.js$/;

/** A fresh page on `path`, storage cleared first, with the page's first view ready. */
async function open(path, context = site.context) {
  const page = await context.newPage();
  await page.goto(`${site.origin}/`);
  await page.evaluate(() => localStorage.clear());
  const watch = watchPage(page);
  await page.goto(site.origin + path);
  await firstViewReady(page);
  return { page, ...watch };
}

/** The nonlinear oscillator's angular frequency released from rest at b, from upward zero crossings of a plain RK4 integration (step 1e-4), independent of the book's code. */
function frequencyByRk4(omega0, alpha, beta, b) {
  const force = (q) => -(omega0 ** 2 * q + 3 * alpha * q * q + 4 * beta * q ** 3);
  let [q, p, t] = [b, 0, 0];
  const dt = 1e-4;
  const ups = [];
  while (ups.length < 6) {
    const k1 = [p, force(q)];
    const k2 = [p + (dt / 2) * k1[1], force(q + (dt / 2) * k1[0])];
    const k3 = [p + (dt / 2) * k2[1], force(q + (dt / 2) * k2[0])];
    const k4 = [p + dt * k3[1], force(q + dt * k3[0])];
    const next = q + (dt / 6) * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
    p += (dt / 6) * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
    if (q < 0 && next >= 0) ups.push(t + (dt * -q) / (next - q));
    q = next;
    t += dt;
  }
  return (2 * Math.PI * (ups.length - 1)) / (ups[ups.length - 1] - ups[0]);
}

test('no exercise code loads with a chapter’s first view; it loads when an exercise comes near', async () => {
  const { page, requests, problems } = await open('/nonlinear-oscillator/');
  await page.waitForTimeout(300);
  assert.deepEqual(requests.filter((url) => EXERCISE_CHUNK.test(url)), []);
  await reach(page, 'escape-amplitude');
  assert.ok(requests.some((url) => EXERCISE_CHUNK.test(url)));
  assert.deepEqual(problems, []);
  await page.close();
});

test('introduction: each number exercise passes its right answer and fails two wrong ones, saying why', async () => {
  const { page, problems } = await open('/introduction/');
  // T = 2π/ω (Landau & Lifshitz §21)
  assert.equal((await answer(page, 'period-at-omega-5', String(2 * Math.PI / 5))).result, 'passed');
  let v = await answer(page, 'period-at-omega-5', String(2 * Math.PI * 5));
  assert.equal(v.result, 'failed');
  assert.match(v.text, /divided by ω, not multiplied/);
  v = await answer(page, 'period-at-omega-5', '0.7958');
  assert.match(v.text, /frequency in cycles per unit time/);
  // The forced response of a linear system is at the drive's κ/2π (Landau & Lifshitz §22).
  assert.equal((await answer(page, 'drive-line', (8 / (2 * Math.PI)).toFixed(4))).result, 'passed');
  v = await answer(page, 'drive-line', '8');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /angular frequency/);
  v = await answer(page, 'drive-line', '1.5915');
  assert.match(v.text, /free oscillator/);
  // |R(iy)| = 1 at y = 2√2 for every four-stage fourth-order RK method (Hairer & Wanner II §IV.2).
  assert.equal((await answer(page, 'rk-stable-step', String(2 * Math.SQRT2 / 10))).result, 'passed');
  v = await answer(page, 'rk-stable-step', '2.828');
  assert.match(v.text, /divided by ω = 10/);
  v = await answer(page, 'rk-stable-step', '0.2');
  assert.match(v.text, /leapfrog/);
  // Bad input is said under the field, and nothing breaks.
  v = await answer(page, 'drive-line', '1,27');
  assert.equal(v.result, 'problem');
  assert.match(v.text, /decimal point/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('introduction: the code exercise passes the reference H written otherwise, and fails a missing mass and a wrong sign with each check’s sentence', async () => {
  const { page, problems } = await open('/introduction/');
  let v = await answerCode(page, 'oscillator-hamiltonian', 'myH', 'myH = "9*q^2 + p^2/4 + 1"');
  assert.equal(v.result, 'passed', v.text);
  assert.match(v.text, /All 2 checks passed/);
  v = await answerCode(page, 'oscillator-hamiltonian', 'myH', 'myH = "p^2/2 + 9*q^2/2"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /1 of 2 checks failed/);
  assert.match(v.text, /Failed: Hamilton’s equations differ at \(q, p\)/);
  assert.match(v.text, /Passed: Released from/);
  v = await answerCode(page, 'oscillator-hamiltonian', 'myH', 'myH = "p^2/4 - 9*q^2"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /2 of 2 checks failed/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('"Check my code" grades the code the reader sees: a Run still compiling is waited for, text not yet run is run first, and text that does not compile is said', async () => {
  const { page, problems } = await open('/introduction/');
  await reach(page, 'oscillator-hamiltonian');
  const check = () => exercise(page, 'oscillator-hamiltonian').getByRole('button', { name: 'Check my code' }).click();
  // The page's first edit: Run fetches the parser and the sandbox before the new code is defined, and Check comes at once.
  let v = await verdictAfter(page, 'oscillator-hamiltonian', async () => {
    await typeIntoCell(page, 'myH', 'myH = "p^2/4 + 9*q^2"');
    await check();
  });
  assert.equal(v.result, 'passed', v.text);
  // Typed, not run: the check runs it, and the cell then holds it.
  v = await verdictAfter(page, 'oscillator-hamiltonian', async () => {
    await typeIntoCell(page, 'myH', 'myH = "p^2/2 + 9*q^2/2"', { run: 'none' });
    await check();
  });
  assert.equal(v.result, 'failed', v.text);
  await waitForOutput(page, 'myH', (out) => out.includes('p^2/2 + 9*q^2/2'));
  // Text that does not compile: the old code still runs, and the check says it is not grading it.
  v = await verdictAfter(page, 'oscillator-hamiltonian', async () => {
    await typeIntoCell(page, 'myH', 'myH = "p^2/4 + 9*q^2', { run: 'none' });
    await check();
  });
  assert.equal(v.result, 'problem');
  assert.match(v.text, /did not compile/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('introduction: a throwing answer and a runaway one are reported under their cell and by the exercise', async () => {
  const { page } = await open('/introduction/');
  let v = await answerCode(page, 'oscillator-hamiltonian', 'myH', 'myH = { throw new Error("no H yet") }');
  assert.equal(v.result, 'problem');
  assert.match(v.text, /Your cell myH stopped with an error, shown under it: .*no H yet/);
  assert.match(await errorOf(page, 'myH'), /no H yet/);
  v = await answerCode(page, 'oscillator-hamiltonian', 'myH', 'myH = { while (true) {} }');
  assert.equal(v.result, 'problem');
  assert.match(v.text, /stopped with an error/);
  assert.match(await errorOf(page, 'myH'), /loop .* was stopped/);
  v = await answerCode(page, 'oscillator-hamiltonian', 'myH', 'myH = 42');
  assert.equal(v.result, 'problem');
  assert.match(v.text, /holds number, not an H/);
  await page.close();
});

test('nonlinear oscillator: numbers against an independent RK4 integration and the barrier’s closed form; the code exercise', async () => {
  const { page, problems } = await open('/nonlinear-oscillator/');
  const atHalf = frequencyByRk4(10, -2, -3, 0.5);
  assert.equal((await answer(page, 'frequency-at-half', atHalf.toFixed(4))).result, 'passed');
  // What the formula ω₀ + ω₂b² gives (Landau & Lifshitz §28), within its neglected terms.
  assert.equal((await answer(page, 'frequency-at-half', String(10 - 0.465 * 0.25))).result, 'passed');
  let v = await answer(page, 'frequency-at-half', '10.116');
  assert.match(v.text, /wrong sign/);
  v = await answer(page, 'frequency-at-half', '9.9715');
  assert.match(v.text, /Landau’s coefficients/);
  assert.equal((await answer(page, 'symmetric-well', frequencyByRk4(10, 0, -3, 1).toFixed(3))).result, 'passed');
  v = await answer(page, 'symmetric-well', '10.45');
  assert.match(v.text, /wrong sign/);
  v = await answer(page, 'symmetric-well', '10');
  assert.match(v.text, /That is ω₀/);
  // The barrier's top: the positive root of ω₀² + 3αq + 4βq² = 0.
  const edge = (-3 * -2 - Math.sqrt(9 * 4 + 16 * 3 * 100)) / (8 * -3);
  assert.equal((await answer(page, 'escape-amplitude', edge.toFixed(3))).result, 'passed');
  v = await answer(page, 'escape-amplitude', '3.148');
  assert.match(v.text, /negative side/);
  v = await answer(page, 'escape-amplitude', '1.98');
  assert.match(v.text, /negative b/);
  v = await answerCode(page, 'landau-force', 'landauH', 'landauH = "p^2/2 + 50*q^2 - 2*q^3 - 3*q^4"');
  assert.equal(v.result, 'passed', v.text);
  v = await answerCode(page, 'landau-force', 'landauH', 'landauH = "p^2/2 + 50*q^2 - 6*q^3 - 12*q^4"');
  assert.equal(v.result, 'failed');
  assert.match(v.text, /2 of 2 checks failed/);
  v = await answerCode(page, 'landau-force', 'landauH', 'landauH = "p^2/2 + 50*q^2 + 2*q^3 + 3*q^4"');
  assert.equal(v.result, 'failed');
  assert.deepEqual(problems, []);
  await page.close();
});

test('hints one at a time, the solution with a confirmation before any attempt, and "show me in the simulator" undone', async () => {
  const { page } = await open('/introduction/');
  await reach(page, 'rk-stable-step');
  const root = exercise(page, 'rk-stable-step');
  const hint = root.getByRole('button', { name: /^Hint 1 of 3$/ });
  await hint.click();
  assert.equal(await root.locator('.exercise-hints li').count(), 1);
  await root.getByRole('button', { name: 'Hint 2 of 3' }).click();
  await root.getByRole('button', { name: 'Hint 3 of 3' }).click();
  assert.equal(await root.locator('.exercise-hints li').count(), 3);
  assert.equal(await root.getByRole('button', { name: 'No more hints' }).isDisabled(), true);
  // Before an attempt the solution asks first; "Not yet" keeps it hidden.
  await root.getByRole('button', { name: 'Show the solution' }).click();
  await root.getByRole('button', { name: 'Not yet' }).click();
  assert.equal(await root.locator('.exercise-solution').isVisible(), false);
  await root.getByRole('button', { name: 'Show the solution' }).click();
  await root.getByRole('button', { name: 'Show it' }).click();
  assert.match((await root.locator('.exercise-solution').textContent()) ?? '', /2√2\/10|0\.283/);
  // The simulator's set-up changes the cells; the undo puts them back.
  await root.getByRole('button', { name: 'Show me in the simulator' }).click();
  await waitForOutput(page, 'dt', (out) => out.includes('0.25'));
  await waitForOutput(page, 'params', (out) => /f: 0\b/.test(out));
  await root.getByRole('button', { name: 'Undo: put the cells back' }).click();
  await waitForOutput(page, 'dt', (out) => out.includes('0.0005'));
  await waitForOutput(page, 'params', (out) => /f: 20\b/.test(out));
  assert.equal(await cell(page, 'dt').locator('[data-cell-reset]').isDisabled(), true, 'the undone cell is the chapter’s again');
  await page.close();
});

test('progress survives a reload, shows on the progress page, and goes through export, reset and import', async () => {
  const { page, problems } = await open('/introduction/');
  await answer(page, 'period-at-omega-5', '31.4');
  await answer(page, 'period-at-omega-5', String(2 * Math.PI / 5));
  await answer(page, 'drive-line', '8');
  await page.reload();
  await firstViewReady(page);
  await reach(page, 'period-at-omega-5');
  assert.match((await exercise(page, 'period-at-omega-5').locator('[data-exercise-status]').textContent()) ?? '', /Solved \(2 checks\)/);
  assert.equal(await exercise(page, 'period-at-omega-5').getByLabel(/Your answer/).inputValue(), String(2 * Math.PI / 5));
  await reach(page, 'drive-line');
  assert.match((await exercise(page, 'drive-line').locator('[data-exercise-status]').textContent()) ?? '', /Not solved yet \(1 check\)/);

  await page.goto(`${site.origin}/progress/`);
  const state = (id) => page.locator(`[data-progress-id="${id}"] [data-progress-state]`).textContent();
  await page.waitForFunction(() => document.querySelector('[data-progress-summary]')?.textContent !== '');
  assert.match(await state('period-at-omega-5'), /Solved/);
  assert.match(await state('drive-line'), /Not solved yet/);
  assert.match(await state('landau-force'), /Not tried/);
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Export to a file' }).click()]);
  const file = JSON.parse(await readFile(await download.path(), 'utf8'));
  assert.equal(file.chapters.introduction['period-at-omega-5'].status, 'solved');

  await page.getByRole('button', { name: 'Reset all progress' }).click();
  await page.getByRole('button', { name: 'Forget them' }).click();
  await page.waitForFunction(() => /Every result was forgotten/.test(document.querySelector('[data-progress-message]')?.textContent ?? ''));
  assert.match(await state('period-at-omega-5'), /Not tried/);

  await page.locator('[data-progress-import]').setInputFiles(await download.path());
  await page.waitForFunction(() => /Imported 2 exercise results/.test(document.querySelector('[data-progress-message]')?.textContent ?? ''));
  assert.match(await state('period-at-omega-5'), /Solved \(2 checks\)/);
  assert.match(await state('drive-line'), /Not solved yet/);

  await page.locator('[data-progress-import]').setInputFiles({ name: 'x.json', mimeType: 'application/json', buffer: Buffer.from('{"format": "something else"}') });
  await page.waitForFunction(() => /not a Phasebook progress export/.test(document.querySelector('[data-progress-message]')?.textContent ?? ''));
  assert.deepEqual(problems, []);
  await page.close();
});

test('a browser that keeps nothing: the exercise still grades, and says its result will not be kept', async () => {
  const page = await site.context.newPage();
  await page.addInitScript(() => {
    Storage.prototype.setItem = function () {
      throw new DOMException('full', 'QuotaExceededError');
    };
  });
  // Nothing kept from earlier tests either: not even the book's secret, which nothing can now write.
  await page.goto(`${site.origin}/`);
  await page.evaluate(() => localStorage.clear());
  await page.goto(`${site.origin}/introduction/`);
  await firstViewReady(page);
  const v = await answer(page, 'drive-line', '1.2732');
  assert.equal(v.result, 'passed');
  const note = exercise(page, 'drive-line').locator('[data-exercise-storage]');
  assert.equal(await note.getAttribute('role'), 'alert');
  assert.match((await note.textContent()) ?? '', /holds for this visit only/);
  await page.goto(`${site.origin}/progress/`);
  await page.waitForFunction(() => /keeps nothing/.test(document.querySelector('[data-progress-message]')?.textContent ?? ''));
  await page.close();
});

test('by keyboard alone: Tab to the labelled field, type, Enter; the verdict is in a polite live region', async () => {
  const { page } = await open('/introduction/');
  await reach(page, 'drive-line');
  const root = exercise(page, 'drive-line');
  const field = root.getByLabel('Your answer, in cycles per unit time');
  // Focus the element just before the field, then Tab into it.
  await root.locator('.exercise-prompt').evaluate((prompt) => {
    prompt.tabIndex = -1;
    prompt.focus();
  });
  await page.keyboard.press('Tab');
  assert.ok(await field.evaluate((input) => input === document.activeElement));
  const v = await verdictAfter(page, 'drive-line', async () => {
    await page.keyboard.type('1.2732');
    await page.keyboard.press('Enter');
  });
  assert.equal(v.result, 'passed');
  const feedback = root.locator('[data-exercise-feedback]');
  assert.equal(await feedback.getAttribute('aria-live'), 'polite');
  assert.equal(await feedback.getAttribute('role'), 'status');
  await page.keyboard.press('Tab');
  await page.keyboard.press('Tab');
  assert.match(await page.evaluate(() => document.activeElement?.textContent ?? ''), /Hint 1 of 2/);
  await page.keyboard.press('Enter');
  assert.equal(await root.locator('.exercise-hints li').count(), 1);
  await page.close();
});

async function axeViolations(page) {
  await page.evaluate(AXE);
  return page.evaluate(async () =>
    (await window.axe.run(document, { resultTypes: ['violations'] })).violations.map((v) => `${v.id} (${v.nodes.length}): ${v.nodes[0]?.target.join(' ')}`),
  );
}

for (const [width, options] of [[1280, { viewport: { width: 1280, height: 900 } }], [390, { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true }]]) {
  test(`axe finds nothing with exercises answered, hints and a solution shown, at ${width} px; nor on the progress page`, async () => {
    const browser = width === 1280 ? null : await launchBrowser(options);
    const { page } = await open('/nonlinear-oscillator/', browser?.context ?? site.context);
    await answer(page, 'frequency-at-half', '10');
    await answer(page, 'escape-amplitude', '2.648');
    const root = exercise(page, 'escape-amplitude');
    await root.getByRole('button', { name: /^Hint 1/ }).click();
    await root.getByRole('button', { name: 'Show the solution' }).click();
    assert.deepEqual(await axeViolations(page), []);
    if (width === 390) {
      const small = await root.locator('button').evaluateAll((buttons) => buttons.map((b) => b.getBoundingClientRect()).filter((r) => r.width && (r.height < 44 || r.width < 44)).length);
      assert.equal(small, 0, 'every button is a 44 px target under a finger');
    }
    await page.goto(`${site.origin}/progress/`);
    assert.deepEqual(await axeViolations(page), []);
    await page.close();
    await browser?.close();
  });
}
