/**
 * What a reader sees when a model misbehaves, on /playground/: a blow-up
 * stops the widget with a message, a slow H cannot freeze the page, a full
 * record says it drops old samples, a hidden tab computes nothing, and bad
 * options give a one-line error under the cell while the rest keeps running.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { cell, cellsReady, errorOf, openSite, outputOf, typeIntoCell, waitForOutput, watchPage } from './fixture.mjs';
import { mostStepsInAFrame, watchFrames } from './frame-watch.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

const SIM = '[data-cell="sim"] [data-widget="simulator"]';

/** The playground with no saved edits, its simulator drawn. */
async function openPlayground() {
  const page = await site.context.newPage();
  // Edits are saved in localStorage; every test starts from the chapter's cells.
  await page.addInitScript(() => localStorage.clear());
  const watch = watchPage(page);
  await page.goto(`${site.origin}/playground/`);
  await cellsReady(page);
  await page.waitForSelector(`${SIM}[data-ready]`);
  await inView(page);
  return { page, ...watch };
}

/** What the simulator widget shows and does. */
function widget(page) {
  return page.evaluate((selector) => {
    const el = document.querySelector(selector);
    if (!el) return null;
    const s = el.simulator;
    const alert = el.querySelector('.pb-alert');
    const note = el.querySelector('.pb-note');
    return {
      t: s.simulation.t,
      steps: s.simulation.steps,
      playing: s.driver.playing,
      error: s.simulation.error?.message ?? null,
      alert: alert && !alert.hidden ? alert.textContent : null,
      note: note && !note.hidden ? note.textContent : null,
      readoutT: el.querySelector('.pb-readouts output')?.textContent ?? '',
      speedText: el.querySelector('.pb-speed-text')?.textContent ?? '',
      playDisabled: el.querySelector('.pb-transport button')?.disabled ?? null,
      rows: s.simulation.record.length,
      capacity: s.simulation.record.capacity,
      dropped: s.simulation.record.dropped,
      source: s.model.source,
      route: s.model.route,
    };
  }, SIM);
}

/** Marks the current widget so that a replacement can be told apart. */
const markOld = (page) => page.evaluate((selector) => document.querySelector(selector)?.setAttribute('data-old', ''), SIM);

/** Waits for a simulator created after markOld, drawn and satisfying `check` (run in the page on its handle). */
async function waitForNewWidget(page, check = 'true') {
  await inView(page);
  await page.waitForFunction(
    ({ selector, check }) => {
      const el = document.querySelector(selector);
      if (!el || el.hasAttribute('data-old') || !el.hasAttribute('data-ready')) return false;
      return new Function('s', `return ${check};`)(el.simulator);
    },
    { selector: SIM, check },
  );
  // The new widget may have appeared elsewhere (cells above it re-laid out): out of view it would pause.
  await inView(page);
}

/** Brings the simulator into view: one out of view pauses until it is seen. */
async function inView(page) {
  await page.waitForSelector(SIM);
  await page.evaluate((selector) => document.querySelector(selector)?.scrollIntoView({ block: 'center' }), SIM);
}

/** Resolves when simulated time has moved on by `dt` from `from`. */
async function waitForTime(page, from, dt = 0.05) {
  await inView(page);
  return page.waitForFunction(
    ({ selector, target }) => document.querySelector(selector)?.simulator.simulation.t >= target,
    { selector: SIM, target: from + dt },
  );
}

