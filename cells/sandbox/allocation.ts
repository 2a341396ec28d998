/**
 * Allocations a cell asks for by size, refused before they take the tab
 * down: `[...Array(1e9).keys()]` crashed the renderer (V8 gives up, and the
 * tab with it, past about 1.3·10⁸ elements of one array), and
 * `new Float64Array(1e10)` asks for 80 GB. Where the size is known when the
 * array is made — `Array(n)`, `new Array(n)`, `Array.from({length: n})`, a
 * typed array or buffer of n — a cell gets a RangeError saying the size and
 * the book's bound instead. Sizes that only grow later (pushing in a loop)
 * cannot be known this way; the loop guard stops those loops.
 *
 * Reader code sees these constructors in place of the page's (compileCell's
 * scope): the book's own code keeps the plain ones, at full speed.
 */

/** Elements in one array a cell may make at once: 240 MB of numbers, under a quarter of what V8 allows. */
export const MAX_ARRAY_LENGTH = 3e7;
/** Bytes in one typed array or buffer a cell may make at once. */
export const MAX_BUFFER_BYTES = 1e9;

/** A count as the reader would write it: 1e9, 33554432. */
function count(n: number): string {
  return n >= 1e6 && Number.isFinite(n) ? Number(n.toPrecision(3)).toExponential().replace('e+', 'e') : String(n);
}

/** Bytes in the unit that reads best: 80 GB, 1 GB. */
function bytes(n: number): string {
  const units: [number, string][] = [[1e12, 'TB'], [1e9, 'GB'], [1e6, 'MB'], [1e3, 'kB']];
  for (const [size, unit] of units) if (n >= size) return `${Number((n / size).toPrecision(3))} ${unit}`;
  return `${n} bytes`;
}

/** The refusal of an array of `length` elements made by `what`, or null when it is within the bound. */
export function arrayRefusal(what: string, length: number): string | null {
  if (!(length > MAX_ARRAY_LENGTH)) return null;
  return `${what} would make an array of ${count(length)} elements, more than the ${count(MAX_ARRAY_LENGTH)} the book lets a cell make at once: an array that size can crash the tab`;
}

/** The refusal of `size` bytes asked for by `what`, or null when it is within the bound. */
export function bufferRefusal(what: string, size: number): string | null {
  if (!(size > MAX_BUFFER_BYTES)) return null;
  return `${what} would take ${bytes(size)}, more than the ${bytes(MAX_BUFFER_BYTES)} the book lets a cell allocate at once`;
}

/** The length an array-like claims (`{length: n}`, another array), when it is not iterated but indexed. */
function claimedLength(source: unknown): number {
  if (typeof source !== 'object' || source === null) return 0;
  const length = (source as { length?: unknown }).length;
  return typeof length === 'number' ? length : 0;
}

function refuse(message: string | null): void {
  if (message) throw new RangeError(message);
}

type Constructor = abstract new (...args: never[]) => unknown;

/** `Array`, refusing a length past the bound given to `Array(n)`, `new Array(n)` and `Array.from({length: n})`. */
function guardedArray(Real: ArrayConstructor): ArrayConstructor {
  const check = (args: readonly unknown[]) => {
    if (args.length === 1 && typeof args[0] === 'number') refuse(arrayRefusal(`Array(${count(args[0])})`, args[0]));
  };
  const from = function (this: unknown, source: unknown, ...rest: unknown[]) {
    if (typeof source === 'object' && source !== null && !(Symbol.iterator in source)) refuse(arrayRefusal('Array.from', claimedLength(source)));
    return Reflect.apply(Real.from, this === proxy ? Real : this, [source, ...rest]) as unknown[];
  };
  const proxy: ArrayConstructor = new Proxy(Real, {
    apply(target, self, args) {
      check(args);
      return Reflect.apply(target, self, args) as unknown;
    },
    construct(target, args, newTarget) {
      check(args);
      return Reflect.construct(target, args, newTarget === proxy ? target : newTarget) as object;
    },
    get(target, key, receiver) {
      return key === 'from' ? from : (Reflect.get(target, key, receiver === proxy ? target : receiver) as unknown);
    },
  });
  return proxy;
}

/** A typed array or buffer constructor, refusing more bytes than the bound. */
function guardedBuffer<T extends Constructor>(Real: T, name: string, bytesPerElement: number): T {
  const proxy: T = new Proxy(Real, {
    construct(target, args, newTarget) {
      const [first] = args as unknown[];
      // A buffer (with offset and length) is viewed, not allocated.
      const length = typeof first === 'number' ? first : first instanceof ArrayBuffer || ArrayBuffer.isView(first) ? 0 : claimedLength(first);
      refuse(bufferRefusal(`new ${name}(${count(length)})`, length * bytesPerElement));
      const max = (args[1] as { maxByteLength?: unknown } | undefined)?.maxByteLength;
      if (name.endsWith('Buffer') && typeof max === 'number') refuse(bufferRefusal(`new ${name}(…, {maxByteLength: ${count(max)}})`, max));
      return Reflect.construct(target, args, newTarget === proxy ? target : newTarget) as object;
    },
  });
  return proxy;
}

const TYPED = [
  'Int8Array', 'Uint8Array', 'Uint8ClampedArray', 'Int16Array', 'Uint16Array', 'Int32Array', 'Uint32Array',
  'Float32Array', 'Float64Array', 'BigInt64Array', 'BigUint64Array',
] as const;

/** The guarded constructors, by the names reader code uses for them. */
export function allocationScope(global: typeof globalThis = globalThis): Record<string, unknown> {
  const scope: Record<string, unknown> = { Array: guardedArray(global.Array), ArrayBuffer: guardedBuffer(global.ArrayBuffer, 'ArrayBuffer', 1) };
  for (const name of TYPED) {
    const Real = global[name] as unknown as Constructor & { BYTES_PER_ELEMENT: number };
    if (Real) scope[name] = guardedBuffer(Real, name, Real.BYTES_PER_ELEMENT);
  }
  return scope;
}
