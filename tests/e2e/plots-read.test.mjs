/**
 * Plots that read (issue 10): axis labels that never touch or get cut, at
 * any magnitude, on the built pages; autoscale that hugs the data and keeps
 * a quantity that cannot be negative above zero; symlog axes labelled at
 * every decade; each plot's text alternative and data-table view. (Every
 * simulator on every page fitting a 360 px phone, with axes that read, is
 * checked in the sweep of every page, every-page.mjs.)
 *
 * Axes are read through each plot element's `axes` property (the labels as
 * drawn: text, position and measured width in CSS px, and the font size),
 * so overlap is judged with the browser's own text widths.
 */
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { after, before, test } from 'node:test';
import { HANG_MS } from './browser.mjs';
import { openChapter, openSite, typeIntoCell } from './fixture.mjs';
import { plotAxes, plotProblems } from './plot-axes.mjs';

/** The least time between two rewrites of a plot's text, as the plot declares it (read from its source: this file is not compiled). */
const TEXT_INTERVAL_MS = Number(readFileSync(new URL('../../widgets/plots/plot-table.ts', import.meta.url), 'utf8').match(/TEXT_INTERVAL_MS = (\d+)/)[1]);

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

/** Edits a cell that rebuilds the simulator `selector`: the one there now is marked, so that only its successor is awaited. */
async function editRebuilding(page, id, source, selector) {
  await page.evaluate((s) => document.querySelector(s)?.setAttribute('data-stale', ''), selector);
  await typeIntoCell(page, id, source);
}

/** Scrolls the simulator `selector` into view once it is rebuilt and ready (an edited cell replaces it). */
async function showSimulator(page, selector) {
  for (let attempt = 0; ; attempt++) {
    await page.waitForSelector(`${selector}[data-ready]:not([data-stale])`);
    try {
      await page.locator(`${selector}:not([data-stale])`).scrollIntoViewIfNeeded();
      return;
    } catch (error) {
      if (attempt > 4) throw error;
      await page.waitForTimeout(300);
    }
  }
}

/** Waits until `predicate(axes of the plot)` holds, polling; returns the last axes. */
async function waitForAxes(page, selector, predicate) {
  const deadline = Date.now() + HANG_MS;
  let last;
  while (Date.now() < deadline) {
    last = await page.locator(selector).evaluate((el) => JSON.parse(JSON.stringify(el.axes)));
    if (predicate(last)) return last;
    await page.waitForTimeout(200);
  }
  throw new Error(`axes of ${selector} never matched; last ${JSON.stringify(last).slice(0, 600)}`);
}

test('introduction at dt = 0.5: the blown-up phase portrait and time plot have labels that neither touch nor get cut', async () => {
  for (const width of [1100, 390]) {
    const { page, problems } = await openChapter(site, '/introduction/');
    await page.setViewportSize({ width, height: 900 });
    const sim = '[data-cell="sim"] [data-widget="simulator"]';
    await editRebuilding(page, 'dt', 'dt = 0.5', sim);
    await showSimulator(page, sim);
    // q and p grow past 1e12 within a few seconds at this step
    await waitForAxes(page, `${sim} [data-widget="phase-portrait"]`, ([a]) => Math.max(...a.x.domain.map(Math.abs)) > 1e9);
    const plots = await plotAxes(page, sim);
    assert.deepEqual(plotProblems(plots), [], `at ${width} px`);
    for (const p of plots) for (const a of p.axes) for (const l of [...a.x.labels, ...a.y.labels]) assert.doesNotMatch(l.text, /\d,\d{3},/);
    assert.deepEqual(problems, []);
    await page.close();
  }
});

/**
 * The nonlinear oscillator's other turning point q₋ < 0, where
 * V(q) = 50q² − 2q³ − 3q⁴ equals the energy V(1) = 45 it starts with
 * (energy conservation; H of the chapter with ω0 = 10, α = −2, β = −3).
 */
function turningPoint() {
  const V = (q) => 50 * q * q - 2 * q ** 3 - 3 * q ** 4 - 45;
  let [a, b] = [-1.5, 0];
  for (let i = 0; i < 100; i++) {
    const m = (a + b) / 2;
    if (V(m) > 0) a = m;
    else b = m;
  }
  return (a + b) / 2;
}

