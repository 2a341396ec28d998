/**
 * The part of mathjs the expression route uses: parse, derivative and five
 * node constructors. Built with `create` from just those factories,
 * it bundles to about half of the whole library (100 kB gzip rather than
 * 190 kB), and it is loaded only when a model takes this route.
 */
import type { MathJsInstance } from 'mathjs';

export type MathJs = Pick<MathJsInstance, 'parse' | 'derivative' | 'SymbolNode' | 'OperatorNode' | 'ConstantNode' | 'ConditionalNode' | 'FunctionNode'>;

let instance: Promise<MathJs> | undefined;

export function loadMathjs(): Promise<MathJs> {
  return (instance ??= import('./mathjs-instance.ts').then((m) => m.math));
}

/**
 * Hands over an instance imported statically, for hosts where a dynamic
 * import cannot run when it is needed (the build runs the compiler from
 * Astro's config, whose module loader is closed by then).
 */
export function provideMathjs(math: MathJs): void {
  instance = Promise.resolve(math);
}
