/**
 * Grading a number against a truth, within the exercise's tolerance, with a
 * verdict that explains itself: how far off, in which direction, and, when
 * the answer is near a known mistake, what that mistake is.
 */
import type { NumberMistake, Tolerance } from './exercise-spec.ts';

export interface Verdict {
  readonly passed: boolean;
  /** One or two sentences for the reader. */
  readonly message: string;
}

/**
 * The reader's text as a number: a decimal with an optional sign, point and
 * exponent (`0.63`, `-1.5e-3`); a comma for the point is refused with a
 * word, as is anything else.
 */
export function readNumber(text: string): { value: number } | { error: string } {
  const trimmed = text.trim().replace(/\u2212/g, '-');
  if (trimmed === '') return { error: 'Enter a number first.' };
  if (/^[-+]?\d+,\d+$/.test(trimmed)) return { error: `Write the decimal point as a point: ${trimmed.replace(',', '.')}.` };
  if (!/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(trimmed)) return { error: `“${trimmed}” is not a number: write it as 0.63 or 6.3e-1, without units.` };
  return { value: Number(trimmed) };
}

/** The allowed distance from `truth`: the larger of the absolute and relative allowances. */
export function allowance(truth: number, tolerance: Tolerance): number {
  return Math.max(tolerance.absolute ?? 0, (tolerance.relative ?? 0) * Math.abs(truth));
}

const digits = (x: number) => Number(x.toPrecision(4)).toString();

/** How far `value` is from `truth`, in words: "3.2 % high", "a factor 2.0 low". */
function offBy(value: number, truth: number): string {
  if (truth === 0) return value > 0 ? 'too high' : 'too low';
  if (Math.sign(value) !== Math.sign(truth) && value !== 0) return 'of the wrong sign';
  const ratio = value / truth;
  if (ratio >= 1.5) return `about ${ratio.toFixed(1)} times too large`;
  if (ratio <= 1 / 1.5) return `about ${(1 / ratio).toFixed(1)} times too small`;
  const percent = Math.abs(ratio - 1) * 100;
  return `${percent < 1 ? percent.toPrecision(2) : percent.toFixed(1)} % ${ratio > 1 ? 'high' : 'low'}`;
}

/**
 * The verdict on `value` against `truth`. A mistake is named when the answer
 * lies within the tolerance of it (so a mistake must sit farther from the
 * truth than the tolerance, which the tests check for every exercise).
 */
export function gradeNumber(value: number, truth: number, tolerance: Tolerance, mistakes: readonly NumberMistake[], unit = ''): Verdict {
  const units = unit ? ` ${unit}` : '';
  if (!Number.isFinite(truth)) return { passed: false, message: 'This exercise has no true value for its settings: the book cannot grade it (tell the author).' };
  const allowed = allowance(truth, tolerance);
  const distance = Math.abs(value - truth);
  if (distance <= allowed) {
    return { passed: true, message: `Right: ${digits(value)}${units} is within ${digits(allowed)} of the true ${digits(truth)}${units}. ${tolerance.why}` };
  }
  const mistake = mistakes.find((m) => Math.abs(value - m.value) <= allowance(m.value, tolerance));
  const off = `Not yet: your ${digits(value)}${units} is ${offBy(value, truth)}.`;
  return { passed: false, message: mistake ? `${off} ${mistake.why}` : `${off} The check allows ${digits(allowed)}${units}: ${tolerance.why}` };
}
