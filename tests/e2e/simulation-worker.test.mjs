/**
 * Simulators of expression models whose integration costs the page more
 * than a sixth of the frame budget move to a worker (issue 11), and cheap
 * ones stay on the page (issue 7): the page integrates none of a huge batch, the numbers are those the page itself
 * computes (the same generated stepper), an opaque JS function still runs on
 * the page within its frame budget, and a restart or a new dt mid-flight
 * never shows a stale sample. On /playground/, whose simulator shows the
 * model of its cells.
 */
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { after, before, test } from 'node:test';
import { cellsReady, openChapter, openSite, typeIntoCell, watchPage } from './fixture.mjs';
import { watchFrames, mostStepsInAFrame } from './frame-watch.mjs';
import { DIST } from './server.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

const SIM = '[data-cell="sim"] [data-widget="simulator"]';

/** Simulators off screen pause: bring the playground's into view, and play it. */
async function playInView(page) {
  await page.locator(SIM).scrollIntoViewIfNeeded();
  await page.evaluate((selector) => document.querySelector(selector).simulator.play(), SIM);
}

/**
 * Moves the simulator to the worker at its next frame, whatever the model
 * costs: the playground's oscillator is far too cheap to go by itself, and
 * these tests are about what the worker computes.
 */
async function moveToWorker(page) {
  await page.evaluate((selector) => {
    document.querySelector(selector).simulator.driver.offloadMs = -1;
  }, SIM);
}

/** Waits until the simulator integrates in the worker. */
async function waitForWorker(page) {
  await page.waitForFunction((selector) => document.querySelector(selector)?.simulator?.driver.integrator === 'worker', SIM);
}

