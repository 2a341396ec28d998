import type { MathNode } from 'mathjs';

/**
 * Turns mathjs expression trees into JavaScript source for generated steppers.
 *
 * Every operation and call becomes a `const` temporary, deduplicated by its
 * code across all the expressions emitted through one `Emitter`: the partial
 * derivatives of one stage are evaluated at the same state, so r³ computed
 * for ∂H/∂q0 is reused by ∂H/∂q1 (common subexpressions are eliminated
 * textually, before V8 sees the code). Integer powers are written as
 * products because `Math.pow` measured 2.6× slower on Kepler.
 */
export class Emitter {
  /** `const` declarations, in dependency order. */
  readonly temps: string[] = [];
  private readonly byCode = new Map<string, string>();
  /**
   * Code of each node already emitted. A derivative tree may share a subtree
   * between places (mathjs reuses nodes), and would otherwise be walked once
   * per place; the code is the same each time, so it is looked up instead.
   */
  private readonly byNode = new Map<MathNode, string>();

  /**
   * @param symbol maps a symbol name to the JS expression that reads it
   * @param hoisted names a subexpression computed elsewhere (the fused
   *   stepper's terms that depend on time alone), or undefined to emit it here
   */
  constructor(
    private readonly symbol: (name: string) => string,
    private readonly prefix = '$v',
    private readonly hoisted: (node: MathNode) => string | undefined = () => undefined,
  ) {}

  emit(node: MathNode): string {
    let code = this.byNode.get(node);
    if (code === undefined) this.byNode.set(node, (code = this.code(node)));
    return code;
  }

  private code(node: MathNode): string {
    const name = this.hoisted(node);
    if (name !== undefined) return name;
    switch (node.type) {
      case 'ConstantNode':
        return literal((node as unknown as { value: unknown }).value);
      case 'SymbolNode':
        return this.symbol((node as unknown as { name: string }).name);
      case 'ParenthesisNode':
        return this.emit((node as unknown as { content: MathNode }).content);
      case 'OperatorNode':
        return this.operator(node as unknown as OperatorLike);
      case 'FunctionNode':
        return this.call(node as unknown as FunctionLike);
      case 'ConditionalNode': {
        // Both branches are computed (they are plain numbers), and the condition picks one.
        const c = node as unknown as { condition: MathNode; trueExpr: MathNode; falseExpr: MathNode };
        return this.temp(`${this.emit(c.condition)} ? ${this.emit(c.trueExpr)} : ${this.emit(c.falseExpr)}`);
      }
      default:
        throw new Error(`${node.type.replace(/Node$/, '').toLowerCase()} expressions are not supported in H`);
    }
  }

  private temp(code: string): string {
    const known = this.byCode.get(code);
    if (known) return known;
    const name = `${this.prefix}${this.temps.length}`;
    this.temps.push(`const ${name} = ${code};`);
    this.byCode.set(code, name);
    return name;
  }

  private operator(node: OperatorLike): string {
    const [a, b] = node.args;
    switch (node.fn) {
      case 'add':
        return this.temp(`${this.emit(a)} + ${this.emit(b)}`);
      case 'subtract':
        return this.temp(`${this.emit(a)} - ${this.emit(b)}`);
      case 'multiply':
        return this.temp(`${this.emit(a)} * ${this.emit(b)}`);
      case 'divide':
        return this.quotient(a, b);
      case 'unaryMinus':
        return `(-${this.emit(a)})`;
      case 'unaryPlus':
        return this.emit(a);
      case 'pow':
        return this.power(a, b);
      case 'not':
        return this.temp(`!${this.emit(a)}`);
      default: {
        const js = COMPARISONS[node.fn];
        if (js) return this.temp(`${this.emit(a)} ${js} ${this.emit(b)}`);
        throw new Error(`the operator ${node.op} is not supported in H`);
      }
    }
  }

  /**
   * A non-constant divisor becomes a shared reciprocal: the four Kepler
   * forces divide by one r³, and one division plus four products is much
   * cheaper than four divisions (at most one rounding more).
   */
  private quotient(a: MathNode, b: MathNode): string {
    const numerator = this.emit(a);
    if (constantValue(b) !== undefined) return this.temp(`${numerator} / ${this.emit(b)}`);
    const reciprocal = this.temp(`1 / ${this.emit(b)}`);
    return this.temp(`${numerator} * ${reciprocal}`);
  }

  private power(base: MathNode, exponent: MathNode): string {
    const n = constantValue(exponent);
    if (n === undefined) return this.temp(`Math.pow(${this.emit(base)}, ${this.emit(exponent)})`);
    if (n === 0) return '1';
    if (n === 1) return this.emit(base);
    if (n === 0.5) return this.temp(`Math.sqrt(${this.emit(base)})`);
    if (n === -0.5) return this.temp(`1 / Math.sqrt(${this.emit(base)})`);
    const b = this.atom(this.emit(base));
    const m = Math.abs(n);
    if (Number.isInteger(m) && m <= 8) {
      const product = this.temp(Array(m).fill(b).join(' * '));
      return n > 0 ? product : this.temp(`1 / ${product}`);
    }
    if (Number.isInteger(2 * m) && m <= 8) {
      // x^(k/2) = x^⌊k/2⌋·√x: one square root instead of a pow.
      const whole = Math.floor(m);
      const root = this.temp(`Math.sqrt(${b})`);
      const product = this.temp([...Array(whole).fill(b), root].join(' * '));
      return n > 0 ? product : this.temp(`1 / ${product}`);
    }
    return this.temp(`Math.pow(${b}, ${literal(n)})`);
  }

