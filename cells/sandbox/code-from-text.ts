/**
 * Code a cell makes from text at run time — `new Function(…)`, `eval(…)`,
 * the async and generator Function constructors, a string passed to
 * setTimeout, WebAssembly — is refused with one clear line. The page's
 * Content-Security-Policy must allow eval (cells and the generated steppers
 * are compiled with `new Function`), so the policy cannot refuse it; and
 * such code would run outside the loop guard, which instruments only the
 * cell's own text. The book's own code still compiles its steppers: only a
 * call whose caller is a cell is refused (caller.ts).
 */
import { callerCell } from './caller.ts';

export class CodeFromText extends Error {
  override name = 'EvalError';
  constructor(what: string) {
    super(`${what} cannot be used in a cell: code made from text at run time would run outside the book's loop guard. Write the code in the cell itself.`);
  }
}

type Constructor = new (...args: unknown[]) => object;
type Callable = (...args: unknown[]) => unknown;

/**
 * `real`, refusing calls and `new` from cells. `prototypeOf` is what the
 * guarded constructor reports as its prototype: the async and generator
 * constructors inherit from Function, which would otherwise lead back to
 * the unguarded one.
 */
function guarded<T extends object>(real: T, what: string, prototypeOf?: () => object): T {
  const proxy: T = new Proxy(real, {
    apply(target, self, args) {
      if (callerCell() !== null) throw new CodeFromText(what);
      return Reflect.apply(target as unknown as Callable, self, args);
    },
    construct(target, args, newTarget) {
      if (callerCell() !== null) throw new CodeFromText(what);
      return Reflect.construct(target as unknown as Constructor, args, (newTarget === proxy ? target : newTarget) as Constructor);
    },
    getPrototypeOf(target) {
      return prototypeOf ? prototypeOf() : Reflect.getPrototypeOf(target);
    },
  });
  return proxy;
}

/** Replaces a property of `owner` (writable or configurable ones only; others are left as they are). */
function replace(owner: object, name: string, value: unknown): void {
  try {
    Object.defineProperty(owner, name, { value, writable: true, configurable: true, enumerable: false });
  } catch {
    // A property the engine will not let go: left as it is.
  }
}

/** The guarded versions a cell's scope holds directly (compileCell's scope), beside the globals replaced below. */
export interface CodeFromTextScope {
  readonly Function: unknown;
  readonly eval: unknown;
}

/**
 * Puts the guarded constructors and eval in place of the page's: the
 * globals, and each kind of function's `constructor`, which is how
 * `(() => {}).constructor('…')` reaches them. WebAssembly, which the book
 * does not use and which would also run code beyond the guard, is removed.
 */
export function guardCodeFromText(global: typeof globalThis = globalThis): CodeFromTextScope {
  const RealFunction = global.Function;
  const FunctionGuard = guarded(RealFunction, 'new Function');
  replace(global, 'Function', FunctionGuard);
  replace(RealFunction.prototype, 'constructor', FunctionGuard);
  const kinds: [object, string][] = [
    [Object.getPrototypeOf(async function () {}), 'The async Function constructor'],
    [Object.getPrototypeOf(function* () {}), 'The generator Function constructor'],
    [Object.getPrototypeOf(async function* () {}), 'The async generator Function constructor'],
  ];
  for (const [prototype, what] of kinds) {
    const real = (prototype as { constructor: object }).constructor;
    replace(prototype, 'constructor', guarded(real, what, () => FunctionGuard));
  }
  const evalGuard = guarded(global.eval, 'eval');
  replace(global, 'eval', evalGuard);
  Reflect.deleteProperty(global, 'WebAssembly');
  return { Function: FunctionGuard, eval: evalGuard };
}
