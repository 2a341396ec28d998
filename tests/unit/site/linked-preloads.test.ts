import { createHash } from 'node:crypto';
import { existsSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import {
  linkedSimulators,
  preloadScript,
  simulatorChunks,
  simulatorModules,
  withLinkedPreloads,
} from '../../../site/lib/linked-preloads.mjs';
import { VIEW_MODULES } from '../../../widgets/simulator/view-modules.ts';

/** A client bundle as chunkGraph() gives it: an entry, the boot chunk it imports, and the simulator's chunks. */
const GRAPH = [
  { fileName: '_astro/Cells.abc.js', modules: ['/w/cells/entry.ts'], imports: ['_astro/boot.b1.js'], isEntry: true },
  { fileName: '_astro/boot.b1.js', modules: ['/w/cells/boot.ts'], imports: [], isEntry: false },
  { fileName: '_astro/simulator.s1.js', modules: ['/w/simulator/simulator.ts', '/w/simulator/driver.ts'], imports: ['_astro/plots.p1.js', '_astro/core.c1.js', '_astro/boot.b1.js'], isEntry: false },
  { fileName: '_astro/plots.p1.js', modules: ['/w/plots/scale.ts'], imports: ['_astro/boot.b1.js'], isEntry: false },
  { fileName: '_astro/core.c1.js', modules: ['/w/core/record.ts'], imports: [], isEntry: false },
  { fileName: '_astro/time-plot.t1.js', modules: ['/w/plots/time/time-plot.ts'], imports: ['_astro/plots.p1.js'], isEntry: false },
  { fileName: '_astro/plane-views.v1.js', modules: ['/w/plots/plane/trajectory-view.ts', '/w/plots/plane/phase-portrait.ts'], imports: ['_astro/plots.p1.js', '_astro/core.c1.js'], isEntry: false },
  { fileName: '_astro/spectrum.f1.js', modules: ['/w/plots/spectrum/spectrum-view.ts'], imports: ['_astro/plots.p1.js', '_astro/fft.x1.js'], isEntry: false },
  { fileName: '_astro/fft.x1.js', modules: ['/n/fft.js'], imports: [], isEntry: false },
];
const MODULES = {
  simulator: '/w/simulator/simulator.ts',
  views: {
    time: '/w/plots/time/time-plot.ts',
    trajectory: '/w/plots/plane/trajectory-view.ts',
    phase: '/w/plots/plane/phase-portrait.ts',
    spectrum: '/w/plots/spectrum/spectrum-view.ts',
  },
};

const cellHtml = (id: string, inner: string) =>
  `<figure class="cell" id="${id}" data-cell="${id.slice(5)}" data-cell-hash="0"><div class="cell-box">${inner}</div></figure>`;
const reserve = (views: string) => `<div class="pb-simulator pb-reserve" aria-hidden="true" data-reserve="simulator" data-reserve-views="${views}"></div>`;
const PAGE = (body: string, head = '<link rel="stylesheet" href="/_astro/boot.css">') =>
  `<!DOCTYPE html><html><head><meta charset="utf-8"><meta http-equiv="Content-Security-Policy" content="default-src 'self'; script-src 'self' 'unsafe-eval' 'sha256-x='; style-src 'self'">` +
  `<script type="module" src="/_astro/Cells.abc.js"></script>${head}</head><body><article data-chapter="k">${body}</article></body></html>`;

/** Runs the preload script as a browser would at `hash`; returns the hrefs it asked for. */
function preloadsAt(script: string, hash: string): string[] {
  const appended: string[] = [];
  const document = {
    createElement: () => ({ rel: '', href: '' }),
    head: { append: (link: { rel: string; href: string }) => appended.push(`${link.rel} ${link.href}`) },
  };
  new Function('location', 'document', script)({ hash }, document);
  return appended;
}

describe('site/lib/linked-preloads.mjs: a link to a simulator fetches its modules with the boot script', () => {
  it('reads the views from widgets/simulator/view-modules.ts, every one of them, as files that exist', () => {
    const { simulator, views } = simulatorModules();
    expect(Object.keys(views).sort()).toEqual(Object.keys(VIEW_MODULES).sort());
    for (const path of [simulator, ...Object.values(views)]) expect([path, existsSync(path)]).toEqual([path, true]);
  });

  it('gives each view the chunks it imports, transitively, less those the entry loads anyway', () => {
    const chunks = simulatorChunks(GRAPH, MODULES);
    expect(chunks[''].sort()).toEqual(['_astro/core.c1.js', '_astro/plots.p1.js', '_astro/simulator.s1.js']);
    expect(chunks.time.sort()).toEqual(['_astro/plots.p1.js', '_astro/time-plot.t1.js']);
    expect(chunks.phase.sort()).toEqual(['_astro/core.c1.js', '_astro/plane-views.v1.js', '_astro/plots.p1.js']);
    expect(chunks.spectrum.sort()).toEqual(['_astro/fft.x1.js', '_astro/plots.p1.js', '_astro/spectrum.f1.js']);
  });

  it('refuses a bundle without the simulator: the build changed under this step', () => {
    expect(() => simulatorChunks(GRAPH.filter((c) => !c.fileName.includes('simulator')), MODULES)).toThrow(/no chunk of the client bundle holds .*simulator\.ts/);
  });

  it('finds the cells that hold a simulator, with their views, each reserve in its own cell', () => {
    const html = PAGE(
      cellHtml('cell-model', '<pre>model = …</pre>') +
        '<p>text</p>' +
        cellHtml('cell-sim', reserve('time phase')) +
        cellHtml('cell-plain', '<div class="cell-output"></div>') +
        cellHtml('cell-other', reserve('spectrum')),
    );
    expect(linkedSimulators(html)).toEqual([
      { id: 'cell-sim', views: ['time', 'phase'] },
      { id: 'cell-other', views: ['spectrum'] },
    ]);
  });

  it('asks, at a link to a simulator, for exactly its modules, each once; elsewhere for nothing', () => {
    const chunks = simulatorChunks(GRAPH, MODULES);
    const script = preloadScript([{ id: 'cell-sim', views: ['time', 'phase'] }, { id: 'cell-other', views: ['spectrum'] }], chunks, '/book/');
    const sim = preloadsAt(script, '#cell-sim');
    expect(sim.sort()).toEqual(
      ['simulator.s1', 'plots.p1', 'core.c1', 'time-plot.t1', 'plane-views.v1'].map((c) => `modulepreload /book/_astro/${c}.js`).sort(),
    );
    expect(preloadsAt(script, '#cell-other')).toContain('modulepreload /book/_astro/spectrum.f1.js');
    expect(preloadsAt(script, '#cell-other')).not.toContain('modulepreload /book/_astro/time-plot.t1.js');
    for (const elsewhere of ['', '#', '#cell-plain', '#share=abc', '#%E0%A4%A', '#toString', '#__proto__']) expect([elsewhere, preloadsAt(script, elsewhere)]).toEqual([elsewhere, []]);
  });

  it('writes its data so that nothing in it can end the inline script', () => {
    const chunks = simulatorChunks(GRAPH, MODULES);
    const script = preloadScript([{ id: 'cell-</script><b>', views: ['time'] }], chunks, '/');
    expect(script).not.toMatch(/<\//);
    expect(preloadsAt(script, `#${encodeURIComponent('cell-</script><b>')}`).length).toBe(4);
  });

  it('puts the script before the stylesheet (a script after one waits for it) and names its hash in the policy', () => {
    const chunks = simulatorChunks(GRAPH, MODULES);
    const html = PAGE(cellHtml('cell-sim', reserve('time')));
    const out = withLinkedPreloads(html, chunks, '/');
    const script = /<script>([\s\S]*?)<\/script>/.exec(out)![1];
    expect(out.indexOf('<script>')).toBeLessThan(out.indexOf('<link rel="stylesheet"'));
    expect(out.indexOf('<script>')).toBeGreaterThan(out.indexOf('<script type="module"'));
    const hash = `'sha256-${createHash('sha256').update(script, 'utf8').digest('base64')}'`;
    expect(out).toContain(`script-src 'self' ${hash} 'unsafe-eval' 'sha256-x='`);
    expect(preloadsAt(script, '#cell-sim').length).toBe(4); // simulator, plots, core, time-plot
  });

  it('with the stylesheet inlined, puts the script at the end of the head; a page without a simulator is left as it was', () => {
    const chunks = simulatorChunks(GRAPH, MODULES);
    const inlined = PAGE(cellHtml('cell-sim', reserve('time')), '<style>p{}</style>');
    const out = withLinkedPreloads(inlined, chunks, '/');
    expect(out).toMatch(/<script>[\s\S]*?<\/script><\/head>/);
    const plain = PAGE(cellHtml('cell-model', '<pre>x</pre>'));
    expect(withLinkedPreloads(plain, chunks, '/')).toBe(plain);
  });
});
