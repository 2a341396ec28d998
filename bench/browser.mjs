/**
 * `npm run bench:browser`: the live book measured in headless Chromium
 * against the built site, driven the way a reader drives it — by editing the
 * cells of /playground/. Prints a markdown report on stdout (progress goes to
 * stderr):
 *
 * 0. the frame-rate ceiling of an empty page (headless Chromium's
 *    requestAnimationFrame is paced by a virtual display, which need not be
 *    60 Hz), against which the widgets' frame rates are also given;
 * a. the paper's default model (eq. 7) at speed 1 (2000 steps/s): the share of
 *    a 16.7 ms frame spent integrating and drawing, from the driver's own
 *    stats, beside the main thread's busy share and the long tasks;
 * b. the same model at speed 50 (100 000 steps/s): frame rate and steps/s;
 * c. the paper's scattered beam (section 7.3) with 1000 particles: frame rate
 *    (trajectory view; with the time plot; with the full trail);
 * d. per-page JavaScript (gzip) on first load, after the editor loads, and
 *    after the cell parser loads;
 * e. cold-cache loads of every page (cold-load.mjs): JavaScript before any
 *    interaction, navigation to the first widget drawn, plain and under
 *    DevTools' Slow 4G with a 4× CPU slowdown, and cumulative layout shift;
 * f. first visits (first-visit.mjs): each load a fresh profile, by a link to
 *    a chapter's simulator, with where the time goes up to its first draw.
 * g. Lighthouse on every page, mobile and desktop presets (lighthouse.mjs):
 *    its four scores, TBT, LCP, CLS and the DOM's size.
 * h. the standard map's portrait at its default size while its K slider moves
 *    a step every frame (map-frames.mjs): frame rate, redraws, main-thread work.
 * i. the pendulum's ensemble playing at its default size, 20 000 points and its
 *    boundary moved in a worker (ensemble-frames.mjs): frame rate, frames with
 *    a new ensemble, main-thread work.
 *
 * BENCH_ONLY=cold runs part e alone, BENCH_ONLY=first part f alone,
 * BENCH_ONLY=lighthouse part g alone (BENCH_LIGHTHOUSE_RUNS=N: the median of
 * N runs per page and preset); BENCH_PAGES=/introduction/,/kepler/ limits
 * parts e, f and g to those pages; BENCH_LOADS sets the loads per page and
 * profile (default 3; the median is reported).
 * Builds the site first when dist/ (or PHASEBOOK_OUT_DIR) has none.
 * BENCH_SECONDS sets the measuring window per scenario (default 4 s, after a
 * 2 s warm-up).
 */
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync } from 'node:fs';
import { cpus, loadavg, totalmem } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { cellsReady, launchBrowser } from '../tests/e2e/browser.mjs';
import { DIST, startServer } from '../tests/e2e/server.mjs';
import { cell, typeIntoCell } from '../tests/e2e/fixture.mjs';
import { coldLoad, median, CPU_SLOWDOWN } from './cold-load.mjs';
import { firstVisits, printFirstVisits } from './first-visit.mjs';
import { lighthouseTable } from './lighthouse.mjs';
import { mapSweep } from './map-frames.mjs';
import { ensembleWatch } from './ensemble-frames.mjs';

const ROOT = fileURLToPath(new URL('../', import.meta.url));
const SECONDS = Number(process.env.BENCH_SECONDS ?? 4);
const LOADS = Number(process.env.BENCH_LOADS ?? 3);
const ONLY = process.env.BENCH_ONLY ?? null;
const ONLY_PAGES = process.env.BENCH_PAGES?.split(',').filter(Boolean) ?? null;
const WARM_UP_MS = 2000;
const FRAME_MS = 1000 / 60;

const log = (message) => process.stderr.write(`${message}\n`);

