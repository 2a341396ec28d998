import type { MathNode } from 'mathjs';
import type { MathJs } from './mathjs.ts';
import { bottomUp } from './tree.ts';

/**
 * Cheap clean-up of the trees mathjs `derivative` returns unsimplified, e.g.
 * `0 + omega^2 * 2 * 1 * q^(2 - 1) / 2 - 0` for ∂(ω²q²/2)/∂q.
 *
 * mathjs's own `simplify` (which `derivative` runs by default) rewrites with
 * a rule set to a fixed point, which measured exponential in the number of
 * terms of H: 2.4 s for one derivative of a 10-term H. This pass visits each
 * node once (twice where a term tidies into a sum or product that is spread
 * into the enclosing one), never searches, and does only what makes the
 * generated code and the LaTeX better:
 * - sums are flattened; zero terms dropped, numbers added up (where the
 *   first of them stood), positive terms written first (so `q2 - q0`, not
 *   `-q0 + q2`);
 * - products and quotients are flattened into one numeric coefficient (a
 *   reduced fraction when it is not a whole number) and factors, a factor
 *   met twice gets one power (√s · (√s)² → (√s)³, as the Kepler force is
 *   read), ×1 dropped, ×0 gives 0, and the factors free of the state come
 *   first, so that a product's part that depends on time alone is one
 *   subtree the fused stepper can compute once per stage time;
 * - x^1 → x, x^0 → 1, whole powers of numbers are folded;
 * - parentheses go: the tree holds the grouping, and the LaTeX puts back
 *   only those needed.
 * A sign is kept out of products and numbers, as an outer unary minus, so
 * that a sum sees it and writes `a - b`.
 *
 * Equal subtrees are recognised by a structural key built bottom-up
 * (hash-consing), so comparing two factors is one integer comparison.
 */
export class Tidy {
  /** Each node met to its tidy form; every node this pass makes maps to itself, so a tidy tree is never reworked. */
  private readonly tidied = new Map<MathNode, MathNode>();
  private readonly keys = new Map<MathNode, number>();
  private readonly interned = new Map<string, number>();
  private readonly stateful = new Map<MathNode, boolean>();

  /**
   * @param isState true for the name of a state component: factors free of
   *   the state are written first
   */
  constructor(
    private readonly math: MathJs,
    private readonly isState: (name: string) => boolean,
  ) {}

  tidy(node: MathNode): MathNode {
    let out = this.tidied.get(node);
    if (out === undefined) {
      out = this.rewrite(node);
      this.tidied.set(node, out);
      this.tidied.set(out, out);
    }
    return out;
  }

  /**
   * −node written for reading: a sum with its signs flipped, a product with
   * a difference in it turned round (−500(q0 − q2)/r³ → 500(q2 − q0)/r³),
   * else a unary minus. Expects a tidy tree.
   */
  negated(node: MathNode): MathNode {
    const value = numberOf(node);
    if (value !== undefined) return this.constant(0 - value);
    if (isSum(node)) return this.sum(node, true);
    const turned = this.turnDifference(node);
    return turned ?? this.make('-', 'unaryMinus', [node]);
  }

  private rewrite(node: MathNode): MathNode {
    if (node.type === 'ParenthesisNode') return this.tidy(contentOf(node));
    if (node.type === 'FunctionNode') return node.map((child: MathNode, path: string) => (path === 'fn' ? child : this.tidy(child)));
    if (node.type === 'ConditionalNode') return node.map((child: MathNode) => this.tidy(child));
    if (node.type !== 'OperatorNode') return node;
    if (isSum(node)) return this.sum(node, false);
    if (isProduct(node)) return this.product(node);
    const { fn, args } = operator(node);
    if (fn === 'pow') return this.power(this.tidy(args[0]), this.tidy(args[1]));
    return node.map((child: MathNode) => this.tidy(child));
  }

