import { describe, expect, test } from 'vitest';
import { assignCellIds, hashSource, PRINTED_CODE_LINES, remarkCells } from '../../../site/lib/remark-cells.mjs';
import { recordedProblems } from '../../../site/lib/cell-failures.ts';

/** Runs the plugin on a hand-made tree of fenced code blocks. */
async function transform(fences) {
  const tree = {
    type: 'root',
    children: fences.map(([meta, value]) => ({ type: 'code', lang: 'js', meta, value })),
  };
  const file = { data: {}, messages: [], message(text) { this.messages.push(text); } };
  await remarkCells()(tree, file);
  return { tree, file };
}

/** The page data the plugin appended, parsed. */
function pageData(tree) {
  const node = tree.children.find((child) => child.type === 'phasebookPageData');
  return node ? JSON.parse(node.data.hProperties.dataPhasebookPageData) : null;
}

/** All text under a hast node. */
function textOf(node) {
  return node.type === 'text' ? node.value : (node.children ?? []).map(textOf).join('');
}

describe('remarkCells()', () => {
  test('turns ```js cell fences into figures carrying id, hash and the build-time parse', async () => {
    const { tree, file } = await transform([['cell', 'omega = 10'], ['cell', 'period = 2 * PI / omega'], [null, 'not a cell']]);
    const [omega, period, plain] = tree.children;
    expect(omega.type).toBe('liveCell');
    expect(omega.data.hName).toBe('figure');
    expect(omega.data.hProperties).toMatchObject({ dataCell: 'omega', dataCellName: 'omega', dataCellHash: hashSource('omega = 10') });
    expect(JSON.parse(period.data.hProperties.dataCellSpec)).toEqual({
      name: 'period', inputs: ['PI', 'omega'], async: false, generator: false, body: [9, 23], block: false, loops: [],
    });
    expect(plain.type).toBe('code');
    expect(file.data.astro.frontmatter.cells).toBe(2);
  });

  test('records which cell reads which, and which draw a widget, for the embed pages', async () => {
    const { file } = await transform([['cell', 'omega = 10'], ['cell', 'sim = simulator({omega})'], ['cell', 'omega * 2'], ['cell', 'broken = (']]);
    expect(file.data.astro.frontmatter.cellGraph).toEqual([
      { id: 'omega', name: 'omega', inputs: [], widget: false },
      { id: 'sim', name: 'sim', inputs: ['simulator', 'omega'], widget: true },
      { id: 'cell-3', name: null, inputs: ['omega'], widget: false },
      { id: 'cell-4', name: null, inputs: [], widget: false },
    ]);
  });

  test('highlights the source with the editor\'s tok-* classes and keeps its text exact', async () => {
    const { tree } = await transform([['cell', '{\n  return "a";\n}\n\n']]);
    const pre = JSON.stringify(tree.children[0].data.hChildren);
    expect(pre).toContain('tok-keyword');
    expect(pre).toContain('tok-string');
    const text = [];
    const walk = (node) => (node.type === 'text' ? text.push(node.value) : node.children?.forEach(walk));
    const code = tree.children[0].data.hChildren[0].children[0].children[0].children[0];
    walk(code);
    expect(text.join('')).toBe('{\n  return "a";\n}');
  });

  test('gives the code its number of shown lines, which keeps its place while it is not laid out', async () => {
    const { tree } = await transform([['cell', 'x = 1'], ['cell', '{\n  return "a";\n}\n\n'], ['cell', 'y = `\n\n`']]);
    const lines = tree.children.map((cell) => {
      const pre = cell.data.hChildren[0].children[0].children[0];
      const shown = [];
      const walk = (node) => (node.type === 'text' ? shown.push(node.value) : node.children?.forEach(walk));
      walk(pre);
      return [pre.properties.style, shown.join('').split('\n').length];
    });
    expect(lines).toEqual([['--lines: 1', 1], ['--lines: 3', 3], ['--lines: 3', 3]]);
  });

  test('renders a cell that does not parse with its error, and reports it to the build', async () => {
    const { tree } = await transform([['cell', 'x = = 1']]);
    expect(tree.children[0].data.hProperties.dataCellBuildError).toBe('SyntaxError: Unexpected token (1:4)');
    expect(tree.children[0].data.hProperties.dataCellSpec).toBeUndefined();
    expect(recordedProblems()).toContain('(chapter):0: cell cell-1: SyntaxError: Unexpected token (1:4)');
  });
});

