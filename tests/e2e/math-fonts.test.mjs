/**
 * Math in KaTeX's own faces on a first visit, every time (issue 25).
 *
 * KaTeX lays a formula out in its fonts' metrics and builds a stretchy
 * delimiter from KaTeX_Size1–4 glyphs; drawn in a system serif, the
 * introduction's J = (0 I; −I 0) kept small, unstretched parentheses. With
 * `font-display: optional`, fresh profiles over Slow 4G drew the math in
 * Liberation Serif. What the renderer actually drew with is read from
 * Chromium itself (CDP CSS.getPlatformFontsForNode), not from the CSS.
 *
 * Ten fresh profiles (a new browser on a new profile directory each), five
 * on loopback, one at a time, and five over Slow 4G, side by side, as this issue gives it
 * (400 kbit/s down, 400 ms round trip) with a 4× CPU slowdown: each opens
 * /introduction/ and then a second chapter. On each page, once its fonts are
 * ready, every piece of math text in the first view, and the J matrix's
 * delimiters, is drawn in KaTeX's faces only.
 */
import assert from 'node:assert/strict';
import { after, before, describe, test } from 'node:test';
import { launchBrowser } from './browser.mjs';
import { startServer } from './server.mjs';

/** Slow 4G as issue 25 measured it, in CDP's units (bytes/s, ms). */
const SLOW_4G = { offline: false, latency: 400, downloadThroughput: 400_000 / 8, uploadThroughput: 400_000 / 8 };
const CPU_SLOWDOWN = 4;

/** Each profile's second page; a different one each, so that five chapters are seen both ways. */
const SECOND = ['/parametric-resonance/', '/how-the-simulator-integrates/', '/kepler/', '/nonlinear-oscillator/', '/adiabatic-invariants/'];

/** The TeX of the introduction's symplectic matrix, as KaTeX keeps it in its MathML annotation. */
const J_MATRIX = /J\s*=\s*\\begin\{pmatrix\}\s*0\s*&\s*I/;

/** @type {Awaited<ReturnType<typeof startServer>>} */
let server;
before(async () => (server = await startServer()));
after(() => server?.close());

/**
 * Marks the elements to ask about, in the page, and returns how many: with
 * no `texSource`, every element of KaTeX's visible output (not its MathML)
 * holding text of its own (a zero-width space that only carries a strut is
 * not text) and lying at least partly in the viewport; with one, the
 * delimiters of the formula whose TeX matches it, scrolled into view first.
 * Earlier marks are cleared.
 */
function markMath(texSource) {
  for (const el of document.querySelectorAll('[data-font-probe]')) el.removeAttribute('data-font-probe');
  const ownText = (el) => [...el.childNodes].some((n) => n.nodeType === Node.TEXT_NODE && /[^\s\u200b]/.test(n.textContent));
  let candidates;
  if (texSource) {
    const tex = new RegExp(texSource);
    const formula = [...document.querySelectorAll('.katex')].find((k) => tex.test(k.querySelector('annotation')?.textContent ?? ''));
    if (!formula) return -1;
    formula.scrollIntoView({ block: 'center' });
    candidates = formula.querySelectorAll('.katex-html :is(.mopen, .mclose) *');
  } else {
    candidates = [...document.querySelectorAll('.katex-html *')].filter((el) => {
      const box = el.getBoundingClientRect();
      return box.width > 0 && box.bottom > 0 && box.top < innerHeight && box.right > 0 && box.left < innerWidth;
    });
  }
  let count = 0;
  for (const el of candidates) {
    if (!ownText(el)) continue;
    el.setAttribute('data-font-probe', '');
    count++;
  }
  return count;
}

/** Waits until what is on screen is laid out and every font it asked for has loaded or failed. */
async function fontsSettled(page) {
  await page.evaluate(async () => {
    await new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)));
    await document.fonts.ready;
  });
}

