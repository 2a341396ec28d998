import type { MathNode } from 'mathjs';

/**
 * Walking mathjs trees without recursion. H with thousands of terms parses
 * into a left-leaning chain thousands of nodes deep, and a recursive walk
 * through closures (`forEach`) costs several stack frames per level: enough
 * to overflow the stack at a few thousand terms.
 */

/** The operands of a node: its arguments, a parenthesis's content, a conditional's three parts; a call's own name is not one. */
export function childrenOf(node: MathNode): readonly MathNode[] {
  if (node.type === 'OperatorNode' || node.type === 'FunctionNode') return (node as unknown as { args: MathNode[] }).args;
  if (node.type === 'ParenthesisNode') return [(node as unknown as { content: MathNode }).content];
  if (node.type === 'ConditionalNode') {
    const c = node as unknown as { condition: MathNode; trueExpr: MathNode; falseExpr: MathNode };
    return [c.condition, c.trueExpr, c.falseExpr];
  }
  return [];
}

/**
 * `combine(node, values of its children)` for `root` and every node below
 * it not yet in `memo`, children first, each node once; the results are
 * kept in `memo`, so that a later call over an overlapping tree reuses them.
 */
export function bottomUp<T>(root: MathNode, memo: Map<MathNode, T>, combine: (node: MathNode, children: T[]) => T): T {
  const stack: { node: MathNode; expanded: boolean }[] = [{ node: root, expanded: false }];
  while (stack.length) {
    const top = stack.pop()!;
    if (memo.has(top.node)) continue;
    const children = childrenOf(top.node);
    if (top.expanded) {
      memo.set(top.node, combine(top.node, children.map((c) => memo.get(c)!)));
      continue;
    }
    stack.push({ node: top.node, expanded: true });
    for (const child of children) if (!memo.has(child)) stack.push({ node: child, expanded: false });
  }
  return memo.get(root)!;
}
