/**
 * What the preview shows for MDX's own syntax, which the book compiles to
 * JavaScript and the preview does not: comments and imports vanish (as on
 * the page), an HTML element such as `<section>` stays with its literal
 * attributes, and a component such as `<Pendulum />` or an expression
 * `{…}` becomes a note saying the built book shows it there.
 */
import type { Nodes, Parent, RootContent } from 'mdast';

const COMMENT = /^\s*\/\*[\s\S]*\*\/\s*$/;

interface MdxAttribute {
  type: string;
  name?: string;
  value?: unknown;
}

interface MdxJsxNode {
  type: 'mdxJsxFlowElement' | 'mdxJsxTextElement';
  name: string | null;
  attributes: MdxAttribute[];
  children: RootContent[];
  data?: Record<string, unknown>;
}

function note(text: string, flow: boolean): RootContent {
  const data = { hName: flow ? 'div' : 'span', hProperties: { className: ['pb-preview-note'] } };
  return { type: 'paragraph', data, children: [{ type: 'text', value: text }] } as RootContent;
}

/** Literal attributes only: `style={{…}}` and the like are JavaScript the preview does not run. */
function literalProperties(attributes: readonly MdxAttribute[]): Record<string, string | boolean> {
  const properties: Record<string, string | boolean> = {};
  for (const attribute of attributes) {
    if (attribute.type !== 'mdxJsxAttribute' || !attribute.name) continue;
    const name = attribute.name === 'class' ? 'className' : attribute.name;
    if (typeof attribute.value === 'string') properties[name] = attribute.value;
    else if (attribute.value === null || attribute.value === undefined) properties[name] = true;
  }
  return properties;
}

/** The node as the preview shows it, or null when it shows nothing. */
function display(node: RootContent): RootContent | null {
  const type = node.type as string;
  if (type === 'mdxjsEsm') return null;
  if (type === 'mdxFlowExpression' || type === 'mdxTextExpression') {
    const value = (node as { value: string }).value;
    return COMMENT.test(value) ? null : note(`{${value.trim()}} (an expression: the built book shows its value here)`, type === 'mdxFlowExpression');
  }
  if (type === 'mdxJsxFlowElement' || type === 'mdxJsxTextElement') {
    const jsx = node as unknown as MdxJsxNode;
    const flow = type === 'mdxJsxFlowElement';
    if (jsx.name && /^[A-Z]|\./.test(jsx.name)) return note(`<${jsx.name} /> (a component: the built book shows it here)`, flow);
    jsx.data = { ...jsx.data, hName: jsx.name ?? (flow ? 'div' : 'span'), hProperties: literalProperties(jsx.attributes) };
  }
  return node;
}

/** Rewrites the MDX nodes of `tree` in place for display (see the module comment). */
export function prepareMdx(tree: Parent): void {
  tree.children = tree.children.flatMap((child) => {
    const shown = display(child);
    if (shown && 'children' in shown) prepareMdx(shown as Nodes & Parent);
    return shown ? [shown] : [];
  }) as typeof tree.children;
}
