/**
 * Number formats for readouts and controls: fixed significant digits with a
 * true minus sign, so a column of live numbers does not jump about, and
 * powers of ten written as × 10ⁿ.
 */

const SUPERSCRIPT: Record<string, string> = {
  '0': '⁰', '1': '¹', '2': '²', '3': '³', '4': '⁴', '5': '⁵', '6': '⁶', '7': '⁷', '8': '⁸', '9': '⁹', '-': '⁻',
};

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
  if (magnitude >= 1e-3 && magnitude < 1e6) return x.toPrecision(digits).replace('-', '−');
  const [mantissa, exponent] = x.toExponential(digits - 1).split('e');
  return `${mantissa.replace('-', '−')} × 10${superscript(String(Number(exponent)))}`;
}

/** A time: fixed decimals from the step, so t advances without its width flickering. */
export function formatTime(t: number, dt: number): string {
  const decimals = Math.max(0, Math.min(8, Math.ceil(-Math.log10(dt) - 1e-9)));
  return t.toFixed(decimals).replace('-', '−');
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
