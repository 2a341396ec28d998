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

/** Chunks only an interaction loads, checked for by tests/e2e/lazy.test.mjs. */
const LAZY = [
  [/[\\/]node_modules[\\/](@codemirror|@lezer|style-mod|w3c-keyname|crelt)[\\/]|[\\/]widgets[\\/]cells[\\/]editor\.ts$/, 'editor'],
  [/[\\/]node_modules[\\/](@observablehq[\\/]parser|acorn|acorn-walk)[\\/]/, 'parser'],
];

/** Every other module of the book, by what loads it; the first rule that matches wins. */
const GROUPS = [
  // Rollup's helper for CommonJS modules (fft.js, mathjs's dependencies), a few lines every such chunk imports.
  [/commonjsHelpers/, 'boot'],
  [/node_modules\/(d3-|internmap)/, 'plots'],
  [/widgets\/plots\/time\//, 'time-plot'],
  [/widgets\/plots\/plane\//, 'plane-views'],
  [/widgets\/plots\/spectrum\/|node_modules\/fft\.js\/|widgets\/core\/(spectrum|window|peaks)\.ts/, 'spectrum'],
  // The panel a reader picks a point on serves the Poincaré section and the stability chart, on two pages: a chunk of its own, not in the one every plot loads.
  [/widgets\/plots\/point-panel\.ts$/, 'point-panel'],
  [/widgets\/plots\/[^/]+$|widgets\/controls\/(dom|format)\.ts/, 'plots'],
  [/widgets\/data\/(export|download)\.ts|widgets\/core\/(export-meta|csv|json)\.ts/, 'export'],
  // The page's side of the simulation worker: a simulator loads it only once its model proves costly (driver.ts).
  [/widgets\/simulator\/(worker-integrator|chunk-protocol|portable-model)\.ts/, 'worker-integrator'],
  [/widgets\/(simulator|controls|data)\//, 'simulator'],
  [/widgets\/core\/analysis\/|widgets\/book\/analysis\.ts/, 'analysis'],
  [/widgets\/core\/(expression\/(?!names|mathjs-instance)|compile-model|js-function\/translate)/, 'compiler'],
  [/widgets\/core\/(integrators\/|js-function\/|expression\/names|canonical-equations|compiled-model|model-from-compiled|rk38)/, 'model'],
  [/widgets\/core\/dataset\//, 'dataset'],
  // The guards reader code runs under: loaded only when an edit first runs (cells/sandbox/index.ts).
  [/widgets\/cells\/sandbox\//, 'sandbox'],
  // What the page says when storage or the page itself was damaged.
  [/widgets\/cells\/recovery\.ts$/, 'recovery'],
  // The cells a reader adds: built only on a page that has one, or when one is added.
  [/widgets\/cells\/added-cells\.ts$/, 'added-cells'],
  [/widgets\/core\/(?!index|expression\/mathjs-instance)[^/]+$|widgets\/book\/cell-simulation\.ts/, 'core'],
  [/widgets\/book\/(chart|table|theory-check|tex|stability-chart|compile-client|poincare-section|method-comparison)/, (m) => m[1]],
  [/widgets\/book\/check-verdict/, 'theory-check'],
  [/widgets\/book\/typeset/, 'tex'],
  [/widgets\/book\/(section-systems|kepler-run)/, 'poincare-section'],
];

/** The core's front door: what the boot code imports through it is followed name by name. */
const CORE_INDEX = /[\\/]widgets[\\/]core[\\/]index\.ts$/;

/** The names `code` imports from a module whose path ends with `index.ts` under core/. */
function namesFromCoreIndex(code) {
  const names = [];
  for (const m of (code ?? '').matchAll(/import\s*\{([^}]*)\}\s*from\s*["']([^"']+)["']/g)) {
    if (!/core\/index\.ts$/.test(m[2])) continue;
    for (const part of m[1].split(',')) {
      const name = part.trim().split(/\s+as\s+/)[0];
      if (name) names.push(name);
    }
  }
  return names;
}

/**
 * The modules the entries import statically, as used: through the core's
 * front door only the modules exporting the names imported from it, since
 * Rollup's graph lists every module the index re-exports.
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
      if (!CORE_INDEX.test(dependency)) {
        stack.push(dependency);
        continue;
      }
      const names = new Set(namesFromCoreIndex(info.code));
      for (const part of getModuleInfo(dependency)?.importedIds ?? []) {
        if ((getModuleInfo(part)?.exports ?? []).some((name) => names.has(name))) stack.push(part);
      }
    }
  }
  return boot;
}

/** The group a module of the book belongs to, or undefined for Rollup to place. */
export function groupOf(id) {
  const path = id.replace(/\\/g, '/');
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
    for (const [pattern, name] of LAZY) if (pattern.test(id)) return name;
    if (!bootOf.has(getModuleInfo)) bootOf.set(getModuleInfo, bootModules(getModuleIds, getModuleInfo));
    if (bootOf.get(getModuleInfo).has(id)) return 'boot';
    return groupOf(id);
  };
}
