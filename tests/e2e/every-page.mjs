/**
 * The sweep of every page of the built book at one width: each page is
 * loaded once, in a fresh tab, read through as a reader does (every cell run,
 * every widget ready), and every check that holds for every page runs on
 * that one load. Two test files run it side by side, each in its own
 * browser: at 1280 px (every-page-desk.test.mjs), and at 390 px then,
 * on the same load, narrowed to 360 px (every-page-phone.test.mjs).
 *
 * On every page, at every width:
 * - no console error or warning, page error, failed or foreign request, or
 *   HTTP error, and every request to this host (or a data: URL).
 * At 1280 and 390 px:
 * - axe finds no violation, every cell run;
 * - every simulator appears in the box the build reserved for it, to 1.5 px
 *   (the box as the first paint shows it, before any cell ran, against the
 *   simulator once ready, less the notes it shows later).
 * At 1280 px (a cell is 58rem wide from 1024 px on, so this is the desk
 * layout of 1100 px as well):
 * - a cell's code far from the view, not laid out, keeps the place it
 *   takes when laid out, to the layout's rounding (lines/64 px);
 * - reading the page loads none of the heavy modules (mathjs, KaTeX's
 *   JavaScript, the cell parser, the editor), after a while idle too;
 * - no cell shows an error, and every theory check agrees (its verdict, and
 *   its numbers recomputed here); except on /order-and-chaos/, whose checks
 *   at the paper's factor 1.5 are outside their formulas' validity by design
 *   (chapter-order-and-chaos.test.mjs asserts each of its verdicts).
 * At 390 and 360 px, the phone audit (phone-audit.mjs): nothing cut off,
 * every column of every table shown, text at 11 px or more; Kepler's table
 * and the three scattering figures among what was audited.
 * At 360 px, every simulator fits the width (its box and everything in it
 * that is not inside a box that clips or scrolls), and every plot's axes
 * read (labels that neither touch nor get cut, text ≥ 11 px).
 *
 * Every page is checked in the book's fonts (see inTheBooksFonts).
 *
 * A last test asserts what the sweep covered: every chapter the contents
 * page lists, and enough simulators, reserved boxes and codes compared.
 */
import assert from 'node:assert/strict';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { after, before, describe, test } from 'node:test';
import { HEAVY } from '../../bench/cold-load.mjs';
import { assertAgrees, theoryChecks, widgetsReady } from './chapter-checks.mjs';
import { cellsReady, openSite, watchPage } from './fixture.mjs';
import { audit, settle, SMALLEST_TEXT } from './phone-audit.mjs';
import { plotAxes, plotProblems } from './plot-axes.mjs';
import { DIST } from './server.mjs';

/** Every page of the built book: the contents and each folder holding an index.html. */
export function pages() {
  const found = ['/'];
  for (const entry of readdirSync(DIST, { withFileTypes: true })) {
    if (entry.isDirectory() && !entry.name.startsWith('_') && existsSync(join(DIST, entry.name, 'index.html'))) found.push(`/${entry.name}/`);
  }
  return found;
}

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

/** What each width checks (see the file's comment). */
const PLAN = {
  1280: { height: 900, axe: true, reserved: true, codePlaces: true, heavy: true, healthy: true },
  // Then, on the same load, the page narrowed to 360 px, as a phone turned or a window resized makes it: the
  // layout must follow a width that changes, and a third load of every page would cost the suite a minute.
  390: { height: 800, axe: true, reserved: true, phone: true, narrower: { width: 360, phone: true, fits: true } },
};

/** How long the reader stays on a page before it is checked for heavy modules, ms: idle time must fetch none. */
const IDLE_MS = 1500;

/** Pages whose theory checks do not all agree on purpose (see the file's comment). */
const CHECKS_DISAGREE = new Set(['/order-and-chaos/']);

const heavyIn = (requests) => HEAVY.filter(([, pattern]) => requests.some((url) => pattern.test(url))).map(([name]) => name);

