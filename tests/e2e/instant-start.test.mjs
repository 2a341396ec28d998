/**
 * Instant start: what the build did ahead (compiled models, typeset
 * equations; chapter/models/page-data.ts) lets every chapter run without its heavy
 * modules, and nothing depends on it being there.
 *
 * - Reading a chapter through, however long, requests none of mathjs,
 *   KaTeX's JavaScript, the cell parser or the editor; every simulator
 *   appears in the box the build reserved for it; code not laid out keeps
 *   its place (these three on every page, in the sweep of every-page.mjs).
 * - With the build's data missing, or from another version, every chapter
 *   still runs and its theory checks still agree: the page compiles and
 *   typesets for itself, and it must be seen doing so (mathjs is fetched).
 * - A reader's new H in any chapter is compiled on the page and the
 *   simulator follows its physics: checked against the closed form of the
 *   new motion.
 */
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { after, before, describe, test } from 'node:test';
import { gzipSync } from 'node:zlib';
import { HEAVY } from '../../bench/cold-load.mjs';
import { assertAgrees, theoryChecks, widgetsReady } from './chapter-checks.mjs';
import { cell, cellsReady, openSite, typeIntoCell, watchPage } from './fixture.mjs';
import { DIST } from './server.mjs';

/** Every page whose cells define models or show formulas. */
const CHAPTERS = [
  '/introduction/',
  '/how-the-simulator-integrates/',
  '/parametric-resonance/',
  '/nonlinear-oscillator/',
  '/kepler/',
  '/adiabatic-invariants/',
  '/scattering/',
  '/special-relativity/',
  '/playground/',
  '/for-teachers/',
];

const PAGE_DATA = /<template data-phasebook-page-data="[^"]*"><\/template>/g;

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite()));
after(() => site?.close());

const heavyIn = (requests) => HEAVY.filter(([, pattern]) => requests.some((url) => pattern.test(url))).map(([name]) => name);

/**
 * Opens `path` with no saved edits; `rewrite` may change the page's HTML on
 * its way in (to take the build's data out). Reads the chapter through.
 */
async function open(path, rewrite) {
  const page = await site.context.newPage();
  await page.goto(`${site.origin}/`);
  await page.evaluate(() => localStorage.clear());
  if (rewrite) {
    await page.route(`${site.origin}${path}`, async (route) => {
      const response = await route.fetch();
      const body = rewrite(await response.text());
      await route.fulfill({ response, body });
    });
  }
  const watch = watchPage(page);
  await page.goto(`${site.origin}${path}`);
  await cellsReady(page);
  await widgetsReady(page);
  return { page, ...watch };
}

/** Every theory check on the page agrees, and no cell shows an error. */
async function assertChapterHealthy(page) {
  const errors = await page.locator('[data-cell-error]:visible').allTextContents();
  assert.deepEqual(errors, []);
  const checks = await theoryChecks(page);
  for (const check of checks) assertAgrees(check);
  return checks.length;
}

test('the stability chart’s worker carries no mathjs: it builds its model from the compiled data it is sent', () => {
  const assets = join(DIST, '_astro');
  const workers = readdirSync(assets).filter((name) => /^stability-worker.*\.js$/.test(name));
  assert.equal(workers.length, 1);
  const code = readFileSync(join(assets, workers[0]), 'utf8');
  // Strings of mathjs's own code (its typed-function dispatch and its parser), checked to be in the mathjs chunk.
  const markers = ['Unexpected type of argument', 'Undefined symbol'];
  const mathjs = readdirSync(assets).filter((name) => /^mathjs.*\.js$/.test(name)).map((name) => readFileSync(join(assets, name), 'utf8')).join('');
  for (const marker of markers) {
    assert.ok(mathjs.includes(marker), `mathjs's chunk has "${marker}"`);
    assert.ok(!code.includes(marker), `the worker has "${marker}"`);
  }
  // Nor does it import a chunk that holds mathjs.
  for (const [, imported] of code.matchAll(/from\s*["']\.\/([^"']+)["']/g)) assert.doesNotMatch(imported, /mathjs/);
  assert.ok(gzipSync(code).length < 10_000, `the worker is ${gzipSync(code).length} B gzip`);
});