test('nonlinear oscillator: the time plot hugs q between its turning points once it has settled', async () => {
  const { page, problems } = await openChapter(site, '/nonlinear-oscillator/');
  const plot = '[data-cell="oscillator"] [data-widget="time-plot"]';
  await page.locator(plot).scrollIntoViewIfNeeded();
  const low = turningPoint();
  const span = 1 - low;
  // a window of 2 time units without growth, then the range fits what is in view
  const [axes] = await waitForAxes(page, plot, ([a]) => a.x.domain[1] > 3 && a.y.domain[1] - a.y.domain[0] < 1.25 * span);
  const [y0, y1] = axes.y.domain;
  assert.ok(y0 <= low + 1e-3 && y1 >= 1 - 1e-3, `[${y0}, ${y1}] holds [${low}, 1]`);
  assert.ok(span >= 0.8 * (y1 - y0), `[${y0}, ${y1}] wastes more than a fifth on q in [${low.toFixed(3)}, 1]`);
  assert.deepEqual(plotProblems([{ kind: 'time-plot', axes: [axes] }]), []);
  assert.deepEqual(problems, []);
  await page.close();
});

test('kepler with k = 200: the distance r of stars flying apart is plotted from 0 up, never below', async () => {
  const { page, problems } = await openChapter(site, '/kepler/');
  await editRebuilding(page, 'k', 'k = 200', '[data-cell="stars"] [data-widget="simulator"]');
  const plot = '[data-cell="stars"] [data-widget="time-plot"]';
  await showSimulator(page, '[data-cell="stars"] [data-widget="simulator"]');
  // unbound: r grows without end, and the range with it
  const [axes] = await waitForAxes(page, plot, ([a]) => a.y.domain[1] > 40 && a.x.domain[1] > 4);
  const r = await page.locator('[data-cell="stars"] [data-widget="simulator"]').evaluate((el) => {
    const rec = el.simulator.simulation.record;
    const c = rec.columnIndex('r');
    let min = Infinity;
    for (let i = 0; i < rec.length; i++) min = Math.min(min, rec.get(i, c));
    return min;
  });
  assert.ok(r > 0);
  assert.equal(axes.y.domain[0], 0, `r ≥ ${r} drawn on [${axes.y.domain}]`);
  for (const l of axes.y.labels) assert.doesNotMatch(l.text, /^−/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('log y labels every decade of a growing motion (introduction, f = 0, γ = 21.3)', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  // the chapter's first "Try it": no drive, γ in the unstable band
  await editRebuilding(page, 'params', 'params = ({u: 0.3, gamma: 21.3, beta: 0.2, kappa: 8, omega: 10, f: 0})', '[data-cell="sim"] [data-widget="simulator"]');
  const plot = '[data-cell="sim"] [data-widget="time-plot"]';
  await showSimulator(page, '[data-cell="sim"] [data-widget="simulator"]');
  await page.locator(`${plot} button`, { hasText: 'log y' }).click();
  const [axes] = await waitForAxes(page, plot, ([a]) => a.y.kind === 'symlog' && Math.max(...a.y.domain.map(Math.abs)) >= 1e3);
  const labels = axes.y.labels.map((l) => l.text);
  const top = Math.floor(Math.log10(Math.max(...axes.y.domain.map(Math.abs))) + 1e-9);
  const power = (k) => (k < 4 ? String(10 ** k) : `10${String(k).replace(/\d/g, (d) => '⁰¹²³⁴⁵⁶⁷⁸⁹'[d])}`);
  // every decade from 10 up on each side the range reaches (1 may give way to 0, a line of text away on a short plot)
  for (let k = 1; k <= top; k++) {
    if (axes.y.domain[1] >= 10 ** k) assert.ok(labels.includes(power(k)), `${power(k)} missing from ${labels}`);
    if (axes.y.domain[0] <= -(10 ** k)) assert.ok(labels.includes(`−${power(k)}`), `−${power(k)} missing from ${labels}`);
  }
  assert.ok(labels.includes('0'));
  assert.deepEqual(plotProblems([{ kind: 'time-plot', axes: [axes] }]), []);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the batch readout says the drift, then which trajectory: the count never runs into the number', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  const sim = page.locator('[data-cell="batch"] [data-widget="simulator"]');
  await sim.scrollIntoViewIfNeeded();
  await page.waitForTimeout(500);
  const item = await sim.evaluate((el) => {
    const value = [...el.querySelectorAll('.pb-readout')].find((r) => r.textContent.includes('ΔH'));
    return [...value.children].map((c) => c.textContent);
  });
  assert.equal(item[0], '|ΔH/H₀|');
  assert.match(item[1], /^(0|\d\.\d × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)$/);
  assert.equal(item[2], '(worst of 9)');
  assert.deepEqual(problems, []);
  await page.close();
});

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

test('every plot has a text alternative with its ranges and current values, rewritten a few times a second, not each frame', async (t) => {
  // A browser of its own, with a clock the test can stop and move on by hand: a clock is the whole
  // context's (page.clock is context.clock), and stopped it would stop every later test's pages.
  const own = await openSite();
  t.after(() => own.close());
  await own.context.clock.install();
  const { page, problems } = await openChapter(own, '/introduction/');
  const sim = '[data-cell="sim"] [data-widget="simulator"]';
  await page.locator(sim).scrollIntoViewIfNeeded();
  // The spectrum names its strongest peak once its window holds enough of the motion: soon on a quiet machine,
  // later on a busy one, where fewer frames come. On a desk the whole simulator is in view, so that can come
  // within a few tenths of a time unit, before p has swung both ways: the texts are read after a whole unit.
  await page.waitForFunction(
    (selector) =>
      /strongest peak/.test(document.querySelector(`${selector} [data-widget="spectrum"] canvas`)?.getAttribute('aria-label') ?? '') &&
      document.querySelector(selector).simulator.simulation.t > 1,
    sim,
  );
  const texts = () =>
    page.locator(sim).evaluate((root) => {
      const time = root.querySelector('[data-widget="time-plot"] .pb-stage');
      return {
        // described by the scroll hint, then the text alternative
        time: document.getElementById(time.getAttribute('aria-describedby').split(' ').pop())?.textContent ?? '',
        phase: root.querySelector('[data-widget="phase-portrait"] canvas').getAttribute('aria-label'),
        spectrum: root.querySelector('[data-widget="spectrum"] canvas').getAttribute('aria-label'),
      };
    });
  const first = await texts();
  // A number as the plots write it: plain, or with a power of ten when very small or large (1.200 × 10⁻⁶).
  const n = String.raw`−?[\d.]+(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?`;
  assert.match(first.time, new RegExp(`^q, p against t, t from ${n} to ${n}; y from ${n} to ${n}, linear scale\\. At t = ${n}: q = ${n}, p = ${n}\\.$`));
  assert.match(first.phase, new RegExp(`^Phase portrait: momentum against coordinate, t = ${n}: p against q; q from ${n} to ${n}, p from ${n} to ${n}; now q = ${n}, p = ${n}$`));
  assert.match(first.spectrum, /strongest peak at f = [\d.]+; dashed line: drive κ\/2π at f = [\d.]+/);
  // The plot rewrites its text at most every 500 ms by the page's clock (widgets/plots/plot-table.ts). That
  // clock is stopped here and moved on by hand, one 16 ms frame at a time, so that the gaps are exact on any
  // machine: each rewrite is stamped by the same clock the plot reads, and a busy machine only makes the
  // frames take longer, not come farther apart.
  await page.clock.pauseAt(await page.evaluate(() => Date.now() + 1000));
  await page.locator(sim).evaluate((root) => {
    const canvas = root.querySelector('[data-widget="phase-portrait"] canvas');
    const seen = { frames: 0, rewrites: [] };
    window.__rewrites = seen;
    new MutationObserver(() => seen.rewrites.push(performance.now())).observe(canvas, { attributes: true, attributeFilter: ['aria-label'] });
    const tick = () => {
      seen.frames++;
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  const span = 8 * TEXT_INTERVAL_MS;
  await page.clock.runFor(span);
  const changes = await page.evaluate(() => window.__rewrites);
  const gaps = changes.rewrites.slice(1).map((t, i) => t - changes.rewrites[i]);
  // At most one rewrite per interval, and a rewrite in (nearly) every interval: it moves, but not each frame.
  assert.ok(changes.rewrites.length >= span / TEXT_INTERVAL_MS - 2, `rewritten ${changes.rewrites.length} times in ${span} ms: ${JSON.stringify(changes)}`);
  assert.ok(changes.frames > 5 * changes.rewrites.length, `rewritten ${changes.rewrites.length} times in ${changes.frames} frames`);
  for (const gap of gaps) assert.ok(gap >= TEXT_INTERVAL_MS, `rewrites ${gap} ms apart: ${JSON.stringify(changes)}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('every plot has a Table toggle, operable by keyboard, showing its data as an HTML table a screen reader can walk', async () => {
  const { page, problems } = await openChapter(site, '/introduction/');
  const sim = page.locator('[data-cell="sim"] [data-widget="simulator"]');
  await sim.scrollIntoViewIfNeeded();
  await page.waitForTimeout(3000);
  // paused, so that the table and the plot it is compared with hold the same samples (the spectrum's last recompute comes after)
  await sim.evaluate((el) => el.simulator.pause());
  await page.waitForTimeout(800);
  for (const kind of ['time-plot', 'phase-portrait', 'spectrum']) {
    const plot = sim.locator(`[data-widget="${kind}"]`);
    const button = plot.locator('button.pb-table-toggle');
    assert.equal(await button.getAttribute('aria-expanded'), 'false');
    await button.focus();
    await page.keyboard.press('Enter');
    assert.equal(await button.getAttribute('aria-expanded'), 'true');
    const region = plot.locator(`#${await button.getAttribute('aria-controls')}`);
    assert.equal(await region.isVisible(), true);
    const table = await region.evaluate((r) => ({
      caption: r.querySelector('caption')?.textContent ?? '',
      head: [...r.querySelectorAll('thead th')].map((th) => [th.textContent, th.scope]),
      rows: [...r.querySelectorAll('tbody tr')].map((tr) => [...tr.children].map((c) => c.textContent)),
      rowHeads: [...r.querySelectorAll('tbody th')].map((th) => th.scope),
    }));
    assert.ok(table.caption.length > 10, table.caption);
    for (const [, scope] of table.head) assert.equal(scope, 'col');
    for (const scope of table.rowHeads) assert.equal(scope, 'row');
    assert.ok(table.rows.length >= 2 && table.rows.length <= 12, `${kind}: ${table.rows.length} rows`);
    if (kind === 'spectrum') {
      assert.deepEqual(table.head.map(([h]) => h), ['peak', 'f (cycles per time unit)', 'ω = 2πf', 'amplitude']);
      assert.ok(table.rows.some((r) => r[0] === 'dashed line: drive κ/2π'));
      // the strongest peak in the table is the one the plot reports
      const peak = await plot.evaluate((el) => el.peaks[0].frequency);
      assert.ok(Math.abs(Number(table.rows[0][1]) - peak) < 1e-3 * peak, `${table.rows[0][1]} vs ${peak}`);
    } else {
      assert.deepEqual(table.head.map(([h]) => h).slice(0, 3), ['t', 'q', 'p']);
      // each row is the record's sample at that time: a row whose t and q round to what the table says (4 significant digits)
      const ok = await sim.evaluate((el, rows) => {
        const rec = el.simulator.simulation.record;
        const read = (text) => Number(text.replace('−', '-').replace(' × 10', 'e').replace(/[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+$/, (e) => e.replace('⁻', '-').replace(/[⁰¹²³⁴⁵⁶⁷⁸⁹]/g, (d) => '⁰¹²³⁴⁵⁶⁷⁸⁹'.indexOf(d))));
        const halfDigit = (v) => (v === 0 ? 5e-5 : 0.5 * 10 ** (Math.floor(Math.log10(Math.abs(v))) - 3)) * (1 + 1e-9);
        return rows.every(([t, q]) => {
          const [tv, qv] = [read(t), read(q)];
          const [from, to] = rec.range(tv - halfDigit(tv), tv + halfDigit(tv));
          for (let r = from; r < to; r++) if (Math.abs(rec.get(r, 1) - qv) <= halfDigit(qv)) return true;
          return false;
        });
      }, table.rows);
      assert.ok(ok, JSON.stringify(table.rows.slice(0, 3)));
    }
    // axe on the open table and its toggle
    await page.evaluate(AXE);
    const violations = await region.evaluate(async (r) => (await window.axe.run(r.closest('[data-widget]'), { resultTypes: ['violations'] })).violations.map((v) => v.id));
    assert.deepEqual(violations, [], kind);
    await page.keyboard.press('Enter');
    assert.equal(await button.getAttribute('aria-expanded'), 'false');
    assert.equal(await region.isVisible(), false);
  }
  assert.deepEqual(problems, []);
  await page.close();
});
