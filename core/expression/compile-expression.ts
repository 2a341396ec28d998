import type { MathNode } from 'mathjs';
import { BuildTracker, throwIfAborted, type BuildControl } from '../model/build-control.ts';
import { InputError } from '../errors.ts';
import { LOGICAL_OPERATORS, SUPPORTED_FUNCTIONS } from './emit.ts';

const ARITHMETIC = new Set(['add', 'subtract', 'multiply', 'divide', 'unaryMinus', 'unaryPlus', 'pow']);
import { evaluatorSource, fusedStepperSource, type RateExpressions } from './fused-stepper.ts';
import { jacobianEntries, jacobianSource } from './jacobian.ts';
import { requireSeparable } from './separable.ts';
import { splitStepperSource } from './split-stepper.ts';
import { CONSTANTS, checkName, stateNames } from './names.ts';
import { latexOf } from './latex.ts';
import { loadMathjs, type MathJs } from './mathjs.ts';
import { Partials } from './partials.ts';
import { Tidy } from './tidy.ts';

export interface ExpressionSpec {
  /** H in mathjs syntax, e.g. `p^2/2 + omega0^2*q^2/2 + alpha*q^3` */
  source: string;
  dof: number;
  paramNames?: readonly string[];
  coordinates?: readonly string[];
  momenta?: readonly string[];
  /**
   * A method that needs code of its own (integrators/methods.ts): the
   * splittings get their fused stepper in place of RK 3/8's, after H is
   * checked to separate; the midpoint rule gets the Jacobian as well.
   */
  method?: 'verlet' | 'yoshida4' | 'midpoint';
}

/** The generated code and LaTeX of an expression H (see CompiledModel). */
export interface CompiledExpression {
  names: string[];
  code: { stepper: string; field: string; hamiltonian: string; jacobian?: string };
  latex: { hamiltonian: string; equations: string[] };
}

/** H parsed, checked and with its names resolved: the first stage of a compile. */
export interface ParsedHamiltonian {
  dof: number;
  /** q's then p's */
  names: string[];
  paramNames: readonly string[];
  hamiltonian: MathNode;
}

/** Hamilton's equations of H: the second stage of a compile. */
export interface HamiltonEquations {
  /** The rate of each state component, as the stepper computes it: ∂H/∂p, or ∂H/∂q to be negated. */
  rates: { node: MathNode; negate: boolean }[];
  /** The right-hand sides as read: ∂H/∂p, and −∂H/∂q with the minus worked in. */
  readable: MathNode[];
}

/**
 * Compiles H given as a math expression: exact symbolic partial derivatives
 * (mathjs `derivative`, term by term) written out as one fused RK 3/8
 * stepper and two evaluators, all as source text for `new Function`.
 *
 * The work is 2·dof derivatives and then the code; `control` can watch it
 * (one unit per derivative, one for the code) and abort it between any two.
 */
export async function compileExpression(spec: ExpressionSpec, control: BuildControl = {}): Promise<CompiledExpression> {
  throwIfAborted(control.signal);
  const math = await loadMathjs();
  const parsed = parseHamiltonian(math, spec);
  const extra = spec.method === 'midpoint' ? parsed.names.length : 0;
  const tracker = new BuildTracker(control, parsed.names.length + 1 + extra);
  const equations = await hamiltonEquations(math, parsed, tracker);
  const compiled = spec.method ? await methodCode(math, parsed, equations, spec.method, tracker) : generateCode(parsed, equations);
  await tracker.step();
  return compiled;
}

/**
 * The code of H for a method other than RK 3/8: a splitting's fused stepper
 * (for an H that separates, else an InputError saying why not), or RK 3/8's
 * code plus the Jacobian of the field for the midpoint rule.
 */
export async function methodCode(
  math: MathJs,
  parsed: ParsedHamiltonian,
  equations: HamiltonEquations,
  method: NonNullable<ExpressionSpec['method']>,
  tracker?: BuildTracker,
): Promise<CompiledExpression> {
  const compiled = generateCode(parsed, equations);
  const { names, paramNames, dof } = parsed;
  const model: RateExpressions = { names, paramNames, rates: equations.rates };
  if (method === 'midpoint') {
    const entries = jacobianEntries(math, model);
    for (let i = 0; i < names.length; i++) await tracker?.step();
    return { ...compiled, code: { ...compiled.code, jacobian: jacobianSource(model, entries) } };
  }
  // ∂H/∂q_i is the rate of p_i, ∂H/∂p_i that of q_i.
  const derivatives = names.map((_, i) => equations.rates[i < dof ? i + dof : i - dof].node);
  requireSeparable(method, names, derivatives);
  return { ...compiled, code: { ...compiled.code, stepper: splitStepperSource(model, method) } };
}

/** Parses H, resolves aliases and rejects what the compiler cannot handle. */
export function parseHamiltonian(math: MathJs, spec: ExpressionSpec): ParsedHamiltonian {
  const { names, aliases } = stateNames(spec.dof, spec.coordinates, spec.momenta);
  const paramNames = spec.paramNames ?? [];
  for (const name of paramNames) {
    checkName(name, 'parameter');
    if (names.includes(name)) throw new InputError(`the parameter ${name} has the name of a state component`);
  }
  const hamiltonian = prepare(math, parseExpression(math, spec.source), names, aliases, paramNames);
  return { dof: spec.dof, names, paramNames, hamiltonian };
}

