/**
 * What a chapter's load costs the main thread, counted as work rather than
 * time: a Chrome trace of a fresh load at a phone's size (412 × 823, touch)
 * with a 4× CPU slowdown, from the navigation until the cells wanted at
 * first have shown (`data-cells-ready`) and three seconds more, so that the
 * idle passes after the load are in it too.
 *
 * On a shared machine a load's times swing tenfold with the other work on
 * it; the counts do not. So beside the main thread's time by kind (style,
 * layout, HTML parsing, script, paint) this prints the elements styled and
 * the layout objects laid out, summed over every style recalculation and
 * layout, the layouts and style recalculations the page's script forced,
 * and which functions forced them. Compare two builds with `--against DIR`:
 * their loads are interleaved, so both meet the same load.
 *
 *   PHASEBOOK_OUT_DIR=/tmp/dist node bench/load-work.mjs [--runs N] [--against DIR] /kepler/ /introduction/ …
 */
import { chromium } from 'playwright-core';
import { DIST, startServer } from '../tests/e2e/server.mjs';
import { CPU_SLOWDOWN } from './cold-load.mjs';

const ARGS = ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'];
const CATEGORIES = ['devtools.timeline', 'disabled-by-default-devtools.timeline', 'disabled-by-default-devtools.timeline.stack', 'v8.execute'];
/** Main-thread events by kind; script counts only its outermost events, since they nest. */
const KINDS = {
  style: ['UpdateLayoutTree'],
  layout: ['Layout'],
  parse: ['ParseHTML'],
  script: ['EvaluateScript', 'v8.compileModule', 'v8.evaluateModule', 'FunctionCall', 'TimerFire', 'FireIdleCallback', 'FireAnimationFrame', 'EventDispatch', 'RunMicrotasks'],
  paint: ['PrePaint', 'Paint', 'Layerize', 'Commit'],
};

/** The trace events of one load of `url` in a fresh context of `browser`. */
async function traceLoad(browser, url) {
  const context = await browser.newContext({ viewport: { width: 412, height: 823 }, isMobile: true, hasTouch: true });
  try {
    const page = await context.newPage();
    const session = await context.newCDPSession(page);
    await session.send('Emulation.setCPUThrottlingRate', { rate: CPU_SLOWDOWN });
    const events = [];
    session.on('Tracing.dataCollected', ({ value }) => events.push(...value));
    const complete = new Promise((resolve) => session.once('Tracing.tracingComplete', resolve));
    await session.send('Tracing.start', { categories: CATEGORIES.join(','), transferMode: 'ReportEvents' });
    await page.goto(url, { waitUntil: 'load', timeout: 120_000 });
    await page.waitForFunction(() => document.body.dataset.cellsReady !== undefined || !document.querySelector('[data-cell]'), null, { timeout: 60_000 });
    // The idle work after the load (the far boxes' pass, lazy starts) belongs to the load's cost.
    await page.waitForTimeout(3000);
    const elements = await page.evaluate(() => document.getElementsByTagName('*').length);
    await session.send('Tracing.end');
    await complete;
    return { events, elements, url: page.url() };
  } finally {
    await context.close();
  }
}

