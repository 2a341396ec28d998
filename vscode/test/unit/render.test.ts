import { describe, expect, test } from 'vitest';
import { ChapterRenderer } from '../../src/preview/render.ts';
import { readBook } from './support.ts';

describe('ChapterRenderer.render(text)', () => {
  test('the template: its title, typeset math, cells as the build marks them up, comments gone', () => {
    const text = readBook('templates/chapter.mdx');
    const { blocks, cells } = new ChapterRenderer().render(text);
    // The title's block is the front matter: from line 0 to the line after its closing ---.
    expect(blocks[0]).toEqual({ html: '<h1>The pendulum</h1>', line: 0, endLine: text.split('\n').indexOf('---', 1) + 1 });
    const html = blocks.map((b) => b.html).join('\n');
    expect(html).toContain('class="katex-display"');
    expect(html).toMatch(/<figure class="cell" id="cell-pendulumSimulator" data-cell="pendulumSimulator"[^>]* data-cell-spec="/);
    expect(html).not.toContain('This is an MDX comment');
    expect([...cells.keys()]).toEqual(['pendulum', 'pendulumH', 'pendulumStart', 'pendulumModel', 'pendulumEquations', 'pendulumSimulator', 'periodCheck', 'myPendulum']);
    // Each cell's lines are its fences' (from 0).
    const lines = text.split('\n');
    const { line, endLine } = cells.get('pendulum')!;
    expect([lines[line], lines[line + 1], lines[endLine]]).toEqual(['```js cell', 'pendulum = ({omega0: 2})', '```']);
  });

  test('blocks carry their source lines, in order', () => {
    const text = '---\ntitle: T\ndescription: d\norder: 1\n---\n\nFirst paragraph\nstill first.\n\n## A heading\n\n```js cell\nx = 1\n```\n';
    const { blocks } = new ChapterRenderer().render(text);
    expect(blocks.map((b) => [b.line, b.endLine])).toEqual([[0, 5], [6, 7], [9, 9], [11, 13]]);
    expect(blocks[1].html).toBe('<p>First paragraph\nstill first.</p>');
  });

  test('an unchanged block renders to the same HTML, so the page can keep it', () => {
    const renderer = new ChapterRenderer();
    const before = renderer.render('Some $x^2$ math.\n\n```js cell\nx = 1\n```\n');
    const after = renderer.render('Some $x^2$ math, edited.\n\n```js cell\nx = 1\n```\n');
    expect(after.blocks[1].html).toBe(before.blocks[1].html);
    expect(after.blocks[0].html).not.toBe(before.blocks[0].html);
  });

  test('MDX: HTML elements stay with literal attributes, components and expressions become notes', () => {
    const text = "import Pendulum from '../templates/chapter.mdx';\n\n<section aria-label=\"The template\" style={{color: 'red'}}>\n  <Pendulum />\n</section>\n\nValue: {1 + 1}.\n";
    const html = new ChapterRenderer().render(text).blocks.map((b) => b.html).join('\n');
    expect(html).not.toContain('import');
    expect(html).toContain('<section aria-label="The template">');
    expect(html).toContain('&#x3C;Pendulum /> (a component: the built book shows it here)');
    expect(html).toContain('{1 + 1} (an expression: the built book shows its value here)');
  });

  test("an MDX error shows where the book's build fails, and the rest still renders", () => {
    const { blocks } = new ChapterRenderer().render('---\ntitle: T\n---\n\nA {broken + } brace.\n\n```js cell\nx = 1\n```\n');
    expect(blocks[1].html).toMatch(/^<p class="pb-preview-error">The book’s build fails on line 5: MDX: /);
    expect(blocks.at(-1)!.html).toContain('data-cell="x"');
  });

  test('bad input never throws', () => {
    const renderer = new ChapterRenderer();
    for (const text of ['', '---', '$$\n\\frac{\n$$\n', '```js cell\n(((\n```\n', '<div>\n', '{']) expect(() => renderer.render(text)).not.toThrow();
  });
});
