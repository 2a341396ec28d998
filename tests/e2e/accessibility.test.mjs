/**
 * Reading and using the book without a mouse, and with the system's
 * accessibility settings: every control reachable and operable by keyboard,
 * the stability chart included; reduced motion respected; boxes that scroll
 * sideways reachable; axe with an editor open. (axe on every page, every cell
 * run, at 1280 and 390 px is part of the sweep of every page, every-page.mjs.)
 */
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { after, before, test } from 'node:test';
import { cell, cellsReady, openChapter, openSite } from './fixture.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

test('the stability chart is operable by keyboard: arrows move the point over the grid, Enter applies it', async () => {
  const { page, problems } = await openChapter(site, '/parametric-resonance/');
  const chart = page.locator('[data-widget="stability-chart"]');
  await page.waitForSelector('[data-widget="stability-chart"][data-ready]');
  const explorer = cell(page, 'explorer').locator('[data-widget="simulator"]');
  const params = () => explorer.evaluate((el) => Object.fromEntries(el.simulator.model.paramNames.map((n, i) => [n, el.simulator.model.params[i]])));
  const before = await params();
  await chart.locator('canvas').focus();
  // The grid: γ over [15, 25] in 120 points, u over [0, 1] in 60 (the chapter's chart).
  for (let i = 0; i < 3; i++) await page.keyboard.press('Shift+ArrowRight');
  await page.keyboard.press('ArrowUp');
  const reading = chart.locator('.pb-stability-reading');
  assert.match((await reading.textContent()) ?? '', /^gamma = [\d.]+, u = [\d.]+: (stable|unstable, growth rate [\d.e-]+)$/);
  // Moving is not choosing: the explorer keeps its parameters until Enter.
  assert.deepEqual(await params(), before);
  await page.keyboard.press('Enter');
  await page.waitForFunction(
    (old) => {
      const el = document.querySelector('[data-cell="explorer"] [data-widget="simulator"]');
      const gamma = el?.simulator.model.params[el.simulator.model.paramNames.indexOf('gamma')];
      return gamma !== undefined && gamma !== old;
    },
    before.gamma,
  );
  const after = await params();
  // Three large steps of ten grid cells, (25 − 15)/119 each, from the chosen γ; one cell of 1/59 up in u.
  assert.ok(Math.abs(after.gamma - Math.min(25, before.gamma + (3 * 10 * 10) / 119)) < 1e-9, `γ = ${after.gamma}`);
  assert.ok(Math.abs(after.u - (before.u + 1 / 59)) < 1e-9, `u = ${after.u}`);
  assert.match((await reading.textContent()) ?? '', /\(chosen\)$/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('with reduced motion asked for, simulators wait for Play', async () => {
  const page = await site.context.newPage();
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await page.goto(`${site.origin}/playground/`);
  await cellsReady(page);
  const sim = page.locator('[data-cell="sim"] [data-widget="simulator"]');
  await sim.waitFor();
  await sim.scrollIntoViewIfNeeded();
  await page.waitForTimeout(500);
  assert.equal(await sim.evaluate((el) => el.simulator.driver.playing), false);
  assert.equal(await sim.evaluate((el) => el.simulator.simulation.t), 0);
  await sim.locator('.pb-transport button').first().click();
  await page.waitForFunction(() => document.querySelector('[data-cell="sim"] [data-widget="simulator"]').simulator.simulation.t > 0);
  await page.close();
});

test('with reduced motion asked for, a chart its cell animates holds its first picture until Play', async () => {
  const page = await site.context.newPage();
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await page.goto(`${site.origin}/introduction/`);
  await cellsReady(page);
  const figure = cell(page, 'phasePortrait').locator('[data-widget="chart"][data-ready]');
  await figure.scrollIntoViewIfNeeded();
  const toggle = figure.locator('.pb-chart-tools button[data-motion]');
  await toggle.waitFor();
  assert.equal(await toggle.textContent(), 'Play');
  const state = () => figure.evaluate((f) => f.chart.series[1].curves[0].x[0]);
  const held = await state();
  // The generator keeps yielding (its inspected value changes); the figure does not move.
  const phase = () => page.locator('[data-cell="phase"] [data-cell-output]').textContent();
  const before = await phase();
  await page.waitForFunction((text) => document.querySelector('[data-cell="phase"] [data-cell-output]')?.textContent !== text, before);
  await page.waitForTimeout(300);
  assert.equal(await state(), held);
  await toggle.click();
  assert.equal(await toggle.textContent(), 'Pause');
  await page.waitForFunction((q) => document.querySelector('[data-cell="phasePortrait"] [data-widget="chart"]').chart.series[1].curves[0].x[0] !== q, held);
  await page.close();
});

test('display math wider than a phone’s column can be reached by keyboard and says that it scrolls', async () => {
  const page = await site.context.newPage();
  await page.setViewportSize({ width: 360, height: 800 });
  await page.goto(`${site.origin}/kepler/`);
  await cellsReady(page);
  // Prose far from the view is not laid out (global.css, content-visibility): each formula is read as a reader
  // meets it, in view, once the page has had a frame to mark it.
  const count = await page.locator('.katex-display').count();
  const scrollables = [];
  for (let i = 0; i < count; i++) {
    scrollables.push(
      await page.evaluate(async (i) => {
        const box = document.querySelectorAll('.katex-display')[i];
        box.scrollIntoView({ block: 'center' });
        await new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(done, 50))));
        return {
          overflows: box.scrollWidth > box.clientWidth + 1,
          focusable: box.tabIndex === 0,
          label: box.getAttribute('aria-label'),
          role: box.getAttribute('role'),
        };
      }, i),
    );
  }
  assert.ok(count >= 10, `Kepler’s display formulas, ${count}`);
  assert.ok(scrollables.some((s) => s.overflows), 'some formula is wider than 360 px');
  for (const s of scrollables) {
    assert.equal(s.focusable, s.overflows);
    if (s.overflows) {
      assert.match(s.label, /^Formula \d+, scrolls sideways$/);
      assert.equal(s.role, 'region');
    }
  }
  await page.close();
});

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

test('axe finds no violation with a cell’s editor open on a line wider than the phone', async () => {
  const page = await site.context.newPage();
  await page.setViewportSize({ width: 390, height: 900 });
  await page.goto(`${site.origin}/playground/`);
  await cellsReady(page);
  await page.locator('[data-cell="params"] .cell-editor').click();
  await page.waitForSelector('[data-cell="params"] .cm-content');
  await page.keyboard.press('End');
  await page.keyboard.insertText(' // a comment long enough to make this line wider than any phone is');
  const scrolls = await page.locator('[data-cell="params"] .cm-scroller').evaluate((e) => e.scrollWidth > e.clientWidth);
  assert.ok(scrolls, 'the editor scrolls sideways');
  await page.evaluate(AXE);
  const violations = await page.evaluate(async () =>
    (await window.axe.run(document, { resultTypes: ['violations'] })).violations.map((v) => `${v.id} (${v.nodes.length}): ${v.nodes[0]?.target.join(' ')}`),
  );
  assert.deepEqual(violations, []);
  await page.close();
});