// ── the paper's models, as a reader types them into the playground ──────────
const DEFAULT_MODEL = {
  H: 'H = "p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t + beta)"',
  dof: 'dof = 1',
  params: 'params = ({u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 10, f: 20})',
  initial: 'initial = [2, 0]',
};
const DEFAULT_H = 'p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t + beta)';
const BEAM_H = 'p0^2 + p1^2 + 30/sqrt(q0^2 + q1^2)';
const BEAM_MODEL = {
  H: `H = "${BEAM_H}"`,
  dof: 'dof = 2',
  params: 'params = ({})',
  initial: 'initial = Array.from({length: 1000}, (_, i) => [-20, (i - 500) * 0.006, 4, 0])',
};

function ensureBuilt() {
  if (existsSync(join(DIST, 'index.html'))) return;
  log(`No built site in ${DIST}: building (astro build)…`);
  const result = spawnSync('npx', ['astro', 'build'], {
    cwd: ROOT,
    stdio: ['ignore', process.stderr, process.stderr],
    env: { ...process.env, ASTRO_TELEMETRY_DISABLED: '1' },
  });
  if (result.status !== 0) throw new Error('astro build failed');
}

// ── driving cells ─────────────────────────────────────────────────────────────

/** The text of a cell as the page holds it (editor or static code). */
async function sourceOf(page, id) {
  return cell(page, id).evaluate((root) => {
    const lines = root.querySelectorAll('.cm-content .cm-line');
    if (lines.length) return [...lines].map((line) => line.textContent).join('\n');
    return root.querySelector('pre.cell-code')?.textContent ?? '';
  });
}

/** Replaces a cell's text like a reader and runs it, unless it already holds that text. */
async function setCell(page, id, source) {
  if ((await sourceOf(page, id)) !== source) await typeIntoCell(page, id, source);
}

/** Sets the playground's cells, then waits for the simulator they describe to be drawn. */
async function setPlayground(page, model, options, expect) {
  for (const [id, source] of Object.entries(model)) await setCell(page, id, source);
  await setCell(page, 'options', `options = (${options})`);
  await page.waitForFunction(
    ({ h, count, speed }) => {
      const el = document.querySelector('[data-cell="sim"] [data-widget="simulator"]');
      const s = el?.simulator;
      return !!s && el.hasAttribute('data-ready') && s.model.source === h && s.simulation.count === count && s.driver.speed === speed;
    },
    expect,
    { timeout: 60_000 },
  );
}

/**
 * Measures the running simulator for `ms`: rAF timestamps, the driver's
 * per-frame integrate/draw times, long tasks, and steps taken.
 */
function measureInPage(ms) {
  return new Promise((resolve) => {
    const el = document.querySelector('[data-cell="sim"] [data-widget="simulator"]');
    const { driver } = el.simulator;
    const costs = [];
    const off = driver.on('frame', (s) => costs.push([s.integrateMs, s.drawMs, s.steps]));
    const stamps = [];
    let running = true;
    const loop = (t) => {
      stamps.push(t);
      if (running) requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
    const longTasks = [];
    let observer = null;
    try {
      observer = new PerformanceObserver((list) => list.getEntries().forEach((e) => longTasks.push(e.duration)));
      observer.observe({ type: 'longtask' });
    } catch {
      observer = null;
    }
    const sim0 = el.simulator.simulation;
    const steps0 = sim0.steps;
    const t0 = performance.now();
    setTimeout(() => {
      running = false;
      off();
      observer?.disconnect();
      const sim = el.simulator.simulation;
      const wall = performance.now() - t0;
      resolve({
        wall,
        stamps,
        costs,
        longTasks,
        longTaskSupported: observer !== null,
        steps: sim === sim0 ? sim.steps - steps0 : NaN,
        driverRate: driver.stats.stepsPerSecond,
        pace: driver.stats.pace,
        targetRate: driver.targetRate,
        playing: driver.playing,
        error: sim.error ? sim.error.message : null,
        recordRows: sim.record.length,
        dropped: sim.record.dropped,
      });
    }, ms);
  });
}

/** Counts rAF callbacks on a blank page: the frame-rate ceiling of this browser. */
function rafCeilingInPage(ms) {
  return new Promise((resolve) => {
    const stamps = [];
    const start = performance.now();
    const loop = (t) => {
      stamps.push(t);
      if (performance.now() - start < ms) requestAnimationFrame(loop);
      else resolve(stamps);
    };
    requestAnimationFrame(loop);
  });
}

// ── statistics ────────────────────────────────────────────────────────────────
const mean = (xs) => (xs.length ? xs.reduce((a, b) => a + b, 0) / xs.length : NaN);
function quantile(xs, q) {
  if (!xs.length) return NaN;
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.floor(q * s.length))];
}
function frameStats(stamps) {
  const gaps = stamps.slice(1).map((t, i) => t - stamps[i]);
  const span = stamps.length > 1 ? stamps.at(-1) - stamps[0] : NaN;
  return {
    fps: ((stamps.length - 1) * 1000) / span,
    p95: quantile(gaps, 0.95),
    worst: gaps.length ? Math.max(...gaps) : NaN,
    // a gap over 1.5 frames means at least one frame was missed
    missed: gaps.filter((g) => g > 1.5 * FRAME_MS).length,
    frames: gaps.length,
  };
}

