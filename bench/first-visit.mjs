/**
 * A first visit as a reader meets it: a browser that has finished starting,
 * a profile that has never seen the book, and a link to a chapter's
 * simulator (`/kepler/#cell-stars`), timed from navigation to that
 * simulator's first draw.
 *
 * The cold loads of cold-load.mjs share one browser and one profile (only
 * the HTTP cache is kept out, by the server's `no-store`); a reader's first
 * visit has neither. Each load here gets a profile of its own, in one of two
 * ways, so that the difference can be placed:
 *
 * - "new context": a fresh in-memory profile (browser.newContext) in a
 *   browser that has already loaded the book once, on another profile; what
 *   is new is the profile: its renderer process, its network context.
 * - "new profile": a fresh persistent profile on disk
 *   (launchPersistentContext), so a browser process of its own too, started
 *   and idle (a blank page drawn) before the navigation; the Chromium files
 *   are warm in the OS cache from a throw-away profile started first.
 *
 * For each load, where the time goes, all in ms from the navigation's start
 * (performance entries in the page, CDP's counters at the first draw):
 * response (first byte of the HTML) → first paint (text on screen) → boot
 * script (the page's module entry has arrived) → modules (the last script
 * fetched before the first draw) → fonts (the last font fetched before it)
 * → first draw; beside them the main thread's script time (parse, compile,
 * run) and style and layout time up to the draw.
 */
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium } from 'playwright-core';
import { SLOW_4G, CPU_SLOWDOWN } from './cold-load.mjs';

const ARGS = ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'];
const LAUNCH = { executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true, args: ARGS };
const VIEWPORT = { width: 1100, height: 900 };

/**
 * Runs in the page before its scripts: the moment the first simulator is
 * drawn (`data-ready` on a simulator the page's scripts made), and the
 * resources fetched up to it.
 */
function instrumentFirstDraw() {
  const marks = { draw: null, resources: [] };
  Object.defineProperty(window, '__firstVisit', { value: marks });
  const check = () => {
    if (marks.draw !== null || !document.querySelector('[data-widget="simulator"][data-ready]')) return;
    marks.draw = performance.now();
    marks.resources = performance.getEntriesByType('resource').map((r) => ({ name: r.name, type: r.initiatorType, end: r.responseEnd }));
  };
  new MutationObserver(check).observe(document, { subtree: true, childList: true, attributes: true, attributeFilter: ['data-ready'] });
}

async function metrics(session) {
  const { metrics: list } = await session.send('Performance.getMetrics');
  return Object.fromEntries(list.map((m) => [m.name, m.value]));
}

/**
 * Navigates `page` (whose profile is fresh) to `url` and measures up to the
 * simulator's first draw; `throttled`: Slow 4G and a 4× CPU slowdown.
 */
async function measure(context, page, url, throttled, timeoutMs) {
  const session = await context.newCDPSession(page);
  await session.send('Performance.enable');
  if (throttled) {
    await session.send('Network.enable');
    await session.send('Network.emulateNetworkConditions', SLOW_4G);
    await session.send('Emulation.setCPUThrottlingRate', { rate: CPU_SLOWDOWN });
  }
  await page.addInitScript(instrumentFirstDraw);
  const before = await metrics(session);
  await page.goto(url, { waitUntil: 'commit', timeout: timeoutMs });
  await page.waitForFunction(() => window.__firstVisit.draw !== null, null, { timeout: timeoutMs, polling: 'raf' });
  const after = await metrics(session);
  const marks = await page.evaluate(() => {
    const nav = performance.getEntriesByType('navigation')[0];
    const paint = performance.getEntriesByName('first-contentful-paint')[0];
    return { ...window.__firstVisit, response: nav.responseStart, paint: paint?.startTime ?? NaN };
  });
  const before_ = marks.resources.filter((r) => r.end <= marks.draw);
  const scripts = before_.filter((r) => /\.m?js(\?|$)/.test(r.name));
  const fonts = before_.filter((r) => /\.woff2?(\?|$)/.test(r.name));
  const last = (list) => (list.length ? Math.max(...list.map((r) => r.end)) : NaN);
  const seconds = (name) => 1000 * (after[name] - before[name]);
  return {
    response: marks.response,
    paint: marks.paint,
    boot: scripts.length ? Math.min(...scripts.map((r) => r.end)) : NaN,
    modules: last(scripts),
    scriptFiles: scripts.length,
    fonts: last(fonts),
    fontFiles: fonts.length,
    draw: marks.draw,
    script: seconds('ScriptDuration'),
    layout: seconds('LayoutDuration') + seconds('RecalcStyleDuration'),
  };
}