/** The work on the renderer's main thread of the page's navigation, from the trace. */
function mainThreadWork({ events, elements, url }) {
  // The page's main thread: the one that parsed its HTML.
  const parse = events.find((e) => e.name === 'ParseHTML' && e.args?.beginData?.url === url);
  const main = events.filter((e) => e.pid === parse?.pid && e.tid === parse?.tid && e.ph === 'X' && e.dur).sort((a, b) => a.ts - b.ts);
  const ms = Object.fromEntries(Object.keys(KINDS).map((kind) => [kind, 0]));
  const forcedBy = new Map();
  let scriptEnd = -1;
  let styled = 0;
  let laidOut = 0;
  let forced = 0;
  for (const e of main) {
    for (const [kind, names] of Object.entries(KINDS)) {
      if (!names.includes(e.name)) continue;
      if (kind === 'script') {
        if (e.ts < scriptEnd) continue;
        scriptEnd = e.ts + e.dur;
      }
      ms[kind] += e.dur / 1000;
    }
    if (e.name === 'UpdateLayoutTree') styled += e.args?.elementCount ?? 0;
    if (e.name === 'Layout') laidOut += e.args?.beginData?.dirtyObjects ?? 0;
    const stack = e.args?.beginData?.stackTrace;
    if ((e.name === 'Layout' || e.name === 'UpdateLayoutTree') && stack) {
      forced++;
      const where = stack.slice(0, 2).map((f) => `${f.functionName || '(anonymous)'}@${(f.url ?? '').split('/').pop().replace(/\.[\w-]{8}\.js$/, '.js')}:${f.lineNumber}`).join(' < ');
      forcedBy.set(where, (forcedBy.get(where) ?? 0) + 1);
    }
  }
  const tasks = main.filter((e) => e.name === 'RunTask');
  return {
    elements,
    styled,
    laidOut,
    forced,
    forcedBy: [...forcedBy].sort((a, b) => b[1] - a[1]).slice(0, 3),
    ms,
    tasks: tasks.reduce((sum, t) => sum + t.dur / 1000, 0),
    longest: Math.max(0, ...tasks.map((t) => t.dur / 1000)),
  };
}

function parseArgs(argv) {
  const options = { runs: 1, against: null, paths: [] };
  for (let i = 0; i < argv.length; i++) {
    if (argv[i] === '--runs') options.runs = Number(argv[++i]);
    else if (argv[i] === '--against') options.against = argv[++i];
    else options.paths.push(argv[i]);
  }
  if (!options.paths.length) options.paths = ['/introduction/', '/kepler/'];
  return options;
}

async function main() {
  const { runs, against, paths } = parseArgs(process.argv.slice(2));
  const builds = [{ name: 'A', root: DIST }, ...(against ? [{ name: 'B', root: against }] : [])];
  for (const build of builds) build.server = await startServer(build.root);
  const browser = await chromium.launch({ executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true, args: ARGS });
  const lines = [];
  try {
    for (const path of paths) {
      for (let run = 0; run < runs; run++) {
        for (const build of builds) {
          const work = mainThreadWork(await traceLoad(browser, build.server.origin + path));
          const ms = (x) => String(Math.round(x));
          lines.push(`| \`${path}\` | ${build.name} | ${run + 1} | ${work.elements} | ${work.styled} | ${work.laidOut} | ${work.forced} | ` +
            `${ms(work.ms.style)} | ${ms(work.ms.layout)} | ${ms(work.ms.parse)} | ${ms(work.ms.script)} | ${ms(work.ms.paint)} | ${ms(work.tasks)} | ${ms(work.longest)} | ` +
            `${work.forcedBy.map(([where, n]) => `${where} ×${n}`).join('; ')} |`);
          process.stderr.write(`${lines.at(-1)}\n`);
        }
      }
    }
  } finally {
    await browser.close();
    for (const build of builds) await build.server.close();
  }
  const print = (line = '') => process.stdout.write(`${line}\n`);
  print(`Main-thread work of a fresh load at 412 × 823 with a ${CPU_SLOWDOWN}× CPU slowdown, to the cells' first values and 3 s more. ` +
    `A = ${builds[0].root}${against ? `, B = ${against} (interleaved)` : ''}. Counts: elements in the page, elements styled and layout ` +
    'objects laid out (summed over every recalculation), layouts and style recalcs forced by script. Times in ms (they swing with the machine\'s load; the counts do not).');
  print();
  print('| Page | build | run | elements | styled | laid out | forced | style | layout | parse | script | paint | tasks | longest task | forced by |');
  print('|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|');
  lines.forEach((line) => print(line));
}

main().catch((error) => {
  process.stderr.write(`load-work failed: ${error?.stack ?? error}\n`);
  process.exitCode = 1;
});
