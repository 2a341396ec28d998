import { describe, expect, it } from 'vitest';
import { TrajectoryRecord } from '../../../../core/record.ts';
import { latestValues, rangeText, recordTable, rowsOver, show, TABLE_ROWS, TABLE_SERIES } from '../../../../widgets/plots/table-data.ts';

/** q = cos t, p = −sin t every 0.01 from 0 to 10: values the table must read back. */
function oscillator(): TrajectoryRecord {
  const record = new TrajectoryRecord(['t', 'q', 'p'], 10_000);
  for (let k = 0; k <= 1000; k++) record.push([k * 0.01, Math.cos(k * 0.01), -Math.sin(k * 0.01)]);
  return record;
}

describe('plots/table-data', () => {
  it('rowsOver(record, t0, t1) picks rows evenly spaced in time, latest last, within the record', () => {
    const record = oscillator();
    const rows = rowsOver(record, 2, 7);
    expect(rows.length).toBe(TABLE_ROWS);
    expect(record.time(rows[0])).toBeCloseTo(2, 9);
    expect(record.time(rows[rows.length - 1])).toBeCloseTo(7, 9);
    for (let i = 1; i < rows.length; i++) expect(record.time(rows[i]) - record.time(rows[i - 1])).toBeCloseTo(0.5, 9);
    // a window reaching before the record starts at its first row
    expect(record.time(rowsOver(record, -5, 1)[0])).toBe(0);
    expect(rowsOver(new TrajectoryRecord(['t', 'q'], 4), 0, 1)).toEqual([]);
  });

  it('recordTable lists t and each series at those rows, as the record holds them', () => {
    const record = oscillator();
    const rows = rowsOver(record, 0, 10);
    const table = recordTable(record, [{ name: 'q', index: 1 }, { name: 'p', index: 2 }], rows, 'caption');
    expect(table.head).toEqual(['t', 'q', 'p']);
    expect(table.rows.length).toBe(TABLE_ROWS);
    table.rows.forEach(([t, q, p]) => {
      const time = Number(t.replace('−', '-'));
      expect(Number(q.replace('−', '-'))).toBeCloseTo(Math.cos(time), 3);
      expect(Number(p.replace('−', '-'))).toBeCloseTo(-Math.sin(time), 3);
    });
  });

  it('a batch’s many series are cut to TABLE_SERIES, and the caption says so', () => {
    const record = oscillator();
    const many = Array.from({ length: 20 }, (_, i) => ({ name: `q[${i}]`, index: 1 }));
    const table = recordTable(record, many, [0, 1], 'Batch');
    expect(table.head.length).toBe(TABLE_SERIES + 1);
    expect(table.caption).toMatch(/first 8 of 20 series/);
  });

  it('latestValues and rangeText say the current values and an axis range in words', () => {
    const record = oscillator();
    expect(latestValues(record, [{ name: 'q', index: 1 }])).toBe(`q = ${show(Math.cos(10))}`);
    expect(show(-3.5999999999999996)).toBe('−3.600');
    expect(rangeText([1.2, -1.2])).toBe('from −1.200 to 1.200');
  });
});
