/**
 * Lighthouse (npm `lighthouse`, pinned at 12.x, which runs on Node 20) over
 * every page of the built site, with its mobile and desktop presets, against
 * Debian's Chromium. The pages come from the local static server, so nothing
 * leaves the machine; Lighthouse's own throttling is simulated (its default),
 * so the scores are computed from the trace, not from a slowed network.
 *
 * Lighthouse is timing-based: its numbers belong in this bench, never in a
 * test. Scores vary with the machine's load (TBT by a factor of ten on a
 * shared machine); BENCH_LIGHTHOUSE_RUNS=N runs each page N times and keeps
 * the run Lighthouse itself calls the median (closest to the median first
 * paint and time to interactive), as its documentation advises.
 */
import { spawn } from 'node:child_process';
import { once } from 'node:events';
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import lighthouse from 'lighthouse';
import { computeMedianRun, filterToValidRuns } from 'lighthouse/core/lib/median-run.js';
import desktopConfig from 'lighthouse/core/config/desktop-config.js';

const CHROME_FLAGS = ['--headless=new', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'];
const CATEGORIES = ['performance', 'accessibility', 'best-practices', 'seo'];
/** The presets: Lighthouse's default config is its mobile one (Moto G Power, slow 4G, 4× CPU). */
export const PRESETS = [
  ['mobile', undefined],
  ['desktop', desktopConfig],
];

/**
 * Chromium listening for DevTools on a free port, in a fresh profile, for
 * Lighthouse to connect to: started here, so the bench depends on no
 * launcher package of its own.
 */
async function startChromium(chromePath) {
  const profile = await mkdtemp(join(tmpdir(), 'phasebook-lighthouse-'));
  const child = spawn(chromePath, [...CHROME_FLAGS, '--remote-debugging-port=0', `--user-data-dir=${profile}`, 'about:blank'], {
    stdio: ['ignore', 'ignore', 'pipe'],
  });
  let said = '';
  const port = await new Promise((resolve, reject) => {
    child.stderr.on('data', (chunk) => {
      said = (said + chunk).slice(-4000);
      const listening = /DevTools listening on ws:\/\/[^:]+:(\d+)\//.exec(said);
      if (listening) resolve(Number(listening[1]));
    });
    child.once('error', reject);
    child.once('exit', (code) => reject(new Error(`${chromePath} exited (${code}) before listening: ${said.trim().split('\n').pop()}`)));
  });
  return {
    port,
    async kill() {
      if (child.exitCode === null && child.signalCode === null) {
        const exited = once(child, 'exit');
        child.kill();
        await exited;
      }
      await rm(profile, { recursive: true, force: true });
    },
  };
}

const RUNS = Math.max(1, Number(process.env.BENCH_LIGHTHOUSE_RUNS ?? 1));

/** The median of `RUNS` Lighthouse runs of `url` with `config`, reduced to the numbers the table shows. */
async function audit(url, port, config) {
  const runs = [];
  for (let i = 0; i < RUNS; i++) runs.push((await lighthouse(url, { port, output: 'json', logLevel: 'error', onlyCategories: CATEGORIES }, config)).lhr);
  const valid = filterToValidRuns(runs);
  const lhr = valid.length ? computeMedianRun(valid) : runs[0];
  const { categories, audits, runtimeError, runWarnings } = lhr;
  const score = (id) => (categories[id]?.score == null ? NaN : Math.round(categories[id].score * 100));
  const value = (id) => audits[id]?.numericValue ?? NaN;
  /** What kept a category from 100: the audits that failed, by id. */
  const failed = (id) =>
    (categories[id]?.auditRefs ?? [])
      .filter((ref) => ref.weight > 0 && audits[ref.id]?.score !== null && audits[ref.id]?.score < 1)
      .map((ref) => ref.id);
  return {
    performance: score('performance'),
    accessibility: score('accessibility'),
    bestPractices: score('best-practices'),
    seo: score('seo'),
    tbt: value('total-blocking-time'),
    lcp: value('largest-contentful-paint'),
    cls: value('cumulative-layout-shift'),
    dom: value('dom-size'),
    mainThread: value('mainthread-work-breakdown'),
    failed: { accessibility: failed('accessibility'), bestPractices: failed('best-practices'), seo: failed('seo') },
    error: runtimeError?.message ?? null,
    warnings: runWarnings ?? [],
  };
}

/**
 * Runs every preset on every path (one Chromium for all, each run in a fresh
 * tab with storage cleared by Lighthouse) and prints the table. `log` takes
 * progress lines; `print` the report's.
 */
export async function lighthouseTable(origin, paths, { print, log, chromePath = process.env.CHROMIUM || '/usr/bin/chromium' }) {
  const chrome = await startChromium(chromePath);
  const rows = [];
  try {
    for (const [preset, config] of PRESETS) {
      for (const path of paths) {
        log(`lighthouse ${preset} ${path}…`);
        rows.push({ path, preset, ...(await audit(origin + path, chrome.port, config)) });
      }
    }
  } finally {
    await chrome.kill();
  }
  const ms = (x) => (Number.isFinite(x) ? `${Math.round(x)} ms` : '—');
  const s = (x) => (Number.isFinite(x) ? `${(x / 1000).toFixed(2)} s` : '—');
  const n = (x) => (Number.isFinite(x) ? String(x) : '—');
  const runs = RUNS === 1 ? 'one run' : `the median of ${RUNS} runs`;
  print(`Lighthouse 12, ${runs} per page and preset (simulated throttling; mobile = its default Moto G Power, slow 4G, 4× CPU; ` +
    'desktop = its desktop preset). Performance, accessibility, best practices and SEO are scores out of 100; TBT total blocking time; ' +
    'LCP largest contentful paint; CLS cumulative layout shift; DOM the elements in the page; main thread the work Lighthouse saw on it.');
  print();
  print('| Page | preset | performance | accessibility | best practices | SEO | TBT | LCP | CLS | DOM elements | main thread |');
  print('|---|---|---|---|---|---|---|---|---|---|---|');
  for (const r of rows) {
    print(`| \`${r.path}\` | ${r.preset} | ${n(r.performance)} | ${n(r.accessibility)} | ${n(r.bestPractices)} | ${n(r.seo)} | ${ms(r.tbt)} | ${s(r.lcp)} | ${Number.isFinite(r.cls) ? r.cls.toFixed(3) : '—'} | ${n(r.dom)} | ${s(r.mainThread)} |`);
  }
  print();
  const misses = [];
  for (const r of rows) {
    const where = `${r.path} (${r.preset})`;
    if (r.error) misses.push(`${where}: ${r.error}`);
    if (r.preset === 'mobile') {
      if (!(r.performance >= 95)) misses.push(`${where}: performance ${r.performance}`);
      if (!(r.tbt <= 200)) misses.push(`${where}: TBT ${ms(r.tbt)}`);
      if (!(r.lcp <= 2500)) misses.push(`${where}: LCP ${s(r.lcp)}`);
    }
    for (const [name, key] of [['accessibility', 'accessibility'], ['best practices', 'bestPractices'], ['SEO', 'seo']]) {
      if (r[key] !== 100) misses.push(`${where}: ${name} ${r[key]} (${r.failed[key].join(', ') || 'no failed audit named'})`);
    }
  }
  print('Targets (issue 25): mobile performance ≥ 95 with TBT ≤ 200 ms and LCP ≤ 2.5 s on a quiet machine; ' +
    'accessibility, best practices and SEO 100 everywhere. ' + (misses.length ? `Missed: ${misses.join('; ')}.` : 'All met.'));
  print();
  return rows;
}
