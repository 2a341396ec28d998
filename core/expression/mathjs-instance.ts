/**
 * mathjs built from only the factories the expression route needs; static
 * named imports let the bundler drop the rest. Imported dynamically by
 * mathjs.ts, never directly.
 */
import {
  ConditionalNodeDependencies,
  ConstantNodeDependencies,
  create,
  derivativeDependencies,
  FunctionNodeDependencies,
  OperatorNodeDependencies,
  parseDependencies,
  SymbolNodeDependencies,
} from 'mathjs';

// No `simplify`: it measured exponential in the terms of H (tidy.ts does a
// linear clean-up instead). `derivative` still depends on it, for its
// default option, so the bundle is no smaller for leaving it out here.
export const math = create({
  parseDependencies,
  derivativeDependencies,
  SymbolNodeDependencies,
  OperatorNodeDependencies,
  ConstantNodeDependencies,
  // To write the derivatives of min, max and conditionals (partials.ts).
  ConditionalNodeDependencies,
  FunctionNodeDependencies,
});