/** The fonts Chromium drew each marked element's text with: `[{ html, fonts: ['KaTeX_Main', …] }]`. */
async function drawnFonts(session) {
  const { root } = await session.send('DOM.getDocument', { depth: 0 });
  const { nodeIds } = await session.send('DOM.querySelectorAll', { nodeId: root.nodeId, selector: '[data-font-probe]' });
  const drawn = [];
  for (const nodeId of nodeIds) {
    const { fonts } = await session.send('CSS.getPlatformFontsForNode', { nodeId });
    const { outerHTML } = await session.send('DOM.getOuterHTML', { nodeId });
    drawn.push({ html: outerHTML.slice(0, 120), fonts: fonts.map((f) => f.familyName) });
  }
  return drawn;
}

/** Asks Chromium what the marked math was drawn with, and fails on any face not KaTeX's. */
async function assertKatexFaces(session, count, what) {
  const drawn = await drawnFonts(session);
  assert.equal(drawn.length, count);
  const fallbacks = drawn.filter((d) => d.fonts.length === 0 || d.fonts.some((family) => !family.startsWith('KaTeX_')));
  assert.deepEqual(fallbacks.map((d) => `${d.fonts.join(', ') || 'no font'} for ${d.html}`), [], `${what}: math drawn in a system font`);
  return drawn;
}

/** Opens `path` and checks the math in its first view, and the J matrix's delimiters if `tex` is given, in KaTeX's faces. */
async function assertMathInKatexFaces(page, session, path, label, tex) {
  await page.goto(server.origin + path, { waitUntil: 'load' });
  await page.waitForSelector('.katex-html', { state: 'attached' });
  await fontsSettled(page);
  const inView = await page.evaluate(markMath, null);
  assert.ok(inView > 0, `${label} ${path}: no math in the first view`);
  await assertKatexFaces(session, inView, `${label} ${path}, first view`);
  if (!tex) return;
  const delimiters = await page.evaluate(markMath, tex.source);
  assert.ok(delimiters >= 2, `${label} ${path}: ${delimiters < 0 ? `no formula matches ${tex}` : `the matrix has ${delimiters} delimiter glyphs`}`);
  // Scrolled into view, blocks not laid out before may ask for more faces.
  await fontsSettled(page);
  const drawn = await assertKatexFaces(session, delimiters, `${label} ${path}, the J matrix`);
  // A two-row matrix's parentheses are stretched: built from a Size face, not KaTeX_Main's text-sized glyph.
  const families = new Set(drawn.flatMap((d) => d.fonts));
  assert.ok([...families].some((family) => /^KaTeX_Size[1-4]$/.test(family)), `${label}: J's delimiters drawn in ${[...families]}`);
}

// The throttled profiles spend their time waiting on the emulated network, which is each page's own (its
// bandwidth is not shared with another browser's), so they wait side by side; the loopback ones run one at a
// time, as before, before them.
for (const throttled of [false, true]) {
  describe(throttled ? `Slow 4G + ${CPU_SLOWDOWN}× CPU, side by side` : 'loopback, one at a time', { concurrency: throttled ? 5 : 1 }, () => {
    for (let i = throttled ? 5 : 0; i < (throttled ? 10 : 5); i++) {
      const label = `profile ${i + 1} (${throttled ? `Slow 4G + ${CPU_SLOWDOWN}× CPU` : 'loopback'})`;
      const second = SECOND[i % SECOND.length];
      test(`${label}: math in KaTeX's faces on /introduction/ and then ${second}`, async () => {
        const browser = await launchBrowser();
        try {
          const page = await browser.context.newPage();
          const session = await browser.context.newCDPSession(page);
          await session.send('DOM.enable');
          await session.send('CSS.enable');
          if (throttled) {
            await session.send('Network.enable');
            await session.send('Network.emulateNetworkConditions', SLOW_4G);
            await session.send('Emulation.setCPUThrottlingRate', { rate: CPU_SLOWDOWN });
          }
          await assertMathInKatexFaces(page, session, '/introduction/', label, J_MATRIX);
          await assertMathInKatexFaces(page, session, second, label, null);
        } finally {
          await browser.close();
        }
      });
    }
  });
}
