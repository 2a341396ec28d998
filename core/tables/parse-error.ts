import { InputError } from '../errors.ts';

/**
 * Bad table input (CSV or JSON). An InputError, so the CLI shows it as the
 * one-line message it is; the line is also kept separately so that a caller
 * can attribute it to a file (`traj.csv line 7: …`) without re-parsing text.
 */
export class ParseError extends InputError {
  override name = 'ParseError';
  /** 1-based line of the input where the problem was found. */
  readonly line: number;
  /** The message without any location, e.g. "expected 5 values, found 4". */
  readonly detail: string;
  /** Name of the input (usually a file name), when the caller supplied one. */
  readonly source?: string;

  constructor(detail: string, line: number, source?: string) {
    super(`${source === undefined ? '' : `${source} `}line ${line}: ${detail}`);
    this.line = line;
    this.detail = detail;
    if (source !== undefined) this.source = source;
  }

  /** The same error attributed to a named input. */
  withSource(source: string): ParseError {
    return new ParseError(this.detail, this.line, source);
  }
}
