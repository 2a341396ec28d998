/**
 * A compact, one-line view of a cell's value, for values that are not DOM
 * nodes: `period = 0.628318530718`, `Float64Array(256) [0, 0.02, …]`,
 * `{q: 1, p: 0}`. Long collections are cut short rather than flooding the
 * page, and a long top-level list opens to show the rest; a typed array
 * inside another value is named, not listed; an object that carries a
 * one-line summary (core/summary.ts: a model, a simulation) shows that.
 */
import { SUMMARY } from '../core/index.ts';

/** Items shown of an array, set or map at the top level (fewer when nested). */
const MAX_ITEMS = 20;
/** Keys shown of a plain object at the top level (fewer when nested). */
const MAX_KEYS = 12;
/** Nesting shown before an object collapses to its summary, e.g. `Array(3)`. */
const MAX_DEPTH = 2;
const MAX_STRING = 200;

type Part = readonly [kind: string, text: string];

function token(kind: string, text: string): Part {
  return [kind, text];
}

/** Significant digits a number is shown with: enough for any reading, few enough that 3.6 is not 3.5999999999999996. */
const DIGITS = 12;

/** Items of a long top-level list shown when the reader opens it. */
const MAX_OPEN_ITEMS = 2000;

function inspectedNumber(value: number): string {
  if (Object.is(value, -0)) return '-0';
  if (!Number.isFinite(value) || Number.isInteger(value)) return String(value);
  return String(Number(value.toPrecision(DIGITS)));
}

function formatString(value: string, depth: number): string {
  const limit = depth === 0 ? MAX_STRING : MAX_STRING / 4;
  const shown = value.length > limit ? `${value.slice(0, limit)}…` : value;
  return JSON.stringify(shown);
}

function constructorName(value: object): string {
  const proto: unknown = Object.getPrototypeOf(value);
  if (proto === null) return 'Object';
  const ctor: unknown = (proto as { constructor?: unknown }).constructor;
  return typeof ctor === 'function' && ctor.name ? ctor.name : 'Object';
}

function isIndexed(value: object): value is ArrayLike<unknown> {
  return Array.isArray(value) || (ArrayBuffer.isView(value) && !(value instanceof DataView));
}

function list(open: string, items: Iterable<Part[]>, count: number, close: string, limit: number): Part[] {
  const parts: Part[] = [token('punct', open)];
  let shown = 0;
  for (const item of items) {
    if (shown === limit) break;
    if (shown > 0) parts.push(token('punct', ', '));
    parts.push(...item);
    shown += 1;
  }
  if (count > shown) parts.push(token('more', `${shown > 0 ? ', ' : ''}… ${count - shown} more`));
  parts.push(token('punct', close));
  return parts;
}

function* take<T, U>(items: Iterable<T>, limit: number, map: (item: T) => U): Iterable<U> {
  let i = 0;
  for (const item of items) {
    if (i++ === limit) return;
    yield map(item);
  }
}

function summaryOf(value: object): string | null {
  const summary: unknown = (value as { [SUMMARY]?: unknown })[SUMMARY];
  if (typeof summary !== 'function') return null;
  try {
    return String(summary.call(value));
  } catch {
    return null;
  }
}

function describeObject(value: object, depth: number): Part[] {
  const summary = summaryOf(value);
  if (summary !== null) return [token('object', summary)];
  if (value instanceof Date) return [token('date', Number.isNaN(value.getTime()) ? 'Invalid Date' : value.toISOString())];
  if (value instanceof RegExp) return [token('regexp', String(value))];
  if (value instanceof Error) return [token('error', `${value.name}: ${value.message}`)];
  const name = constructorName(value);
  const size = isIndexed(value) ? value.length : value instanceof Map || value instanceof Set ? value.size : null;
  if (depth >= MAX_DEPTH || (depth > 0 && ArrayBuffer.isView(value))) return [token('object', size === null ? `${name} {…}` : `${name}(${size})`)];

  const limit = depth === 0 ? MAX_ITEMS : MAX_ITEMS / 4;
  const prefix = name === 'Array' || name === 'Object' ? [] : [token('object', `${name}${size === null ? '' : `(${size})`} `)];
  if (isIndexed(value)) {
    const items = Array.from({ length: Math.min(value.length, limit) }, (_, i) => describe(value[i], depth + 1));
    return [...prefix, ...list('[', items, value.length, ']', limit)];
  }
  if (value instanceof Set) return [...prefix, ...list('{', take(value, limit, (item) => describe(item, depth + 1)), value.size, '}', limit)];
  if (value instanceof Map) {
    const entries = take(value, limit, ([k, v]) => [...describe(k, depth + 1), token('punct', ' => '), ...describe(v, depth + 1)]);
    return [...prefix, ...list('{', entries, value.size, '}', limit)];
  }
  const keys = Object.keys(value);
  const keyLimit = depth === 0 ? MAX_KEYS : MAX_KEYS / 4;
  const fields = take(keys, keyLimit, (key) => [token('key', key), token('punct', ': '), ...describe(Reflect.get(value, key), depth + 1)]);
  return [...prefix, ...list('{', fields, keys.length, '}', keyLimit)];
}

function describe(value: unknown, depth: number): Part[] {
  switch (typeof value) {
    case 'number': return [token('number', inspectedNumber(value))];
    case 'bigint': return [token('number', `${value}n`)];
    case 'string': return [token('string', formatString(value, depth))];
    case 'boolean': return [token('boolean', String(value))];
    case 'undefined': return [token('empty', 'undefined')];
    case 'symbol': return [token('symbol', value.toString())];
    case 'function': return [token('function', `ƒ ${value.name || ''}(${value.length > 0 ? '…' : ''})`)];
    case 'object': return value === null ? [token('empty', 'null')] : describeObject(value, depth);
    default: return [token('empty', String(value))];
  }
}

function render(parts: readonly Part[], into: HTMLElement): HTMLElement {
  for (const [kind, text] of parts) {
    const span = document.createElement('span');
    span.className = `inspect-${kind}`;
    span.textContent = text;
    into.append(span);
  }
  return into;
}

/**
 * The value as a line of `span.inspect-<kind>` pieces, prefixed by `name = `
 * for a named cell. A top-level list longer than the line shows is a
 * <details> that opens to its first MAX_OPEN_ITEMS items.
 */
export function inspect(value: unknown, name: string | null): HTMLElement {
  const parts: Part[] = name ? [token('name', name), token('punct', ' = '), ...describe(value, 0)] : describe(value, 0);
  const line = render(parts, document.createElement('span'));
  line.className = 'inspect';
  const long = typeof value === 'object' && value !== null && isIndexed(value) && value.length > MAX_ITEMS && summaryOf(value) === null;
  if (!long) return line;
  const details = document.createElement('details');
  details.className = 'inspect inspect-list';
  const summary = document.createElement('summary');
  summary.append(...line.childNodes);
  const all = document.createElement('div');
  all.className = 'inspect-all';
  const items = value as ArrayLike<unknown>;
  const shown = Math.min(items.length, MAX_OPEN_ITEMS);
  const listed = Array.from({ length: shown }, (_, i) => describe(items[i], 1).map(([, text]) => text).join('')).join(', ');
  all.textContent = shown < items.length ? `${listed}, … ${items.length - shown} more` : listed;
  details.append(summary, all);
  return details;
}
