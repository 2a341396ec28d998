/**
 * How the book's client code is cut into chunks (Rollup's `manualChunks`).
 *
 * A page fetches the boot chunk, then, for each widget its first view
 * shows, the chunks of that widget, all at once (Vite preloads a dynamic
 * import's dependencies together). So the code is grouped by what a reader
 * meets together: the cell machinery that every page with cells runs
 * (`boot`), the plot foundation with d3, each view, the simulator with its
 * controls, the runtime model, the analysis behind the theory checks, each
 * book widget, and the expression compiler, which only an edit needs.
 *
 * Two rules of Rollup shape this. A manual chunk takes in every dependency
 * that has no chunk of its own, so a module the boot code uses must be named
 * `boot` here, or the boot chunk would import a widget's chunk. And chunks
 * Rollup forms on its own are merged, when small, into any chunk whose side
 * effects allow it, which put lazily loaded widgets into the boot chunk; so
 * every module of the book gets a group, and Rollup forms only the chunks of
 * third-party code loaded on demand (mathjs, KaTeX).
 */
import { fileURLToPath } from 'node:url';

/** The project root: paths are matched relative to it, so that a folder named core/ elsewhere never matches. */
const ROOT = fileURLToPath(new URL('../../', import.meta.url)).replace(/\\/g, '/');

/** A module's path from the project root (a package's from its node_modules/, wherever that is), with forward slashes. */
function pathOf(id) {
  const path = id.replace(/\\/g, '/');
  const packages = path.lastIndexOf('/node_modules/');
  if (packages >= 0) return path.slice(packages + 1);
  return path.startsWith(ROOT) ? path.slice(ROOT.length) : path;
}

