/**
 * The Jacobian ∂f/∂x of Hamilton's vector field f = (∂H/∂p, −∂H/∂q), i.e.
 * H's second derivatives, for the Newton iterations of the implicit
 * midpoint rule. Each rate is differentiated term by term with the same
 * machinery as H itself (partials.ts): only the terms of a rate that
 * contain a state component contribute to its column, so the structurally
 * zero entries (most of a chain's) cost nothing and are never written.
 */
import type { MathNode } from 'mathjs';
import { Emitter } from './emit.ts';
import { symbolReader, type RateExpressions } from './fused-stepper.ts';
import type { MathJs } from './mathjs.ts';
import { Partials } from './partials.ts';
import { Tidy } from './tidy.ts';

export interface JacobianEntry {
  row: number;
  column: number;
  node: MathNode;
  negate: boolean;
}

function isZero(node: MathNode): boolean {
  return node.type === 'ConstantNode' && (node as unknown as { value: unknown }).value === 0;
}

/** The non-zero entries of ∂f/∂x, row by row. */
export function jacobianEntries(math: MathJs, model: RateExpressions): JacobianEntry[] {
  const { names, rates } = model;
  const state = new Set(names);
  const tidy = new Tidy(math, (name) => state.has(name));
  const entries: JacobianEntry[] = [];
  rates.forEach(({ node, negate }, row) => {
    const partials = new Partials(math, node, names);
    names.forEach((name, column) => {
      const d = tidy.tidy(partials.of(name));
      if (!isZero(d)) entries.push({ row, column, node: d, negate });
    });
  });
  return entries;
}

/**
 * Source of `return function ($P) { return function ($t, $x, $J) {…} }`
 * writing the non-zero entries of ∂f/∂x at (t, x) into $J (row-major,
 * dim×dim); the caller zeroes $J once.
 */
export function jacobianSource(model: RateExpressions, entries: readonly JacobianEntry[]): string {
  const dim = model.names.length;
  const emitter = new Emitter(symbolReader(model, (i) => `$x[${i}]`), '$j');
  const writes = entries.map(({ row, column, node, negate }) => {
    const code = emitter.emit(node);
    return `$J[${row * dim + column}] = ${negate ? `(-${code})` : code};`;
  });
  const params = model.paramNames.map((name, j) => `const ${name} = $P[${j}];`);
  const body = [...params, 'const $time = $t;', ...emitter.temps, ...writes];
  return `"use strict";\nreturn function ($P) { return function ($t, $x, $J) {\n${body.join('\n')}\n}; };`;
}