/** In the page: each simulator box the build reserved that no cell has replaced yet, with its output's height. */
export function reservedBoxes() {
  return [...document.querySelectorAll('[data-reserve="simulator"]')].map((box) => ({
    id: box.closest('[data-cell]').id,
    height: box.closest('[data-cell-output]').getBoundingClientRect().height,
  }));
}

/** In the page: the height the simulator in cell `id` takes, less the messages it shows later; null if it has none. */
export function simulatorHeight(id) {
  const output = document.getElementById(id).querySelector('[data-cell-output]');
  const simulator = output.querySelector('[data-widget="simulator"]');
  if (!simulator) return null;
  // A message the widget shows later (behind real time, samples dropped, a blow-up) is news the reader is
  // meant to see arrive; the reservation is for the widget as it first appears. So is the speed readout's
  // "behind real time, 13%", which on a busy machine can wrap the controls onto one more row: it is measured
  // as first shown.
  const messages = [...simulator.querySelectorAll(':scope > .pb-note, :scope > .pb-alert')].reduce((sum, m) => sum + m.getBoundingClientRect().height, 0);
  const speed = simulator.querySelector('.pb-speed-text');
  const shown = speed?.textContent ?? '';
  if (speed) speed.textContent = shown.replace(/ · behind real time, \d+%$/, '');
  const height = output.getBoundingClientRect().height - messages;
  if (speed) speed.textContent = shown;
  return height;
}

/**
 * The code cells far from the view, not laid out (content-visibility), against their height once laid out;
 * the page is left as it was. Must run before the page is scrolled: a block once shown keeps its last size.
 */
async function codePlaces(page) {
  const measure = () =>
    page.evaluate(() =>
      [...document.querySelectorAll('pre.cell-code')].map((pre) => ({
        height: pre.getBoundingClientRect().height,
        lines: Number(pre.style.getPropertyValue('--lines')),
        skipped: !pre.firstElementChild.checkVisibility({ contentVisibilityAuto: true }),
      })),
    );
  const before = await measure();
  const style = await page.addStyleTag({ content: 'pre.cell-code { content-visibility: visible !important; }' });
  const laidOut = await measure();
  await style.evaluate((element) => element.remove());
  return before.flatMap((b, i) => (b.skipped ? [{ index: i, lines: b.lines, kept: b.height, laidOut: laidOut[i].height }] : []));
}

/**
 * In the page, for the simulator `i`: its box and anything inside it that shows beyond the viewport's width
 * (not inside a box that scrolls or hides what overflows it).
 */
function outsideWidth(root) {
  const width = document.documentElement.clientWidth;
  const r = root.getBoundingClientRect();
  const out = r.left < 0 || r.right > width ? [`the simulator spans ${r.left} … ${r.right}`] : [];
  for (const el of root.querySelectorAll('*')) {
    const b = el.getBoundingClientRect();
    if (!el.getClientRects().length || (b.right <= width + 0.5 && b.left >= -0.5)) continue;
    let clipped = false;
    for (let a = el.parentElement; a && a !== root.parentElement && !clipped; a = a.parentElement) {
      const box = a.getBoundingClientRect();
      clipped = getComputedStyle(a).overflowX !== 'visible' && box.right <= width + 0.5 && box.left >= -0.5;
    }
    if (!clipped) out.push(`${el.tagName.toLowerCase()}.${el.className} spans ${Math.round(b.left)} … ${Math.round(b.right)}`);
  }
  return out;
}

/**
 * Runs in the page before its scripts: the book's fonts are declared `font-display: optional`
 * (site/lib/fonts.ts), so a face that has not arrived by the first layout, about 100 ms, is not used on that
 * page view, and on a busy machine some pages come up in the system's fonts, whose wider text wraps a
 * simulator's controls differently (the pendulum's on /for-teachers/ at 1280 px, where its row of controls
 * has 6 px to spare). The sweep checks every page in the book's fonts, as a quiet machine shows it: each face
 * waits for its file (`block`) instead. The rules are the book's own, declared by its head script; only how
 * long a face is waited for changes.
 */
