/**
 * Errors about a dataset file, with the file named: merge reads several and
 * reproduce one, and a message that does not say which (a corrupt Parquet
 * file once said only "internal error: thrift unhandled type: 15") leaves
 * the user to guess.
 */
import { BlowUpError, InputError, ParseError } from '../../core/index.ts';
import { Interrupted } from '../interrupt.ts';
import { OutputError } from '../output/output-error.ts';

/**
 * `error` with `path` named at its start, unless it names it already (a
 * reader's ParseError as `path line N: …`).
 * `reading` says that it came from reading the file, where anything but an
 * InputError is the file's damage (a parser tripping over bytes it does not
 * expect), said as such; otherwise such an error stays internal, a bug, with
 * the file named. A signal's stop and an output error (which names its own
 * file) pass as they are.
 */
export function namingFile(error: unknown, path: string, reading: boolean): Error {
  if (error instanceof Interrupted || error instanceof OutputError) return error;
  // A reader's error names the line; the file goes before it, as everywhere: "data.json line 5: …".
  if (error instanceof ParseError && error.source === undefined) return error.withSource(path);
  const message = String((error as Error)?.message ?? error).split('\n')[0];
  if (error instanceof InputError || error instanceof BlowUpError) return message.includes(path) ? (error as Error) : new InputError(`${path}: ${message}`);
  if (reading) return new InputError(`${path} is damaged, or not a dataset phasebook wrote: ${message}`);
  return new Error(`${path}: ${message}`);
}
