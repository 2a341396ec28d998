/**
 * The shape of widgets/: layers that point one way, one front door to the
 * core, and no import cycles (type-only imports included), read from the
 * source's import statements.
 */
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

const ROOT = resolve(__dirname, '../..');
const WIDGETS = join(ROOT, 'widgets');
const CORE = join(WIDGETS, 'core');
const CORE_INDEX = join(CORE, 'index.ts');

/**
 * What each folder of widgets/ may import, lowest first: core → controls →
 * plots → data → simulator → book → the catalogue (library.ts) → cells, the
 * page's boot. The CLI stands on the core alone.
 */
const LAYERS = ['core', 'controls', 'plots', 'data', 'simulator', 'book', 'library', 'cells'];
const ALLOWED: Record<string, readonly string[]> = {
  ...Object.fromEntries(LAYERS.map((layer, i) => [layer, LAYERS.slice(0, i + 1)])),
  cli: ['core', 'cli'],
};

function sources(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return sources(path);
    return path.endsWith('.ts') ? [path] : [];
  });
}

interface Import {
  target: string;
  dynamic: boolean;
}

/** Relative imports of a file: static and type-only, re-exports, and dynamic `import()`. */
function importsOf(file: string): Import[] {
  const text = readFileSync(file, 'utf8');
  const found: Import[] = [];
  for (const m of text.matchAll(/^(?:import|export)\b[^;]*?\bfrom\s+'(\.[^']+)'/gms)) found.push({ target: resolve(dirname(file), m[1]), dynamic: false });
  for (const m of text.matchAll(/\bimport\(\s*'(\.[^']+)'\s*\)/g)) found.push({ target: resolve(dirname(file), m[1]), dynamic: true });
  return found;
}

function layerOf(file: string): string {
  const path = relative(WIDGETS, file);
  return path === 'library.ts' ? 'library' : path.split('/')[0];
}

const files = sources(WIDGETS);

describe('widgets/ layers', () => {
  it('the import reader sees static, type-only, re-exported and dynamic imports', () => {
    const library = importsOf(join(WIDGETS, 'library.ts')).map((i) => relative(WIDGETS, i.target));
    expect(library).toContain('book/page-data.ts');
    expect(library).toContain('simulator/simulator.ts');
    expect(importsOf(CORE_INDEX).length).toBeGreaterThan(20);
  });

  it('every folder imports only from its own layer or those below it', () => {
    const upward: string[] = [];
    for (const file of files) {
      const allowed = ALLOWED[layerOf(file)];
      expect(allowed, `${relative(WIDGETS, file)} is in no known layer`).toBeDefined();
      for (const { target } of importsOf(file)) {
        if (!target.startsWith(WIDGETS)) continue;
        if (!allowed.includes(layerOf(target))) upward.push(`${relative(WIDGETS, file)} → ${relative(WIDGETS, target)}`);
      }
    }
    expect(upward).toEqual([]);
  });

  it('outside the core, static imports of the core come through core/index.ts', () => {
    const extension = join(ROOT, 'vscode/src');
    const clients = [...files.filter((f) => !f.startsWith(CORE + '/')), ...sources(extension)];
    const around: string[] = [];
    for (const file of clients) {
      for (const { target, dynamic } of importsOf(file)) {
        if (!dynamic && target.startsWith(CORE + '/') && target !== CORE_INDEX) around.push(`${relative(ROOT, file)} → ${relative(ROOT, target)}`);
      }
    }
    expect(around).toEqual([]);
  });

  it('no module imports itself back through a chain of imports, type-only imports included', () => {
    const graph = new Map(files.map((f) => [f, importsOf(f).map((i) => i.target).filter((t) => t.endsWith('.ts'))]));
    // Depth-first search with three colours; a grey target is a cycle.
    const colour = new Map<string, 'grey' | 'black'>();
    const cycles: string[] = [];
    const visit = (file: string, path: string[]): void => {
      colour.set(file, 'grey');
      for (const next of graph.get(file) ?? []) {
        if (colour.get(next) === 'grey') cycles.push([...path.slice(path.indexOf(next)), next].map((f) => relative(WIDGETS, f)).join(' → '));
        else if (!colour.has(next)) visit(next, [...path, next]);
      }
      colour.set(file, 'black');
    };
    for (const file of files) if (!colour.has(file)) visit(file, [file]);
    expect(cycles).toEqual([]);
  });
});
