import { describe, expect, it } from 'vitest';
import { bookChunks, groupOf } from '../../../src/lib/chunks.mjs';

const at = (path: string) => `/repo/${path}`;

describe('src/lib/chunks.mjs: what loads together', () => {
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
      'widgets/core/window.ts': 'spectrum',
      'widgets/simulator/driver.ts': 'simulator',
      'widgets/controls/transport.ts': 'simulator',
      'widgets/simulator/worker-integrator.ts': 'worker-integrator',
      'widgets/simulator/portable-model.ts': 'worker-integrator',
      'widgets/data/export.ts': 'export',
      'widgets/core/canonical-equations.ts': 'model',
      'widgets/core/integrators/dormand-prince.ts': 'model',
      'widgets/core/expression/names.ts': 'model',
      'widgets/core/expression/compile-expression.ts': 'compiler',
      'widgets/core/js-function/translate.ts': 'compiler',
      'widgets/core/record.ts': 'core',
      'widgets/core/analysis/kepler.ts': 'analysis',
      'widgets/book/chart-scale.ts': 'chart',
      'widgets/book/check-verdict.ts': 'theory-check',
      'widgets/book/typeset.ts': 'tex',
      'widgets/book/section-systems.ts': 'poincare-section',
      'widgets/book/method-comparison-run.ts': 'method-comparison',
      // Rollup places these: mathjs's own chunk, and the front door, which holds no code of its own
      'widgets/core/expression/mathjs-instance.ts': undefined,
      'widgets/core/index.ts': undefined,
      'node_modules/mathjs/lib/esm/entry/pureFunctionsAny.generated.js': undefined,
    };
    for (const [path, group] of Object.entries(expected)) expect([path, groupOf(at(path))]).toEqual([path, group]);
  });

  it('bookChunks names boot what the entry imports, following the core front door only for the names imported through it', () => {
    const modules: Record<string, { isEntry?: boolean; importedIds: string[]; exports?: string[]; code?: string }> = {
      [at('src/entry.ts')]: { isEntry: true, importedIds: [at('widgets/cells/boot.ts')] },
      [at('widgets/cells/boot.ts')]: { importedIds: [at('widgets/core/index.ts'), at('widgets/controls/dom.ts')], code: 'import { SUMMARY } from "../core/index.ts";' },
      [at('widgets/core/index.ts')]: { importedIds: [at('widgets/core/summary.ts'), at('widgets/core/record.ts')] },
      [at('widgets/core/summary.ts')]: { importedIds: [], exports: ['SUMMARY', 'withSummary'] },
      [at('widgets/core/record.ts')]: { importedIds: [], exports: ['Record'] },
      [at('widgets/controls/dom.ts')]: { importedIds: [] },
      [at('node_modules/@codemirror/view/dist/index.js')]: { importedIds: [] },
    };
    const meta = { getModuleIds: () => Object.keys(modules)[Symbol.iterator](), getModuleInfo: (id: string) => modules[id] ?? null };
    const chunkOf = bookChunks();
    expect(chunkOf(at('widgets/cells/boot.ts'), meta)).toBe('boot');
    expect(chunkOf(at('widgets/core/summary.ts'), meta)).toBe('boot');
    // used by the boot code, so boot's, though the plots' group would take it otherwise
    expect(chunkOf(at('widgets/controls/dom.ts'), meta)).toBe('boot');
    // re-exported by the front door but not imported through it by the boot code
    expect(chunkOf(at('widgets/core/record.ts'), meta)).toBe('core');
    expect(chunkOf(at('node_modules/@codemirror/view/dist/index.js'), meta)).toBe('editor');
  });
});