const f1 = (x) => (Number.isFinite(x) ? x.toFixed(1) : '–');
const f2 = (x) => (Number.isFinite(x) ? x.toFixed(2) : '–');
const pct = (x) => (Number.isFinite(x) ? `${(100 * x).toFixed(1)} %` : '–');
const int = (x) => (Number.isFinite(x) ? Math.round(x).toLocaleString('en') : '–');
const kb = (bytes) => `${(bytes / 1024).toFixed(1)} KB`;

async function cdpMetrics(session) {
  const { metrics } = await session.send('Performance.getMetrics');
  return Object.fromEntries(metrics.map((m) => [m.name, m.value]));
}

/** Runs one scenario: set the cells, warm up, measure. */
async function scenario(page, session, { model, options, expect }) {
  await setPlayground(page, model, options, expect);
  await page.waitForTimeout(WARM_UP_MS);
  const before = await cdpMetrics(session);
  const m = await page.evaluate(measureInPage, SECONDS * 1000);
  const after = await cdpMetrics(session);
  const wallS = m.wall / 1000;
  const busy = (after.TaskDuration - before.TaskDuration) / wallS;
  const script = (after.ScriptDuration - before.ScriptDuration) / wallS;
  const work = m.costs.map(([i, d]) => i + d);
  const frames = frameStats(m.stamps);
  return {
    ...m,
    frames,
    busy,
    script,
    integrate: mean(m.costs.map(([i]) => i)),
    draw: mean(m.costs.map(([, d]) => d)),
    work: mean(work),
    workP95: quantile(work, 0.95),
    stepsPerSecond: m.steps / wallS,
    longTotal: m.longTasks.reduce((a, b) => a + b, 0),
  };
}

// ── per-page JavaScript ───────────────────────────────────────────────────────
const EDITOR_CHUNK = /\/_astro\/editor\.[\w-]+\.js$/;
const PARSER_CHUNK = /\/_astro\/(parse|parser)\.[\w-]+\.js$/;

function sitePages() {
  const pages = ['/'];
  for (const entry of readdirSync(DIST, { withFileTypes: true })) {
    if (entry.isDirectory() && !entry.name.startsWith('_') && existsSync(join(DIST, entry.name, 'index.html'))) pages.push(`/${entry.name}/`);
  }
  return pages;
}

/** The pages of parts e and f: every page, or those BENCH_PAGES names. */
const measuredPages = () => sitePages().filter((path) => !ONLY_PAGES || ONLY_PAGES.includes(path));

