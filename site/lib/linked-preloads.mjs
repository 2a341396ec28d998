/**
 * A link to a simulator's cell (`/kepler/#cell-stars`) says what the reader
 * came for. Without help the page fetches the simulator's modules only once
 * its boot script has arrived and run, after the first layout of a long
 * chapter: over a slow network that is a second wave of requests after the
 * first. This build step writes into each chapter's head a small script
 * that, when the address names a cell holding a simulator, asks for that
 * simulator's modules (`modulepreload`) while the boot script is still on
 * its way. Opened at its top, or at any other cell, the page fetches
 * nothing more than before.
 *
 * What a simulator needs is read from the client bundle: the chunk of
 * widgets/simulator/simulator.ts and those of the views the cell shows
 * (widgets/simulator/view-modules.ts, read here so that the table of views
 * lives in one place), with every chunk they import statically, less what
 * the page's entry script imports anyway. Which cells hold a simulator, and
 * which views, the build already wrote into the HTML: the space reserved
 * for it (widgets/simulator/reserve.ts).
 *
 * The script is inline, so the page's Content-Security-Policy names its
 * hash, like the page's other inline scripts (site/lib/csp.ts).
 */
import { readFileSync } from 'node:fs';
import { readdir, readFile, writeFile } from 'node:fs/promises';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { scriptHash } from './csp.ts';

const here = dirname(fileURLToPath(import.meta.url));
const SIMULATOR_DIR = resolve(here, '../../widgets/simulator');

/**
 * The source modules a simulator's first draw loads: its own and one per
 * view, read from view-modules.ts (`time: () => import('../plots/time/time-plot.ts')`).
 */
export function simulatorModules(viewModulesSource = readFileSync(join(SIMULATOR_DIR, 'view-modules.ts'), 'utf8')) {
  const views = {};
  for (const m of viewModulesSource.matchAll(/^\s*(\w+):\s*\(\)\s*=>\s*import\(\s*['"]([^'"]+)['"]\s*\)/gm)) {
    views[m[1]] = resolve(SIMULATOR_DIR, m[2]);
  }
  return { simulator: join(SIMULATOR_DIR, 'simulator.ts'), views };
}

/** The chunks of a Rollup bundle: file name, the modules it holds, its static imports, whether it is an entry. */
export function chunkGraph(bundle) {
  return Object.values(bundle)
    .filter((item) => item.type === 'chunk')
    .map((chunk) => ({ fileName: chunk.fileName, modules: chunk.moduleIds ?? Object.keys(chunk.modules ?? {}), imports: chunk.imports ?? [], isEntry: chunk.isEntry }));
}

/** `files` and every chunk they import statically, transitively. */
function closure(graph, files) {
  const byName = new Map(graph.map((chunk) => [chunk.fileName, chunk]));
  const seen = new Set();
  const stack = [...files];
  while (stack.length) {
    const file = stack.pop();
    if (seen.has(file) || !byName.has(file)) continue;
    seen.add(file);
    stack.push(...byName.get(file).imports);
  }
  return seen;
}

/**
 * For each view name, and for the simulator itself (key ''), the chunk files
 * to preload, without those the entry scripts load anyway. A module missing
 * from the bundle is an error: the build has changed under this step.
 * @returns {Record<string, string[]>}
 */
export function simulatorChunks(graph, modules = simulatorModules()) {
  const chunkOf = (id) => {
    const chunk = graph.find((c) => c.modules.includes(id));
    if (!chunk) throw new Error(`linked-preloads: no chunk of the client bundle holds ${id}`);
    return chunk.fileName;
  };
  const loaded = closure(graph, graph.filter((c) => c.isEntry).map((c) => c.fileName));
  const needs = (id) => [...closure(graph, [chunkOf(id)])].filter((file) => !loaded.has(file));
  /** @type {Record<string, string[]>} */
  const table = { '': needs(modules.simulator) };
  for (const [view, id] of Object.entries(modules.views)) table[view] = needs(id);
  return table;
}

/**
 * The cells of a page's HTML that hold a simulator, with the views reserved
 * for it, in page order. Cells do not nest, so each reserve belongs to the
 * last cell opened before it.
 */
