/**
 * Cold-cache loads of the book's pages, as a new reader meets them: for each
 * page, the JavaScript (gzip) fetched before any interaction, the time from
 * navigation to the first widget drawn, and the cumulative layout shift.
 *
 * Every load is a fresh page in a profile whose server sends `no-store`, so
 * nothing comes from a cache. The throttled profile is Chromium DevTools'
 * "Slow 4G" preset (562.5 ms latency, 1.4 Mbit/s down, 0.66 Mbit/s up: the
 * Lighthouse mobile profile, 150 ms RTT and 1.6 Mbit/s, with DevTools'
 * 3.75× latency and 0.9× throughput factors) with a 4× CPU slowdown.
 */
import { gzipSync } from 'node:zlib';

export const SLOW_4G = {
  offline: false,
  latency: 562.5,
  downloadThroughput: (1.6 * 1024 * 1024 * 0.9) / 8,
  uploadThroughput: (750 * 1024 * 0.9) / 8,
};
export const CPU_SLOWDOWN = 4;

/** The heavy modules no page may fetch before interaction. */
export const HEAVY = [
  ['mathjs', /\/_astro\/mathjs[\w.-]*\.js$/],
  ['KaTeX', /\/_astro\/katex[\w.-]*\.js$/],
  ['parser', /\/_astro\/(parse|parser)\.[\w-]+\.js$/],
  ['editor', /\/_astro\/editor\.[\w-]+\.js$/],
];

/**
 * Runs in the page before any of its scripts: times the first contentful
 * paint (text on screen) and the first live widget that becomes ready (one the page's scripts made, not a formula the build
 * typeset into the HTML, which is "ready" as soon as it is parsed) and the
 * first simulator, and sums layout shifts.
 */
function instrument() {
  const marks = { widget: null, simulator: null, paint: null, cls: 0, shifts: [] };
  Object.defineProperty(window, '__coldLoad', { value: marks });
  /** The widgets in the built HTML, known once it is parsed. */
  let built = null;
  const check = () => {
    if (!built) return;
    for (const widget of document.querySelectorAll('[data-widget][data-ready]')) {
      if (built.has(widget)) continue;
      marks.widget ??= performance.now();
      if (widget.dataset.widget === 'simulator') marks.simulator ??= performance.now();
    }
  };
  document.addEventListener('readystatechange', () => {
    if (built) return;
    built = new Set(document.querySelectorAll('[data-widget]'));
    check();
  });
  new MutationObserver(check).observe(document, { subtree: true, childList: true, attributes: true, attributeFilter: ['data-ready'] });
  new PerformanceObserver((list) => {
    for (const entry of list.getEntries()) if (entry.name === 'first-contentful-paint') marks.paint = entry.startTime;
  }).observe({ type: 'paint', buffered: true });
  try {
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) {
        if (entry.hadRecentInput) continue;
        marks.cls += entry.value;
        marks.shifts.push({
          at: Math.round(entry.startTime),
          value: entry.value,
          sources: (entry.sources ?? []).map((s) => s.node?.nodeName + (s.node?.className ? `.${String(s.node.className).split(' ')[0]}` : '')),
        });
      }
    }).observe({ type: 'layout-shift', buffered: true });
  } catch {
    marks.cls = NaN;
  }
}

/**
 * Loads `path` once in a fresh page and measures it. `throttled` applies the
 * Slow 4G network and the 4× CPU slowdown through the DevTools protocol.
 * With `waitFor: 'simulator'` (for a link to a simulator's cell) the load
 * lasts until that simulator has drawn.
 */
export async function coldLoad(context, origin, path, { throttled = false, settleMs = 1500, timeoutMs = 30_000, waitFor = 'widget' } = {}) {
  const page = await context.newPage();
  const session = await context.newCDPSession(page);
  if (throttled) {
    await session.send('Network.enable');
    await session.send('Network.emulateNetworkConditions', SLOW_4G);
    await session.send('Emulation.setCPUThrottlingRate', { rate: CPU_SLOWDOWN });
  }
  await page.addInitScript(() => localStorage.clear());
  await page.addInitScript(instrument);
  /** @type {Map<string, Promise<number>>} */
  const scripts = new Map();
  page.on('response', (response) => {
    const url = response.url();
    if (!/\.m?js(\?|$)/.test(url) || scripts.has(url)) return;
    scripts.set(url, response.body().then((body) => gzipSync(body, { level: 9 }).length, () => 0));
  });
  await page.goto(origin + path, { waitUntil: 'load', timeout: timeoutMs });
  const hasCells = await page.evaluate(() => document.querySelector('[data-cell]') !== null);
  if (hasCells) {
    // The cells near the view have run (a first view may hold no widget at all) …
    await page.waitForSelector('body[data-cells-ready]', { state: 'attached', timeout: timeoutMs }).catch(() => {});
    // … and, when a simulator is what the reader came for, it has drawn.
    if (waitFor === 'simulator') {
      await page.waitForFunction(() => window.__coldLoad.simulator !== null, null, { timeout: timeoutMs }).catch(() => {});
    }
  }
  await page.waitForLoadState('networkidle', { timeout: timeoutMs }).catch(() => {});
  await page.waitForTimeout(settleMs);
  const marks = await page.evaluate(() => ({ ...window.__coldLoad }));
  const bytes = await Promise.all([...scripts.values()]);
  const urls = [...scripts.keys()];
  await page.close();
  return {
    path,
    jsBytes: bytes.reduce((a, b) => a + b, 0),
    jsFiles: urls.length,
    scripts: urls.map((url, i) => ({ name: new URL(url).pathname.split('/').pop(), bytes: bytes[i] })),
    heavy: HEAVY.filter(([, pattern]) => urls.some((url) => pattern.test(url))).map(([name]) => name),
    paintMs: marks.paint,
    widgetMs: marks.widget,
    simulatorMs: marks.simulator,
    cls: marks.cls,
    shifts: marks.shifts,
  };
}

/** The median of the finite values, or NaN. */
export function median(values) {
  const finite = values.filter((v) => Number.isFinite(v)).sort((a, b) => a - b);
  if (!finite.length) return NaN;
  const mid = finite.length >> 1;
  return finite.length % 2 ? finite[mid] : (finite[mid - 1] + finite[mid]) / 2;
}
