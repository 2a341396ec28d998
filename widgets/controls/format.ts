/**
 * Number formats for readouts and controls: fixed significant digits with a
 * true minus sign, so a column of live numbers does not jump about, and
 * powers of ten written as × 10ⁿ.
 */

const SUPERSCRIPT: Record<string, string> = {
  '0': '⁰', '1': '¹', '2': '²', '3': '³', '4': '⁴', '5': '⁵', '6': '⁶', '7': '⁷', '8': '⁸', '9': '⁹', '-': '⁻',
};

/**
 * A number's text as JavaScript or d3 wrote it (toFixed, toPrecision,
 * toExponential), as the page prints it: a true minus sign, and none on a
 * number that reads as zero. Rounding to fixed decimals keeps the sign of a
 * small negative it rounds away ((−0.00004).toFixed(2) is "-0.00"), and
 * every "−0.00" a readout showed came from there.
 */
export function minusSign(text: string): string {
  if (!text.startsWith('-')) return text;
  const magnitude = text.slice(1);
  return /^[0.]*(e[+-]?\d+)?$/i.test(magnitude) ? magnitude : `−${magnitude}`;
}

/** `x` to `decimals` places, with a true minus sign and never "−0": what rounds to zero reads 0.00. */
export function fixedNumber(x: number, decimals: number): string {
  if (!Number.isFinite(x)) return readoutNumber(x);
  return minusSign(x.toFixed(decimals));
}

/** The same with its sign always written, for a difference: "+0.01", "−0.01", and "0.00" (no sign) for what rounds to zero. */
export function signedFixed(x: number, decimals: number): string {
  const text = fixedNumber(x, decimals);
  return /^[\d.]+$/.test(text) && /[1-9]/.test(text) ? `+${text}` : text;
}

/**
 * A number for reading on the page (the readouts, the plots' tables and text
 * alternatives, notes): x with `digits` significant digits, plain when
 * 1e-3 ≤ |x| < 1e6, else m × 10ⁿ.
 */
export function readoutNumber(x: number, digits = 6): string {
  if (Number.isNaN(x)) return 'NaN';
  if (!Number.isFinite(x)) return x > 0 ? '∞' : '−∞';
  if (x === 0) return '0';
  const magnitude = Math.abs(x);
  if (magnitude >= 1e-3 && magnitude < 1e6) return minusSign(x.toPrecision(digits));
  const [mantissa, exponent] = x.toExponential(digits - 1).split('e');
  return `${minusSign(mantissa)} × 10${superscript(String(Number(exponent)))}`;
}

/** A time: fixed decimals from the step, so t advances without its width flickering. */
export function formatTime(t: number, dt: number): string {
  const decimals = Math.max(0, Math.min(8, Math.ceil(-Math.log10(dt) - 1e-9)));
  return fixedNumber(t, decimals);
}

/** A relative drift, always in scientific form with 2 digits: 3.1 × 10⁻¹². */
export function formatDrift(d: number): string {
  if (d === 0) return '0';
  if (!Number.isFinite(d)) return readoutNumber(d);
  const [mantissa, exponent] = d.toExponential(1).split('e');
  return `${mantissa} × 10${superscript(String(Number(exponent)))}`;
}

/** A speed in time units per second, compactly: 0.05, 1, 200. */
export function formatSpeed(speed: number): string {
  return speed >= 1 ? String(Math.round(speed * 100) / 100) : String(Number(speed.toPrecision(2)));
}

/** A rate in steps per second: 2000, 1.2 k, 3.4 M. */
export function formatRate(rate: number): string {
  if (rate >= 1e6) return `${(rate / 1e6).toPrecision(2)} M`;
  if (rate >= 1e4) return `${Math.round(rate / 1e3)} k`;
  return String(Math.round(rate));
}

function superscript(text: string): string {
  return text.replace(/[0-9-]/g, (c) => SUPERSCRIPT[c]);
}
