/**
 * The value of a --param given as arithmetic: `2*pi`, `sqrt(2)/2`,
 * `9.81*l` with l an earlier parameter. Numbers, + − * / ^ (or **),
 * parentheses, the constants pi, e and tau, and the functions of Math with
 * one argument (sqrt, exp, sin …) or two (atan2, hypot, min, max, pow).
 * A few dozen lines of recursive descent, so that reading a parameter never
 * loads mathjs.
 */
import { InputError } from '../../core/index.ts';

const CONSTANTS: Record<string, number> = { pi: Math.PI, PI: Math.PI, e: Math.E, E: Math.E, tau: 2 * Math.PI };
const FUNCTIONS: Record<string, (...args: number[]) => number> = {
  sqrt: Math.sqrt, cbrt: Math.cbrt, exp: Math.exp, log: Math.log, log10: Math.log10, log2: Math.log2, abs: Math.abs,
  sin: Math.sin, cos: Math.cos, tan: Math.tan, asin: Math.asin, acos: Math.acos, atan: Math.atan,
  sinh: Math.sinh, cosh: Math.cosh, tanh: Math.tanh, atan2: Math.atan2, hypot: Math.hypot, min: Math.min, max: Math.max, pow: Math.pow,
};

const TOKEN = /\s*(?:(\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)|([A-Za-z_][A-Za-z0-9_]*)|(\*\*|[-+*/^(),]))/y;

/** Evaluates `text`, where `known` gives the names already defined; `what` names it in messages. */
export function evaluateParameter(text: string, known: Readonly<Record<string, number>>, what: string): number {
  const tokens: string[] = [];
  TOKEN.lastIndex = 0;
  let at = 0;
  while (at < text.length) {
    if (/^\s*$/.test(text.slice(at))) break;
    TOKEN.lastIndex = at;
    const m = TOKEN.exec(text);
    if (!m) throw new InputError(`${what}: cannot read "${text.slice(at).trim()}" in "${text}"`);
    tokens.push(m[1] ?? m[2] ?? m[3]);
    at = TOKEN.lastIndex;
  }
  let i = 0;
  const peek = () => tokens[i];
  const expect = (t: string) => {
    if (tokens[i] !== t) throw new InputError(`${what}: expected "${t}" in "${text}"`);
    i++;
  };
  const sum = (): number => {
    let v = product();
    while (peek() === '+' || peek() === '-') v = tokens[i++] === '+' ? v + product() : v - product();
    return v;
  };
  const product = (): number => {
    let v = unary();
    while (peek() === '*' || peek() === '/') v = tokens[i++] === '*' ? v * unary() : v / unary();
    return v;
  };
  const unary = (): number => {
    if (peek() === '-') return i++, -unary();
    if (peek() === '+') return i++, unary();
    return power();
  };
  const power = (): number => {
    const base = atom();
    if (peek() === '^' || peek() === '**') return i++, base ** unary();
    return base;
  };
  const atom = (): number => {
    const t = tokens[i++];
    if (t === undefined) throw new InputError(`${what}: "${text}" ends too early`);
    if (t === '(') {
      const v = sum();
      expect(')');
      return v;
    }
    if (/^[\d.]/.test(t)) return Number(t);
    if (/^[A-Za-z_]/.test(t)) {
      if (peek() === '(') {
        const f = FUNCTIONS[t];
        if (!f) throw new InputError(`${what}: ${t}() is not a function a parameter may use`);
        i++;
        const args = [sum()];
        while (peek() === ',') i++, args.push(sum());
        expect(')');
        return f(...args);
      }
      if (t in known) return known[t];
      if (t in CONSTANTS) return CONSTANTS[t];
      throw new InputError(`${what}: unknown name ${t} in "${text}" (a parameter may use pi, e, tau and the parameters given before it)`);
    }
    throw new InputError(`${what}: unexpected "${t}" in "${text}"`);
  };
  if (tokens.length === 0) throw new InputError(`${what} is empty`);
  const value = sum();
  if (i < tokens.length) throw new InputError(`${what}: unexpected "${tokens[i]}" in "${text}"`);
  return value;
}
