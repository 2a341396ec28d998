import type { Peak } from '../../../core/index.ts';
import { minusSign, signedFixed } from '../../controls/format.ts';

/** Lines of the readout under a spectrum listing up to `peaks` peaks (shared with simulator/reserve.ts). */
export function readoutLines(peaks: number): number {
  return peaks + 2;
}

/**
 * The text under a spectrum: a numbered list of peaks (numbered as on the
 * plot), the comparison with the theoretical value, and what the spectrum
 * was computed from. Text rather than canvas so it can be read by a screen
 * reader and copied; elements are reused, since it changes a few times a second.
 */
export class SpectrumReadout {
  readonly element: HTMLDivElement;
  private readonly list: HTMLOListElement;
  private readonly comparison: HTMLParagraphElement;
  private readonly note: HTMLParagraphElement;
  private readonly basis: HTMLParagraphElement;

  /**
   * @param peaks the most peaks it lists: with the comparison and the line
   *   on what the spectrum was computed from, the lines it is tall enough for
   *   (readoutLines). Its height is fixed, so that peaks coming and going
   *   never move the page; text that wraps on a narrow screen scrolls.
   */
  constructor(peaks: number) {
    this.element = document.createElement('div');
    this.element.className = 'pb-spectrum-readout';
    this.element.style.setProperty('--pb-readout-lines', String(readoutLines(peaks)));
    // Scrollable, so it must be reachable by keyboard.
    this.element.tabIndex = 0;
    this.element.setAttribute('role', 'region');
    this.element.setAttribute('aria-label', 'Spectrum peaks');
    this.list = document.createElement('ol');
    this.list.className = 'pb-spectrum-peaks';
    this.list.style.cssText = 'margin:0;padding-left:1.6em;';
    const paragraph = (name: string, muted: boolean) => {
      const p = document.createElement('p');
      p.className = name;
      p.style.cssText = `margin:0.15em 0 0;${muted ? 'color:var(--muted,#5e5b55);' : ''}`;
      return p;
    };
    this.comparison = paragraph('pb-spectrum-theory', false);
    this.note = paragraph('pb-spectrum-note', true);
    this.basis = paragraph('pb-spectrum-basis', true);
    this.element.append(this.list, this.comparison, this.note, this.basis);
  }

  show(peaks: readonly string[], basis: string, comparison?: string, note?: string): void {
    const items = this.list.children;
    while (items.length > peaks.length) items[items.length - 1].remove();
    while (items.length < peaks.length) this.list.append(document.createElement('li'));
    peaks.forEach((text, i) => set(items[i], text));
    set(this.comparison, comparison ?? '');
    set(this.note, note ?? '');
    set(this.basis, basis);
  }
}

function set(element: Element, text: string): void {
  if (element.textContent !== text) element.textContent = text;
  (element as HTMLElement).hidden = text === '';
}

/**
 * Text of the spectrum readouts. A peak is given as f in cycles per time
 * unit and as the angular frequency ω = 2πf in radians per time unit (the
 * form a chapter's formula usually predicts), with its amplitude.
 */

/** `v` to `decimals` places, with a true minus sign and no '-0'. */
export function fixed(v: number, decimals: number): string {
  if (!Number.isFinite(v)) return String(v);
  return minusSign(v.toFixed(decimals));
}

/** `v` to `digits` significant digits, plain for ordinary sizes and as a×10ⁿ otherwise. */
export function significant(v: number, digits = 4): string {
  if (!Number.isFinite(v)) return String(v);
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e-4 && a < 1e6) return minusSign(Number(v.toPrecision(digits)).toString());
  const [mantissa, exponent] = v.toExponential(digits - 1).split('e');
  return `${minusSign(mantissa)}×10^${Number(exponent)}`;
}

/**
 * Decimal places worth showing for a frequency measured over `duration`
 * time units: the refined peak is good to a small fraction of the
 * resolution 1/duration, so one place below a twentieth of it, 2 to 6.
 */
export function frequencyDecimals(duration: number): number {
  if (!(duration > 0)) return 3;
  const step = 1 / duration / 20;
  return Math.max(2, Math.min(6, Math.ceil(-Math.log10(step))));
}

export interface PeakText {
  frequency: string;
  omega: string;
  amplitude: string;
}

/** The three numbers of one peak as text. */
export function describePeak(peak: Peak, duration: number): PeakText {
  const decimals = frequencyDecimals(duration);
  return {
    frequency: fixed(peak.frequency, decimals),
    omega: fixed(2 * Math.PI * peak.frequency, Math.max(1, decimals - 1)),
    amplitude: significant(peak.amplitude, 3),
  };
}

/** One line per peak, e.g. "f = 1.518 cycles per time unit · ω = 2πf = 9.54 · amplitude 0.998". */
export function peakLine(peak: Peak, duration: number): string {
  const t = describePeak(peak, duration);
  return `f = ${t.frequency} cycles per time unit · ω = 2πf = ${t.omega} rad per time unit · amplitude ${t.amplitude}`;
}

/** The line under the peaks: what the spectrum was computed from. */
export function basisLine(window: 'hamming' | 'none', t0: number, duration: number, samples: number, stride: number): string {
  const decimals = Math.max(0, Math.min(4, 2 - Math.floor(Math.log10(Math.max(duration, 1e-9)))));
  const parts = [
    window === 'hamming' ? 'Hamming window' : 'no window',
    `t = ${fixed(t0, decimals)} … ${fixed(t0 + duration, decimals)}`,
    `${samples.toLocaleString('en')} samples${stride > 1 ? ` (means of ${stride})` : ''}`,
    `resolution 1/T = ${significant(1 / duration, 2)}`,
  ];
  return parts.join(' · ');
}

/**
 * How a peak compares with the chapter's prediction, e.g. "strongest peak 1.518 vs theory 1.518: +0.01%";
 * `name` says which peak it is when it is not the strongest (e.g. "peak 2").
 */
export function compareWithTheory(peak: Peak, theory: { frequency: number; label: string }, duration: number, name = 'strongest peak'): string {
  const relative = (peak.frequency - theory.frequency) / theory.frequency;
  // signed as rounded: a peak 0.001% below theory reads 0.00%, not −0.00%
  const percent = `${signedFixed(100 * relative, 2)}%`;
  return `${name} ${fixed(peak.frequency, frequencyDecimals(duration))} vs ${theory.label}: ${percent}`;
}

/** The index of the peak nearest a predicted frequency: the one a prediction is about, which need not be the strongest. */
export function nearestPeak(peaks: readonly Peak[], frequency: number): number {
  let best = 0;
  peaks.forEach((p, i) => {
    if (Math.abs(p.frequency - frequency) < Math.abs(peaks[best].frequency - frequency)) best = i;
  });
  return best;
}