/** A fresh in-memory profile in `browser`, already started. */
async function inNewContext(browser, url, throttled, timeoutMs) {
  const context = await browser.newContext({ viewport: VIEWPORT });
  try {
    const page = await context.newPage();
    return await measure(context, page, url, throttled, timeoutMs);
  } finally {
    await context.close();
  }
}

/** A fresh profile on disk, in a browser process of its own, measured once it has started and drawn a blank page. */
async function inNewProfile(url, throttled, timeoutMs) {
  const dir = await mkdtemp(join(tmpdir(), 'phasebook-first-visit-'));
  const context = await chromium.launchPersistentContext(dir, { ...LAUNCH, viewport: VIEWPORT });
  try {
    const page = context.pages()[0] ?? (await context.newPage());
    await page.goto('about:blank');
    await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
    return await measure(context, page, url, throttled, timeoutMs);
  } finally {
    await context.close();
    await rm(dir, { recursive: true, force: true });
  }
}

/**
 * Measures each of `urls` `loads` times in each way and profile. Returns
 * rows keyed `${way} ${profile} ${url}`, each a list of loads.
 * @param {string[]} urls absolute URLs, each a link to a simulator's cell
 */
export async function firstVisits(urls, { loads = 3, timeoutMs = 60_000, log = () => {} } = {}) {
  // Chromium's files into the OS cache, and the book's way through the browser once, on a throw-away profile.
  const warm = await chromium.launch(LAUNCH);
  try {
    // Closed once loaded: a simulator left playing would take the CPU from every load that follows.
    const page = await warm.newPage();
    await page.goto(urls[0]);
    await page.waitForLoadState('load');
    await page.context().close();
  } catch (error) {
    await warm.close();
    throw error;
  }
  const results = new Map();
  try {
    for (const [profile, throttled] of [['loopback', false], [`Slow 4G + ${CPU_SLOWDOWN}× CPU`, true]]) {
      for (const url of urls) {
        for (const [way, load] of [
          ['new context', () => inNewContext(warm, url, throttled, timeoutMs)],
          ['new profile', () => inNewProfile(url, throttled, timeoutMs)],
        ]) {
          log(`first visit: ${url}, ${way}, ${profile}…`);
          const runs = [];
          for (let i = 0; i < loads; i++) runs.push(await load().catch((error) => (log(`  failed: ${error.message}`), null)));
          results.set(`${way}|${profile}|${url}`, { way, profile, url, runs: runs.filter(Boolean) });
        }
      }
    }
  } finally {
    await warm.close();
  }
  return [...results.values()];
}

/** The median of the finite values, or NaN. */
function median(values) {
  const finite = values.filter((v) => Number.isFinite(v)).sort((a, b) => a - b);
  if (!finite.length) return NaN;
  const mid = finite.length >> 1;
  return finite.length % 2 ? finite[mid] : (finite[mid - 1] + finite[mid]) / 2;
}

/** Prints the first visits as a markdown table: medians, and the range of the first draw. */
export function printFirstVisits(rows, print, { loads }) {
  const ms = (x) => (Number.isFinite(x) ? `${Math.round(x)}` : '—');
  print(`f. First visits by link to a simulator, each load a fresh profile (median of ${loads}; the first draw's range ` +
    'in brackets). All times in ms from the navigation\'s start: response = first byte of the HTML; paint = first ' +
    'text on screen; boot = the page\'s first script has arrived; modules = the last script fetched before the first ' +
    'draw (files); fonts = the last font fetched before it (files); draw = the simulator\'s first draw (`data-ready`). ' +
    'Script and style + layout: main-thread time up to about the draw (CDP). "new context": a fresh in-memory profile ' +
    'in a browser already running; "new profile": a fresh profile on disk in a browser process of its own, started ' +
    'and idle before the navigation.');
  print();
  print('| Link | profile | way | response | paint | boot | modules | fonts | **draw** | script | style + layout |');
  print('|---|---|---|---|---|---|---|---|---|---|---|');
  for (const { url, profile, way, runs } of rows) {
    const m = (key) => median(runs.map((r) => r[key]));
    const draws = runs.map((r) => r.draw).filter(Number.isFinite);
    const range = draws.length ? ` (${ms(Math.min(...draws))}–${ms(Math.max(...draws))})` : '';
    const link = new URL(url);
    print(`| \`${link.pathname}${link.hash}\` | ${profile} | ${way} | ${ms(m('response'))} | ${ms(m('paint'))} | ${ms(m('boot'))} | ` +
      `${ms(m('modules'))} (${ms(m('scriptFiles'))}) | ${ms(m('fonts'))} (${ms(m('fontFiles'))}) | **${ms(m('draw'))}**${range} | ${ms(m('script'))} | ${ms(m('layout'))} |`);
  }
  print();
  print('Goal: the first draw ≤ 500 ms on loopback and ≤ 2.5 s throttled, in a fresh profile.');
  print();
}