async function pageBytes(context, origin, path) {
  const page = await context.newPage();
  await page.addInitScript(() => localStorage.clear());
  let stage = 'first';
  /** @type {Map<string, {stage: string, bytes: number}>} */
  const scripts = new Map();
  const pending = [];
  page.on('response', (response) => {
    const url = response.url();
    if (!/\.m?js(\?|$)/.test(url) || scripts.has(url)) return;
    const at = EDITOR_CHUNK.test(url) ? 'editor' : PARSER_CHUNK.test(url) ? 'parser' : stage;
    scripts.set(url, { stage: at, bytes: 0 });
    pending.push(
      response.body().then(
        (body) => (scripts.get(url).bytes = gzipSync(body, { level: 9 }).length),
        () => {},
      ),
    );
  });
  await page.goto(origin + path);
  await page.waitForLoadState('load');
  const cells = await page.locator('[data-cell]').count();
  if (cells > 0) {
    await page.waitForSelector('body[data-cells-ready]', { state: 'attached', timeout: 30_000 });
    await page
      .waitForFunction(() => [...document.querySelectorAll('[data-widget]')].every((w) => w.hasAttribute('data-ready')), null, { timeout: 30_000 })
      .catch(() => log(`  ${path}: some widgets were not ready after 30 s`));
  }
  await page.waitForLoadState('networkidle').catch(() => {});
  if (cells > 0) {
    stage = 'editor';
    const first = cell(page, await page.locator('[data-cell]').first().getAttribute('data-cell'));
    await first.locator('.cell-editor').click();
    await first.locator('.cm-content').waitFor({ timeout: 10_000 });
    await page.waitForLoadState('networkidle').catch(() => {});
    stage = 'parser';
    // An edit the build did not parse: a space at the end of the first cell, run.
    await first.locator('.cm-content').click();
    await page.keyboard.press('ControlOrMeta+End');
    await page.keyboard.insertText(' ');
    await page.keyboard.press('Shift+Enter');
    await page.waitForResponse((r) => PARSER_CHUNK.test(r.url()), { timeout: 10_000 }).catch(() => {});
    await page.waitForTimeout(300);
    await page.waitForLoadState('networkidle').catch(() => {});
  }
  await Promise.all(pending);
  await page.close();
  const sum = (stages) => {
    const list = [...scripts.values()].filter((s) => stages.includes(s.stage));
    return { files: list.length, bytes: list.reduce((a, s) => a + s.bytes, 0) };
  };
  return {
    path,
    cells,
    scripts: [...scripts].map(([url, v]) => ({ name: new URL(url).pathname.split('/').pop(), ...v })),
    first: sum(['first']),
    editor: cells > 0 ? sum(['first', 'editor']) : null,
    parser: cells > 0 ? sum(['first', 'editor', 'parser']) : null,
  };
}

