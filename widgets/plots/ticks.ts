/** Labels of powers of ten, for symlog axes (tick-labels.ts). */
const SUPERSCRIPT = '⁰¹²³⁴⁵⁶⁷⁸⁹';

function superscript(n: number): string {
  return String(n).replace(/\d/g, (d) => SUPERSCRIPT[Number(d)]).replace('-', '⁻');
}

/** 0, ±1, ±10, ±100, ±1000, then ±10⁴ … with a true minus sign. */
export function formatPower(value: number): string {
  if (value === 0) return '0';
  const sign = value < 0 ? '−' : '';
  const exponent = Math.round(Math.log10(Math.abs(value)));
  if (exponent < 4) return sign + String(Math.abs(value));
  return `${sign}10${superscript(exponent)}`;
}
