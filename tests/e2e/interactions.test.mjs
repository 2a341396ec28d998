/**
 * Interactions that respect the page, and a book a finger can work (issue
 * 25): the wheel over a plot scrolls the page, and moving a plot through
 * time takes a drag, a sideways wheel or a modifier, which the plot says;
 * start-up is not announced as a failure; no readout prints −0; surfaces of
 * section, trajectories and phase portraits whose axes share a unit are
 * drawn at one scale; a simulator's views go side by side on a desk, its
 * bar stays in view, and the stability chart sits by the simulator it
 * drives; every control is a target of 24 px, and of 44 px under a finger
 * at 390 px, where the run hint names the Run button and each simulator
 * still fills the box reserved for it.
 */
import assert from 'node:assert/strict';
import { after, before, describe, test } from 'node:test';
import { widgetsReady } from './chapter-checks.mjs';
import { inTheBooksFonts, reservedBoxes, simulatorHeight } from './every-page.mjs';
import { cell, openChapter, openSite, typeIntoCell } from './fixture.mjs';

/** The introduction's first simulator: time plot, phase portrait and spectrum. */
const SIM = '[data-cell="sim"] [data-widget="simulator"]';

/** Everything a reader can press, type into or slide, inside the widgets and the cells' toolbars. */
const CONTROLS = ':is([data-widget], .cell-toolbar) :is(button, input, select, summary, [role="button"])';

/**
 * In the page: each control shown, with its target's size: its own box, or
 * for a radio or checkbox inside a label, the label's (a tap on the label is a tap on it).
 */
function targets(selector) {
  return [...document.querySelectorAll(selector)]
    .filter((el) => el.checkVisibility())
    .map((el) => {
      const labelled = /^(radio|checkbox)$/.test(el.type) ? el.closest('label') : null;
      const box = (labelled ?? el).getBoundingClientRect();
      const name = el.getAttribute('aria-label') || el.textContent?.trim() || el.type || el.tagName;
      const where = el.closest('[data-widget]')?.dataset.widget ?? 'cell toolbar';
      return { what: `${where} ${el.tagName.toLowerCase()} “${name.slice(0, 30)}”`, width: box.width, height: box.height };
    });
}

/** The targets on `page` smaller than `least` px either way, as lines; and how many were measured. */
async function smallTargets(page, least) {
  const all = await page.evaluate(targets, CONTROLS);
  const small = all.filter((t) => t.width < least - 0.01 || t.height < least - 0.01).map((t) => `${t.what}: ${t.width.toFixed(1)} × ${t.height.toFixed(1)}`);
  return { small, count: all.length, least: Math.min(...all.map((t) => Math.min(t.width, t.height))) };
}

/**
 * In the page: pixels per unit across (x) and up (y) of each panel of each plot matching `selector`, as drawn,
 * from the first and last labels of each axis that read as numbers (with a true minus, or as m×10ⁿ).
 */
function planeScales(selector) {
  const superscripts = '⁰¹²³⁴⁵⁶⁷⁸⁹';
  const read = (text) => {
    const plain = text.replace(/[−⁻]/g, '-').replace(/[⁰-⁹]/g, (d) => String(superscripts.indexOf(d)));
    const scientific = /^(-?[\d.]+)×10(-?\d+)$/.exec(plain);
    return scientific ? Number(scientific[1]) * 10 ** Number(scientific[2]) : plain === '' ? NaN : Number(plain);
  };
  const perUnit = (axis) => {
    const labels = axis.labels.map((l) => ({ at: l.at, value: read(l.text) })).filter((l) => Number.isFinite(l.value));
    if (labels.length < 2) return NaN;
    const [a, b] = [labels[0], labels[labels.length - 1]];
    return Math.abs((b.at - a.at) / (b.value - a.value));
  };
  return [...document.querySelectorAll(selector)].flatMap((el) => (el.axes ?? []).map((a) => ({ kind: el.dataset.widget, x: perUnit(a.x), y: perUnit(a.y) })));
}

