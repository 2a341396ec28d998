/**
 * rehype plugin: every section heading of a chapter gets a link to itself,
 * so a reader can copy the address of the place they are reading.
 *
 *   <div class="heading heading-h2">
 *     <h2 id="live-cells">Live cells</h2>
 *     <a class="heading-anchor" href="#live-cells">
 *       <span aria-hidden="true">§</span><span class="visually-hidden">Link to the section “Live cells”</span>
 *     </a>
 *   </div>
 *
 * The link sits beside the heading, not inside it: inside, its words would
 * join the heading's name, and a screen reader listing the headings would
 * read each one twice. The `§` shows on hover and focus (site/styles/
 * navigation.css) and is an ordinary link, so the keyboard always reaches
 * it. Headings need their ids first: Astro gives them after the
 * markdown's rehype plugins, so astro.config.mjs runs its rehypeHeadingIds
 * before this one.
 */

/** The heading levels that mark sections: the title (h1) is the page's, not a section's. */
const SECTION_LEVELS = new Set(['h2', 'h3', 'h4']);

/**
 * The text of a hast node, for the link's name. KaTeX sets a formula three
 * times (its HTML for the eye, MathML for screen readers, the TeX source
 * inside the MathML): the MathML's text alone is kept.
 */
function textOf(node) {
  if (node.type === 'text') return node.value;
  if (node.type !== 'element' && node.type !== 'root') return '';
  const classes = node.properties?.className;
  if (node.tagName === 'annotation' || (Array.isArray(classes) && classes.includes('katex-html'))) return '';
  return (node.children ?? []).map(textOf).join('');
}

/** The anchor link of a heading with this id and text. */
function anchorFor(id, text) {
  return {
    type: 'element',
    tagName: 'a',
    properties: { className: ['heading-anchor'], href: `#${id}` },
    children: [
      { type: 'element', tagName: 'span', properties: { ariaHidden: 'true' }, children: [{ type: 'text', value: '§' }] },
      { type: 'element', tagName: 'span', properties: { className: ['visually-hidden'] }, children: [{ type: 'text', value: `Link to the section “${text}”` }] },
    ],
  };
}

/** Wraps each section heading that has an id, among `parent`'s children, with its anchor link. */
function wrapHeadings(parent) {
  if (!parent.children) return;
  parent.children = parent.children.map((child) => {
    if (child.type !== 'element') return child;
    const id = child.properties?.id;
    if (!SECTION_LEVELS.has(child.tagName) || typeof id !== 'string' || id === '') {
      wrapHeadings(child);
      return child;
    }
    const text = textOf(child).replace(/\s+/g, ' ').trim() || id;
    return { type: 'element', tagName: 'div', properties: { className: ['heading', `heading-${child.tagName}`] }, children: [child, anchorFor(id, text)] };
  });
}

/** @returns {(tree: import('hast').Root) => void} */
export function rehypeHeadingAnchors() {
  return (tree) => wrapHeadings(tree);
}
