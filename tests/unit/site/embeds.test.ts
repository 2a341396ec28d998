import { describe, expect, it } from 'vitest';
import { cellsUsedBy, embeddableCells, embedParts, embedPath, type CellNode } from '../../../site/lib/embeds.ts';

const node = (id: string, inputs: string[], widget = false, name: string | null = id): CellNode => ({ id, name, inputs, widget });

// The introduction's shape: parameters → H → model → a simulator, beside cells the simulator never reads.
const graph: CellNode[] = [
  node('omega', []),
  node('period', ['omega', 'PI']),
  node('params', []),
  node('H', []),
  node('model', ['canonicalEquations', 'H', 'params']),
  node('initial', []),
  node('dt', []),
  node('sim', ['simulator', 'model', 'initial', 'dt', 'params', 'PI', 'invalidation'], true),
  node('cell-9', ['theoryCheck', 'sim', 'period'], true, null),
];

describe('site/lib/embeds.ts: what an embed page holds', () => {
  it('offers every cell that draws a widget, named or not', () => {
    expect(embeddableCells(graph).map((cell) => cell.id)).toEqual(['sim', 'cell-9']);
  });

  it('takes the cells a widget reads, through the cells between, in page order, and not the builtins or cells it never reads', () => {
    expect(cellsUsedBy(graph, 'sim')).toEqual(['params', 'H', 'model', 'initial', 'dt']);
    expect(cellsUsedBy(graph, 'cell-9')).toEqual(['omega', 'period', 'params', 'H', 'model', 'initial', 'dt', 'sim']);
  });

  it('ends on a cycle (which the page reports as an error) and on an unknown cell', () => {
    const cyclic = [node('a', ['b']), node('b', ['a'], true)];
    expect(cellsUsedBy(cyclic, 'b')).toEqual(['a']);
    expect(cellsUsedBy(graph, 'nowhere')).toEqual([]);
  });

  it('puts the page under the base path', () => {
    expect(embedPath('/', 'kepler', 'stars')).toBe('/embed/kepler/stars/');
    expect(embedPath('/course', 'kepler', 'stars')).toBe('/course/embed/kepler/stars/');
  });
});

describe('site/lib/embeds.ts: embedParts cuts the embed out of the chapter as built', () => {
  const figure = (id: string, inner: string) => `<figure class="cell" id="cell-${id}" data-cell="${id}" data-cell-spec="{&quot;x&quot;:1}"><div>${inner}</div></figure>`;
  const chapter = [
    '<p>Prose with a <figure><img alt=""></figure> of its own.</p>',
    figure('params', '<pre>params = 1</pre>'),
    '<h2 id="s">Section</h2>',
    figure('sim', '<div data-reserve="simulator"><figure class="legend">nested</figure></div>'),
    figure('sim-2', 'another cell whose id starts the same'),
    figure('other', 'not read'),
    '<template data-phasebook-page-data="{&quot;models&quot;:[]}"></template>',
  ].join('\n');

  it('takes the widget’s cell whole, nested figures included, and the cells it reads, in order, and the page’s data', () => {
    const parts = embedParts(chapter, 'sim', ['params']);
    expect(parts.widget).toBe(figure('sim', '<div data-reserve="simulator"><figure class="legend">nested</figure></div>'));
    expect(parts.uses).toBe(figure('params', '<pre>params = 1</pre>'));
    expect(parts.data).toBe('<template data-phasebook-page-data="{&quot;models&quot;:[]}"></template>');
  });

  it('leaves the prose and every other cell out', () => {
    const parts = embedParts(chapter, 'sim', ['params']);
    const all = parts.widget + parts.uses + parts.data;
    for (const absent of ['Prose', 'Section', 'not read', 'another cell']) expect(all).not.toContain(absent);
  });

  it('refuses a cell the chapter does not have, rather than build an empty page', () => {
    expect(() => embedParts(chapter, 'nowhere', [])).toThrow(/no cell "nowhere"/);
  });
});
