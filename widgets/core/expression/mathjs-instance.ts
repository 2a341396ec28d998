/**
 * mathjs built from only the factories the expression route needs; static
 * named imports let the bundler drop the rest. Imported dynamically by
 * mathjs.ts, never directly.
 */
import {
  create,
  derivativeDependencies,
  OperatorNodeDependencies,
  parseDependencies,
  simplifyDependencies,
  SymbolNodeDependencies,
} from 'mathjs';

export const math = create({
  parseDependencies,
  derivativeDependencies,
  simplifyDependencies,
  SymbolNodeDependencies,
  OperatorNodeDependencies,
});
