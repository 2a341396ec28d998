/**
 * The one CSV reader (csv-read.ts: RFC 4180 records, one number grammar)
 * and the one reader of the book's JSON export (json-read.ts), whole or in
 * pieces; round trips of every double are in export.test.ts.
 */
import { describe, expect, it } from 'vitest';
import { csvNumber, csvRecords, JsonExportReader, parseCSV, parseJSON, roundTripNumber, toJSON, type ExportMeta } from '../../../../core/index.ts';
import { ParseError } from '../../../../core/tables/parse-error.ts';

const records = (text: string) => Array.from(csvRecords(text));

describe('csvRecords(text): RFC 4180', () => {
  it('unquotes fields with commas, line breaks and doubled quotes, and knows the line each record starts on', () => {
    expect(records('"a,b","say ""hi""",c\n1,"two\nlines",3\n4,5,6')).toEqual([
      { fields: ['a,b', 'say "hi"', 'c'], line: 1 },
      { fields: ['1', 'two\nlines', '3'], line: 2 },
      { fields: ['4', '5', '6'], line: 4 },
    ]);
  });

  it('takes CRLF and LF, a byte-order mark, spaces around a quoted field, and drops blank lines at the end only', () => {
    expect(records('\ufeff"q", "p" \r\n1,2\r\n\r\n3,4\r\n\r\n  \n')).toEqual([
      { fields: ['q', 'p'], line: 1 },
      { fields: ['1', '2'], line: 2 },
      { fields: [''], line: 3 },
      { fields: ['3', '4'], line: 4 },
    ]);
    expect(records('')).toEqual([]);
    expect(records('\n\n')).toEqual([]);
    // A quoted empty field was written on purpose: not a blank line.
    expect(records('a\n""\n')).toEqual([{ fields: ['a'], line: 1 }, { fields: [''], line: 2 }]);
  });

  it.each([
    ['"q,p\n1,2\n', 1, 'a quoted field opens here and is never closed'],
    ['q,p\n1,"2\n\n', 2, 'a quoted field opens here and is never closed'],
    ['q"x",p\n', 1, 'a quote inside a field'],
    ['q,p\n"1\n2"x,3\n', 3, 'text after a closing quote'],
  ])('refuses bad quoting in %j, naming line %i', (text, line, message) => {
    let error: unknown;
    try {
      records(text);
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(ParseError);
    expect((error as ParseError).line).toBe(line);
    expect((error as ParseError).detail).toContain(message);
  });
});

describe('csvNumber(field): the one number grammar', () => {
  it.each([
    ['0', 0], ['-0', -0], ['+1', 1], ['1.', 1], ['.5', 0.5], ['-.5e-3', -0.0005], ['1e+21', 1e21], ['5e-324', 5e-324],
    ['1.7976931348623157e+308', Number.MAX_VALUE], ['1.0000000000000000e-03', 0.001], ['0.30000000000000004', 0.1 + 0.2],
    ['1E5', 1e5], ['007', 7], ['1e400', Infinity],
    ['NaN', NaN], ['nan', NaN], ['-nan', NaN], ['NAN', NaN],
    ['Infinity', Infinity], ['-Infinity', -Infinity], ['inf', Infinity], ['-inf', -Infinity], ['+INF', Infinity], ['infinity', Infinity],
  ])('reads %j as %d', (field, value) => {
    expect(Object.is(csvNumber(field), value)).toBe(true);
  });

  it.each(['', ' ', '0x10', '0b1', '1_000', '1,5', '1.2.3', '1e', 'e5', '.', '-', '+-1', 'NA', 'nan1', 'infinit', 'Infinity1', '١'])('refuses %j', (field) => {
    expect(csvNumber(field)).toBeUndefined();
  });

  it('reads back what roundTripNumber writes, for every kind of double', () => {
    const view = new DataView(new ArrayBuffer(8));
    let seed = 7;
    for (let i = 0; i < 20_000; i++) {
      seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
      view.setUint32(0, seed);
      view.setUint32(4, Math.imul(seed, 2654435761) >>> 0);
      const x = view.getFloat64(0);
      const back = csvNumber(roundTripNumber(x));
      if (!Object.is(back, x) && !(Number.isNaN(x) && Number.isNaN(back))) throw new Error(`${x} read back as ${back}`);
    }
  });
});

describe('parseCSV(text), on the records', () => {
  it('reads a quoted header and quoted numbers as pandas writes them with QUOTE_ALL, and a multi-line field names the right line', () => {
    const table = parseCSV('"t","q"\n"0","1.5"\n"1","-2"\n');
    expect(table.columns).toEqual(['t', 'q']);
    expect(Array.from(table.data)).toEqual([0, 1.5, 1, -2]);
    expect(() => parseCSV('"t","q\nr"\n0,1\n1,zz\n')).toThrow(/^line 4: column q\nr: "zz" is not a number$/);
  });
});

const META: ExportMeta = { hamiltonian: 'p^2/2', params: {}, dof: 1, dt: 0.5, method: 'rk38', every: 1, t0: 0, initial: [1, 0], version: '0.1.0' };

describe('JsonExportReader: the export read a row at a time, whole or in pieces', () => {
  const rows = Array.from({ length: 3000 }, (_, i) => [i * 0.5, Math.sin(i) * 1e-300, i % 7 === 0 ? NaN : -Math.cos(i)]);
  const table = { columns: ['t', 'q', 'p'], rows: rows.length, data: Float64Array.from(rows.flat()) };
  const text = toJSON(table, META);

  /** The text in pieces of `size` characters, as a file is read. */
  function pieces(size: number): () => string | undefined {
    let at = 0;
    return () => {
      if (at >= text.length) return undefined;
      const piece = text.slice(at, at + size);
      at += size;
      return piece;
    };
  }

  it.each([1, 2, 3, 7, 64, 4096, 1 << 20])('gives every row, exactly, from pieces of %i characters', (size) => {
    const reader = new JsonExportReader('', pieces(size)).head();
    expect(reader.meta?.value).toEqual(META);
    expect(reader.columns?.value).toEqual(['t', 'q', 'p']);
    const row: number[] = [];
    let r = 0;
    while (reader.row(row)) {
      for (let c = 0; c < 3; c++) if (!Object.is(row[c], rows[r][c])) throw new Error(`row ${r}, column ${c}: ${row[c]} for ${rows[r][c]}`);
      r++;
    }
    expect(r).toBe(rows.length);
  });

  it('names the line of a bad row far into a file read in pieces', () => {
    const lines = text.split('\n');
    // Line 4 holds row 0: line 2504 is row 2500.
    lines[2503] = '[1250,2,"three"],';
    const bad = lines.join('\n');
    let at = 0;
    const reader = new JsonExportReader('', () => (at < bad.length ? bad.slice(at, (at += 1000)) : undefined)).head();
    const row: number[] = [];
    expect(() => {
      while (reader.row(row));
    }).toThrow(/^line 2504: "three" is not a number$/);
  });

  it('reads what parseJSON reads: the same meta, columns and numbers', () => {
    const { meta, table: read } = parseJSON(text);
    expect(meta).toEqual(META);
    expect(read.columns).toEqual(table.columns);
    expect(read.data.length).toBe(table.data.length);
    expect(read.data.every((v, i) => Object.is(v, table.data[i]))).toBe(true);
  });
});