  /** A base that is not a plain name or number is hoisted so it is computed once. */
  private atom(code: string): string {
    return /^[$\w.]+$/.test(code) ? code : this.temp(code);
  }

  private call(node: FunctionLike): string {
    const name = node.fn.name;
    const args = node.args.map((a) => this.emit(a));
    const template = FUNCTIONS[name];
    if (!template || template.length !== args.length) {
      throw new Error(`the function ${name}(${args.map(() => '·').join(', ')}) is not supported in H`);
    }
    return this.temp(template.code(...args));
  }
}

/** Comparisons and logic, as conditionals and min/max derivatives use them: JS booleans, numbers where mathjs's are. */
const COMPARISONS: Record<string, string> = {
  larger: '>',
  smaller: '<',
  largerEq: '>=',
  smallerEq: '<=',
  equal: '===',
  unequal: '!==',
  and: '&&',
  or: '||',
};

/** Operators of comparison and logic, whose value is piecewise constant: derivative 0. */
export const LOGICAL_OPERATORS: ReadonlySet<string> = new Set([...Object.keys(COMPARISONS), 'not']);

interface OperatorLike {
  op: string;
  fn: string;
  args: MathNode[];
}
interface FunctionLike {
  fn: { name: string };
  args: MathNode[];
}

function constantValue(node: MathNode): number | undefined {
  if (node.type === 'ParenthesisNode') return constantValue((node as unknown as { content: MathNode }).content);
  if (node.type === 'ConstantNode') {
    const v = (node as unknown as { value: unknown }).value;
    return typeof v === 'number' ? v : undefined;
  }
  if (node.type === 'OperatorNode') {
    const op = node as unknown as OperatorLike;
    if (op.fn === 'unaryMinus') {
      const v = constantValue(op.args[0]);
      return v === undefined ? undefined : -v;
    }
    if (op.fn === 'divide') {
      const a = constantValue(op.args[0]);
      const b = constantValue(op.args[1]);
      return a === undefined || b === undefined ? undefined : a / b;
    }
  }
  return undefined;
}

function literal(value: unknown): string {
  if (typeof value !== 'number') throw new Error(`the constant ${String(value)} is not a number`);
  if (Number.isNaN(value)) return 'NaN';
  if (!Number.isFinite(value)) return value > 0 ? 'Infinity' : '(-Infinity)';
  return value < 0 || Object.is(value, -0) ? `(${String(value)})` : String(value);
}

interface Template {
  length: number;
  code: (...args: string[]) => string;
}
const binary = (fn: string): Template => ({ length: 2, code: (a, b) => `Math.${fn}(${a}, ${b})` });
const unary = (f: (a: string) => string): Template => ({ length: 1, code: (a) => f(a) });
const math = (fn: string) => unary((a) => `Math.${fn}(${a})`);

/** The functions an expression H may use: those mathjs can differentiate, and min, max, atan2 (see partials.ts). */
const FUNCTIONS: Record<string, Template> = {
  sqrt: math('sqrt'),
  cbrt: math('cbrt'),
  exp: math('exp'),
  expm1: math('expm1'),
  log: math('log'),
  log1p: math('log1p'),
  log10: math('log10'),
  log2: math('log2'),
  abs: math('abs'),
  sign: math('sign'),
  sin: math('sin'),
  cos: math('cos'),
  tan: math('tan'),
  asin: math('asin'),
  acos: math('acos'),
  atan: math('atan'),
  sinh: math('sinh'),
  cosh: math('cosh'),
  tanh: math('tanh'),
  asinh: math('asinh'),
  acosh: math('acosh'),
  atanh: math('atanh'),
  sec: unary((a) => `(1 / Math.cos(${a}))`),
  csc: unary((a) => `(1 / Math.sin(${a}))`),
  cot: unary((a) => `(1 / Math.tan(${a}))`),
  sech: unary((a) => `(1 / Math.cosh(${a}))`),
  csch: unary((a) => `(1 / Math.sinh(${a}))`),
  coth: unary((a) => `(1 / Math.tanh(${a}))`),
  // Differentiated by partials.ts's own rules, not by mathjs.
  min: binary('min'),
  max: binary('max'),
  atan2: binary('atan2'),
};

/** Names of functions H may call, for validation and for translating JS. */
export const SUPPORTED_FUNCTIONS: ReadonlySet<string> = new Set(Object.keys(FUNCTIONS));
