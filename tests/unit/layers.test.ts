/**
 * The shape of the code, read from its import statements: top-level folders
 * in layers that point one way (core → widgets → cells → site, and the CLI
 * on the core alone), the widgets' own layers, one front door to each of
 * core/, widgets/ and cells/, no import cycles (type-only imports included),
 * and tests/unit/ mirroring the tree.
 */
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

const ROOT = resolve(__dirname, '../..');

/** What each top-level folder may import from the others (its own folder always). */
const TOP: Record<string, readonly string[]> = {
  core: [],
  cli: ['core'],
  widgets: ['core'],
  cells: ['core', 'widgets'],
  site: ['core', 'widgets', 'cells'],
  'vscode/src': ['core', 'widgets', 'cells', 'site'],
};

/** The widgets' layers, lowest first; the front door and the catalogue stand on all of them. */
const WIDGET_LAYERS = ['controls', 'plots', 'exports', 'simulator', 'chapter', 'catalogue.ts', 'index.ts'];

/** Where other folders enter: a static import from outside names this module or none. */
const FRONT_DOORS: Record<string, string> = { core: 'core/index.ts', widgets: 'widgets/index.ts', cells: 'cells/index.ts' };

/**
 * Static imports that pass a front door on purpose, with the reason: the build hands mathjs to the core
 * itself, where a page loads it on demand (core/index.ts says so).
 */
const THROUGH_THE_WALL = new Set(['site/lib/precompile.ts → core/expression/mathjs-instance.ts']);

function sources(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return name === 'node_modules' ? [] : sources(path);
    return /\.(ts|mjs|astro)$/.test(path) ? [path] : [];
  });
}

interface Import {
  target: string;
  dynamic: boolean;
}

/** Relative imports of a file: static and type-only, re-exports, side-effect imports and dynamic `import()`. */
function importsOf(file: string): Import[] {
  const text = readFileSync(file, 'utf8');
  const found: Import[] = [];
  for (const m of text.matchAll(/^\s*(?:import|export)\b[^;]*?\bfrom\s+'(\.[^']+)'/gms)) found.push({ target: resolve(dirname(file), m[1]), dynamic: false });
  for (const m of text.matchAll(/^\s*import\s+'(\.[^']+)'/gm)) found.push({ target: resolve(dirname(file), m[1]), dynamic: false });
  for (const m of text.matchAll(/\bimport\(\s*'(\.[^']+)'\s*\)/g)) found.push({ target: resolve(dirname(file), m[1]), dynamic: true });
  return found;
}

/** The top-level folder a file belongs to, as TOP names it. */
function topOf(file: string): string | undefined {
  const path = relative(ROOT, file);
  return Object.keys(TOP).find((top) => path.startsWith(top + '/'));
}

/** The widgets' layer of a file under widgets/ (its first folder, or the file at the top). */
function widgetLayerOf(file: string): number {
  return WIDGET_LAYERS.indexOf(relative(join(ROOT, 'widgets'), file).split('/')[0]);
}

const files = Object.keys(TOP).flatMap((top) => sources(join(ROOT, top)));
const code = files.filter((f) => !/\.css$/.test(f));
const rel = (file: string) => relative(ROOT, file);

describe('the layers of the code', () => {
  it('the import reader sees static, type-only, re-exported, side-effect and dynamic imports', () => {
    const catalogue = importsOf(join(ROOT, 'widgets/catalogue.ts'));
    expect(catalogue.some((i) => i.dynamic && rel(i.target) === 'widgets/simulator/simulator.ts')).toBe(true);
    expect(catalogue.some((i) => !i.dynamic && rel(i.target) === 'widgets/chapter/models/page-data.ts')).toBe(true);
    expect(importsOf(join(ROOT, 'site/components/Cells.astro')).map((i) => rel(i.target))).toContain('cells/boot.ts');
    expect(importsOf(join(ROOT, 'core/index.ts')).length).toBeGreaterThan(20);
  });

  it('every top-level folder imports only from itself and the folders below it', () => {
    const upward: string[] = [];
    for (const file of code) {
      const top = topOf(file)!;
      for (const { target } of importsOf(file)) {
        const to = topOf(target) ?? rel(target).split('/')[0];
        // Data (the extension's generated catalogue) and packages are no layer.
        if (to === top || to === 'node_modules' || target.endsWith('.json')) continue;
        if (!TOP[top].includes(to)) upward.push(`${rel(file)} → ${rel(target)}`);
      }
    }
    expect(upward).toEqual([]);
  });

  it('inside widgets/, every layer imports only from its own layer or those below it', () => {
    const upward: string[] = [];
    for (const file of code.filter((f) => topOf(f) === 'widgets')) {
      const layer = widgetLayerOf(file);
      expect(layer, `${rel(file)} is in no known layer of widgets/`).toBeGreaterThanOrEqual(0);
      for (const { target } of importsOf(file)) {
        if (topOf(target) === 'widgets' && widgetLayerOf(target) > layer) upward.push(`${rel(file)} → ${rel(target)}`);
      }
    }
    expect(upward).toEqual([]);
  });

  it('outside core/, widgets/ and cells/, static imports of them come through their front doors', () => {
    const around: string[] = [];
    for (const file of code) {
      for (const { target, dynamic } of importsOf(file)) {
        const to = topOf(target);
        if (dynamic || to === undefined || to === topOf(file) || !FRONT_DOORS[to] || /\.css$/.test(target)) continue;
        const edge = `${rel(file)} → ${rel(target)}`;
        // The page's entry is the cells' boot script, loaded by the chapter's page.
        if (rel(target) === FRONT_DOORS[to] || rel(target) === 'cells/boot.ts' || THROUGH_THE_WALL.has(edge)) continue;
        around.push(edge);
      }
    }
    expect(around).toEqual([]);
  });

  it('no module imports itself back through a chain of imports, type-only imports included', () => {
    const graph = new Map(code.map((f) => [f, importsOf(f).map((i) => i.target).filter((t) => /\.(ts|mjs)$/.test(t))]));
    // Depth-first search with three colours; a grey target is a cycle.
    const colour = new Map<string, 'grey' | 'black'>();
    const cycles: string[] = [];
    const visit = (file: string, path: string[]): void => {
      colour.set(file, 'grey');
      for (const next of graph.get(file) ?? []) {
        if (colour.get(next) === 'grey') cycles.push([...path.slice(path.indexOf(next)), next].map(rel).join(' → '));
        else if (!colour.has(next)) visit(next, [...path, next]);
      }
      colour.set(file, 'black');
    };
    for (const file of code) if (!colour.has(file)) visit(file, [file]);
    expect(cycles).toEqual([]);
  });

  it('tests/unit/ mirrors the tree: each folder of tests names a folder of code', () => {
    const unit = join(ROOT, 'tests/unit');
    const folders = (dir: string): string[] =>
      readdirSync(dir).flatMap((name) => {
        const path = join(dir, name);
        return statSync(path).isDirectory() ? [path, ...folders(path)] : [];
      });
    const strays = folders(unit)
      .map((dir) => relative(unit, dir))
      .filter((dir) => dir !== 'support' && !dir.startsWith('support/') && !existsSync(join(ROOT, dir)));
    expect(strays).toEqual([]);
  });
});
