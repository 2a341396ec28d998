import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { toCSV } from '../../../../core/tables/csv.ts';
import { parseJSON, toJSON } from '../../../../core/index.ts';
import { TrajectoryRecord } from '../../../../core/record.ts';
import { Simulation } from '../../../../core/simulation.ts';
import { VERSION } from '../../../../core/version.ts';
import { BLOCK_ROWS, csvParts, jsonParts } from '../../../../widgets/exports/export.ts';
import { exportName, selectRows } from '../../../../widgets/exports/interval.ts';
import { exportMeta } from '../../../../core/tables/export-meta.ts';

function ring(rows: number, capacity: number): TrajectoryRecord {
  const record = new TrajectoryRecord(['t', 'q', 'p', 'H'], capacity);
  for (let i = 0; i < rows; i++) record.push([i * 0.5, Math.sin(i), -0 * i, i % 7 === 0 ? NaN : 1 / (i + 1)]);
  return record;
}

describe('data/interval', () => {
  it('selectRows(record, null, null) is everything recorded', () => {
    const record = ring(100, 1000);
    expect(selectRows(record, null, null)).toEqual({ from: 0, to: 100, rows: 100, first: 0, last: 49.5 });
  });

  it('selectRows(record, t0, t1) takes the rows with t0 ≤ t ≤ t1, ends included', () => {
    const record = ring(100, 1000);
    expect(selectRows(record, 10, 20)).toEqual({ from: 20, to: 41, rows: 21, first: 10, last: 20 });
    expect(selectRows(record, 10.1, 10.4)).toEqual({ error: 'no samples with 10.1 ≤ t ≤ 10.4; the record holds t from 0 to 49.5' });
    expect(selectRows(record, 30, null)).toMatchObject({ from: 60, to: 100 });
    expect(selectRows(record, null, 0)).toMatchObject({ from: 0, to: 1 });
  });

  it('selectRows(…) explains a reversed interval, an empty record and a dropped start', () => {
    expect(selectRows(ring(10, 100), 5, 2)).toEqual({ error: 't0 = 5 is after t1 = 2' });
    expect(selectRows(ring(0, 10), null, null)).toEqual({ error: 'nothing is recorded yet' });
    const capped = ring(100, 30); // holds t from 35 on
    expect(selectRows(capped, 0, 10)).toEqual({ error: 'no samples with 0 ≤ t ≤ 10; the record holds t from 35 to 49.5' });
    expect(selectRows(capped, 0, 36)).toMatchObject({ from: 0, to: 3, first: 35 });
  });

  it('exportName(first, last, ext) names the file after its time span', () => {
    expect(exportName(0, 30, 'csv')).toBe('phasebook-t0-30.csv');
    expect(exportName(-1.5, 2.123456789, 'json')).toBe('phasebook-tm1.5-2.12346.json');
  });
});

describe('data/export', () => {
  it('csvParts(record, from, to).join("") is the core’s toCSV of those rows, across the ring’s wrap', () => {
    const record = ring(BLOCK_ROWS * 2 + 777, BLOCK_ROWS + 1234); // wrapped ring, more than one block
    for (const [from, to] of [[0, record.length], [5, 6], [100, BLOCK_ROWS + 1000], [7, 7]]) {
      expect(csvParts(record, from, to).join('')).toBe(toCSV(record.table(from, to)));
    }
  });

  it('jsonParts(record, meta, from, to).join("") is the core’s toJSON of those rows and reads back', () => {
    const record = ring(BLOCK_ROWS + 500, BLOCK_ROWS + 100);
    const meta = { hamiltonian: 'H', params: {}, dof: 1, dt: 0.5, method: 'rk38', every: 1, t0: 0, initial: [0, 0], version: VERSION };
    for (const [from, to] of [[0, record.length], [3, 3], [10, 20]]) {
      const text = jsonParts(record, meta, from, to).join('');
      expect(text).toBe(toJSON(record.table(from, to), meta));
      expect(parseJSON(text).table.rows).toBe(to - from);
    }
  });

  it('exportMeta(simulation) has the CLI’s keys in the CLI’s order, then count and dropped when they apply', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + omega^2*q^2/2', params: { omega: 10 } });
    const single = new Simulation(model, { initial: [2, 0], dt: 1e-3, every: 2 });
    const meta = exportMeta(single);
    // the keys of cli/commands/simulate.ts, in its order
    expect(Object.keys(meta)).toEqual(['hamiltonian', 'params', 'dof', 'dt', 'method', 'every', 't0', 'initial', 'route', 'names', 'derived', 'version']);
    expect(meta).toMatchObject({ hamiltonian: 'p^2/2 + omega^2*q^2/2', params: { omega: 10 }, dof: 1, dt: 1e-3, method: 'rk38', every: 2, t0: 0, initial: [2, 0], names: ['q', 'p'], derived: ['H'], version: '0.1.0' });
    const batch = new Simulation(model, { initial: [1, 0, 2, 0], capacity: 3 });
    batch.run(10);
    expect(exportMeta(batch)).toMatchObject({ count: 2, dropped: 8 });
    expect(parseJSON(jsonParts(batch.record, exportMeta(batch)).join('')).meta).toEqual(exportMeta(batch));
  });
});
