import type { Node as AcornNode } from 'acorn';
import { SUPPORTED_FUNCTIONS } from '../expression/emit.ts';

/**
 * Translates H written as a JS function — `(t, x) => …`, as in the paper's
 * `canonicalEquation(dof, H)` — into a math expression over the canonical
 * names, so that it gets exact derivatives instead of finite differences.
 *
 * Accepted: parameters `(t, x)` or `(t, [q, p])`; a body that is an
 * expression, or a block of `const`/`let`/`var` declarations (array
 * destructuring of the state, or names bound to expressions) ending in one
 * `return`; numbers, + − * / **, Math's functions and constants (bare or as
 * `Math.…`), `x[i]` with a literal index, and the model's parameters.
 * Anything else returns a reason, and the caller falls back to differences.
 */
export type Translation = { expression: string } | { reason: string };

// acorn's node type lists no fields per node kind; the walk reads each kind's own fields after checking `type`.
type N = AcornNode & Record<string, any>;

class Untranslatable extends Error {}

export function translateFunction(
  program: AcornNode,
  names: readonly string[],
  paramNames: readonly string[],
): Translation {
  try {
    const fn = functionOf(program as N);
    const scope = new Map<string, string>();
    const [time, state] = fn.params as N[];
    if (time) scope.set(bindingName(time), 't');
    let stateName: string | undefined;
    if (state?.type === 'Identifier') stateName = state.name;
    else if (state) bindPattern(state, names, scope);
    const translator = new Translator(scope, stateName, names, new Set(paramNames));
    const body = fn.body as N;
    if (body.type !== 'BlockStatement') return { expression: translator.expr(body) };
    for (const statement of body.body as N[]) {
      if (statement.type === 'VariableDeclaration') {
        for (const d of statement.declarations as N[]) {
          if (!d.init) throw new Untranslatable(`a declaration without a value`);
          if (d.id.type === 'ArrayPattern' && d.init.type === 'Identifier' && d.init.name === stateName) {
            bindPattern(d.id, names, scope);
          } else if (d.id.type === 'Identifier') {
            scope.set(d.id.name, `(${translator.expr(d.init)})`);
          } else throw new Untranslatable(`a destructuring of something other than the state`);
        }
      } else if (statement.type === 'ReturnStatement' && statement.argument) {
        return { expression: translator.expr(statement.argument) };
      } else throw new Untranslatable(`a ${statement.type} statement`);
    }
    throw new Untranslatable('no return statement');
  } catch (error) {
    if (error instanceof Untranslatable) return { reason: error.message };
    throw error;
  }
}

function functionOf(program: N): N {
  const first = program.type === 'Program' ? (program.body as N[])[0] : program;
  const node = first?.type === 'ExpressionStatement' ? first.expression : first;
  if (node?.type === 'ArrowFunctionExpression' || node?.type === 'FunctionExpression' || node?.type === 'FunctionDeclaration') {
    if (node.async || node.generator) throw new Untranslatable('an async or generator function');
    return node;
  }
  throw new Untranslatable('not a function');
}

function bindingName(node: N): string {
  if (node.type !== 'Identifier') throw new Untranslatable('a pattern where the time parameter should be');
  return node.name;
}

function bindPattern(pattern: N, names: readonly string[], scope: Map<string, string>): void {
  if (pattern.type !== 'ArrayPattern') throw new Untranslatable('a state parameter that is neither a name nor an array pattern');
  (pattern.elements as (N | null)[]).forEach((element, i) => {
    if (!element) return;
    if (element.type !== 'Identifier' || i >= names.length) throw new Untranslatable('an unusual state pattern');
    scope.set(element.name, names[i]);
  });
}

const MATH_CONSTANTS: Record<string, string> = { PI: 'pi', E: 'e' };
/** JS Math functions that need a different spelling or a rewrite in mathjs. */
const MATH_REWRITES: Record<string, (args: string[]) => string> = {
  pow: ([a, b]) => `(${a})^(${b})`,
  hypot: (args) => `sqrt(${args.map((a) => `(${a})^2`).join(' + ')})`,
};

class Translator {
  constructor(
    private readonly scope: ReadonlyMap<string, string>,
    private readonly stateName: string | undefined,
    private readonly names: readonly string[],
    private readonly params: ReadonlySet<string>,
  ) {}

  expr(node: N): string {
    switch (node.type) {
      case 'Literal':
        if (typeof node.value !== 'number') throw new Untranslatable('a literal that is not a number');
        return String(node.value);
      case 'Identifier':
        return this.identifier(node.name);
      case 'UnaryExpression':
        if (node.operator === '-') return `(-(${this.expr(node.argument)}))`;
        if (node.operator === '+') return this.expr(node.argument);
        throw new Untranslatable(`the operator ${node.operator}`);
      case 'BinaryExpression': {
        const op = node.operator === '**' ? '^' : node.operator;
        if (!['+', '-', '*', '/', '^'].includes(op)) throw new Untranslatable(`the operator ${node.operator}`);
        return `(${this.expr(node.left)}) ${op} (${this.expr(node.right)})`;
      }
      case 'MemberExpression':
        return this.member(node);
      case 'CallExpression':
        return this.call(node);
      default:
        throw new Untranslatable(`a ${node.type}`);
    }
  }

  private identifier(name: string): string {
    const bound = this.scope.get(name);
    if (bound) return bound;
    if (this.params.has(name)) return name;
    if (Object.hasOwn(MATH_CONSTANTS, name)) return MATH_CONSTANTS[name];
    throw new Untranslatable(`the free name ${name}`);
  }

  private member(node: N): string {
    const object = node.object as N;
    const property = node.property as N;
    if (object.type === 'Identifier' && object.name === this.stateName && node.computed && property.type === 'Literal') {
      const i = property.value;
      if (typeof i === 'number' && Number.isInteger(i) && i >= 0 && i < this.names.length) return this.names[i];
      throw new Untranslatable(`the state index ${String(i)}`);
    }
    if (object.type === 'Identifier' && object.name === 'Math' && !node.computed && Object.hasOwn(MATH_CONSTANTS, property.name)) {
      return MATH_CONSTANTS[property.name];
    }
    throw new Untranslatable('a property access');
  }

  private call(node: N): string {
    const callee = node.callee as N;
    let name: string | undefined;
    if (callee.type === 'Identifier' && !this.scope.has(callee.name) && !this.params.has(callee.name)) name = callee.name;
    else if (callee.type === 'MemberExpression' && !callee.computed && callee.object.type === 'Identifier' && callee.object.name === 'Math') {
      name = callee.property.name;
    }
    if (!name) throw new Untranslatable('a call of something other than a Math function');
    const args = (node.arguments as N[]).map((a) => this.expr(a));
    // Own keys only: a name such as constructor must not find Object's.
    const rewrite = Object.hasOwn(MATH_REWRITES, name) ? MATH_REWRITES[name] : undefined;
    if (rewrite) return rewrite(args);
    if (SUPPORTED_FUNCTIONS.has(name)) return `${name}(${args.join(', ')})`;
    throw new Untranslatable(`the function ${name}`);
  }
}
