/**
 * The names a cell may use without defining them, beside the book's own
 * catalogue: plain JavaScript, a few browser facilities, and Math's
 * functions and constants by bare name. Shared by the page (builtins.ts) and
 * by the build's headless run of the cells (headless.ts), so a name means
 * the same in both.
 */

/** Plain JavaScript globals a cell may use by name. */
export const JAVASCRIPT_GLOBALS = [
  'Array', 'ArrayBuffer', 'BigInt', 'Boolean', 'DataView', 'Date', 'Error', 'EvalError', 'Infinity',
  'Intl', 'JSON', 'Map', 'Math', 'NaN', 'Number', 'Object', 'Promise', 'Proxy', 'RangeError',
  'ReferenceError', 'Reflect', 'RegExp', 'Set', 'String', 'Symbol', 'SyntaxError', 'TypeError',
  'URIError', 'WeakMap', 'WeakSet', 'Float32Array', 'Float64Array', 'Int8Array', 'Int16Array',
  'Int32Array', 'Uint8Array', 'Uint8ClampedArray', 'Uint16Array', 'Uint32Array', 'BigInt64Array',
  'BigUint64Array', 'isFinite', 'isNaN', 'parseFloat', 'parseInt', 'structuredClone', 'queueMicrotask',
] as const;

/** Browser globals a cell may use by name: timing, drawing, observing. */
export const BROWSER_GLOBALS = [
  'console', 'performance', 'document', 'requestAnimationFrame', 'cancelAnimationFrame',
  'setTimeout', 'clearTimeout', 'setInterval', 'clearInterval', 'ResizeObserver',
  'IntersectionObserver', 'Path2D', 'ImageData', 'DOMMatrix', 'devicePixelRatio',
] as const;

/**
 * Free functions such as `setTimeout` throw "Illegal invocation" in some
 * engines when called without their global as `this`; constructors must not
 * be bound (a bound class loses its statics).
 */
function fromGlobal(name: string): unknown {
  const value: unknown = Reflect.get(globalThis, name);
  const isConstructorName = name[0] === name[0]?.toUpperCase();
  return typeof value === 'function' && !isConstructorName ? value.bind(globalThis) : value;
}

/** Math's functions and constants by bare name: sin, cos, sqrt, hypot, PI, E, … */
export function mathByName(): Record<string, unknown> {
  const entries = Object.getOwnPropertyNames(Math).map((name) => [name, Reflect.get(Math, name)] as const);
  return Object.fromEntries(entries);
}

/** The globals above that this environment has, with Math's names. */
export function standardValues(): Record<string, unknown> {
  const values: Record<string, unknown> = {};
  for (const name of [...JAVASCRIPT_GLOBALS, ...BROWSER_GLOBALS]) {
    if (name in globalThis) values[name] = fromGlobal(name);
  }
  return { ...values, ...mathByName() };
}
