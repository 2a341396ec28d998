import { describe, expect, it } from 'vitest';
import { estimateWidth, labelsFit, linearLabels, scientific, symlogLabels, type AxisLabels, type LabelRoom } from '../../../../widgets/plots/ticks.ts';

const FONT = 11;
const SUPER = '⁰¹²³⁴⁵⁶⁷⁸⁹';

/** A label read back as a number: "−2.5×10⁻¹²" → −2.5e-12, "1,000" → 1000. */
function parse(label: string): number {
  const text = label.replace(/−/g, '-').replace(/,/g, '');
  const m = /^([-+]?[\d.]+)(?:×10([⁻]?[⁰-⁹¹²³]+))?$/.exec(text);
  if (!m) throw new Error(`unreadable label ${label}`);
  const exponent = m[2] ? Number(m[2].replace('⁻', '-').replace(/./g, (c) => (c === '-' ? '-' : String(SUPER.indexOf(c))))) : 0;
  return Number(m[1]) * 10 ** exponent;
}

function room(lo: number, hi: number, along: 'x' | 'y', length: number): LabelRoom {
  return {
    along,
    length,
    font: FONT,
    measure: (text) => estimateWidth(text, FONT),
    position: (v) => ((v - lo) / (hi - lo)) * length,
    room: along === 'y' ? 48 : undefined,
  };
}

/** The labelled ticks read back, offset added, against their values: each within a tenth of a step. */
function assertReadsBack(axis: AxisLabels): void {
  const step = axis.values.length > 1 ? axis.values[1] - axis.values[0] : Math.abs(axis.values[0]) || 1;
  axis.values.forEach((v, i) => {
    if (!axis.labels[i]) return;
    const read = parse(axis.labels[i]) + axis.offset;
    expect(Math.abs(read - v), `${axis.labels[i]} + ${axis.offsetText} for ${v}`).toBeLessThanOrEqual(step / 10 + Math.abs(v) * 1e-15);
  });
}

function check(lo: number, hi: number): void {
  for (const [along, length] of [['x', 300], ['x', 640], ['y', 150], ['y', 300]] as const) {
    const r = room(lo, hi, along, length);
    const axis = linearLabels(lo, hi, r);
    const shown = axis.labels.filter(Boolean);
    expect(shown.length, `${along} ${lo} … ${hi}: ${shown}`).toBeGreaterThanOrEqual(2);
    expect(new Set(shown).size).toBe(shown.length);
    expect(labelsFit(axis.values, axis.labels, r), `${along} ${lo} … ${hi}: ${shown}`).toBe(true);
    for (const v of axis.values) {
      expect(v).toBeGreaterThanOrEqual(lo - (hi - lo) * 1e-9);
      expect(v).toBeLessThanOrEqual(hi + (hi - lo) * 1e-9);
    }
    assertReadsBack(axis);
  }
}