  /** Terms of a sum, with their signs, collected through +, −, unary ± and parentheses. */
  private sum(node: MathNode, negative: boolean): MathNode {
    const terms: { node: MathNode; negative: boolean }[] = [];
    let constant = 0;
    // The numbers are added up where the first of them stood: 1 + u·cos(γt) stays so.
    let constantAt = -1;
    // A stack, not recursion: a sum of thousands of terms is a chain thousands deep (tree.ts).
    const stack: [MathNode, boolean][] = [[node, negative]];
    while (stack.length) {
      const [n, minus] = stack.pop()!;
      if (n.type === 'ParenthesisNode') {
        stack.push([contentOf(n), minus]);
        continue;
      }
      if (isSum(n)) {
        // Operands pushed last first, so that terms come off in their order; the second
        // operand of a subtraction, and the one of a unary minus, change sign.
        const { fn, args } = operator(n);
        for (let i = args.length - 1; i >= 0; i--) stack.push([args[i], (fn === 'subtract' && i === 1) || fn === 'unaryMinus' ? !minus : minus]);
        continue;
      }
      const t = this.tidy(n);
      // A term may tidy into a sum ((a + b)·1) or a negated product: spread it.
      if (isSum(t)) {
        stack.push([t, minus]);
        continue;
      }
      const value = numberOf(t);
      if (value === undefined) terms.push({ node: t, negative: minus });
      else {
        constant += minus ? -value : value;
        if (constantAt < 0) constantAt = terms.length;
      }
    }
    if (constant !== 0) terms.splice(constantAt, 0, { node: this.constant(Math.abs(constant)), negative: constant < 0 });
    const ordered = [...terms.filter((t) => !t.negative), ...terms.filter((t) => t.negative)];
    if (ordered.length === 0) return this.constant(0);
    const [first, ...rest] = ordered;
    let out = first.negative ? this.make('-', 'unaryMinus', [first.node]) : first.node;
    for (const t of rest) out = t.negative ? this.make('-', 'subtract', [out, t.node]) : this.make('+', 'add', [out, t.node]);
    return out;
  }

  /** Factors of a product or quotient, collected through ×, ÷, unary ± and parentheses. */
  private product(node: MathNode): MathNode {
    const factors: { base: MathNode; exponent: number }[] = [];
    const byKey = new Map<number, number>();
    let numerator = 1;
    let denominator = 1;
    let negative = false;
    let zero = false;
    // A stack, as for sums: factors come off in their order, each with its side of the fraction bar.
    const stack: [MathNode, 1 | -1][] = [[node, 1]];
    while (stack.length) {
      const [n, side] = stack.pop()!;
      if (n.type === 'ParenthesisNode') {
        stack.push([contentOf(n), side]);
        continue;
      }
      if (n.type === 'OperatorNode') {
        const { fn, args } = operator(n);
        if (isProduct(n)) {
          // The divisor of a quotient goes to the other side of the fraction bar.
          for (let i = args.length - 1; i >= 0; i--) stack.push([args[i], fn === 'divide' && i === 1 ? (-side as 1 | -1) : side]);
          continue;
        }
        if (fn === 'unaryMinus' || fn === 'unaryPlus') {
          if (fn === 'unaryMinus') negative = !negative;
          stack.push([args[0], side]);
          continue;
        }
      }
      const t = this.tidy(n);
      // A factor may tidy into a product, or a product under a minus: spread it.
      if (isProduct(t) || (t.type === 'OperatorNode' && operator(t).fn === 'unaryMinus')) {
        stack.push([t, side]);
        continue;
      }
      const value = numberOf(t);
      if (value !== undefined && (side > 0 || (value !== 0 && Number.isFinite(value)))) {
        if (value < 0) negative = !negative;
        if (side > 0) numerator *= Math.abs(value);
        else denominator *= Math.abs(value);
        if (value === 0) zero = true;
        continue;
      }
      let base = t;
      let exponent: number = side;
      if (t.type === 'OperatorNode' && operator(t).fn === 'pow') {
        const power = signedNumberOf(operator(t).args[1]);
        if (power !== undefined) {
          base = operator(t).args[0];
          exponent = side * power;
        }
      }
      const key = this.key(base);
      const at = byKey.get(key);
      if (at === undefined) {
        byKey.set(key, factors.length);
        factors.push({ base, exponent });
      } else factors[at].exponent += exponent;
    }
    if (zero) return this.constant(0);

    const [top, bottom] = ratio(numerator, denominator);
    // State-free factors first: ω²·(1 + u cos γt)·q groups as (ω²·(1 + u cos γt))·q.
    const ordered = [...factors.filter((f) => !this.mentionsState(f.base)), ...factors.filter((f) => this.mentionsState(f.base))];
    const up = ordered.filter((f) => f.exponent > 0).map((f) => this.power(f.base, this.constant(f.exponent)));
    const down = ordered.filter((f) => f.exponent < 0).map((f) => this.power(f.base, this.constant(-f.exponent)));
    if (top !== 1 || up.length === 0) up.unshift(this.constant(top));
    if (bottom !== 1) down.unshift(this.constant(bottom));
    let out = this.chain(up);
    if (down.length) out = this.make('/', 'divide', [out, this.chain(down)]);
    return negative ? this.make('-', 'unaryMinus', [out]) : out;
  }