test('a blow-up pauses the widget with a message naming t and the component; the rest of the page keeps working', async (t) => {
  const { page, problems } = await openPlayground();
  await markOld(page);
  await typeIntoCell(page, 'H', 'H = "p^2/2 - q^4"');
  await typeIntoCell(page, 'initial', 'initial = [1, 0]');
  await waitForNewWidget(page, `s.model.source === 'p^2/2 - q^4' && s.simulation.initial[0] === 1`);
  // From (1, 0), q̈ = 4q³ sends q to infinity at t* = ∫₁^∞ dq / √(2(q⁴ − 1)) ≈ 0.93.
  // Cells above may still re-lay out (the equations of the new H are typeset): the simulator is kept in view, since out of view it pauses.
  await page.waitForFunction(
    (selector) => {
      const el = document.querySelector(selector);
      const box = el?.getBoundingClientRect();
      if (box && (box.bottom < 0 || box.top > innerHeight)) el.scrollIntoView({ block: 'center' });
      return !document.querySelector(`${selector} .pb-alert`)?.hidden;
    },
    SIM,
  );
  const stopped = await widget(page);
  const match = /^Stopped: the state became (-?Infinity|NaN) at t = ([\d.e-]+) in (q|p);.*Restart, or try a smaller dt\.$/.exec(stopped.alert);
  assert.ok(match, `alert: ${stopped.alert}`);
  const tBlowUp = Number(match[2]);
  // t* = K(1/√2)/2 = π / (4 AGM(1, 1/√2)); the state overflows within a few steps after it.
  let [a, b] = [1, Math.SQRT1_2];
  for (let i = 0; i < 8; i++) [a, b] = [(a + b) / 2, Math.sqrt(a * b)];
  const tStar = Math.PI / (4 * a);
  t.diagnostic(stopped.alert);
  assert.ok(tBlowUp >= tStar && tBlowUp < tStar + 0.01, `blow-up at t = ${tBlowUp}, t* = ${tStar}`);
  assert.equal(stopped.playing, false);
  assert.equal(stopped.playDisabled, true, 'play is disabled until a restart');
  assert.doesNotMatch(stopped.speedText, /behind/, 'stopped is not behind real time');
  assert.ok(Math.abs(stopped.t - tBlowUp) < 1e-3, `readout t ${stopped.t} vs message ${tBlowUp}`);
  // Paused: time stands still.
  await page.waitForTimeout(400);
  assert.equal((await widget(page)).steps, stopped.steps);

  // The rest of the page: the equations are still shown, another cell still runs.
  assert.equal(await errorOf(page, 'sim'), '');
  assert.match(await cell(page, 'hamiltonsEquations').locator('[data-widget="equations"]').textContent(), /q\^?/);
  await typeIntoCell(page, 'H0', 'H0 = 6 * 7');
  await waitForOutput(page, 'H0', (text) => text === 'H0 = 42');
  assert.equal((await widget(page)).alert, stopped.alert, 'the stopped widget keeps its message');
  // Restart clears the message and runs again until the next blow-up.
  await page.locator(`${SIM} button[aria-label="Restart"], ${SIM} button[title="Back to the initial state"]`).first().click();
  await page.waitForFunction((selector) => document.querySelector(`${selector} .pb-alert`)?.hidden, SIM);
  assert.ok((await widget(page)).t < tBlowUp);

  // Two Kepler bodies started at one point: the force is infinite at once.
  await markOld(page);
  await typeIntoCell(page, 'H', 'H = "p0^2 + p1^2 + p2^2 + p3^2 - 500/sqrt((q0-q2)^2 + (q1-q3)^2)"');
  await typeIntoCell(page, 'dof', 'dof = 4');
  await typeIntoCell(page, 'initial', 'initial = [0, 0, 0, 0, 2, -3, -2, 3]');
  await waitForNewWidget(page, 's.model.dof === 4');
  await page.waitForFunction((selector) => !document.querySelector(`${selector} .pb-alert`)?.hidden, SIM);
  const met = await widget(page);
  assert.match(met.alert, /^Stopped: the state became NaN at t = 0\.0005 in q0;/);
  assert.equal(met.playing, false);
  assert.doesNotMatch(met.speedText, /behind/);
  await typeIntoCell(page, 'H0', 'H0 = 7 * 7');
  await waitForOutput(page, 'H0', (text) => text === 'H0 = 49');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a slow H cannot freeze the page: frames keep coming and the speed readout says it is behind', async (t) => {
  const { page, problems } = await openPlayground();
  await markOld(page);
  // A loop makes the function opaque to the translator: 5-point differences, 32 calls of H per step.
  await typeIntoCell(
    page,
    'H',
    'H = (t, [q, p]) => {\n  let v = 0;\n  for (let i = 0; i < 40000; i++) v += q * q / 80000;\n  return p * p / 2 + v;\n}',
  );
  await waitForNewWidget(page, `s.model.route === 'js-stencil'`);
  const start = await widget(page);
  // Frames keep coming while it integrates, none more than real time owes it (at most 100 ms of it), and, once it
  // is behind, not all of that: a frame that integrated every step owed would take 200 steps of this H (40 000
  // terms a call, 32 calls a step) and the page would freeze. Counted, not timed: a busy machine thins the
  // frames but does not change how the budget cuts them.
  const seen = await watchFrames(page, SIM, 30);
  assert.ok(seen.complete, `only ${seen.frames.length} frames came`);
  const steps = seen.frames.map((f) => f.steps);
  assert.ok(Math.max(...steps) <= mostStepsInAFrame(seen), `steps per frame: ${steps.join(' ')}`);
  // The speed readout (steps a frame ÷ real time, a frame's time counted up to 100 ms) says it is behind: the
  // budget cut the frames. Had frames integrated all they were owed, it would read 100 %.
  await page.waitForFunction((selector) => /behind real time/.test(document.querySelector(`${selector} .pb-speed-text`)?.textContent ?? ''), SIM);
  const later = await widget(page);
  const behind = /behind real time, (\d+)%/.exec(later.speedText);
  assert.ok(behind && Number(behind[1]) < 90, later.speedText);
  t.diagnostic(`${seen.fps.toFixed(1)} fps, steps per frame ${Math.min(...steps)} to ${Math.max(...steps)}; ${later.speedText}`);
  assert.ok(seen.pageSteps > 0, 'it integrated');
  assert.ok(later.t > start.t, 'it still advances');
  // The page answers: a cell runs at once.
  await typeIntoCell(page, 'H0', 'H0 = 1 + 1');
  await waitForOutput(page, 'H0', (text) => text === 'H0 = 2');
  assert.deepEqual(problems, []);
  await page.close();
});