export function linkedSimulators(html) {
  const found = [];
  for (const part of html.split(/(?=<figure\b[^>]*\bdata-cell=)/).slice(1)) {
    const id = /^<figure\b[^>]*\bid="([^"]+)"/.exec(part)?.[1];
    const reserve = /data-reserve="simulator"[^>]*?data-reserve-views="([^"]*)"/.exec(part);
    if (id && reserve) found.push({ id, views: reserve[1].split(/\s+/).filter(Boolean) });
  }
  return found;
}

/** The inline script: the modules of the cell the address names, if it holds a simulator. */
export function preloadScript(simulators, chunks, base) {
  const files = [];
  const indexOf = (file) => (files.includes(file) ? files.indexOf(file) : files.push(file) - 1);
  const byCell = {};
  for (const { id, views } of simulators) {
    const wanted = [...chunks[''], ...views.flatMap((view) => chunks[view] ?? [])];
    byCell[id] = [...new Set(wanted.map(indexOf))];
  }
  const urls = files.map((file) => `${base}${file}`);
  // As script text, inline in HTML: no `</script>` may appear in the data.
  const literal = (value) => JSON.stringify(value).replace(/</g, '\\u003c');
  return (
    `(() => {\n` +
    `  const cells = ${literal(byCell)}, files = ${literal(urls)};\n` +
    `  let id;\n` +
    `  try { id = decodeURIComponent(location.hash.slice(1)); } catch { return; }\n` +
    `  for (const i of (Object.hasOwn(cells, id) ? cells[id] : [])) {\n` +
    `    const link = document.createElement('link');\n` +
    `    link.rel = 'modulepreload';\n` +
    `    link.href = files[i];\n` +
    `    document.head.append(link);\n` +
    `  }\n` +
    `})();`
  );
}

/**
 * `html` with the preload script for its simulators, placed before the
 * stylesheet (an inline script after a stylesheet waits for it) and named in
 * the page's policy; unchanged when the page holds no simulator.
 */
export function withLinkedPreloads(html, chunks, base) {
  const simulators = linkedSimulators(html);
  if (!simulators.length) return html;
  const script = preloadScript(simulators, chunks, base);
  const stylesheet = html.search(/<link rel="stylesheet"/);
  const headEnd = html.indexOf('</head>');
  const at = stylesheet >= 0 && stylesheet < headEnd ? stylesheet : headEnd;
  if (at < 0) throw new Error('linked-preloads: a page without a head');
  const withScript = `${html.slice(0, at)}<script>${script}</script>${html.slice(at)}`;
  const policy = /(<meta http-equiv="Content-Security-Policy" content="[^"]*script-src 'self')/;
  if (!policy.test(withScript)) return withScript;
  return withScript.replace(policy, `$1 ${scriptHash(script)}`);
}

async function* htmlFiles(dir) {
  for (const entry of await readdir(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) yield* htmlFiles(path);
    else if (entry.name.endsWith('.html')) yield path;
  }
}

/** The Astro integration: reads the client bundle's chunks as Vite writes them, then rewrites the built pages. */
export function linkedPreloads() {
  let chunks = null;
  let base = '/';
  let client = false;
  return {
    name: 'phasebook:linked-preloads',
    hooks: {
      'astro:config:setup': ({ updateConfig }) => {
        updateConfig({
          vite: {
            plugins: [
              {
                name: 'phasebook:linked-preloads-graph',
                configResolved(config) {
                  client = !config.build.ssr;
                },
                generateBundle(_options, bundle) {
                  if (client) chunks = simulatorChunks(chunkGraph(bundle));
                },
              },
            ],
          },
        });
      },
      'astro:config:done': ({ config }) => {
        base = config.base.endsWith('/') ? config.base : `${config.base}/`;
      },
      'astro:build:done': async ({ dir }) => {
        if (!chunks) throw new Error('linked-preloads: the client bundle was not seen');
        for await (const file of htmlFiles(fileURLToPath(dir))) {
          const html = await readFile(file, 'utf8');
          const changed = withLinkedPreloads(html, chunks, base);
          if (changed !== html) await writeFile(file, changed);
        }
      },
    },
  };
}