  private power(base: MathNode, exponent: MathNode): MathNode {
    const e = signedNumberOf(exponent);
    if (e === 1) return base;
    if (e === 0) return this.constant(1);
    const b = numberOf(base);
    if (b !== undefined && e !== undefined && Number.isInteger(e) && e > 0) {
      const value = b ** e;
      if (Number.isSafeInteger(value)) return this.constant(value);
    }
    return this.make('^', 'pow', [base, exponent]);
  }

  /** The product with its first difference factor turned round (the negation), or undefined if it has none. */
  private turnDifference(node: MathNode): MathNode | undefined {
    if (node.type !== 'OperatorNode') return undefined;
    const { op, fn, args } = operator(node);
    if (fn === 'subtract') return this.sum(node, true);
    if (fn !== 'multiply' && fn !== 'divide') return undefined;
    // Only the numerator of a quotient: (a − b)/c reads better turned than c/(a − b).
    const sides = fn === 'divide' ? [0] : args.map((_, i) => i);
    for (const i of sides) {
      const turned = this.turnDifference(args[i]);
      if (turned) return this.make(op, fn, args.map((a, j) => (j === i ? turned : a)));
    }
    return undefined;
  }

  private chain(factors: readonly MathNode[]): MathNode {
    return factors.reduce((a, b) => this.make('*', 'multiply', [a, b]));
  }

  private make(op: string, fn: string, args: MathNode[]): MathNode {
    const node = new this.math.OperatorNode(op as never, fn as never, args);
    this.tidied.set(node, node);
    return node;
  }

  private constant(value: number): MathNode {
    const node = new this.math.ConstantNode(value);
    this.tidied.set(node, node);
    return node;
  }

  /** An integer naming the structure of a node: equal keys, equal subtrees. */
  private key(node: MathNode): number {
    return bottomUp(node, this.keys, (n, children) => {
      if (n.type === 'ParenthesisNode') return children[0];
      let text: string;
      if (n.type === 'ConstantNode') text = `c${String((n as unknown as { value: unknown }).value)}`;
      else if (n.type === 'SymbolNode') text = `s${(n as unknown as { name: string }).name}`;
      else if (n.type === 'OperatorNode') text = `o${operator(n).fn}(${children.join(',')})`;
      else if (n.type === 'FunctionNode') text = `f${(n as unknown as { fn: { name: string } }).fn.name}(${children.join(',')})`;
      else text = `?${n.toString()}`;
      let key = this.interned.get(text);
      if (key === undefined) this.interned.set(text, (key = this.interned.size));
      return key;
    });
  }

  private mentionsState(node: MathNode): boolean {
    return bottomUp(node, this.stateful, (n, children) =>
      n.type === 'SymbolNode' ? this.isState((n as unknown as { name: string }).name) : children.some(Boolean),
    );
  }
}

interface OperatorLike {
  op: string;
  fn: string;
  args: MathNode[];
}

function operator(node: MathNode): OperatorLike {
  return node as unknown as OperatorLike;
}

function contentOf(node: MathNode): MathNode {
  return (node as unknown as { content: MathNode }).content;
}

/** +, − and unary ±: a unary minus counts as a one-term sum, so that its sign joins the enclosing sum's. */
function isSum(node: MathNode): boolean {
  if (node.type !== 'OperatorNode') return false;
  const { fn, args } = operator(node);
  return fn === 'add' || (fn === 'subtract' && args.length === 2) || fn === 'unaryPlus' || fn === 'unaryMinus';
}

/** × of any number of factors (mathjs may make one node of a·b·c), or a binary ÷. */
function isProduct(node: MathNode): boolean {
  if (node.type !== 'OperatorNode') return false;
  const { fn, args } = operator(node);
  return fn === 'multiply' || (fn === 'divide' && args.length === 2);
}

function numberOf(node: MathNode): number | undefined {
  if (node.type !== 'ConstantNode') return undefined;
  const value = (node as unknown as { value: unknown }).value;
  return typeof value === 'number' ? value : undefined;
}

/** A number, or minus one: a tidy tree writes −2 as a unary minus of 2. */
function signedNumberOf(node: MathNode): number | undefined {
  if (node.type === 'OperatorNode' && operator(node).fn === 'unaryMinus') {
    const value = numberOf(operator(node).args[0]);
    return value === undefined ? undefined : -value;
  }
  return numberOf(node);
}

/** n/d as a whole number, a reduced fraction of whole numbers, or failing both a single number. */
function ratio(n: number, d: number): [number, number] {
  if (d === 1 || Number.isInteger(n / d)) return [n / d, 1];
  if (Number.isSafeInteger(n) && Number.isSafeInteger(d)) {
    const g = gcd(n, d);
    return [n / g, d / g];
  }
  return [n / d, 1];
}

function gcd(a: number, b: number): number {
  while (b) [a, b] = [b, a % b];
  return a;
}