// ── main ──────────────────────────────────────────────────────────────────────
/** Parts 0 and a–d: the simulator driven through /playground/, and bytes per page. */
async function interactive(browser, server, print) {
  const blank = await browser.context.newPage();
  await blank.setContent('<!doctype html><title>blank</title>');
  log('measuring the frame-rate ceiling of an empty page…');
  const ceiling = frameStats(await blank.evaluate(rafCeilingInPage, 3000));
  await blank.close();

  const page = await browser.context.newPage();
  await page.addInitScript(() => localStorage.clear());
  const session = await browser.context.newCDPSession(page);
  await session.send('Performance.enable');
  await page.goto(`${server.origin}/playground/`);
  await page.waitForSelector('body[data-cells-ready]', { state: 'attached', timeout: 30_000 });
  await page.waitForSelector('[data-cell="sim"] [data-widget="simulator"][data-ready]', { timeout: 30_000 });

  log('a. the default model at speed 1…');
  const a = await scenario(page, session, {
    model: DEFAULT_MODEL,
    options: "{dt: 5e-4, speed: 1, views: ['time', 'phase', 'spectrum']}",
    expect: { h: DEFAULT_H, count: 1, speed: 1 },
  });
  log('b. the default model at speed 50…');
  const b = await scenario(page, session, {
    model: DEFAULT_MODEL,
    options: "{dt: 5e-4, speed: 50, views: ['time', 'phase', 'spectrum']}",
    expect: { h: DEFAULT_H, count: 1, speed: 50 },
  });
  log('c. the 1000-particle beam, trajectory view…');
  const c1 = await scenario(page, session, {
    model: BEAM_MODEL,
    options: "{speed: 1, views: ['trajectory']}",
    expect: { h: BEAM_H, count: 1000, speed: 1 },
  });
  log('c. the 1000-particle beam, trajectory and time views…');
  const c2 = await scenario(page, session, {
    model: BEAM_MODEL,
    options: "{speed: 1, views: ['trajectory', 'time']}",
    expect: { h: BEAM_H, count: 1000, speed: 1 },
  });
  log('c. the 1000-particle beam, trajectory view with the full trail…');
  const c3 = await scenario(page, session, {
    model: BEAM_MODEL,
    options: "{speed: 1, views: ['trajectory'], trajectory: {trail: 'full'}}",
    expect: { h: BEAM_H, count: 1000, speed: 1 },
  });
  await page.close();
  log('h. the standard map, its K slider moved every frame…');
  const h = await mapSweep(browser.context, server.origin, { ms: SECONDS * 1000, warmUpMs: WARM_UP_MS });
  log('i. the pendulum’s ensemble, playing…');
  const ens = await ensembleWatch(browser.context, server.origin, { ms: SECONDS * 1000, warmUpMs: WARM_UP_MS });

  log('d. JavaScript per page…');
  // Bytes do not depend on timing, so three pages at a time.
  const paths = sitePages();
  const pages = new Array(paths.length);
  let next = 0;
  const worker = async () => {
    while (next < paths.length) {
      const i = next++;
      log(`  ${paths[i]}`);
      pages[i] = await pageBytes(browser.context, server.origin, paths[i]);
    }
  };
  await Promise.all([worker(), worker(), worker()]);

  // ── report ──
  print(`Each scenario: ${WARM_UP_MS / 1000} s warm-up, then ${SECONDS} s measured. Frame budget 16.7 ms (60 Hz).`);
  print();
  print(`Empty-page frame-rate ceiling (rAF on a blank page, 3 s): **${f1(ceiling.fps)} fps** ` +
    `(p95 frame interval ${f1(ceiling.p95)} ms, ${ceiling.missed} missed frame(s) of ${ceiling.frames}).`);
  print();
  const rel = (fps) => pct(fps / ceiling.fps);
  print('| Scenario | Measure | Result | Target |');
  print('|---|---|---|---|');
  const row = (s, m, r, t = '') => print(`| ${s} | ${m} | ${r} | ${t} |`);
  const A = 'a. eq. 7, speed 1 (time, phase, spectrum)';
  row(A, 'integrate + draw per frame (driver stats), mean / p95',
    `${f2(a.work)} ms / ${f2(a.workP95)} ms = **${pct(a.work / FRAME_MS)}** / ${pct(a.workP95 / FRAME_MS)} of 16.7 ms`, '< 10 %');
  row(A, 'of which integrate / draw', `${f2(a.integrate)} ms / ${f2(a.draw)} ms`);
  row(A, 'main thread busy (CDP TaskDuration) / of it script', `${pct(a.busy)} / ${pct(a.script)}`);
  row(A, 'long tasks (> 50 ms)', a.longTaskSupported ? `${a.longTasks.length} (${f1(a.longTotal)} ms)` : 'not reported', '0');
  row(A, 'frame rate (rAF)', `${f1(a.frames.fps)} fps = ${rel(a.frames.fps)} of ceiling; p95 interval ${f1(a.frames.p95)} ms, ${a.frames.missed} missed`);
  row(A, 'steps/s achieved', `${int(a.stepsPerSecond)} (requested ${int(a.targetRate)})`, '≈ 2000');
  const B = 'b. eq. 7, speed 50 (time, phase, spectrum)';
  row(B, 'frame rate (rAF)', `**${f1(b.frames.fps)} fps** = ${rel(b.frames.fps)} of ceiling; p95 interval ${f1(b.frames.p95)} ms, ${b.frames.missed} missed`, '60 fps');
  row(B, 'steps/s achieved', `**${int(b.stepsPerSecond)}** (requested ${int(b.targetRate)}; pace ${pct(b.pace)})`, '≥ 100 000');
  row(B, 'integrate + draw per frame, mean / p95', `${f2(b.work)} ms / ${f2(b.workP95)} ms (integrate ${f2(b.integrate)}, draw ${f2(b.draw)})`);
  row(B, 'main thread busy / long tasks', `${pct(b.busy)} / ${b.longTaskSupported ? `${b.longTasks.length} (${f1(b.longTotal)} ms)` : '–'}`);
  const beams = [
    ['c. beam of 1000, trajectory view', c1],
    ['c. beam of 1000, trajectory + time views', c2],
    ["c. beam of 1000, trajectory view, trail: 'full'", c3],
  ];
  for (const [label, c] of beams) {
    row(label, 'frame rate (rAF)', `**${f1(c.frames.fps)} fps** = ${rel(c.frames.fps)} of ceiling; p95 interval ${f1(c.frames.p95)} ms, ${c.frames.missed} missed`, '≥ 30 fps');
    row(label, 'steps/s achieved (per particle)', `${int(c.stepsPerSecond)} (requested ${int(c.targetRate)}; pace ${pct(c.pace)}) = ${int(c.stepsPerSecond * 1000)} particle-steps/s`);
    row(label, 'integrate + draw per frame, mean / p95', `${f2(c.work)} ms / ${f2(c.workP95)} ms (integrate ${f2(c.integrate)}, draw ${f2(c.draw)})`);
    row(label, 'main thread busy / long tasks', `${pct(c.busy)} / ${c.longTaskSupported ? `${c.longTasks.length} (${f1(c.longTotal)} ms)` : '–'}`);
    if (c.error) row(label, 'stopped', c.error);
  }
  const H = 'h. standard map, 1024 orbits × 300 iterates, K moved every frame';
  const hFrames = frameStats(h.stamps);
  row(H, 'frame rate (rAF)', `**${f1(hFrames.fps)} fps** = ${rel(hFrames.fps)} of ceiling; p95 interval ${f1(hFrames.p95)} ms, ${hFrames.missed} missed`, '60 fps');
  row(H, 'portraits drawn / points each', `${int(h.redraws)} of ${int(hFrames.frames)} frames / ${int(h.points)}`);
  row(H, 'main thread busy, per frame', `${pct(h.busy)} = ${f2((h.busy * 1000) / hFrames.fps)} ms`, '< 16.7 ms');
  const I = 'i. ensemble, 20 000 points and the boundary, playing';
  const iFrames = frameStats(ens.stamps);
  row(I, 'frame rate (rAF)', `${f1(iFrames.fps)} fps = ${rel(iFrames.fps)} of ceiling; p95 interval ${f1(iFrames.p95)} ms, ${iFrames.missed} missed`, '60 fps');
  row(I, 'frames with a new ensemble / points drawn / boundary vertices at the end', `${int(ens.updates)} of ${int(iFrames.frames)} / ${int(ens.points)} / ${int(ens.vertices)} (t = ${f1(ens.t)}, ${ens.state})`);
  row(I, 'main thread busy, per frame', `${pct(ens.busy)} = ${f2((ens.busy * 1000) / iFrames.fps)} ms`, '< 16.7 ms');
  for (const [label, s] of [['a', a], ['b', b], ...beams]) {
    if (s.error || !s.playing) log(`warning: scenario ${label} was not playing at the end${s.error ? `: ${s.error}` : ''}`);
  }
  print();
  print('d. JavaScript per page, gzip (zlib level 9) of each JS response, cumulative:');
  print();
  print('| Page | Cells | First load | + editor (focus a cell) | + parser (run an edited cell) |');
  print('|---|---|---|---|---|');
  const files = (n) => `${n} file${n === 1 ? '' : 's'}`;
  for (const p of pages) {
    const cellText = (s) => (s ? `${kb(s.bytes)} (${files(s.files)})` : '—');
    print(`| \`${p.path}\` | ${p.cells} | ${kb(p.first.bytes)} (${files(p.first.files)}) | ${cellText(p.editor)} | ${cellText(p.parser)} |`);
  }
  const big = new Map();
  for (const p of pages) {
    for (const script of p.scripts) {
      if (script.bytes < 20 * 1024) continue;
      const entry = big.get(script.name) ?? { bytes: script.bytes, stage: script.stage, pages: 0 };
      entry.pages++;
      big.set(script.name, entry);
    }
  }
  print();
  print('Scripts over 20 KB gzip: ' +
    [...big].sort((x, y) => y[1].bytes - x[1].bytes)
      .map(([name, e]) => `\`${name}\` ${kb(e.bytes)} (${e.stage === 'first' ? 'first load' : e.stage}, ${e.pages} page${e.pages === 1 ? '' : 's'})`)
      .join('; ') + '.');
  print();
}

