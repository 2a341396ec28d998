import { toHtml } from 'hast-util-to-html';
import type { Root } from 'hast';
import { describe, expect, it } from 'vitest';
import { rehypeHeadingAnchors } from '../../../site/lib/rehype-heading-anchors.mjs';

const h = (tagName: string, properties: Record<string, unknown>, ...children: Root['children']) =>
  ({ type: 'element', tagName, properties, children }) as Root['children'][number];
const text = (value: string) => ({ type: 'text', value }) as Root['children'][number];

const anchored = (tree: Root) => {
  rehypeHeadingAnchors()(tree);
  return toHtml(tree);
};

describe('site/lib/rehype-heading-anchors.mjs: a link beside every section heading', () => {
  it('wraps an h2 with an id, with a link to it named after the heading, its § hidden from screen readers', () => {
    const html = anchored({ type: 'root', children: [h('h2', { id: 'live-cells' }, text('Live cells')), h('p', {}, text('Text.'))] });
    expect(html).toBe(
      '<div class="heading heading-h2"><h2 id="live-cells">Live cells</h2>' +
        '<a class="heading-anchor" href="#live-cells"><span aria-hidden="true">§</span>' +
        '<span class="visually-hidden">Link to the section “Live cells”</span></a></div><p>Text.</p>',
    );
  });

  it('leaves the title (h1), headings without an id, and deeper levels than h4 as they are', () => {
    const tree: Root = {
      type: 'root',
      children: [h('h1', { id: 'title' }, text('Title')), h('h2', {}, text('No id')), h('h5', { id: 'deep' }, text('Deep'))],
    };
    expect(anchored(tree)).toBe('<h1 id="title">Title</h1><h2>No id</h2><h5 id="deep">Deep</h5>');
  });

  it('finds headings inside other elements, and names a formula by its MathML text, not KaTeX\'s HTML or TeX', () => {
    const formula = h(
      'span',
      { className: ['katex'] },
      h('span', { className: ['katex-mathml'] }, h('math', {}, h('semantics', {}, h('mi', {}, text('q')), h('annotation', {}, text('q'))))),
      h('span', { className: ['katex-html'], ariaHidden: 'true' }, text('q-soup')),
    );
    const html = anchored({ type: 'root', children: [h('section', {}, h('h3', { id: 'the-q' }, text('The  coordinate '), formula))] });
    expect(html).toContain('<section><div class="heading heading-h3"><h3 id="the-q">');
    expect(html).toContain('Link to the section “The coordinate q”');
  });
});