/**
 * The 2·dof partial derivatives of H, term by term and unsimplified
 * (partials.ts), each tidied in time linear in its size (tidy.ts). For an H
 * that is a sum of terms of a few coordinates each, as a chain's is, the
 * whole costs time about linear in dof; at worst, an H of one term with
 * every coordinate in it, 2·dof derivatives of the whole of H.
 */
export async function hamiltonEquations(math: MathJs, parsed: ParsedHamiltonian, tracker?: BuildTracker): Promise<HamiltonEquations> {
  const { names, dof, hamiltonian } = parsed;
  const state = new Set(names);
  const partials = new Partials(math, hamiltonian, names);
  const tidy = new Tidy(math, (name) => state.has(name));
  const rates: HamiltonEquations['rates'] = [];
  for (let i = 0; i < names.length; i++) {
    const conjugate = i < dof ? names[i + dof] : names[i - dof];
    rates.push({ node: tidy.tidy(partials.of(conjugate)), negate: i >= dof });
    await tracker?.step();
  }
  const readable = rates.map(({ node, negate }) => (negate ? tidy.negated(node) : node));
  return { rates, readable };
}

/** The stepper, the two evaluators and the LaTeX, from H and its equations. */
export function generateCode(parsed: ParsedHamiltonian, equations: HamiltonEquations): CompiledExpression {
  const { names, paramNames, hamiltonian, dof } = parsed;
  const { rates } = equations;
  const model: RateExpressions = { names, paramNames, rates };
  return {
    names,
    code: {
      stepper: fusedStepperSource(model),
      field: evaluatorSource(model, rates, 'vector'),
      hamiltonian: evaluatorSource(model, [{ node: hamiltonian, negate: false }], 'scalar'),
    },
    latex: latexOf(hamiltonian, equations.readable, names, dof),
  };
}

function parseExpression(math: MathJs, source: string): MathNode {
  if (!source.trim()) throw new InputError('H is empty');
  try {
    return math.parse(source);
  } catch (error) {
    const e = error as Error & { char?: number };
    const where = e.char !== undefined ? ` at column ${e.char}` : '';
    const message = e.message.replace(/\s*\(char \d+\)$/, '');
    throw new InputError(`syntax error in H${where}: ${message}`);
  }
}

/**
 * Resolves aliases, rewrites functions mathjs cannot differentiate into ones
 * it can (hypot(a, b) = √(a² + b²)), and rejects unknown names and functions
 * before any derivative is taken, so the user hears about a typo, not about
 * a failed derivative.
 */
function prepare(
  math: MathJs,
  node: MathNode,
  names: readonly string[],
  aliases: ReadonlyMap<string, string>,
  paramNames: readonly string[],
): MathNode {
  const known = new Set([...names, ...paramNames, 't', ...Object.keys(CONSTANTS)]);
  return node.transform((n: MathNode, path: string) => {
    if (path === 'fn') return n;
    if (n.type === 'FunctionNode') {
      const f = n as unknown as { fn: { name: string }; args: MathNode[] };
      const name = f.fn.name;
      if (name === 'hypot') {
        const squares = f.args.map((a) => `(${a.toString()})^2`).join(' + ');
        return prepare(math, math.parse(`sqrt(${squares})`), names, aliases, paramNames);
      }
      if ((name === 'min' || name === 'max') && f.args.length > 2) {
        // min(a, b, c) = min(min(a, b), c): the emitter and the derivative rules take two arguments.
        const nested = f.args.slice(1).reduce((acc, arg) => new math.FunctionNode(new math.SymbolNode(name), [acc, arg]), f.args[0]);
        return prepare(math, nested, names, aliases, paramNames);
      }
      if (!SUPPORTED_FUNCTIONS.has(name)) throw new InputError(`H calls ${name}(), which is not a supported function`);
      const arity = name === 'min' || name === 'max' || name === 'atan2' ? 2 : 1;
      if (f.args.length !== arity) throw new InputError(`H calls ${name}() with ${f.args.length} argument(s); it takes ${arity}`);
      return n;
    }
    if (n.type === 'SymbolNode') {
      const name = (n as unknown as { name: string }).name;
      const alias = aliases.get(name);
      if (alias) return new math.SymbolNode(alias);
      if (!known.has(name)) throw new InputError(`unknown name ${name} in H: give it a value as a parameter`);
    }
    if (n.type === 'OperatorNode') {
      const fn = (n as unknown as { fn: string }).fn;
      if (!ARITHMETIC.has(fn) && !LOGICAL_OPERATORS.has(fn)) throw new InputError(`H may not use the operator ${(n as unknown as { op: string }).op}`);
    }
    const allowed = ['ConstantNode', 'OperatorNode', 'ParenthesisNode', 'SymbolNode', 'ConditionalNode'];
    if (!allowed.includes(n.type)) {
      throw new InputError(`H may use only arithmetic, comparisons, conditionals (c ? a : b), functions, numbers and names, not ${n.toString()}`);
    }
    return n;
  });
}