/** Chunks only an interaction loads, checked for by tests/e2e/lazy.test.mjs. */
const LAZY = [
  [/^node_modules\/(@codemirror|@lezer|style-mod|w3c-keyname|crelt)\/|^cells\/editor\.ts$/, 'editor'],
  [/^node_modules\/(@observablehq\/parser|acorn|acorn-walk)\//, 'parser'],
  // The search box's code, which its inline script imports when the reader asks (site/lib/search-box.ts).
  [/^site\/search\//, 'search'],
  // The progress page's script (site/pages/progress.astro), an entry that would otherwise join the boot chunk and run on every page.
  [/^site\/pages\/progress\.astro\?/, 'progress'],
];

/** Every other module of the book, by what loads it; the first rule that matches wins. */
const GROUPS = [
  // Rollup's helper for CommonJS modules (fft.js, mathjs's dependencies), a few lines every such chunk imports.
  [/commonjsHelpers/, 'boot'],
  [/^node_modules\/(d3-|internmap)/, 'plots'],
  [/^widgets\/plots\/time\//, 'time-plot'],
  [/^widgets\/plots\/plane\//, 'plane-views'],
  [/^widgets\/plots\/spectrum\/|^node_modules\/fft\.js\/|^core\/spectrum\//, 'spectrum'],
  // The panel a reader picks a point on serves the Poincaré section and the stability chart, on two pages: a chunk of its own, not in the one every plot loads.
  [/^widgets\/plots\/point-panel\.ts$/, 'point-panel'],
  [/^widgets\/plots\/[^/]+$|^widgets\/controls\/(dom|format)\.ts/, 'plots'],
  [/^widgets\/exports\/(export|download)\.ts|^core\/tables\/(export-meta|csv|json)\.ts/, 'export'],
  // The page's side of the simulation worker: a simulator loads it only once its model proves costly (driver.ts).
  [/^widgets\/simulator\/(worker-integrator|chunk-protocol|portable-model)\.ts/, 'worker-integrator'],
  [/^widgets\/(simulator|controls|exports)\//, 'simulator'],
  [/^widgets\/chapter\/analysis\/kepler-run\.ts/, 'poincare-section'],
  // The standard map and what its chapter computes of it: one chunk, which only that chapter loads.
  [/^core\/maps\/|^core\/analysis\/standard-map\.ts$|^widgets\/chapter\/standard-map\//, 'standard-map'],
  // Liouville's chapter: the ensemble, its boundary and area, and the recurrence of a section; only that chapter loads it.
  [/^core\/ensemble\/|^core\/analysis\/(recurrence|model-section)\.ts$|^widgets\/chapter\/ensemble\//, 'liouville'],
  // A model's non-Hamiltonian terms, their rules and sentences: loaded only for a spec that has some.
  [/^core\/model\/non-hamiltonian\.ts$/, 'non-hamiltonian'],
  // The counter-based generator the standard map's diffusion draws its starts from (and the datasets, in the
  // CLI and the workers): in the core chunk, which a chapter's first simulator loads, it added 0.5 KB to each.
  [/^core\/dataset\/philox\.ts$/, 'random'],
  // The action–angle chapter's measurements, apart from the analysis chunk that other chapters' checks load.
  [/^core\/analysis\/(action|flow-map)\.ts$/, 'action-angle'],
  // The pendulum's closed forms, which the action–angle chapter's simulator reads for its spectrum's marker:
  // with the analysis chunk, a link to that simulator loaded 85 KB, over the 80 KB budget.
  [/^core\/analysis\/pendulum\.ts$/, 'pendulum'],
  [/^core\/analysis\/|^widgets\/chapter\/analysis\//, 'analysis'],
  [/^core\/(expression\/(?!names|mathjs-instance)|model\/compile-model|js-function\/translate)/, 'compiler'],
  // The integration methods besides RK 3/8, and how a model is switched to one: loaded only by a model that asks for one.
  [/^core\/integrators\/(apply|dormand-prince|dormand-prince-step|continuations|midpoint|linear-solve)\.ts$|^core\/model\/model-from-compiled\.ts$/, 'methods'],
  [/^core\/(integrators\/|js-function\/|expression\/names|model\/(canonical-equations|compiled-model|compiled-parts))/, 'model'],
  // The guards reader code runs under: loaded only when an edit first runs (cells/sandbox/index.ts).
  [/^cells\/sandbox\//, 'sandbox'],
  // What the page says when storage or the page itself was damaged.
  [/^cells\/recovery\.ts$/, 'recovery'],
  // An embed page's side of the page around it (site/pages/embed/): loaded on those pages only.
  [/^cells\/embed\.ts$/, 'embed'],
  // The cells a reader adds: built only on a page that has one, or when one is added.
  [/^cells\/added-cells\.ts$/, 'added-cells'],
  [/^core\/(?:(?:model|tables|dataset)\/)?(?!index\.ts)[^/]+$|^widgets\/chapter\/models\/cell-simulation\.ts/, 'core'],
  [/^widgets\/chapter\/(chart|table|theory-check|stability-chart|poincare-section|method-comparison)\//, (m) => m[1]],
  // The exercise widget, its truths and its checks: loaded when an exercise comes near, never with the boot chunk.
  [/^widgets\/chapter\/exercise\//, 'exercise'],
  [/^widgets\/chapter\/models\/compile-client/, 'compile-client'],
  // The exercises' widget with its truths: left to Rollup, a small chunk of it was merged into the boot chunk,
  // which then imported the analysis chunk statically, and through it the core chunk, which imports the boot chunk: a cycle.
  [/^widgets\/chapter\/exercise\//, 'exercise'],
  [/^widgets\/chapter\/math\//, 'tex'],
];

/** The front doors of the core, the widgets and the cells: what the boot code imports through one is followed name by name. */
const FRONT_DOOR = /^(core|widgets|cells)\/index\.ts$/;

/** The names `code` imports from the front door of `folder` (its index.ts). */
function namesThroughDoor(code, folder) {
  const names = [];
  for (const m of (code ?? '').matchAll(/import\s*\{([^}]*)\}\s*from\s*["']([^"']+)["']/g)) {
    if (!m[2].endsWith(`${folder}/index.ts`)) continue;
    for (const part of m[1].split(',')) {
      const name = part.trim().split(/\s+as\s+/)[0];
      if (name) names.push(name);
    }
  }
  return names;
}

/**
 * The modules the entries import statically, as used: through a front door
 * only the modules exporting the names imported from it, since Rollup's
 * graph lists every module the door re-exports.
 */
function bootModules(getModuleIds, getModuleInfo) {
  const boot = new Set();
  const stack = [...getModuleIds()].filter((id) => getModuleInfo(id)?.isEntry);
  while (stack.length) {
    const id = stack.pop();
    if (boot.has(id)) continue;
    boot.add(id);
    const info = getModuleInfo(id);
    for (const dependency of info?.importedIds ?? []) {
      const door = FRONT_DOOR.exec(pathOf(dependency));
      if (!door) {
        stack.push(dependency);
        continue;
      }
      const names = new Set(namesThroughDoor(info.code, door[1]));
      for (const part of getModuleInfo(dependency)?.importedIds ?? []) {
        if ((getModuleInfo(part)?.exports ?? []).some((name) => names.has(name))) stack.push(part);
      }
    }
  }
  return boot;
}

/** The group a module of the book belongs to, or undefined for Rollup to place. */
export function groupOf(id) {
  const path = pathOf(id);
  for (const [pattern, name] of GROUPS) {
    const match = pattern.exec(path);
    if (match) return typeof name === 'function' ? name(match) : name;
  }
  return undefined;
}

/** Rollup's `manualChunks` for the client build (one per build: it keeps that build's boot modules). */
export function bookChunks() {
  const bootOf = new WeakMap();
  return (id, { getModuleIds, getModuleInfo }) => {
    for (const [pattern, name] of LAZY) if (pattern.test(pathOf(id))) return name;
    if (!bootOf.has(getModuleInfo)) bootOf.set(getModuleInfo, bootModules(getModuleIds, getModuleInfo));
    if (bootOf.get(getModuleInfo).has(id)) return 'boot';
    return groupOf(id);
  };
}
