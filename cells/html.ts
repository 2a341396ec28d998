/**
 * `html` for cells: a tagged template that returns a DOM node.
 *
 * Interpolated DOM nodes are inserted as nodes (so a cell can place a widget
 * inside markup), arrays are inserted item by item, null/undefined/false
 * vanish, and everything else is inserted as escaped text — `${"a < b"}` shows
 * "a < b" rather than breaking the markup.
 */

const SLOT = 'phasebook-slot:';

function escapeText(value: string): string {
  return value.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

function flatten(value: unknown, nodes: Node[]): string {
  if (value === null || value === undefined || value === false) return '';
  if (Array.isArray(value)) return value.map((item) => flatten(item, nodes)).join('');
  if (value instanceof Node) {
    nodes.push(value);
    return `<!--${SLOT}${nodes.length - 1}-->`;
  }
  return escapeText(String(value));
}

function fillSlots(root: DocumentFragment, nodes: readonly Node[]): void {
  const walker = document.createTreeWalker(root, NodeFilter.SHOW_COMMENT);
  const slots: Comment[] = [];
  while (walker.nextNode()) {
    const comment = walker.currentNode as Comment;
    if (comment.data.startsWith(SLOT)) slots.push(comment);
  }
  for (const slot of slots) {
    const node = nodes[Number(slot.data.slice(SLOT.length))];
    if (node) slot.replaceWith(node);
  }
}

/** Returns the single element the markup makes, or a `<span>` holding several nodes. */
export function html(strings: TemplateStringsArray, ...values: unknown[]): Node {
  const nodes: Node[] = [];
  let markup = strings[0] ?? '';
  values.forEach((value, i) => {
    markup += flatten(value, nodes) + (strings[i + 1] ?? '');
  });
  const template = document.createElement('template');
  template.innerHTML = markup.trim();
  const fragment = template.content;
  fillSlots(fragment, nodes);
  if (fragment.childNodes.length === 1) return fragment.firstChild as Node;
  const wrapper = document.createElement('span');
  wrapper.append(fragment);
  return wrapper;
}
