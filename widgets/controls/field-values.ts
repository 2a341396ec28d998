/**
 * Reading numbers typed into controls. A bad entry yields a message for the
 * reader and no value, so the control can keep its old value and say why.
 */

import { MAX_DT, MIN_DT } from '../../core/index.ts';

export type Parsed = { value: number; error?: undefined } | { value?: undefined; error: string };

/**
 * A number as typed: JS number syntax (5e-4, 0.0005, .5), surrounding spaces
 * ignored, a typographic minus (−) accepted; an empty field is an error.
 */
export function parseNumber(text: string, name: string): Parsed {
  const s = text.trim().replace(/\u2212/g, '-');
  if (s === '') return { error: `${name} is empty; type a number such as 5e-4` };
  if (!/^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(s)) return { error: `${name}: “${text.trim()}” is not a number` };
  const value = Number(s);
  if (!Number.isFinite(value)) return { error: `${name}: ${s} is too large` };
  return { value };
}

/** A time step: a positive number within the book's bounds (core/limits.ts). */
export function parseDt(text: string, min = MIN_DT, max = MAX_DT): Parsed {
  const parsed = parseNumber(text, 'dt');
  if (parsed.error !== undefined) return parsed;
  if (!(parsed.value > 0)) return { error: `dt must be positive, not ${parsed.value}` };
  if (parsed.value > max) return { error: `dt = ${parsed.value} is too large; use at most ${max}` };
  if (parsed.value < min) return { error: `dt = ${parsed.value} is too small; use at least ${min}` };
  return parsed;
}

/** An optional bound of a time interval: empty means “from the start” or “to the end”. */
export function parseBound(text: string, name: string): Parsed | { value: null; error?: undefined } {
  if (text.trim() === '') return { value: null };
  return parseNumber(text, name);
}