test('with a small capacity the widget says that old samples are dropped', async () => {
  const { page, problems } = await openPlayground();
  await markOld(page);
  await typeIntoCell(page, 'options', "options = ({speed: 1, capacity: 500, views: ['time']})");
  await waitForNewWidget(page, 's.simulation.record.capacity === 500');
  await page.waitForFunction((selector) => !document.querySelector(`${selector} .pb-note`)?.hidden, SIM);
  const state = await widget(page);
  assert.match(state.note, /^The record is full: it keeps the latest 500 samples \(from t = [\d.]+\) and has dropped [\d,]+ older ones; scrolling back and downloads start there\.$/);
  assert.equal(state.rows, 500);
  assert.ok(state.dropped > 0);
  assert.ok(state.playing);
  await waitForTime(page, state.t, 0.1);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a hidden tab computes nothing, and resumes when shown again', async () => {
  const { page, problems } = await openPlayground();
  await waitForTime(page, 0, 0.1);
  await page.evaluate(() => {
    Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => 'hidden' });
    Object.defineProperty(document, 'hidden', { configurable: true, get: () => true });
    document.dispatchEvent(new Event('visibilitychange'));
  });
  const hidden = await widget(page);
  await page.waitForTimeout(800);
  const still = await widget(page);
  assert.equal(still.steps, hidden.steps, 'no steps while hidden');
  assert.equal(still.playing, true, 'still playing: it resumes by itself');
  // Watched from before it is shown again, so that the first frame after is seen.
  const resuming = watchFrames(page, SIM, 3);
  await page.evaluate(() => {
    delete document.visibilityState;
    delete document.hidden;
    document.dispatchEvent(new Event('visibilitychange'));
  });
  await waitForTime(page, still.t, 0.2);
  // It resumes at real-time pace, without a burst to catch up the hidden time: its first frame integrates what one
  // 60 Hz frame owes (2000 steps a second at dt = 5e-4, and less than a step carried), however long it was hidden.
  const resumed = await resuming;
  assert.ok(resumed.complete);
  assert.ok(resumed.frames[0].steps <= Math.ceil((resumed.speed / resumed.dt) / 60) + 1, `the first frame after took ${resumed.frames[0].steps} steps`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('bad options show a one-line error under the cell; the other cells keep running; fixing the cell recovers', async (t) => {
  const { page, problems } = await openPlayground();
  const oneLine = (text) => assert.ok(text.length > 0 && !text.includes('\n') && text.length < 200, `one line: ${JSON.stringify(text)}`);
  const recovers = async () => {
    await waitForNewWidget(page);
    assert.equal(await errorOf(page, 'sim'), '');
    await waitForTime(page, (await widget(page)).t, 0.05);
  };

  // A misspelt option name.
  await markOld(page);
  await typeIntoCell(page, 'options', "options = ({dt: 5e-4, sped: 2, views: ['time']})");
  await page.waitForFunction(() => document.querySelector('[data-cell="sim"] [data-cell-error]')?.textContent?.includes('sped'));
  const typo = await errorOf(page, 'sim');
  oneLine(typo);
  assert.equal(typo, 'InputError: simulator: unknown option "sped"; did you mean "speed"?');
  assert.equal(await page.locator(SIM).count(), 0, 'the old widget is gone, not left running');
  // Another cell still runs.
  await typeIntoCell(page, 'initial', 'initial = [1, 0]');
  // H at (q, p) = (1, 0), t = 0: ω²(1 + u)/2 − f cos β.
  await waitForOutput(page, 'H0', (text) => Math.abs(Number(text.replace('H0 = ', '')) - (50 * (1 + 0.3) - 20 * Math.cos(0.2))) < 1e-9);
  assert.equal(await errorOf(page, 'H0'), '');
  assert.equal(await errorOf(page, 'model'), '');
  await typeIntoCell(page, 'options', "options = ({dt: 5e-4, speed: 2, views: ['time']})");
  await recovers();
  assert.equal(await page.evaluate((s) => document.querySelector(s).simulator.driver.speed, SIM), 2);

  // A wrong number of initial values.
  await markOld(page);
  await typeIntoCell(page, 'initial', 'initial = [2, 0, 1]');
  await page.waitForFunction(() => document.querySelector('[data-cell="sim"] [data-cell-error]')?.textContent?.includes('initial'));
  const count = await errorOf(page, 'sim');
  oneLine(count);
  assert.equal(count, "InputError: simulator: initial has 3 values; it needs 2 (q's then p's for 1 degree(s) of freedom)");
  await typeIntoCell(page, 'initial', 'initial = [2, 0]');
  await recovers();

  // A method with the playground's ready model: the midpoint rule applies to any model; a splitting needs
  // code generated with the model, so it is refused in one line saying where to ask, never dropped.
  await markOld(page);
  await typeIntoCell(page, 'options', "options = ({dt: 5e-4, speed: 1, views: ['time'], method: 'verlet'})");
  await page.waitForFunction(() => document.querySelector('[data-cell="sim"] [data-cell-error]')?.textContent?.includes('verlet'));
  const refused = await errorOf(page, 'sim');
  oneLine(refused);
  assert.match(refused, /^InputError: simulator: the model was built for rk38, and verlet needs code generated with the model; pass method: 'verlet' to canonicalEquations/);
  await typeIntoCell(page, 'options', "options = ({dt: 5e-4, speed: 1, views: ['time'], method: 'midpoint'})");
  await waitForNewWidget(page, "s.model.method?.name === 'midpoint'");
  assert.equal(await errorOf(page, 'sim'), '');
  await waitForTime(page, (await widget(page)).t, 0.05);
  await markOld(page);
  await typeIntoCell(page, 'options', "options = ({dt: 5e-4, speed: 2, views: ['time']})");
  await waitForNewWidget(page, 's.model.method === undefined');

  // A syntax error in H: the cell that reads H says where; the cells that use it say which input failed.
  await markOld(page);
  await typeIntoCell(page, 'H', 'H = "p^2/2 + omega^2*q^2/2 +* q"');
  await page.waitForFunction(() => document.querySelector('[data-cell="model"] [data-cell-error]')?.textContent);
  const syntax = await errorOf(page, 'model');
  oneLine(syntax);
  t.diagnostic(syntax);
  assert.match(syntax, /^InputError: .*(syntax|parse|unexpected|value expected)/i);
  const through = await errorOf(page, 'sim');
  oneLine(through);
  assert.match(through, /^RuntimeError: input model failed: /);
  // Unrelated cells still run: options, and initial.
  await typeIntoCell(page, 'dof', 'dof = 1 + 0');
  await waitForOutput(page, 'dof', (text) => text === 'dof = 1');
  await typeIntoCell(page, 'H', 'H = "p^2/2 + omega^2*q^2/2"');
  await recovers();
  assert.equal(await errorOf(page, 'model'), '');
  assert.equal(await errorOf(page, 'H0'), '');

  // A JavaScript syntax error in the H cell keeps the old H running.
  await typeIntoCell(page, 'H', 'H = "p^2/2 + q^2/2');
  await page.waitForFunction(() => document.querySelector('[data-cell="H"] [data-cell-error]')?.textContent?.includes('SyntaxError'));
  oneLine(await errorOf(page, 'H'));
  assert.equal(await errorOf(page, 'sim'), '');
  await waitForTime(page, (await widget(page)).t, 0.05);
  assert.deepEqual(problems, []);
  await page.close();
});
