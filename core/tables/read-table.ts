import { parseCSV } from './csv-read.ts';
import type { ExportMeta } from './export-meta.ts';
import { parseJSON } from './json-read.ts';
import { ParseError } from './parse-error.ts';
import type { Table } from './table.ts';

/** A table read from a file, with the metadata a JSON export carried. */
export interface LoadedTable extends Table {
  format: 'csv' | 'json';
  /** Present for JSON exports only; CSV has nowhere to keep it. */
  meta?: ExportMeta;
}

/**
 * Reads an export in either format, so `phasebook spectrum --input FILE`
 * need not be told which. The content decides (JSON starts with `{`), except
 * that a name ending in `.json` is read as JSON regardless, because then a
 * JSON syntax error explains the problem better than a CSV one would.
 * `nameHint` also prefixes error messages.
 */
export function readTable(text: string, nameHint?: string): LoadedTable {
  const json = /^\s*\{/.test(text) || (nameHint !== undefined && /\.json$/i.test(nameHint));
  try {
    if (json) {
      const { meta, table } = parseJSON(text);
      return { ...table, format: 'json', meta };
    }
    return { ...parseCSV(text), format: 'csv' };
  } catch (e) {
    if (e instanceof ParseError && nameHint !== undefined && e.source === undefined) throw e.withSource(nameHint);
    throw e;
  }
}