describe('remarkCells(): which code prints (site/styles/print.css)', () => {
  test('a short named cell, a definition of the lesson, is marked to print its code; a long or unnamed one is not', async () => {
    const long = `driveLine = {\n${'  x;\n'.repeat(PRINTED_CODE_LINES)}}`;
    const { tree } = await transform([['cell', 'H = "p^2/2 + q^2/2"'], ['cell', 'equations(model)'], ['cell', long]]);
    const [short, unnamed, longer] = tree.children.map((node) => node.data.hProperties);
    expect(short.dataPrintCode).toBe('');
    expect(unnamed.dataPrintCode).toBeUndefined();
    expect(longer.dataPrintCode).toBeUndefined();
  });
});

describe('remarkCells() at build time', () => {
  test('compiles the models the cells define and puts the typeset equations into the cell that shows them', async () => {
    const { tree } = await transform([
      ['cell', 'params = ({omega: 3})'],
      ['cell', 'H = "p^2/2 + omega^2*q^2/2"'],
      ['cell', 'model = canonicalEquations({dof: 1, hamiltonian: H, params})'],
      ['cell', 'equations(model)'],
      ['cell', 'sim = simulator({hamiltonian: "p^2/2 - cos(q)", initial: [1, 0], invalidation})'],
    ]);
    const data = pageData(tree);
    expect(data.format).toBe(1);
    const sources = data.models.map((m) => JSON.parse(m.key)[2]);
    expect(sources.sort()).toEqual(['p^2/2 + omega^2*q^2/2', 'p^2/2 - cos(q)']);
    expect(data.models.every((m) => m.route === 'expression' && typeof m.code.stepper === 'string')).toBe(true);
    // The harmonic oscillator's equations, derived at build time: q̇ = p, ṗ = −ω²q.
    const equationsCell = tree.children[3].data;
    const output = equationsCell.hChildren.find((c) => c.properties?.dataCellOutput !== undefined);
    const tex = output.children[0].children[0].properties.dataTexSource;
    expect(tex).toContain('\\dot{q}');
    expect(tex).toContain('\\omega');
    expect(textOf(output)).toContain('Exact symbolic derivatives');
    // A formula already on the page is not carried twice in the data.
    expect(Object.keys(data.typeset)).toEqual([]);
  });

  test('adds no page data when no cell compiles or typesets anything', async () => {
    const { tree } = await transform([['cell', 'x = 1'], ['cell', 'y = x + 1']]);
    expect(pageData(tree)).toBeNull();
  });
});

describe('assignCellIds(cells)', () => {
  test('uses the name, cell-N by position for anonymous cells, and -dupN for repeats', () => {
    expect(assignCellIds([{ name: 'a' }, { name: null }, { name: 'a' }, { name: 'cell' }])).toEqual(['a', 'cell-2', 'a-dup2', 'cell']);
  });
});

describe('highlightJs(source)', () => {
  test('highlights a named block cell as a block, not an object literal', async () => {
    const { highlightJs } = await import('../../../site/lib/highlight-js.mjs');
    const nodes = highlightJs('x = {\n  return 1;\n}');
    const returnNode = nodes.find((node) => node.type === 'element' && node.children[0].value === 'return');
    expect(returnNode.properties.className).toEqual(['tok-keyword']);
    const text = nodes.map((node) => (node.type === 'text' ? node.value : node.children[0].value)).join('');
    expect(text).toBe('x = {\n  return 1;\n}');
  });
});

describe('tokenRuns(source), read back by the page (cells/code-tokens.ts readRuns)', () => {
  const source = 'x = {\n  const s = "a\\u00e9 ∂H/∂p — 𝛼";\n  return s.length + 1; // why\n}';

  test('cut the source into the same tokens, with the same classes, as the spans of the first view', async () => {
    const { highlightJs, tokenRuns } = await import('../../../site/lib/highlight-js.mjs');
    const { readRuns } = await import('../../../cells/code-tokens.ts');
    const spans = highlightJs(source)
      .filter((node) => node.type === 'element')
      .map((node) => ({ text: node.children[0].value, classes: node.properties.className.join(' ') }));
    const pieces = readRuns(tokenRuns(source), source);
    expect(pieces.map((p) => p.text).join('')).toBe(source);
    expect(pieces.filter((p) => p.classes)).toEqual(spans);
    expect(spans.map((s) => s.classes)).toContain('tok-keyword');
    // Lengths are counted in UTF-16 units on both sides: 𝛼 is two of them.
    expect(spans.filter((s) => s.classes === 'tok-string').map((s) => s.text)).toEqual(['"a', ' ∂H/∂p — 𝛼"']);
  });

  test('runs that do not add up to the text leave the code plain', async () => {
    const { tokenRuns } = await import('../../../site/lib/highlight-js.mjs');
    const { readRuns } = await import('../../../cells/code-tokens.ts');
    const runs = tokenRuns(source);
    expect(readRuns(runs, `${source} `)).toBeNull();
    expect(readRuns(runs, source.slice(1))).toBeNull();
    expect(readRuns('3.tok-keyword x', 'abcdef')).toBeNull();
  });
});