describe('without the build’s data, a chapter compiles and typesets for itself and still agrees', () => {
  for (const path of CHAPTERS) {
    test(`${path}: data missing`, async (t) => {
      const { page, problems, requests } = await open(path, (html) => {
        assert.ok(html.includes('<template data-phasebook-page-data'), 'the built page carries its data');
        return html.replace(PAGE_DATA, '');
      });
      assert.ok(heavyIn(requests).includes('mathjs'), 'the page compiled its models itself');
      const checks = await assertChapterHealthy(page);
      t.diagnostic(`${checks} theory check(s) agree`);
      assert.deepEqual(problems, []);
      await page.close();
    });
  }

  test('/introduction/: data of another version is not used', async () => {
    const { page, problems, requests } = await open('/introduction/', (html) =>
      // The format a future build might write: the page must not trust it.
      html.replace(PAGE_DATA, (element) => element.replace(/(&quot;|&#34;)format\1:1\b/g, '$1format$1:999')),
    );
    assert.ok(heavyIn(requests).includes('mathjs'));
    assert.ok((await assertChapterHealthy(page)) > 0);
    assert.deepEqual(problems, []);
    await page.close();
  });
});

/**
 * A new H for each chapter and the closed form of the motion it gives, from
 * the chapter's own initial state and parameters. `hamiltonian` is H as the
 * model carries it: the expression in the cell's string, or (`js`) the
 * function's source.
 * `truth(t)` is the state [q…, p…] at time t of one trajectory; for a batch,
 * `truth(t, m)` that of trajectory m.
 */
const EDITS = [
  {
    path: '/introduction/', cell: 'H', hamiltonian: 'p^2/2 + omega^2*q^2/2',
    // ω = 10 from (2, 0): q = 2 cos 10t, p = −20 sin 10t.
    truth: (t) => [2 * Math.cos(10 * t), -20 * Math.sin(10 * t)],
  },
  {
    path: '/parametric-resonance/', cell: 'H', hamiltonian: 'p^2/2 + omega^2*q^2/2 - f*q',
    // f = 0 in this chapter, so again q = 2 cos 10t.
    truth: (t) => [2 * Math.cos(10 * t), -20 * Math.sin(10 * t)],
  },
  {
    path: '/nonlinear-oscillator/', cell: 'H', hamiltonian: 'p^2/2 + omega0^2*q^2/2',
    // The anharmonic terms dropped: ω0 = 10 from (b, 0) = (1, 0).
    truth: (t) => [Math.cos(10 * t), -10 * Math.sin(10 * t)],
  },
  {
    path: '/kepler/', cell: 'H', hamiltonian: '(t, [x1, y1, x2, y2, px1, py1, px2, py2]) => px1**2 + py1**2 + px2**2 + py2**2 + 0*k',
    js: true,
    // Gravity switched off: q̇ = ∂H/∂p = 2p, straight lines from (−3, −3), (3, 3) with p = (2, −3), (−2, 3).
    truth: (t) => [-3 + 4 * t, -3 - 6 * t, 3 - 4 * t, 3 + 6 * t, 2, -3, -2, 3],
  },
  {
    path: '/adiabatic-invariants/', cell: 'H', hamiltonian: 'p^2/2 + omega0^2 * q^2/2 + 0*epsilon',
    // No ramp: ω = ω0 = 4 from (1, 0).
    truth: (t) => [Math.cos(4 * t), -4 * Math.sin(4 * t)],
  },
  {
    path: '/scattering/', cell: 'H', hamiltonian: 'p0^2 + p1^2 + 0*alpha',
    // No field: every particle of the beam flies straight at q̇0 = 2p0 = 8 from x0 = −20.
    truth: (t, m) => [-20 + 8 * t, (m - 15) * 0.3, 4, 0],
    batch: true,
  },
  {
    path: '/special-relativity/', cell: 'H', hamiltonian: 'p^2/2/m - F*q',
    // Newton's particle (written unlike the chapter's own, whose model the build compiled) under F = 0.8 from (−10, −10): p = −10 + Ft, q = −10 + (−10t + Ft²/2)/m, m = √10.
    truth: (t) => [-10 + (-10 * t + 0.4 * t * t) / Math.sqrt(10), -10 + 0.8 * t],
  },
  {
    path: '/playground/', cell: 'H', hamiltonian: 'p^2/2 + omega^2*q^2/2',
    truth: (t) => [2 * Math.cos(10 * t), -20 * Math.sin(10 * t)],
  },
  {
    path: '/for-teachers/', cell: 'pendulumH', hamiltonian: 'p^2/2 + omega0^2 * q^2/2',
    // The small-angle pendulum exactly: ω0 = 2 from (0.5, 0).
    truth: (t) => [0.5 * Math.cos(2 * t), -Math.sin(2 * t)],
  },
];

/**
 * In the page: the text of the first equations widget after cell `id` (null
 * when there is none) or, given `before`, whether it now shows other typeset text.
 */
function equationsAfter([id, before]) {
  const h = document.querySelector(`[data-cell="${id}"]`);
  const shown = [...document.querySelectorAll('[data-widget="equations"]')].find(
    (w) => h && h.compareDocumentPosition(w) & Node.DOCUMENT_POSITION_FOLLOWING,
  );
  if (before === null) return shown?.textContent ?? null;
  return !!shown && shown.textContent !== before && shown.querySelector('.katex') !== null;
}

describe('a new H in any chapter is compiled on the page, and the simulator follows its physics', () => {
  for (const edit of EDITS) {
    test(edit.path, async () => {
      const { page, problems, requests } = await open(edit.path);
      const equationsBefore = await page.evaluate(equationsAfter, [edit.cell, null]);
      assert.deepEqual(heavyIn(requests), []);

      await typeIntoCell(page, edit.cell, `${edit.cell} = ${edit.js ? edit.hamiltonian : `"${edit.hamiltonian}"`}`);
      // The simulator built from the new H (it carries H's source) that starts where the closed form does, once it
      // has drawn: others may use H too from other states (the introduction's batch starts at q = 1.8), and on a
      // busy machine one of them may be ready first.
      const handle = await page.waitForFunction(
        ([hamiltonian, start]) =>
          [...document.querySelectorAll('[data-widget="simulator"][data-ready]')].find(
            (el) => el.simulator?.model?.source === hamiltonian && start.every((v, i) => Math.abs(el.simulator.simulation.initial[i] - v) <= 1e-12),
          ),
        [edit.hamiltonian, edit.truth(0, 0)],
      );
      // Let it run a little, then stop it and read where it is.
      await page.waitForTimeout(600);
      const { t, state, dim } = await handle.evaluate((el) => {
        el.simulator.pause();
        const sim = el.simulator.simulation;
        return { t: sim.t, state: Array.from(sim.state), dim: el.simulator.model.dim };
      });
      assert.ok(t > 0, `the simulator ran (t = ${t})`);
      const count = state.length / dim;
      if (edit.batch) assert.ok(count > 1);
      for (let m = 0; m < count; m++) {
        const expected = edit.truth(t, m);
        const got = state.slice(m * dim, (m + 1) * dim);
        // RK 3/8 at dt = 5e-4 is exact for these linear motions up to rounding, and within 1e-9 for the oscillators.
        got.forEach((value, i) => assert.ok(Math.abs(value - expected[i]) < 1e-6, `trajectory ${m}, component ${i} at t = ${t}: ${value} vs ${expected[i]}`));
      }
      assert.ok(heavyIn(requests).includes('mathjs'), 'the new H was compiled on the page');
      if (equationsBefore !== null) {
        // The chapter shows the new H's equations, typeset on the page with KaTeX.
        await page.waitForFunction(equationsAfter, [edit.cell, equationsBefore]);
        assert.ok(heavyIn(requests).includes('KaTeX'));
      }
      assert.deepEqual(problems, []);
      await page.close();
    });
  }
});

/**
 * A link to a place in a chapter (`/kepler/#cell-stars`): the page shows that
 * place from its first paint, and a link to a simulator asks for the
 * simulator's modules from the head (site/lib/linked-preloads.mjs), not once
 * the boot script has arrived and run. Both are checked with the boot script
 * held back: whatever happens then happened without it.
 */
describe('a link to a place in a chapter', () => {
  const BOOT = /\/_astro\/Cells\.astro[\w.-]*\.js$/;
  const chunkOf = (url) => new URL(url).pathname.split('/').pop().split('.')[0];

  /** Opens `path` with the boot script held until `release()`; `scripts` lists the scripts asked for meanwhile. */
  async function openHeld(path) {
    const page = await site.context.newPage();
    let release;
    const held = new Promise((resolve) => (release = resolve));
    await page.route(BOOT, async (route) => {
      await held;
      await route.continue().catch(() => {});
    });
    const scripts = [];
    page.on('request', (request) => {
      if (/\.js$/.test(request.url()) && !BOOT.test(request.url())) scripts.push(chunkOf(request.url()));
    });
    await page.goto(`${site.origin}${path}`, { waitUntil: 'commit' });
    // Parsing is over (the head's and the body's inline scripts have run); the module script has not.
    await page.waitForFunction(() => document.readyState !== 'loading');
    assert.equal(await page.evaluate(() => document.body.hasAttribute('data-cells-ready')), false);
    return { page, scripts, release };
  }

  test('to a simulator: its modules are asked for while the boot script is still on its way, and it then draws', async () => {
    const { page, scripts, release } = await openHeld('/kepler/#cell-stars');
    await page.waitForTimeout(300);
    const early = [...scripts];
    for (const wanted of ['simulator', 'plots', 'core', 'model', 'time-plot', 'plane-views']) assert.ok(early.includes(wanted), `${wanted} in ${early.join(', ')}`);
    assert.ok(!early.includes('spectrum'), 'the spectrum view, which this simulator does not show');
    release();
    await page.locator('#cell-stars [data-widget="simulator"][data-ready]').waitFor();
    await page.close();
  });

  test('to the top, or to a cell without a simulator: nothing more is asked for', async () => {
    for (const path of ['/kepler/', '/kepler/#cell-model', '/kepler/#no-such-place']) {
      const { page, scripts, release } = await openHeld(path);
      await page.waitForTimeout(300);
      assert.deepEqual(scripts, [], path);
      release();
      await page.close();
    }
  });

  test('the linked place is in view from the first paint, before any script of the book has run', async () => {
    for (const [path, id] of [['/kepler/#cell-stars', 'cell-stars'], ['/introduction/#cell-sim', 'cell-sim']]) {
      const { page, release } = await openHeld(path);
      const place = await page.evaluate((id) => ({ top: document.getElementById(id).getBoundingClientRect().top, scrolled: scrollY }), id);
      assert.ok(place.scrolled > 500 && Math.abs(place.top) <= 2, `${path}: ${JSON.stringify(place)}`);
      release();
      await page.close();
    }
  });
});
