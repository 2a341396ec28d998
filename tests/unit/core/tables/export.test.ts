import { describe, expect, it } from 'vitest';
import { csvHeader, csvRows, roundTripNumber, toCSV } from '../../../../core/tables/csv.ts';
import { parseCSV } from '../../../../core/tables/csv-read.ts';
import { jsonHead, jsonRows, jsonTail, parseJSON, toJSON, type ExportMeta } from '../../../../core/index.ts';
import { ParseError } from '../../../../core/tables/parse-error.ts';
import { readTable } from '../../../../core/tables/read-table.ts';
import { TrajectoryRecord, type Table } from '../../../../core/record.ts';
import { InputError } from '../../../../core/errors.ts';

function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Doubles that shortest-round-trip printing gets wrong if anything does. */
function hardValues(): number[] {
  const v = [
    0, -0, 1, -1, 0.1, 0.2, 0.1 + 0.2, 1 / 3, 2 / 3, 1e300, -1e300, 1e-300, 5e-324, -5e-324,
    Number.MIN_VALUE * 7, 2.2250738585072014e-308, 2.225073858507201e-308, // largest subnormal / smallest normal
    Number.MAX_VALUE, -Number.MAX_VALUE, Number.EPSILON, 1 + Number.EPSILON, 2 ** 53, 2 ** 53 + 2,
    Number.MAX_SAFE_INTEGER, 1e21, 1e-7, 123456789012345680000, 9007199254740993, 4.35, 0.3 - 0.1,
    Math.sqrt(2), Math.E, 100 * 1.1, 1.005 * 1000, 4.1 * 100,
  ];
  for (let k = -330; k <= 310; k++) v.push(Math.PI * 10 ** k, -Math.E * 10 ** k);
  let x = 0;
  for (let k = 0; k < 50; k++) v.push((x += 0.1)); // accumulated rounding
  return v;
}

/** Doubles from random bit patterns: every exponent, subnormals, and both infinities and NaNs. */
function randomDoubles(n: number, seed: number): number[] {
  const random = rng(seed);
  const view = new DataView(new ArrayBuffer(8));
  const out: number[] = [];
  for (let i = 0; i < n; i++) {
    view.setUint32(0, (random() * 2 ** 32) >>> 0);
    view.setUint32(4, (random() * 2 ** 32) >>> 0);
    if (i % 5 === 0) view.setUint16(0, view.getUint16(0) & 0x800f); // force a subnormal
    out.push(view.getFloat64(0));
  }
  return out;
}

function tableOf(columns: string[], values: number[]): Table {
  const width = columns.length;
  const rows = Math.floor(values.length / width);
  return { columns, rows, data: Float64Array.from(values.slice(0, rows * width)) };
}

function expectExact(a: Table, b: Table): void {
  expect(a.columns).toEqual(b.columns);
  expect(a.rows).toBe(b.rows);
  expect(a.data.length).toBe(b.data.length);
  for (let i = 0; i < a.data.length; i++) {
    if (!Object.is(a.data[i], b.data[i])) throw new Error(`value ${i}: ${a.data[i]} read back as ${b.data[i]}`);
  }
}

const META: ExportMeta = {
  hamiltonian: 'p^2/2 + 1 - cos(q)', params: { g: 9.81, l: 1 }, dof: 1, dt: 0.01, method: 'rk38', every: 10,
  t0: 0, initial: [1.2, 0.1 + 0.2], route: 'expression', names: ['q', 'p'], derived: ['H'], count: 3,
  version: '0.1.0', dropped: 0, note: { nested: [1, 'two', null] },
};
const COLS = ['t', 'q0', 'q1', 'p0', 'p1', 'H'];
const ALL = [...hardValues(), ...randomDoubles(6000, 3), NaN, Infinity, -Infinity];
const TABLE = tableOf(COLS, ALL);

describe('roundTripNumber(x)', () => {
  it('roundTripNumber(x) keeps the sign of zero and writes non-finite values as words', () => {
    expect(roundTripNumber(-0)).toBe('-0');
    expect(roundTripNumber(0)).toBe('0');
    expect(roundTripNumber(NaN)).toBe('NaN');
    expect(roundTripNumber(-Infinity)).toBe('-Infinity');
    expect(roundTripNumber(5e-324)).toBe('5e-324');
    expect(roundTripNumber(0.1 + 0.2)).toBe('0.30000000000000004');
  });
});