describe('plots/ticks', () => {
  it('linear labels never touch, and read back as their values, for ranges at every decade from 1e-12 to 1e15', () => {
    for (let e = -12; e <= 15; e++) {
      const u = 10 ** e;
      for (const [lo, hi] of [[0, u], [0, 7.3 * u], [-u, u], [-3.2 * u, 1.1 * u], [u, 3 * u], [-9 * u, -2 * u], [1.0001 * u, 1.0009 * u]]) check(lo, hi);
    }
  });

  it('tiny spans far from zero are labelled relative to a round offset (1e9 … 1e9 + 1e-3)', () => {
    const axis = linearLabels(1e9, 1e9 + 1e-3, room(1e9, 1e9 + 1e-3, 'x', 400));
    expect(axis.offset).toBe(1e9);
    expect(axis.offsetText).toBe('1×10⁹');
    for (const label of axis.labels) expect(label.length).toBeLessThanOrEqual(8);
    for (const [offset, span] of [[1e9, 1e-3], [-1e9, 1e-3], [123456789.123, 1e-4], [1e15, 100], [1e12, 1e-2], [1e-6, 1e-15], [-3.3e4, 1e-7], [6.02e15, 1e3]]) {
      check(offset, offset + span);
      const axis = linearLabels(offset, offset + span, room(offset, offset + span, 'y', 200));
      expect(axis.offsetText, `${offset} + ${span}`).not.toBe('');
    }
  });

  it('the issue’s phase portrait at dt = 0.5 (q up to 2e13 over 300 px) gets a few short labels, not 2,000,000,000,000', () => {
    const axis = linearLabels(-5e12, 2.2e13, room(-5e12, 2.2e13, 'x', 290));
    for (const label of axis.labels) expect(label).not.toMatch(/,/);
    expect(labelsFit(axis.values, axis.labels, room(-5e12, 2.2e13, 'x', 290))).toBe(true);
    assertReadsBack(axis);
  });

  it('ordinary ranges keep d3’s labels with a true minus sign', () => {
    const axis = linearLabels(-1, 1, room(-1, 1, 'x', 400));
    expect(axis.labels[0]).toBe('−1.0');
    expect(axis.labels).toContain('0.0');
    for (const label of axis.labels) expect(label).toMatch(/^−?\d\.\d$/);
    expect(axis.offsetText).toBe('');
  });

  it('scientific(v, step) writes m×10ⁿ with the decimals the step needs', () => {
    expect(scientific(2e9, 1e9)).toBe('2×10⁹');
    expect(scientific(1.5e5, 5e4)).toBe('1.5×10⁵');
    expect(scientific(-2.5e-12, 5e-13)).toBe('−2.5×10⁻¹²');
    expect(scientific(0, 1)).toBe('0');
    expect(scientific(9.9999e5, 1e5)).toBe('1.0×10⁶');
  });

  it('symlog labels every decade when a decade is taller than a line of text', () => {
    const T = (v: number) => Math.sign(v) * Math.log1p(Math.abs(v));
    const symRoom = (lo: number, hi: number, length: number): LabelRoom => ({
      along: 'y',
      length,
      font: FONT,
      measure: (t) => estimateWidth(t, FONT),
      position: (v) => ((T(v) - T(lo)) / (T(hi) - T(lo))) * length,
      room: 48,
    });
    // the "log y": q up to a few hundred on a 220 px plot labelled only −100, 0, 100
    const axis = symlogLabels(-500, 500, 1, symRoom(-500, 500, 220));
    expect(axis.labels.filter(Boolean)).toEqual(['−100', '−10', '−1', '0', '1', '10', '100']);
    // thirty decades on 220 px: a tick at every decade, labels every few, none touching
    const wide = symlogLabels(-1e15, 1e15, 1, symRoom(-1e15, 1e15, 220));
    for (let k = 0; k <= 15; k++) expect(wide.values).toContain(10 ** k);
    expect(labelsFit(wide.values, wide.labels, symRoom(-1e15, 1e15, 220))).toBe(true);
    expect(wide.labels.filter(Boolean).length).toBeGreaterThanOrEqual(8);
    // taller plots label more of them
    const tall = symlogLabels(-1e15, 1e15, 1, symRoom(-1e15, 1e15, 900));
    expect(tall.labels.filter(Boolean).length).toBeGreaterThan(wide.labels.filter(Boolean).length);
    for (const [lo, hi, length] of [[0, 1e6, 120], [-200, 2000, 100], [-1e12, 5, 300]]) {
      const r = symRoom(lo, hi, length);
      const a = symlogLabels(lo, hi, 1, r);
      expect(labelsFit(a.values, a.labels, r)).toBe(true);
      expect(a.labels.filter(Boolean).length).toBeGreaterThanOrEqual(2);
    }
  });

  it('a y axis whose labels are a little wider than its room (a fallback font) still gets two, not a lone 0', () => {
    // The time plot's at dt = 0.5 on a page whose font had not loaded: "−2×10¹¹" measured 48.2 px in a 48 px room.
    const wide: LabelRoom = { ...room(-2.6e11, 6e10, 'y', 150), measure: (t) => 1.25 * estimateWidth(t, FONT) };
    const axis = linearLabels(-2.6e11, 6e10, wide);
    expect(axis.labels.filter(Boolean).length).toBeGreaterThanOrEqual(2);
    assertReadsBack(axis);
    // where they fit, as many as fit
    expect(linearLabels(-2.6e11, 6e10, room(-2.6e11, 6e10, 'y', 150)).labels.filter(Boolean).length).toBeGreaterThanOrEqual(2);
  });

  it('labelsFit measures neighbours side by side on x and stacked, within the room, on y', () => {
    const r = room(0, 100, 'x', 100);
    expect(labelsFit([0, 30], ['0', '10'], r)).toBe(true);
    expect(labelsFit([0, 10], ['0', '10'], r)).toBe(false);
    expect(labelsFit([0, 1], ['0000', '1111'], r)).toBe(false);
    const y = room(0, 100, 'y', 100);
    expect(labelsFit([0, 10, 20], ['a', 'b', 'c'], y)).toBe(false); // 10 px apart, an 11 px font
    expect(labelsFit([0, 50], ['a', 'b'], y)).toBe(true);
    expect(labelsFit([0, 50], ['a', 'a very long label indeed'], y)).toBe(false); // wider than the 48 px room
  });
});