/** Asserts that `expected` panels are drawn for `selector`, each with as many pixels per unit across as up, to 1%; returns them. */
async function assertEqualAspect(page, selector, expected) {
  const measured = await page.evaluate(planeScales, selector);
  assert.equal(measured.length, expected, `${selector}: ${JSON.stringify(measured)}`);
  for (const m of measured) {
    assert.ok(Number.isFinite(m.x) && Number.isFinite(m.y), `${m.kind}: unreadable axes ${JSON.stringify(m)}`);
    assert.ok(Math.abs(m.x / m.y - 1) < 0.01, `${m.kind}: ${m.x.toFixed(2)} px per unit across, ${m.y.toFixed(2)} up`);
  }
  return measured;
}

/** A number shown as −0: "−0", "−0.00", "−0.00%", but not "−0.05". */
const NEGATIVE_ZERO = /[−-]0(?:\.0+)?(?![\d.])/;

/** Waits until the page's scroll position satisfies `predicate(scrollY)`. */
const scrolled = (page, predicate, arg) => page.waitForFunction(predicate, arg);

describe('on a desk, 1280 px', () => {
  /** @type {Awaited<ReturnType<typeof openSite>>} */
  let site;
  before(async () => {
    site = await openSite({ viewport: { width: 1280, height: 900 } });
  });
  after(() => site?.close());

  test('a wheel over a paused time plot scrolls the page; a sideways wheel, or Shift, Ctrl or Alt with the wheel, moves it through time', async () => {
    const { page, problems } = await openChapter(site, '/introduction/');
    const sim = page.locator(SIM);
    await sim.evaluate((el) => {
      el.scrollIntoView({ block: 'start' });
      el.simulator.setSpeed(50);
    });
    // A record of several windows (10 t each), then paused: the case where the wheel used to pan.
    await page.waitForFunction((s) => document.querySelector(s).simulator.simulation.t > 40, SIM);
    await sim.evaluate((el) => el.simulator.pause());
    const stage = sim.locator('[data-widget="time-plot"] .pb-stage');
    const live = sim.locator('[data-widget="time-plot"] .pb-scrub-row button', { hasText: 'Live' });
    const overStage = async () => {
      await stage.evaluate((el) => el.scrollIntoView({ block: 'center' }));
      const box = await stage.boundingBox();
      const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
      await page.mouse.move(x, y);
      assert.ok(await stage.evaluate((el, [px, py]) => el.contains(document.elementFromPoint(px, py)), [x, y]), 'the mouse is over the plot');
    };

    await overStage();
    const top = await page.evaluate(() => scrollY);
    await page.mouse.wheel(0, 300);
    await scrolled(page, (y) => scrollY > y + 100, top);
    assert.equal(await live.isDisabled(), true, 'a plain wheel moved the plot back in time');

    for (const key of ['Shift', 'Control', 'Alt', null]) {
      if (!(await live.isDisabled())) await live.click(); // back to live
      assert.equal(await live.isDisabled(), true);
      await overStage();
      const before = await page.evaluate(() => scrollY);
      if (key) await page.keyboard.down(key);
      // Shift, Ctrl and Alt with the vertical wheel; no key: a sideways wheel (a trackpad's swipe).
      await page.mouse.wheel(key ? 0 : -300, key ? -300 : 0);
      if (key) await page.keyboard.up(key);
      await page.waitForFunction((b) => !b.disabled, await live.elementHandle());
      assert.equal(await page.evaluate(() => scrollY), before, `${key ?? 'a sideways'} wheel scrolled the page`);
    }
    assert.equal(await page.evaluate(() => visualViewport.scale), 1, 'Ctrl with the wheel zoomed the page');
    assert.deepEqual(problems, []);
    await page.close();
  });

  test('the time plot says how to move it through time: in its tooltip, its accessible description and a note on keyboard focus', async () => {
    const { page, problems } = await openChapter(site, '/introduction/');
    const plot = page.locator(`${SIM} [data-widget="time-plot"]`);
    await plot.scrollIntoViewIfNeeded();
    const stage = plot.locator('.pb-stage');
    const hint = await stage.evaluate((el) => ({
      title: el.title,
      description: el.getAttribute('aria-describedby').split(' ').map((id) => document.getElementById(id)?.textContent ?? '').join(' '),
      shown: el.querySelector('.pb-stage-hint').checkVisibility(),
    }));
    for (const text of [hint.title, hint.description]) assert.match(text, /drag, scroll sideways, or Shift \+ wheel/);
    assert.match(hint.description, /against t/, 'the description still holds the text alternative');
    assert.equal(hint.shown, false, 'the note shows before the plot has the focus');
    // From the window menu, the control before the plot, Tab brings the keyboard to the plot.
    await plot.locator('select').focus();
    await page.keyboard.press('Tab');
    assert.equal(await stage.evaluate((el) => document.activeElement === el), true);
    assert.equal(await stage.locator('.pb-stage-hint').isVisible(), true, 'no note on keyboard focus');
    assert.deepEqual(problems, []);
    await page.close();
  });

  test('start-up is not announced as a failure: no "behind real time" while a simulator starts, and never in red', async () => {
    const page = await site.context.newPage();
    await page.goto(`${site.origin}/`);
    await page.evaluate(() => localStorage.clear());
    // Every text each speed readout shows, from the page's first moments, with its simulator's state then.
    await page.addInitScript(() => {
      window.speedTexts = [];
      new MutationObserver((records) => {
        for (const record of records) {
          const node = record.target.nodeType === 1 ? record.target : record.target.parentElement;
          const speed = node?.closest?.('.pb-speed-text');
          if (!speed) continue;
          const handle = speed.closest('[data-widget="simulator"]')?.simulator;
          window.speedTexts.push({ text: speed.textContent, t: handle?.simulation.t ?? 0, pace: handle?.driver.stats.pace ?? null });
        }
      }).observe(document, { subtree: true, childList: true, characterData: true });
    });
    await page.goto(`${site.origin}/introduction/`);
    // Its cell starts as it comes near the view.
    await page.locator('[data-cell="sim"]').evaluate((el) => el.scrollIntoView({ block: 'start' }));
    const sim = page.locator(SIM);
    await sim.waitFor();
    // Until the first simulator's pace has been judged: the whole of its start-up has been shown.
    await page.waitForFunction((s) => document.querySelector(s)?.simulator?.driver.stats.pace != null, SIM);
    const texts = await page.evaluate(() => window.speedTexts);
    assert.ok(texts.length > 0 && texts.some((s) => /^1 t\/s · 2000 steps\/s$/.test(s.text)), JSON.stringify(texts.slice(0, 5)));
    // "behind" only once judged, and never in the first half time unit of a run.
    const early = texts.filter((s) => /behind/.test(s.text) && (s.pace === null || s.t < 0.5));
    assert.deepEqual(early, []);
    // Said in the text's colour, as a note on the model, not in the alarm's red.
    const colours = await sim.evaluate((el) => {
      const speed = el.querySelector('.pb-speed-text');
      speed.classList.add('pb-behind');
      const behind = getComputedStyle(speed).color;
      speed.classList.remove('pb-behind');
      return { behind, text: getComputedStyle(el).color, alert: getComputedStyle(el.querySelector('.pb-alert')).color };
    });
    assert.equal(colours.behind, colours.text);
    assert.notEqual(colours.behind, colours.alert);
    await page.close();
  });

  test('no readout, text alternative or axis label shows −0 while the simulators run; a difference that rounds to zero reads 0.00%', async () => {
    /**
     * Every text the readouts, the spectrum's list, the scroll status, the data summary and the plots' text
     * alternatives and axes show in `root`, until the spectrum's comparison with theory has changed `changes`
     * times, or, when `changes` is 0, reads 0.00% (a difference that rounds to nothing); or until the
     * simulation has run 60 time units, when the assertions then say what was missing. (A comparison that
     * settles on one value changes no more, so a count of changes alone could wait for ever.)
     */
    const collect = (root, changes) =>
      new Promise((done) => {
        const texts = new Set();
        const read = () => {
          for (const el of root.querySelectorAll('.pb-readouts, .pb-speed-text, .pb-spectrum-readout, .pb-scrub-status, .pb-data-summary, .pb-visually-hidden')) texts.add(el.textContent);
          for (const canvas of root.querySelectorAll('canvas[aria-label]')) texts.add(canvas.getAttribute('aria-label'));
          for (const plot of root.querySelectorAll('[data-widget]')) for (const a of plot.axes ?? []) for (const l of [...a.x.labels, ...a.y.labels]) texts.add(l.text);
        };
        let comparison = '';
        let changed = 0;
        const observer = new MutationObserver(() => {
          read();
          const now = root.querySelector('.pb-spectrum-theory')?.textContent ?? '';
          if (now && now !== comparison) changed++;
          comparison = now;
          const ranOut = root.simulator?.simulation.t > 60;
          if (ranOut || (changes > 0 ? changed >= changes : /: 0\.00%$/.test(now))) finish();
        });
        const finish = () => {
          observer.disconnect();
          clearTimeout(stalled);
          done({ texts: [...texts], last: comparison, t: root.simulator?.simulation.t });
        };
        // A simulator that stopped changes nothing more: two minutes of page time end the wait too.
        const stalled = setTimeout(finish, 120_000);
        observer.observe(root, { subtree: true, childList: true, characterData: true, attributes: true, attributeFilter: ['aria-label'] });
      });

    // The introduction's simulator: every view and readout, its spectrum compared with the drive.
    const intro = await openChapter(site, '/introduction/');
    const sim = intro.page.locator(SIM);
    await sim.scrollIntoViewIfNeeded();
    const shown = await sim.evaluate(collect, 8);
    assert.ok(shown.texts.some((t) => /strongest peak .* vs .*%/.test(t)), `no comparison with theory among ${shown.texts.length} texts`);
    assert.deepEqual(shown.texts.filter((t) => NEGATIVE_ZERO.test(t)), []);
    assert.deepEqual(intro.problems, []);
    await intro.page.close();

    // A bare oscillator's peak against its own frequency ω/2π: the difference comes and goes about zero, where
    // a sign written before rounding read "−0.00%" (or "+0.00%"); it must read 0.00%, and never −0.
    const playground = await openChapter(site, '/playground/');
    await typeIntoCell(playground.page, 'params', 'params = ({u: 0, gamma: 21.7, beta: 0.2, kappa: 8, omega: 10, f: 0})');
    await typeIntoCell(playground.page, 'options', "options = ({dt: 5e-4, speed: 1, views: ['spectrum'], spectrum: {theory: {frequency: 10 / (2 * PI), label: 'ω/2π'}}})");
    await playground.page.waitForFunction(() => document.querySelector('[data-cell="sim"] [data-widget="simulator"]')?.querySelectorAll('[data-widget]').length === 1, null);
    // In view: a simulator scrolled out of view pauses (simulator/driver.ts), and typing into the options cell may
    // have scrolled it away; it then stood at t = 0.25 for the whole wait.
    await playground.page.locator('[data-cell="sim"] [data-widget="simulator"]').scrollIntoViewIfNeeded();
    const bare = await playground.page.locator('[data-cell="sim"] [data-widget="simulator"]').evaluate(collect, 0);
    assert.match(bare.last, /^strongest peak 1\.59\d* vs ω\/2π: 0\.00%$/, `at t = ${bare.t}`);
    assert.deepEqual(bare.texts.filter((t) => NEGATIVE_ZERO.test(t)), []);
    assert.deepEqual(playground.problems, []);
    await playground.page.close();
  });

  test('sections, trajectories and phase portraits whose axes share a unit are drawn at one scale across and up', async () => {
    const chaos = await openChapter(site, '/order-and-chaos/');
    await widgetsReady(chaos.page, { 'poincare-section': 2 });
    const sections = await assertEqualAspect(chaos.page, '[data-widget="poincare-section"]', 2);
    assert.deepEqual(chaos.problems, []);
    await chaos.page.close();

    const kepler = await openChapter(site, '/kepler/');
    await widgetsReady(kepler.page);
    await assertEqualAspect(kepler.page, '[data-widget="trajectory"]', 1);
    await kepler.page.close();

    const playground = await openChapter(site, '/playground/');
    const selector = '[data-cell="sim"] [data-widget="phase-portrait"]';
    /** Runs the options cell as `source` and waits until the simulator it rebuilt has drawn a time unit. */
    const rerun = async (source) => {
      await playground.page.locator('[data-cell="sim"] [data-widget="simulator"]').evaluate((el) => (el.dataset.before = ''));
      await typeIntoCell(playground.page, 'options', source);
      await playground.page.waitForFunction((s) => {
        const sim = document.querySelector('[data-cell="sim"] [data-widget="simulator"]:not([data-before])');
        return sim?.querySelector(s)?.axes?.length > 0 && sim.simulator.simulation.t > 1;
      }, '[data-widget="phase-portrait"]');
    };
    await rerun("options = ({dt: 5e-4, speed: 1, views: ['phase'], phase: {equal: true}})");
    const [phase] = await assertEqualAspect(playground.page, selector, 1);
    // Without equal, the same portrait fills its panel: p (about 10 q here) is squeezed; the measure tells them apart.
    await rerun("options = ({dt: 5e-4, speed: 1, views: ['phase']})");
    const [unequal] = await playground.page.evaluate(planeScales, selector);
    assert.ok(unequal.x / unequal.y > 2, JSON.stringify({ unequal, phase, sections }));
    assert.deepEqual(playground.problems, []);
    await playground.page.close();
  });

  test('a simulator’s views go side by side and its bar stays in view while any of it is; the stability chart sits by its simulator', async () => {
    const { page, problems } = await openChapter(site, '/introduction/');
    const sim = page.locator(SIM);
    const boxes = await sim.evaluate((el) => Object.fromEntries(['time-plot', 'phase-portrait', 'spectrum'].map((k) => [k, el.querySelector(`[data-widget="${k}"]`).getBoundingClientRect().toJSON()])));
    assert.equal(boxes['time-plot'].top, boxes['phase-portrait'].top, 'the time plot and the phase portrait share a row');
    assert.ok(boxes['phase-portrait'].left > boxes['time-plot'].right, 'the phase portrait is right of the time plot');
    assert.ok(boxes.spectrum.top >= boxes['phase-portrait'].bottom && boxes.spectrum.width > 1.9 * boxes['time-plot'].width, 'the spectrum spans the row under them');
    const height = await sim.evaluate((el) => el.getBoundingClientRect().height);
    // The spectrum's readout, at the simulator's foot, in view with the bar that drives it (1803 px apart before).
    const together = await sim.evaluate(async (el) => {
      el.querySelector('.pb-spectrum-readout').scrollIntoView({ block: 'end' });
      await new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)));
      const [bar, readout] = ['.pb-bar', '.pb-spectrum-readout'].map((s) => el.querySelector(s).getBoundingClientRect());
      return { bar: [bar.top, bar.bottom], readout: [readout.top, readout.bottom], screen: innerHeight };
    });
    assert.ok(together.bar[0] >= 0 && together.readout[1] <= together.screen + 1 && together.bar[1] <= together.readout[0], JSON.stringify(together));
    // Scrolled through: the bar stays at the top while any of the simulator is in view, then goes with it.
    const bar = (offset) =>
      sim.evaluate(async (el, offset) => {
        el.scrollIntoView({ block: 'start' });
        scrollBy(0, offset);
        await new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)));
        const b = el.querySelector('.pb-bar').getBoundingClientRect();
        return { top: b.top, bottom: b.bottom, simulatorBottom: el.getBoundingClientRect().bottom };
      }, offset);
    for (const offset of [300, height - 200]) {
      const at = await bar(offset);
      assert.ok(at.top >= 0 && at.top < 12 && at.bottom < at.simulatorBottom, `scrolled ${offset} px into it: ${JSON.stringify(at)}`);
    }
    const past = await bar(height + 50);
    assert.ok(past.bottom <= 0, `scrolled past it, the bar stays: ${JSON.stringify(past)}`);
    assert.deepEqual(problems, []);
    await page.close();

    const resonance = await openChapter(site, '/parametric-resonance/');
    const gap = await resonance.page.evaluate(() => {
      const chart = document.querySelector('[data-widget="stability-chart"] canvas').getBoundingClientRect();
      const explorer = document.querySelector('[data-cell="explorer"] [data-widget="simulator"]').getBoundingClientRect();
      return explorer.top - chart.bottom;
    });
    // Between them: the chart's reading and caption, and the simulator's three lines of code (808 px before).
    assert.ok(gap > 0 && gap < 300, `the stability chart ends ${gap} px above the simulator it restarts`);
    assert.deepEqual(resonance.problems, []);
    await resonance.page.close();
  });

  test('every control is a target of 24 × 24 px at least, and the run hint names the keys', async () => {
    for (const path of ['/introduction/', '/order-and-chaos/']) {
      const { page, problems } = await openChapter(site, path);
      await widgetsReady(page);
      const { small, count, least } = await smallTargets(page, 24);
      assert.ok(count > 20, `${path}: ${count} controls measured`);
      assert.deepEqual(small, [], `${path}: the smallest ${least.toFixed(1)} px`);
      if (path === '/introduction/') {
        assert.equal(await page.locator('.cell-hint-keys').first().isVisible(), true);
        assert.equal(await page.locator('.cell-hint-touch').first().isVisible(), false);
      }
      assert.deepEqual(problems, []);
      await page.close();
    }
  });
});