describe('CSV: csvHeader(columns) / csvRows(data, width, from, to) / toCSV(table) / parseCSV(text)', () => {
  it('toCSV(table) writes a header and one \\n-terminated line per row', () => {
    const text = toCSV(tableOf(['t', 'q', 'p', 'H'], [0, -0, 1.5, NaN, 0.1, 1e-300, -Infinity, 1e21]));
    expect(text).toBe('t,q,p,H\n0,-0,1.5,NaN\n0.1,1e-300,-Infinity,1e+21\n');
  });

  it('parseCSV(toCSV(table)) reproduces every value exactly, including ±0, subnormals, NaN and ±Infinity', () => {
    expectExact(parseCSV(toCSV(TABLE)), TABLE);
  });

  it('csvHeader(columns) + csvRows(…) blocks equal toCSV(table) for any split', () => {
    const random = rng(11);
    const whole = toCSV(TABLE);
    for (let trial = 0; trial < 20; trial++) {
      let text = csvHeader(COLS);
      for (let from = 0; from < TABLE.rows; ) {
        const to = Math.min(TABLE.rows, from + Math.floor(random() * 300));
        text += csvRows(TABLE.data, COLS.length, from, to);
        from = to;
      }
      expect(text).toBe(whole);
    }
  });

  it('csvRows(record.slices()…) streams a wrapped ring buffer identical to toCSV(record.table())', () => {
    const rec = new TrajectoryRecord(['t', 'q', 'p'], 7);
    for (let k = 0; k < 19; k++) rec.push([k * 0.1, Math.sin(k), Math.cos(k)]);
    let text = csvHeader(rec.columns);
    for (const s of rec.slices()) text += csvRows(s.data, rec.width, s.from, s.to);
    expect(text).toBe(toCSV(rec.table()));
  });

  it('csvHeader(columns) refuses names that would need quoting', () => {
    expect(csvHeader(['t', 'q', 'p'])).toBe('t,q,p\n');
    expect(() => csvHeader(['t', 'a,b'])).toThrow(/quoting/);
    expect(() => csvHeader(['t', 'a"b'])).toThrow(/quoting/);
    expect(() => csvHeader(['t', 't'])).toThrow(/duplicate/);
  });

  it('parseCSV(text) accepts \\r\\n, spaces around fields, trailing blank lines and NumPy nan/inf', () => {
    const t = parseCSV('t, x ,y\r\n0, -0 ,nan\r\n1,inf,-INF\r\n\r\n\n');
    expect(t.columns).toEqual(['t', 'x', 'y']);
    expect(t.rows).toBe(2);
    expect(Array.from(t.data)).toEqual([0, -0, NaN, 1, Infinity, -Infinity]);
    expect(Object.is(t.data[1], -0)).toBe(true);
    expect(parseCSV('t,x').rows).toBe(0);
  });

  function csvError(text: string): ParseError {
    try {
      parseCSV(text);
    } catch (e) {
      expect(e).toBeInstanceOf(ParseError);
      expect(e).toBeInstanceOf(InputError);
      return e as ParseError;
    }
    throw new Error('parseCSV accepted malformed input');
  }

  it('parseCSV(text) names the line of a malformed row', () => {
    const cases: Array<[string, number, RegExp]> = [
      ['t,x\n0,1\n1,2,3\n', 3, /expected 2 values \(t,x\), found 3 values/],
      ['t,x\n0,1\n1\n', 3, /found 1 values/],
      ['t,x\n0,1\n\n2,3\n', 3, /blank line/],
      ['t,x\n0,1\n1,2\n2,1.2.3\n', 4, /column x: "1.2.3" is not a number/],
      ['t,x\n0,0x10\n', 2, /"0x10" is not a number/],
      ['t,x\n0,\n', 2, /"" is not a number/],
      ['t,x\n0,1e\n', 2, /"1e" is not a number/],
      ['t,x\n0,1"\n', 2, /a quote inside a field/],
      ['', 1, /empty input/],
      ['t,t\n0,1\n', 1, /duplicate column name "t"/],
      ['t,,x\n', 1, /empty column name/],
    ];
    for (const [text, line, message] of cases) {
      const e = csvError(text);
      expect(e.line).toBe(line);
      expect(e.message).toMatch(new RegExp(`^line ${line}: `));
      expect(e.message).toMatch(message);
    }
  });
});