test('a batch of 100 000 trajectories integrates in the worker: the page integrates none of it, frames keep coming, and time advances', async () => {
  const { page, problems, requests } = await openChapter(site, '/playground/');
  await typeIntoCell(page, 'options', "options = ({dt: 5e-4, speed: 1, views: ['time', 'phase']})");
  await typeIntoCell(page, 'initial', 'initial = Array.from({length: 100000}, (_, i) => [2 + i * 1e-5, 0])');
  await page.waitForFunction(
    (selector) => document.querySelector(selector)?.simulator?.simulation?.count === 100000 && document.querySelector(selector).hasAttribute('data-ready'),
    SIM,
  );
  await playInView(page);
  await waitForWorker(page);
  // Settle: the first frames after the switch hand over the page's state.
  await page.waitForTimeout(500);
  // Told by work, not by the length of tasks: a busy machine stretches any task by preempting it (traced: 73 ms
  // tasks of 28 ms CPU), but the page integrating the batch would show as steps run on the page, in every frame.
  const seen = await watchFrames(page, SIM, 60);
  console.log(`100 000-trajectory batch in the worker: ${seen.frames.length} frames at ${seen.fps.toFixed(1)} fps, longest main-thread task ${Math.round(seen.longest)} ms, simulated time gained ${seen.gained.toFixed(4)}`);
  assert.ok(seen.complete, `only ${seen.frames.length} frames came`);
  assert.deepEqual([...new Set(seen.frames.map((f) => f.integrator))], ['worker'], 'every frame took its samples from the worker');
  assert.equal(seen.pageSteps, 0, 'the page integrated no step of the batch itself');
  // Each frame appends at most what real time owes it: no backlog is caught up on the page in one go.
  const most = Math.max(...seen.frames.map((f) => f.steps));
  assert.ok(most <= mostStepsInAFrame(seen, { worker: true }), `a frame took ${most} steps`);
  assert.ok(seen.gained > 0, 'the simulation advanced');
  // The worker is the book's own script: no request left the book's host, and the worker was fetched from it.
  const origin = new URL(site.origin);
  assert.ok(requests.some((url) => /\/_astro\/simulation-worker[\w-]*\.js$/.test(url)), 'the simulation worker was loaded');
  assert.deepEqual(requests.filter((url) => !url.startsWith('data:') && new URL(url).host !== origin.host), []);
  // The speed readout says the batch is behind real time (2·10⁸ trajectory steps per second were asked for),
  // once it has measured the pace: waited for, since on a loaded machine the 60 frames can come before it has.
  await page.waitForFunction((bar) => /behind real time/.test(document.querySelector(bar)?.textContent ?? ''), `${SIM} .pb-bar`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a cheap model stays on the page: no worker is started or fetched, and time advances', async () => {
  const { page, problems, requests } = await openChapter(site, '/playground/');
  await page.waitForSelector(`${SIM}[data-ready]`);
  await playInView(page);
  const t0 = await page.evaluate((selector) => document.querySelector(selector).simulator.simulation.t, SIM);
  await page.waitForTimeout(1500);
  const { t, integrator, stepsPerSecond } = await page.evaluate((selector) => {
    const { driver, simulation } = document.querySelector(selector).simulator;
    return { t: simulation.t, integrator: driver.integrator, stepsPerSecond: driver.stats.stepsPerSecond };
  }, SIM);
  console.log(`the playground's oscillator on the page: ${Math.round(stepsPerSecond)} steps a second`);
  assert.equal(integrator, 'page');
  assert.ok(t > t0 + 0.5, `t went from ${t0} to ${t}`);
  assert.deepEqual(requests.filter((url) => /simulation-worker|worker-integrator/.test(url)), []);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the worker computes what the page computes: the same record and state, bit for bit, at the same t', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  await page.waitForSelector(`${SIM}[data-ready]`);
  await moveToWorker(page);
  await playInView(page);
  await waitForWorker(page);
  const before = await page.evaluate((selector) => document.querySelector(selector).simulator.simulation.steps, SIM);
  await page.waitForTimeout(1500);
  const result = await page.evaluate((selector) => {
    const handle = document.querySelector(selector).simulator;
    handle.pause();
    const integrator = handle.driver.integrator;
    // Step, a sample at a time, through what the worker computed ahead (the first) and beyond it.
    const paused = handle.simulation.steps;
    for (let i = 0; i < 600; i++) handle.step();
    const stepped = handle.simulation.steps - paused;
    const sim = handle.simulation;
    // The page's own run of the same model from the same start: Simulation.run on the main thread.
    const Simulation = sim.constructor;
    const reference = new Simulation(sim.model, { initial: sim.initial, dt: sim.dt, every: sim.every, capacity: sim.record.capacity });
    reference.run(sim.steps);
    const same = (a, b) => a.length === b.length && a.every((v, i) => Object.is(v, b[i]));
    const table = sim.record.table();
    const expected = reference.record.table();
    let firstDifference = -1;
    for (let i = 0; i < expected.data.length && firstDifference < 0; i++) if (!Object.is(table.data[i], expected.data[i])) firstDifference = i;
    return {
      integrator,
      stepped,
      steps: sim.steps,
      t: sim.t,
      referenceT: reference.t,
      state: same(Array.from(sim.state), Array.from(reference.state)),
      rows: [table.rows, expected.rows],
      firstDifference,
      sameLength: table.data.length === expected.data.length,
    };
  }, SIM);
  assert.equal(result.integrator, 'worker');
  assert.equal(result.stepped, 600);
  assert.ok(result.steps - before > 1000, `the worker took ${result.steps - before} steps`);
  assert.equal(result.t, result.referenceT);
  assert.ok(result.state, 'the state is the page’s to the last bit');
  assert.deepEqual(result.rows[0], result.rows[1]);
  assert.ok(result.sameLength);
  assert.equal(result.firstDifference, -1, `the records differ from value ${result.firstDifference}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a JS-function H the translator cannot read still runs on the page, within its frame budget', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  // A loop makes H opaque: 5-point differences, a function of the page that no worker can have.
  await typeIntoCell(page, 'H', 'H = (t, [q, p]) => {\n  let s = 0;\n  for (let i = 0; i < 3; i++) s += (p * p + 100 * q * q) / 6;\n  return s;\n}');
  await page.waitForFunction((selector) => document.querySelector(selector)?.simulator?.model?.route === 'js-stencil', SIM);
  await page.waitForSelector(`${SIM}[data-ready]`);
  await playInView(page);
  const seen = await watchFrames(page, SIM, 60);
  assert.ok(seen.complete, `only ${seen.frames.length} frames came`);
  assert.deepEqual([...new Set(seen.frames.map((f) => f.integrator))], ['page']);
  assert.ok(seen.gained > 0, `t advanced by ${seen.gained}`);
  // Within its frame budget, told by work: no frame integrates more than real time owes it (at most 100 ms of it),
  // so a frame never catches up a backlog, however busy the machine.
  const steps = seen.frames.map((f) => f.steps);
  assert.ok(Math.max(...steps) <= mostStepsInAFrame(seen), `steps per frame: ${steps.join(' ')}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('restarts and new dt mid-flight never show a stale sample: every frame’s record is the new run’s', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  await page.waitForSelector(`${SIM}[data-ready]`);
  await moveToWorker(page);
  await playInView(page);
  await waitForWorker(page);
  const report = await page.evaluate(async (selector) => {
    const handle = document.querySelector(selector).simulator;
    const wait = (ms) => new Promise((r) => setTimeout(r, ms));
    const violations = [];
    let frames = 0;
    // One sample per step (every = 1) from t = 0: row i is at t = i·dt, the last row is the present state.
    const check = () => {
      frames++;
      const sim = handle.simulation;
      const r = sim.record;
      const n = r.length;
      if (r.dropped) return;
      if (n !== sim.steps + 1) violations.push(`frame ${frames}: ${n} rows after ${sim.steps} steps`);
      for (const i of [0, n >> 1, n - 1]) {
        if (r.time(i) !== sim.t0 + i * sim.dt) violations.push(`frame ${frames}: row ${i} at t = ${r.time(i)}, not ${i} · ${sim.dt}`);
      }
      if (r.get(0, 1) !== sim.initial[0] || r.get(0, 2) !== sim.initial[1]) violations.push(`frame ${frames}: row 0 is not the initial state`);
      if (r.get(n - 1, 1) !== sim.state[0] || r.get(n - 1, 2) !== sim.state[1]) violations.push(`frame ${frames}: the last row is not the state`);
    };
    const off = handle.driver.on('frame', check);
    const dts = [5e-4, 3e-4, 7e-4, 2e-4];
    for (let round = 0; round < 24; round++) {
      await wait([0, 5, 17, 40, 90][round % 5]);
      if (round % 3 === 2) handle.setDt(dts[round % dts.length]);
      else handle.restart();
      check();
    }
    await wait(600);
    off();
    const sim = handle.simulation;
    handle.pause();
    // And the record is exactly the page's own run of the same model at the final dt.
    const reference = new sim.constructor(sim.model, { initial: sim.initial, dt: sim.dt, every: sim.every, capacity: sim.record.capacity });
    reference.run(sim.steps);
    const a = sim.record.table().data;
    const b = reference.record.table().data;
    const same = a.length === b.length && a.every((v, i) => Object.is(v, b[i]));
    return { violations: violations.slice(0, 5), frames, steps: sim.steps, same, integrator: handle.driver.integrator, dt: sim.dt };
  }, SIM);
  assert.deepEqual(report.violations, []);
  assert.ok(report.frames > 20, `${report.frames} frames checked`);
  assert.equal(report.integrator, 'worker');
  assert.ok(report.steps > 100, `${report.steps} steps after the last change`);
  assert.ok(report.same, 'the record after the changes is the page’s own run');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a blow-up in the worker stops the simulator with the same message as on the page', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  // q̈ = 6q⁵ from q₀ = 0.4 at rest reaches infinity at t = q₀⁻² ∫₁^∞ dx / √(2(x⁶ − 1)) = 0.4957 / 0.16 = 3.10
  // (energy conservation; the integral by quadrature), time enough for the worker to take over first.
  await typeIntoCell(page, 'initial', 'initial = [0.4, 0]');
  await typeIntoCell(page, 'H', 'H = "p^2/2 - q^6"');
  await page.waitForFunction((selector) => document.querySelector(selector)?.simulator?.model?.source === 'p^2/2 - q^6', SIM);
  await page.waitForSelector(`${SIM}[data-ready]`);
  await moveToWorker(page);
  await playInView(page);
  await waitForWorker(page);
  await page.waitForFunction((selector) => document.querySelector(selector).simulator.simulation.error, SIM);
  const { message, reference, alert } = await page.evaluate((selector) => {
    const handle = document.querySelector(selector).simulator;
    const sim = handle.simulation;
    const ref = new sim.constructor(sim.model, { initial: sim.initial, dt: sim.dt, every: sim.every });
    ref.run(1e6);
    return { message: sim.error.message, reference: ref.error?.message, alert: document.querySelector(`${selector} [role="alert"]`).textContent };
  }, SIM);
  assert.equal(message, reference);
  assert.match(alert, /^Stopped: the state became -?Infinity at t = [\d.]+ in [qp]\b|^Stopped: the state became NaN/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('where no worker can run, the simulator integrates on the page as before', async () => {
  const page = await site.context.newPage();
  await page.goto(`${site.origin}/`);
  await page.evaluate(() => localStorage.clear());
  // An old browser, or one whose policy forbids workers: the constructor is missing.
  await page.addInitScript(() => {
    delete window.Worker;
  });
  const { problems, requests } = watchPage(page);
  await page.goto(`${site.origin}/playground/`);
  await cellsReady(page);
  await page.waitForSelector(`${SIM}[data-ready]`);
  await playInView(page);
  const t0 = await page.evaluate((selector) => document.querySelector(selector).simulator.simulation.t, SIM);
  await page.waitForTimeout(1000);
  const { t, integrator } = await page.evaluate((selector) => {
    const handle = document.querySelector(selector).simulator;
    return { t: handle.simulation.t, integrator: handle.driver.integrator };
  }, SIM);
  assert.equal(integrator, 'page');
  assert.ok(t > t0 + 0.3, `t went from ${t0} to ${t}`);
  assert.deepEqual(requests.filter((url) => /simulation-worker/.test(url)), []);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the simulation worker is small and carries no mathjs: it rebuilds the model from its generated code', () => {
  const assets = join(DIST, '_astro');
  const workers = readdirSync(assets).filter((name) => /^simulation-worker.*\.js$/.test(name));
  assert.equal(workers.length, 1);
  const code = readFileSync(join(assets, workers[0]), 'utf8');
  const mathjs = readdirSync(assets).filter((name) => /^mathjs.*\.js$/.test(name)).map((name) => readFileSync(join(assets, name), 'utf8')).join('');
  for (const marker of ['Unexpected type of argument', 'Undefined symbol']) {
    assert.ok(mathjs.includes(marker), `mathjs's chunk has "${marker}"`);
    assert.ok(!code.includes(marker), `the worker has "${marker}"`);
  }
  for (const [, imported] of code.matchAll(/from\s*["']\.\/([^"']+)["']/g)) assert.doesNotMatch(imported, /mathjs/);
  // Nor any way to reach the network.
  assert.doesNotMatch(code, /\bfetch\(|XMLHttpRequest|importScripts|WebSocket/);
  assert.ok(gzipSync(code).length < 10_000, `the worker is ${gzipSync(code).length} B gzip`);
});