describe('on a phone, 390 px, under a finger', () => {
  /** @type {Awaited<ReturnType<typeof openSite>>} */
  let site;
  before(async () => {
    site = await openSite({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
  });
  after(() => site?.close());

  test('every control is a target of 44 × 44 px, the run hint names Run, and each simulator fills the box reserved for it', async () => {
    for (const path of ['/introduction/', '/order-and-chaos/']) {
      const page = await site.context.newPage();
      await page.addInitScript(inTheBooksFonts);
      await page.goto(`${site.origin}/`);
      await page.evaluate(() => localStorage.clear());
      await page.goto(`${site.origin}${path}`);
      // The boxes the build reserved, as the first paint shows them, before their cells run.
      const reserved = await page.evaluate(reservedBoxes);
      await page.close();
      const { page: read, problems } = await openChapter(site, path);
      await widgetsReady(read);
      assert.equal(await read.evaluate(() => matchMedia('(pointer: coarse)').matches), true, 'the phone has a coarse pointer');
      const { small, count, least } = await smallTargets(read, 44);
      assert.ok(count > 20, `${path}: ${count} controls measured`);
      assert.deepEqual(small, [], `${path}: the smallest ${least.toFixed(1)} px`);
      assert.equal(await read.locator('.cell-hint-touch').first().isVisible(), true);
      assert.equal(await read.locator('.cell-hint-keys').first().isVisible(), false);
      if (path === '/introduction/') {
        // Nothing clipped: a legend of a few entries shows them all, the last no longer under log y.
        const legends = await read.locator('[data-widget="time-plot"] .pb-legend-slot').evaluateAll((slots) =>
          slots.map((slot) => {
            const box = slot.getBoundingClientRect();
            const entries = [...slot.querySelectorAll('.pb-legend-entry')];
            const cut = entries.filter((e) => { const b = e.getBoundingClientRect(); return b.left < box.left - 0.5 || b.right > box.right + 0.5; });
            return { entries: entries.length, cut: cut.map((e) => e.textContent) };
          }),
        );
        for (const legend of legends.filter((l) => l.entries <= 4)) assert.deepEqual(legend.cut, [], JSON.stringify(legends));
        assert.ok(legends.some((l) => l.entries === 3), JSON.stringify(legends));
        assert.ok(reserved.length >= 3, `${reserved.length} reserved boxes`);
        for (const { id, height } of reserved) {
          const real = await read.evaluate(simulatorHeight, id);
          assert.ok(real !== null && Math.abs(real - height) <= 1.5, `${id}: reserved ${height} px, the simulator takes ${real} px`);
        }
      }
      // On a phone the bar scrolls with the page: it would take a fifth of the screen.
      const sims = read.locator('[data-widget="simulator"]');
      if ((await sims.count()) > 0) {
        const position = await sims.first().evaluate((el) => getComputedStyle(el.querySelector('.pb-bar')).position);
        assert.equal(position, 'static');
      }
      assert.deepEqual(problems, []);
      await read.close();
    }
  });

  test('a surface of section is round on a phone too', async () => {
    const { page, problems } = await openChapter(site, '/order-and-chaos/');
    await widgetsReady(page, { 'poincare-section': 2 });
    await assertEqualAspect(page, '[data-widget="poincare-section"]', 2);
    assert.deepEqual(problems, []);
    await page.close();
  });
});