/** Part e: cold-cache loads of every page, plain and throttled, against the targets of issue 7. */
/** The id of the cell holding each page's first simulator (null for none), found by reading the page through once. */
async function firstSimulators(context, origin, paths) {
  const found = new Map();
  for (const path of paths) {
    const page = await context.newPage();
    await page.addInitScript(() => localStorage.clear());
    await page.goto(origin + path);
    const hasCells = await page.evaluate(() => document.querySelector('[data-cell]') !== null);
    if (hasCells) await cellsReady(page);
    found.set(
      path,
      await page.evaluate(() => document.querySelector('[data-widget="simulator"]')?.closest('[data-cell]')?.id ?? null),
    );
    await page.close();
  }
  return found;
}

/**
 * Two ways in for each page, each on a cold cache, plain and throttled: at
 * its top, as from the contents, and by a link to its first simulator
 * (`/kepler/#cell-stars`), the widget a reader opens a chapter for.
 */
async function coldLoads(browser, server, print, paths, simulators) {
  const profiles = [
    ['loopback', false],
    [`Slow 4G + ${CPU_SLOWDOWN}× CPU`, true],
  ];
  const results = new Map();
  for (const [name, throttled] of profiles) {
    for (const path of paths) {
      const ways = [['top', path, 'widget']];
      if (simulators.get(path)) ways.push(['simulator', `${path}#${simulators.get(path)}`, 'simulator']);
      for (const [way, url, waitFor] of ways) {
        log(`e. ${url}, ${name}…`);
        const runs = [];
        for (let i = 0; i < LOADS; i++) runs.push(await coldLoad(browser.context, server.origin, url, { throttled, waitFor }));
        results.set(`${name} ${way} ${path}`, runs);
      }
    }
  }
  const ms = (x) => (Number.isFinite(x) ? `${Math.round(x)} ms` : '—');
  const targets = { bytes: 40 * 1024, plain: 500, slow: 2500, cls: 0.02 };
  const misses = [];
  print(`e. Cold-cache loads, median of ${LOADS} per page, way in and profile; the server compresses text with gzip ` +
    'as static hosts do. "Top": the page opened at its top. "Simulator": opened by a link to its first simulator\'s cell. ' +
    'JS: gzip of every script fetched before any interaction (the load, then 1.5 s idle). First paint: navigation to the ' +
    'first text on screen. Drawn: navigation to the first ' +
    'widget the page\'s scripts made and drew (`data-ready`; formulas the build typeset into the HTML do not count), ' +
    'for "simulator" the simulator itself; "—" when the first view holds none. CLS: layout-shift entries without ' +
    'recent input, worst of both profiles.');
  print();
  print(`| Page | way in | JS before interaction | heavy modules | first paint (loopback / throttled) | drawn (loopback) | drawn (Slow 4G + ${CPU_SLOWDOWN}× CPU) | CLS |`);
  print('|---|---|---|---|---|---|---|---|');
  for (const path of paths) {
    for (const way of ['top', 'simulator']) {
      const plain = results.get(`${profiles[0][0]} ${way} ${path}`);
      const slow = results.get(`${profiles[1][0]} ${way} ${path}`);
      if (!plain) continue;
      const bytes = median(plain.map((r) => r.jsBytes));
      const heavy = [...new Set([...plain, ...slow].flatMap((r) => r.heavy))];
      const cls = Math.max(...plain.map((r) => r.cls), ...slow.map((r) => r.cls));
      const key = way === 'simulator' ? 'simulatorMs' : 'widgetMs';
      const plainMs = median(plain.map((r) => r[key]));
      const slowMs = median(slow.map((r) => r[key]));
      const paint = `${ms(median(plain.map((r) => r.paintMs)))} / ${ms(median(slow.map((r) => r.paintMs)))}`;
      if (bytes > targets.bytes) misses.push(`${path} (${way}): ${kb(bytes)} of JS`);
      if (heavy.length) misses.push(`${path} (${way}): ${heavy.join(', ')}`);
      if (plainMs > targets.plain) misses.push(`${path} (${way}): drawn at ${ms(plainMs)} on loopback`);
      if (slowMs > targets.slow) misses.push(`${path} (${way}): drawn at ${ms(slowMs)} throttled`);
      if (way === 'simulator' && !Number.isFinite(plainMs)) misses.push(`${path}: the simulator never drew`);
      if (!(cls < targets.cls)) misses.push(`${path} (${way}): CLS ${cls.toFixed(4)}`);
      const where = way === 'simulator' ? `#${simulators.get(path)}` : 'top';
      print(`| \`${path}\` | ${where} | ${kb(bytes)} (${plain[0].jsFiles} files) | ${heavy.length ? heavy.join(', ') : 'none'} | ${paint} | ${ms(plainMs)} | ${ms(slowMs)} | ${cls.toFixed(4)} |`);
    }
  }
  print();
  print('Targets: ≤ 40 KB of JavaScript and no heavy module (mathjs, KaTeX, parser, editor) before interaction; ' +
    'drawn ≤ 500 ms after navigation on loopback and ≤ 2.5 s throttled; CLS < 0.02. ' +
    (misses.length ? `Missed: ${misses.join('; ')}.` : 'All met.'));
  const worst = [...results.values()].flat().filter((r) => r.shifts.length).sort((a, b) => b.cls - a.cls)[0];
  if (worst) print(`Largest shift: ${worst.path}, ${worst.shifts.map((s) => `${s.value.toFixed(4)} at ${s.at} ms (${s.sources.join(', ')})`).join('; ')}.`);
  print();
}