describe('JSON: jsonHead(meta, columns) / jsonRows(…) / jsonTail() / toJSON(table, meta) / parseJSON(text)', () => {
  it('toJSON(table, meta) is valid JSON of {meta, columns, data} with one row per line', () => {
    const small = tableOf(['t', 'q', 'p'], [0, 1, -0, 0.5, NaN, -Infinity]);
    const text = toJSON(small, META);
    expect(text.split('\n').slice(2)).toEqual(['"data":[', '[0,1,-0],', '[0.5,"NaN","-Infinity"]', ']}', '']);
    const plain = JSON.parse(text) as { meta: unknown; columns: unknown; data: unknown[][] };
    expect(plain.meta).toEqual(META);
    expect(plain.columns).toEqual(['t', 'q', 'p']);
    expect(plain.data).toEqual([[0, 1, -0], [0.5, 'NaN', '-Infinity']]);
    expect(JSON.parse(toJSON(tableOf(['t'], []), META)).data).toEqual([]);
  });

  it('parseJSON(toJSON(table, meta)) reproduces every value and the meta exactly', () => {
    const { meta, table } = parseJSON(toJSON(TABLE, META));
    expectExact(table, TABLE);
    expect(meta).toEqual(META);
  });

  it('parseJSON(text) reads finite data as JSON.parse does', () => {
    const finite = tableOf(COLS, ALL.filter(Number.isFinite));
    const text = toJSON(finite, META);
    const viaBuiltin = Float64Array.from((JSON.parse(text) as { data: number[][] }).data.flat());
    expectExact(parseJSON(text).table, { ...finite, data: viaBuiltin });
  });

  it('jsonHead + jsonRows blocks + jsonTail equal toJSON(table, meta) for any split, empty blocks included', () => {
    const random = rng(5);
    const whole = toJSON(TABLE, META);
    for (let trial = 0; trial < 20; trial++) {
      let text = jsonHead(META, COLS);
      let first = true;
      for (let from = 0; from < TABLE.rows; ) {
        const to = Math.min(TABLE.rows, from + Math.floor(random() * 300));
        text += jsonRows(TABLE.data, COLS.length, from, to, first);
        if (to > from) first = false;
        from = to;
      }
      expect(text + jsonTail()).toBe(whole);
    }
  });

  it('parseJSON(text) accepts other layouts and key orders, and null as NaN', () => {
    const doc = { data: [[0, 1], [0.5, null]], extra: true, columns: ['t', 'x'], meta: META };
    const { meta, table } = parseJSON(`\ufeff${JSON.stringify(doc, null, 2)}`);
    expect(meta).toEqual(META);
    expect(table.columns).toEqual(['t', 'x']);
    expect(Array.from(table.data)).toEqual([0, 1, 0.5, NaN]);
  });

  it('parseJSON(text) decodes string escapes in meta as JSON.parse does', () => {
    const m = { ...META, hamiltonian: 'p²/2 + "q"\\\n\t\u0001 \ud83d\ude00' };
    const text = toJSON(tableOf(['t'], [1]), m);
    expect(parseJSON(text).meta).toEqual(JSON.parse(text).meta);
  });

  it('parseJSON(text) keeps a "__proto__" key as data, as JSON.parse does', () => {
    const text = toJSON(tableOf(['t'], [1]), META).replace('"version"', '"__proto__":{"polluted":1},"version"');
    const { meta } = parseJSON(text);
    expect(Object.getPrototypeOf(meta)).toBe(Object.prototype);
    expect(Object.hasOwn(meta, '__proto__')).toBe(true);
    expect(meta.polluted).toBeUndefined();
  });

  function jsonError(text: string): ParseError {
    try {
      parseJSON(text);
    } catch (e) {
      expect(e).toBeInstanceOf(ParseError);
      return e as ParseError;
    }
    throw new Error('parseJSON accepted malformed input');
  }

  it('parseJSON(text) names the line of malformed input', () => {
    const good = toJSON(tableOf(['t', 'x'], [0, 1, 1, 2, 2, 3]), META).split('\n');
    // lines: 1 meta, 2 columns, 3 "data":[, 4-6 rows, 7 ]}
    const edit = (line: number, text: string): string => good.map((l, i) => (i === line - 1 ? text : l)).join('\n');
    const cases: Array<[string, number, RegExp]> = [
      [edit(5, '[1,2,3],'), 5, /data row 1 has 3 values, expected 2/],
      [edit(5, '[1,2]'), 6, /expected "," or "\]" after a row, found "\["/],
      [edit(6, '[2,"three"]'), 6, /"three" is not a number/],
      [edit(6, '[2,03]'), 6, /expected "," or "\]" in a row, found "3"/],
      [edit(4, '[0,1e]'), 4, /in a row, found "e"/],
      [edit(4, '[0,NaN],'), 4, /expected a number/],
      [edit(2, '"columns":["t","t"],'), 2, /duplicate column name/],
      [edit(2, '"columns":"t,x",'), 2, /columns must be an array of strings/],
      [edit(2, '"columns":["t","x","y"],'), 4, /data row 0 has 2 values, expected 3/],
      [edit(7, ']} x'), 7, /after the end of the JSON value/],
      [edit(7, ']'), 7, /expected "," or "}", found end of input/],
      [good.slice(0, 5).join('\n'), 5, /expected a row "\[", found end of input/],
      [[...good.slice(0, 4), '[1,2]'].join('\n'), 5, /after a row, found end of input/],
      [`{"meta":${JSON.stringify({ ...META, dt: '0.01' })},\n"columns":["t"],\n"data":[]}`, 1, /meta.dt must be a number/],
      [`{"columns":["t"],\n\n"meta":${JSON.stringify({ ...META, version: undefined })},"data":[]}`, 3, /meta.version is missing/],
      [`{"meta":[],"columns":["t"],"data":[]}`, 1, /meta must be an object/],
      [`{"meta":${JSON.stringify(META)},\n"columns":["t"]}`, 1, /no "data" array/],
      [`{"meta":${JSON.stringify(META)},\n"columns":["t"],\n"columns":["t"],"data":[]}`, 3, /duplicate key "columns"/],
      [`{"meta":${JSON.stringify(META)},\n"columns":["t\u0001"],"data":[]}`, 2, /control character/],
      [`{"meta":${JSON.stringify(META)},\n"columns":["t\\q"],"data":[]}`, 2, /invalid escape/],
      ['', 1, /expected a JSON object "\{", found end of input/],
      ['\n\n[1,2]', 3, /expected a JSON object/],
    ];
    for (const [text, line, message] of cases) {
      const e = jsonError(text);
      expect([e.line, e.detail]).toEqual([line, expect.stringMatching(message)]);
      expect(e.message).toBe(`line ${line}: ${e.detail}`);
    }
  });

  it('jsonHead(meta, columns) refuses unusable column names', () => {
    expect(() => jsonHead(META, ['t', 't'])).toThrow(/duplicate/);
  });
});

describe('readTable(text, nameHint?)', () => {
  it('readTable(text) reads JSON when the first non-space character is "{", else CSV', () => {
    const small = tableOf(['t', 'x'], [0, -0, 1, 5e-324]);
    const json = readTable(`  \n${toJSON(small, META)}`);
    expect(json.format).toBe('json');
    expect(json.meta).toEqual(META);
    expectExact(json, small);
    const csv = readTable(toCSV(small), 'run.csv');
    expect(csv.format).toBe('csv');
    expect(csv.meta).toBeUndefined();
    expectExact(csv, small);
  });

  it('readTable(text, nameHint) puts the name and line in errors', () => {
    expect(() => readTable('t,x\n0,1\n1\n', 'run.csv')).toThrow(/^run\.csv line 3: expected 2 values/);
    expect(() => readTable('{"meta":\n}', 'run.json')).toThrow(/^run\.json line 2: unexpected "}"/);
    // a .json name gets a JSON error even when the content does not start with "{"
    expect(() => readTable('t,x\n', 'run.json')).toThrow(/^run\.json line 1: expected a JSON object/);
    expect(() => readTable('t,x\n0,zz\n')).toThrow(/^line 2: column x: "zz" is not a number/);
  });
});
