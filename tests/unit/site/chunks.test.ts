import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { bookChunks, groupOf } from '../../../site/lib/chunks.mjs';

/** A module id as Rollup gives it: the absolute path of a file in this project. */
const at = (path: string) => fileURLToPath(new URL(`../../../${path}`, import.meta.url));

describe('site/lib/chunks.mjs: what loads together', () => {
  it('groupOf puts each part of the book with what loads it', () => {
    const expected: Record<string, string | undefined> = {
      'node_modules/d3-scale/dist/d3-scale.mjs': 'plots',
      'widgets/plots/scale.ts': 'plots',
      'widgets/controls/format.ts': 'plots',
      'widgets/plots/point-panel.ts': 'point-panel',
      'widgets/plots/time/time-plot.ts': 'time-plot',
      'widgets/plots/plane/phase-portrait.ts': 'plane-views',
      'widgets/plots/spectrum/spectrum-view.ts': 'spectrum',
      'node_modules/fft.js/lib/fft.js': 'spectrum',
      'core/spectrum/window.ts': 'spectrum',
      'widgets/simulator/driver.ts': 'simulator',
      'widgets/controls/transport.ts': 'simulator',
      'widgets/simulator/worker-integrator.ts': 'worker-integrator',
      'widgets/simulator/portable-model.ts': 'worker-integrator',
      'widgets/exports/export.ts': 'export',
      'core/model/canonical-equations.ts': 'model',
      'core/integrators/rk38.ts': 'model',
      'core/model/compiled-parts.ts': 'model',
      // only a model run by another method than RK 3/8 loads them (canonical-equations.ts)
      'core/integrators/dormand-prince.ts': 'methods',
      'core/integrators/apply.ts': 'methods',
      'core/integrators/midpoint.ts': 'methods',
      'core/model/model-from-compiled.ts': 'methods',
      'core/expression/names.ts': 'model',
      'core/expression/compile-expression.ts': 'compiler',
      'core/js-function/translate.ts': 'compiler',
      'core/record.ts': 'core',
      'core/analysis/kepler.ts': 'analysis',
      'widgets/chapter/chart/chart-scale.ts': 'chart',
      'widgets/chapter/theory-check/check-verdict.ts': 'theory-check',
      'widgets/chapter/math/typeset.ts': 'tex',
      'widgets/chapter/poincare-section/section-systems.ts': 'poincare-section',
      'core/maps/standard-map.ts': 'standard-map',
      'core/analysis/standard-map.ts': 'standard-map',
      'widgets/chapter/standard-map/standard-map.ts': 'standard-map',
      'core/dataset/philox.ts': 'random',
      'core/analysis/action.ts': 'action-angle',
      'core/analysis/flow-map.ts': 'action-angle',
      'core/analysis/pendulum.ts': 'pendulum',
      'widgets/chapter/method-comparison/method-comparison-run.ts': 'method-comparison',
      'widgets/chapter/exercise/exercise.ts': 'exercise',
      'widgets/chapter/exercise/truths/three-body.ts': 'exercise',
      // Rollup places these: mathjs's own chunk, and the front door, which holds no code of its own
      'core/expression/mathjs-instance.ts': undefined,
      'core/index.ts': undefined,
      'node_modules/mathjs/lib/esm/entry/pureFunctionsAny.generated.js': undefined,
    };
    for (const [path, group] of Object.entries(expected)) expect([path, groupOf(at(path))]).toEqual([path, group]);
  });

  it('bookChunks names boot what the entry imports, following the core front door only for the names imported through it', () => {
    const modules: Record<string, { isEntry?: boolean; importedIds: string[]; exports?: string[]; code?: string }> = {
      [at('site/entry.ts')]: { isEntry: true, importedIds: [at('cells/boot.ts')] },
      [at('cells/boot.ts')]: { importedIds: [at('core/index.ts'), at('widgets/controls/dom.ts')], code: 'import { SUMMARY } from "../core/index.ts";' },
      [at('core/index.ts')]: { importedIds: [at('core/summary.ts'), at('core/record.ts')] },
      [at('core/summary.ts')]: { importedIds: [], exports: ['SUMMARY', 'withSummary'] },
      [at('core/record.ts')]: { importedIds: [], exports: ['Record'] },
      [at('widgets/controls/dom.ts')]: { importedIds: [] },
      [at('node_modules/@codemirror/view/dist/index.js')]: { importedIds: [] },
      // The search box's module is an entry of its own (site/lib/search-index.mjs), which the pages import only when asked.
      [at('site/search/search-ui.ts')]: { isEntry: true, importedIds: [at('site/search/excerpt.ts')] },
      [at('site/search/excerpt.ts')]: { importedIds: [] },
    };
    const meta = { getModuleIds: () => Object.keys(modules)[Symbol.iterator](), getModuleInfo: (id: string) => modules[id] ?? null };
    const chunkOf = bookChunks();
    expect(chunkOf(at('cells/boot.ts'), meta)).toBe('boot');
    expect(chunkOf(at('core/summary.ts'), meta)).toBe('boot');
    // used by the boot code, so boot's, though the plots' group would take it otherwise
    expect(chunkOf(at('widgets/controls/dom.ts'), meta)).toBe('boot');
    // re-exported by the front door but not imported through it by the boot code
    expect(chunkOf(at('core/record.ts'), meta)).toBe('core');
    expect(chunkOf(at('node_modules/@codemirror/view/dist/index.js'), meta)).toBe('editor');
    // an entry, but not one a page loads: search's code stays out of the boot chunk
    expect(chunkOf(at('site/search/search-ui.ts'), meta)).toBe('search');
    expect(chunkOf(at('site/search/excerpt.ts'), meta)).toBe('search');
  });
});