export function inTheBooksFonts() {
  new MutationObserver((records) => {
    for (const record of records) {
      for (const node of record.addedNodes) {
        if (node.nodeName === 'STYLE' && node.textContent?.includes('font-display:optional')) node.textContent = node.textContent.replaceAll('font-display:optional', 'font-display:block');
      }
    }
  }).observe(document, { childList: true, subtree: true });
}

/** Two animation frames: what a scroll or a style changed is laid out and drawn. */
const frames = (page) => page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));

/** Registers the sweep of every page at `width` px (1280, 390 or 360). */
export function sweepEveryPage(width) {
  const plan = PLAN[width];
  /** @type {Awaited<ReturnType<typeof openSite>>} */
  let site;
  /** Paths of the chapters the contents page lists. */
  let listed = [];
  const seen = { paths: [], reserved: 0, codes: 0, worstCode: 0, simulators: 0, keplerTables: [], scatteringCharts: [] };

  before(async () => {
    site = await openSite();
    const page = await site.context.newPage();
    await page.goto(`${site.origin}/`);
    // No saved edits: the profile is fresh, and this says so.
    await page.evaluate(() => localStorage.clear());
    listed = await page.locator('.toc a').evaluateAll((links) => links.map((a) => a.getAttribute('href')));
    await page.close();
  });
  after(() => site?.close());

  describe(`every page at ${width} px, read through once`, () => {
    for (const path of pages()) {
      test(path, async (t) => {
        const page = await site.context.newPage();
        await page.addInitScript(inTheBooksFonts);
        await page.setViewportSize({ width, height: plan.height });
        const { problems, requests } = watchPage(page);
        /** Each check's failure, so that one failing check does not hide the others on this page. */
        const failures = [];
        const check = async (name, body) => {
          try {
            await body();
          } catch (error) {
            failures.push(`${name}: ${error instanceof Error ? error.message : String(error)}`);
          }
        };
        await page.goto(`${site.origin}${path}`);
        const hasCells = (await page.locator('[data-cell]').count()) > 0;
        // Boxes of cells that have not started yet (below the first view) are still the build's.
        const reserved = plan.reserved ? await page.evaluate(reservedBoxes) : [];
        const codes = plan.codePlaces ? await codePlaces(page) : [];
        if (hasCells) {
          await cellsReady(page);
          await widgetsReady(page);
        }
        const readAt = Date.now();
        seen.paths.push(path);

        if (plan.healthy && hasCells) {
          await check('no cell shows an error', async () => assert.deepEqual(await page.locator('[data-cell-error]:visible').allTextContents(), []));
          if (!CHECKS_DISAGREE.has(path)) {
            await check('every theory check agrees', async () => {
              for (const c of await theoryChecks(page)) assertAgrees(c);
            });
          }
        }
        if (plan.axe) {
          await check('axe', async () => {
            // Evaluated, not injected as a <script>: the page's Content-Security-Policy rightly refuses inline scripts.
            await page.evaluate(AXE);
            const violations = await page.evaluate(async () =>
              (await window.axe.run(document, { resultTypes: ['violations'] })).violations.map((v) => `${v.id} (${v.nodes.length}): ${v.nodes[0]?.target.join(' ')}`),
            );
            assert.deepEqual(violations, []);
          });
        }
        if (plan.reserved) {
          await check('each simulator in the box reserved for it', async () => {
            for (const { id, height } of reserved) {
              const real = await page.evaluate(simulatorHeight, id);
              if (real === null) continue;
              seen.reserved++;
              assert.ok(Math.abs(real - height) <= 1.5, `${id}: reserved ${height} px, the simulator takes ${real} px`);
            }
          });
        }
        if (plan.codePlaces) {
          await check('code not laid out keeps its place', async () => {
            for (const code of codes) {
              seen.codes++;
              seen.worstCode = Math.max(seen.worstCode, Math.abs(code.kept - code.laidOut) / code.lines);
              // Each line box is laid out on Chromium's grid of 1/64 px; the place kept is lines × the exact line height.
              assert.ok(Math.abs(code.kept - code.laidOut) <= code.lines / 64 + 0.01, `code ${code.index + 1} (${code.lines} lines): ${code.kept} px kept, ${code.laidOut} px laid out`);
            }
          });
        }
        /** The checks of a phone's width `w`: everything fits it and its axes read (fits), nothing is cut off (phone). */
        const phoneChecks = async (w, { fits, phone }) => {
          if (fits && hasCells) {
            await check(`every simulator fits ${w} px and its axes read`, async () => {
              const report = [];
              const sims = page.locator('[data-widget="simulator"]');
              const count = await sims.count();
              for (let i = 0; i < count; i++) {
                const sim = sims.nth(i);
                await sim.scrollIntoViewIfNeeded();
                await frames(page);
                let outside = await sim.evaluate(outsideWidth);
                if (outside.length) {
                  // What a scroll brings into view may still be laying out: a problem counts if it stays.
                  await page.waitForTimeout(700);
                  outside = await sim.evaluate(outsideWidth);
                }
                report.push(...outside.map((o) => `simulator ${i}: ${o}`));
                seen.simulators++;
              }
              report.push(...plotProblems(await plotAxes(page, 'body')));
              assert.deepEqual(report, []);
            });
          }
          if (phone) {
            await check(`at ${w} px, nothing cut off, every column shown, text at ${SMALLEST_TEXT} px or more`, async () => {
              await settle(page);
              assert.deepEqual(await page.evaluate(audit, SMALLEST_TEXT), []);
              const checked = await page.evaluate(() => ({
                tables: document.querySelectorAll('main.page table').length,
                charts: document.querySelectorAll('main.page [data-widget="chart"]').length,
              }));
              if (path === '/kepler/') seen.keplerTables.push(checked.tables);
              if (path === '/scattering/') seen.scatteringCharts.push(checked.charts);
            });
          }
        };
        await phoneChecks(width, plan);
        if (plan.narrower) {
          await page.setViewportSize({ width: plan.narrower.width, height: plan.height });
          await frames(page);
          await phoneChecks(plan.narrower.width, plan.narrower);
        }
        if (plan.heavy && hasCells) {
          await check('no heavy module, after a while idle too', async () => {
            const idle = readAt + IDLE_MS - Date.now();
            if (idle > 0) await page.waitForTimeout(idle);
            assert.deepEqual(heavyIn(requests), []);
          });
        }
        await check('no console error, page error, failed or foreign request', async () => {
          assert.deepEqual(problems, []);
          assert.deepEqual(requests.filter((url) => !url.startsWith(site.origin) && !url.startsWith('data:')), []);
        });
        t.diagnostic(`${requests.length} requests`);
        await page.close();
        assert.deepEqual(failures, [], `${path} at ${width} px`);
      });
    }

    test('the sweep covered the book', (t) => {
      t.diagnostic(JSON.stringify(seen));
      assert.ok(listed.length >= 2, `the contents page lists ${listed.length} chapters`);
      for (const path of listed) assert.ok(seen.paths.includes(path), `${path}, listed on the contents page, was swept`);
      if (plan.reserved) assert.ok(seen.reserved >= 10, `${seen.reserved} simulators compared with their reserved boxes`);
      if (plan.codePlaces) assert.ok(seen.codes >= 40, `${seen.codes} codes compared while not laid out`);
      if (plan.fits || plan.narrower?.fits) assert.ok(seen.simulators >= 10, `${seen.simulators} simulators checked`);
      if (plan.phone) {
        // Once at each phone width the page was audited at.
        const widths = plan.narrower?.phone ? 2 : 1;
        assert.ok(seen.keplerTables.length === widths && seen.keplerTables.every((n) => n >= 1), `Kepler’s readout table was audited: ${seen.keplerTables}`);
        assert.deepEqual(seen.scatteringCharts, Array(widths).fill(3), 'the scattering figures were audited');
      }
    });
  });
}
