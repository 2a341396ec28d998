/**
 * What the analyzer reports: a problem at a range of offsets in the file,
 * with a stable code (for tests and quick fixes) and, for a duplicate, the
 * places of the other occurrences.
 */
export type Severity = 'error' | 'warning';

export type ProblemCode =
  | 'mdx-syntax'
  | 'cell-syntax'
  | 'unnamed-cell'
  | 'duplicate-name'
  | 'unknown-name'
  | 'front-matter'
  | 'duplicate-order';

export interface Related {
  /** A key of the file (a URI string) when the place is in another file; absent for this file. */
  readonly file?: string;
  readonly start: number;
  readonly end: number;
  readonly message: string;
}

export interface Problem {
  readonly code: ProblemCode;
  readonly severity: Severity;
  readonly message: string;
  readonly start: number;
  readonly end: number;
  readonly related?: readonly Related[];
}