async function main() {
  ensureBuilt();
  const started = Date.now();
  const loadBefore = loadavg()[0];
  const server = await startServer();
  const browser = await launchBrowser();
  const out = [];
  const print = (line = '') => out.push(line);
  try {
    const blank = await browser.context.newPage();
    const version = await (await browser.context.newCDPSession(blank)).send('Browser.getVersion');
    await blank.close();
    const cpu = cpus();
    print('# Phasebook in the browser');
    print();
    print(`Machine: ${cpu[0]?.model ?? 'unknown CPU'}, ${cpu.length} cores, ${(totalmem() / 2 ** 30).toFixed(1)} GiB; ` +
      `Node ${process.version}; ${version.product} (headless, --disable-gpu).`);
    print(`Load average (1 min) ${loadBefore.toFixed(2)} before the run: ` +
      `other work on the machine shows up as missed frames, long tasks and slower loads.`);
    print();
    if (!ONLY) await interactive(browser, server, print);
    const paths = measuredPages();
    const simulators = await firstSimulators(browser.context, server.origin, paths);
    if (!ONLY || ONLY === 'cold') await coldLoads(browser, server, print, paths, simulators);
    if (!ONLY || ONLY === 'lighthouse') {
      print('g. Lighthouse, every page.');
      print();
      await lighthouseTable(server.origin, measuredPages(), { print, log });
    }
    if (!ONLY || ONLY === 'first') {
      // One browser at a time: the shared one is closed before the first visits start their own.
      await browser.close();
      const links = paths.filter((path) => simulators.get(path)).map((path) => `${server.origin}${path}#${simulators.get(path)}`);
      printFirstVisits(await firstVisits(links, { loads: LOADS, log }), print, { loads: LOADS });
    }
    print(`Run took ${((Date.now() - started) / 1000).toFixed(0)} s.`);
  } finally {
    await browser.close();
    await server.close();
  }
  process.stdout.write(`${out.join('\n')}\n`);
}

main().catch((error) => {
  process.stderr.write(`bench:browser failed: ${error?.stack ?? error}\n`);
  process.exitCode = 1;
});
