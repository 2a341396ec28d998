/**
 * The reserved names as the teachers' page lists them (site/components/ReservedNames.astro):
 * read from the core's own list, the one checkName refuses, so the page
 * cannot fall behind the code. Names that mean the same are one row.
 */
import { RESERVED_NAMES } from '../../core/index.ts';

export interface ReservedNameRow {
  readonly meaning: string;
  readonly names: readonly string[];
}

export function reservedNameRows(): ReservedNameRow[] {
  const rows = new Map<string, string[]>();
  for (const { name, meaning } of RESERVED_NAMES) rows.set(meaning, [...(rows.get(meaning) ?? []), name]);
  return [...rows].map(([meaning, names]) => ({ meaning, names }));
}
