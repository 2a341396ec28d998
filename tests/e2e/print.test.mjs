/**
 * A chapter on paper (site/styles/print.css, cells/handout.ts,
 * cells/print-captions.ts, widgets/simulator/print-frame.ts), on
 * /introduction/, whose last two simulators are far below the first view:
 * Print handout runs every cell before it prints; in print media no
 * toolbar or control shows; every simulator has drawn the printed span of
 * its motion; every figure has a caption with the absolute address of its
 * live cell and is not split across pages; a definition's code prints, a
 * widget's does not. And `beforeprint` alone (Ctrl+P) draws a simulator's
 * frame synchronously, since the browser prints right after it.
 */
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { cell, firstViewReady, openSite, watchPage } from './fixture.mjs';

const CHAPTER = '/introduction/';
/** The printed span of simulated time (widgets/simulator/print-frame.ts's PRINT_SPAN). */
const PRINT_SPAN = 10;

/** The simulator cells of the chapter, by name, read from its source: `name = simulator(` in a cell. */
const SOURCE = readFileSync(fileURLToPath(new URL('../../content/introduction.mdx', import.meta.url)), 'utf8');
const SIMULATORS = [...SOURCE.matchAll(/```js cell\n(\w+)\s*=\s*simulator\(/g)].map((m) => m[1]);

/**
 * The browser's print, as a test can see it: Chromium sends `beforeprint` and then prints in one pass; here the
 * pass is recorded instead of opening a dialog, and the page is then looked at in print media.
 */
const RECORD_PRINT = () => {
  window.print = () => {
    dispatchEvent(new Event('beforeprint'));
    document.documentElement.dataset.printed = String(Number(document.documentElement.dataset.printed ?? 0) + 1);
  };
};

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => {
  site = await openSite({ viewport: { width: 1100, height: 900 } });
});
after(() => site?.close());

test('the chapter has simulators far from the first view', () => {
  assert.ok(SIMULATORS.length >= 3, `simulators in ${CHAPTER}: ${SIMULATORS.join(', ')}`);
});

test('Print handout runs every cell, then prints a page with no toolbar, a drawn frame and a captioned figure per simulator', async () => {
  const page = await site.context.newPage();
  await page.addInitScript(RECORD_PRINT);
  const { problems } = watchPage(page);
  await page.goto(site.origin + CHAPTER);
  await firstViewReady(page);
  // The last simulator is far below the first view: it has not run, so without the handout it would print nothing.
  const last = SIMULATORS[SIMULATORS.length - 1];
  assert.equal(await cell(page, last).locator('[data-widget="simulator"]').count(), 0, `${last} ran before it was asked to`);

  await page.getByRole('button', { name: 'Print handout' }).click();
  await page.waitForSelector('html[data-printed="1"]', { state: 'attached', timeout: 240_000 });
  assert.ok(await page.evaluate(() => document.body.hasAttribute('data-cells-complete')), 'printed before every cell had shown its result');

  await page.emulateMedia({ media: 'print' });
  const visibleControls = await page.evaluate(() =>
    [...document.querySelectorAll('button, select, input, textarea, [role="toolbar"], .cell-toolbar, .site-header, .chapter-nav, .on-this-page')]
      .filter((node) => node.checkVisibility())
      .map((node) => `${node.tagName.toLowerCase()}.${node.className} "${node.textContent?.trim().slice(0, 30)}"`),
  );
  assert.deepEqual(visibleControls, [], 'controls visible in print');

  for (const name of SIMULATORS) {
    const root = cell(page, name);
    const state = await root.evaluate((figure) => {
      const simulator = figure.querySelector('[data-widget="simulator"]');
      if (!simulator) return null;
      // The share of a canvas's pixels that differ from its corner, its background.
      const inkOf = (canvas) => {
        const pixels = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
        let ink = 0;
        for (let i = 0; i < pixels.length; i += 4) {
          if (pixels[i] !== pixels[0] || pixels[i + 1] !== pixels[1] || pixels[i + 2] !== pixels[2] || pixels[i + 3] !== pixels[3]) ink++;
        }
        return ink / (canvas.width * canvas.height);
      };
      // A view may stack canvases (its plot, and a layer for the present state over it): its ink is theirs together.
      const views = [...simulator.querySelector('.pb-views').children].filter((view) => view.querySelector('canvas')?.checkVisibility());
      const { simulation } = simulator.simulator;
      return {
        t: simulation.t - simulation.t0,
        views: views.length,
        ink: views.map((view) => [...view.querySelectorAll('canvas')].reduce((sum, canvas) => sum + inkOf(canvas), 0)),
        breakInside: getComputedStyle(figure).breakInside,
        codeShown: figure.querySelector('.cell-box').checkVisibility(),
      };
    });
    assert.ok(state, `no simulator in ${name}`);
    assert.ok(state.t >= PRINT_SPAN - 1e-9, `${name} printed t = ${state.t}, less than the printed span`);
    assert.ok(state.views >= 1, `${name} prints no view`);
    for (const ink of state.ink) assert.ok(ink > 0.01, `${name}: a view is blank (${(ink * 100).toFixed(2)} % drawn)`);
    assert.equal(state.breakInside, 'avoid', `${name} may be split across pages`);
    assert.equal(state.codeShown, false, `${name}'s code prints`);

    const caption = root.locator('.cell-print-caption');
    assert.ok(await caption.isVisible(), `${name} has no caption in print`);
    const live = new URL(`#cell-${name}`, site.origin + CHAPTER).href;
    assert.match(live, /^http:\/\/127\.0\.0\.1:\d+\/introduction\/#cell-/);
    assert.ok((await caption.textContent()).includes(live), `${name}'s caption does not give ${live}: ${await caption.textContent()}`);
    assert.equal(await caption.locator('a').getAttribute('href'), live);
  }
  // A definition of the lesson's inputs prints its code, plain.
  assert.ok(await cell(page, 'H').locator('.cell-code').isVisible(), "H's code does not print");
  assert.deepEqual(problems, []);
  await page.close();
});

test('beforeprint alone (Ctrl+P) draws each simulator on the page at once: the browser prints right after it', async () => {
  // With reduced motion no simulator plays by itself: whatever it shows after the event, the event drew.
  const page = await site.context.newPage({ reducedMotion: 'reduce' });
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await page.goto(site.origin + CHAPTER);
  await firstViewReady(page);
  const first = SIMULATORS[0];
  await cell(page, first).scrollIntoViewIfNeeded();
  await cell(page, first).locator('[data-widget="simulator"]').waitFor({ state: 'attached' });
  const times = await page.evaluate((name) => {
    const simulator = document.querySelector(`[data-cell="${name}"] [data-widget="simulator"]`).simulator;
    const before = simulator.simulation.t - simulator.simulation.t0;
    dispatchEvent(new Event('beforeprint'));
    // Read in the same task as the event: no frame has run in between, as none does before the browser prints.
    return { before, after: simulator.simulation.t - simulator.simulation.t0 };
  }, first);
  assert.ok(times.before < PRINT_SPAN, `${first} had already run ${times.before} time units`);
  assert.ok(times.after >= PRINT_SPAN - 1e-9, `${first} shows t = ${times.after} after beforeprint`);
  await page.close();
});
