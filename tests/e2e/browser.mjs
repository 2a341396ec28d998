/**
 * Headless Chromium for the e2e tests, plus a page watcher that turns the
 * things a reader should never meet — console errors and warnings, uncaught
 * exceptions, failed or foreign requests — into a list the test asserts empty.
 */
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium } from 'playwright-core';

/**
 * How long any wait of a test may last before it counts as a hang: the only limit on a wait, set once on every
 * context, so that no test asserts how long something takes. A wait is for something that does happen; on a
 * machine four times as loaded as a quiet one, it can take four times as long, and more.
 */
export const HANG_MS = 180_000;

const ARGS = [
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];

/**
 * A fresh browser profile (Playwright rejects --user-data-dir in args, hence
 * launchPersistentContext on a new temp dir). `options` go to the context,
 * e.g. `{ javaScriptEnabled: false }` or `{ colorScheme: 'dark' }`.
 * @param {import('playwright-core').BrowserContextOptions} [options]
 */
export async function launchBrowser(options = {}) {
  const profile = await mkdtemp(join(tmpdir(), 'phasebook-e2e-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ARGS,
    viewport: { width: 1100, height: 900 },
    ...options,
  });
  context.setDefaultTimeout(HANG_MS);
  context.setDefaultNavigationTimeout(HANG_MS);
  return {
    context,
    async close() {
      await context.close();
      await rm(profile, { recursive: true, force: true });
    },
  };
}

const LOCAL_HOSTS = new Set(['127.0.0.1', 'localhost', '[::1]']);

/**
 * Records what a page does. `problems` collects console errors/warnings,
 * page errors, failed requests, HTTP errors and any request to a host other
 * than this machine; `requests` lists every URL requested, in order.
 * @param {import('playwright-core').Page} page
 */
export function watchPage(page) {
  /** @type {string[]} */
  const problems = [];
  /** @type {string[]} */
  const requests = [];
  page.on('console', (message) => {
    if (message.type() === 'error' || message.type() === 'warning') {
      problems.push(`console.${message.type()}: ${message.text()} (${message.location().url})`);
    }
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('request', (request) => {
    const url = new URL(request.url());
    requests.push(request.url());
    if (url.protocol !== 'data:' && !LOCAL_HOSTS.has(url.hostname)) problems.push(`foreign request: ${request.url()}`);
  });
  page.on('requestfailed', (request) => {
    // A font declared `font-display: optional` (site/lib/fonts.ts) that misses its moment may be abandoned by
    // the browser: by design, and nothing a reader sees.
    if (request.resourceType() === 'font' && request.failure()?.errorText === 'net::ERR_ABORTED') return;
    // A worker's script still loading when the page reloads or navigates is abandoned with it.
    if (/-worker-[\w-]+\.js$/.test(new URL(request.url()).pathname) && request.failure()?.errorText === 'net::ERR_ABORTED') return;
    problems.push(`request failed: ${request.url()} ${request.failure()?.errorText}`);
  });
  page.on('response', (response) => {
    if (response.status() >= 400) problems.push(`HTTP ${response.status()}: ${response.url()}`);
  });
  return { problems, requests };
}

/** Waits until the cells near the first view (and what they read) have shown their first value or error. */
export async function firstViewReady(page) {
  await page.waitForSelector('body[data-cells-ready]', { state: 'attached' });
}

/**
 * Reads the whole chapter the way a reader does: scrolls down through it a
 * viewport at a time, so that every cell starts (cells start as they come
 * near the view, cells/schedule.ts), waits until every cell has
 * shown its first value or error, and scrolls back to the top.
 */
export async function cellsReady(page) {
  await firstViewReady(page);
  const complete = () => page.evaluate(() => document.body.hasAttribute('data-cells-complete'));
  for (let i = 0; i < 200 && !(await complete()); i++) {
    const atBottom = await page.evaluate(() => {
      window.scrollBy(0, window.innerHeight * 0.8);
      return window.scrollY + window.innerHeight >= document.documentElement.scrollHeight - 2;
    });
    // One frame for the IntersectionObserver to see what came into view; a frame that does not come (a page
    // Chromium counts as hidden draws none) is waited for no longer than a second, the observer's own timer.
    await page.evaluate(() => new Promise((done) => { requestAnimationFrame(() => requestAnimationFrame(done)); setTimeout(done, 1000); }));
    if (atBottom) break;
  }
  await page.waitForSelector('body[data-cells-complete]', { state: 'attached' });
  await page.evaluate(() => window.scrollTo(0, 0));
}
