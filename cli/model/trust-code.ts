/**
 * Whether `phasebook reproduce` may run the JavaScript a file's meta
 * carries. A file is data from whoever made it: an expression H is compiled
 * from its parsed tree, and a JS function that translates to an expression
 * becomes generated code, so neither runs any of the file's code. An H the
 * translator cannot take, or a vector field, is the author's code itself,
 * which runs (in the sandbox) only when the user says they trust its author
 * with --trust-code; otherwise the refusal shows the code, so that they can
 * judge it.
 */
import { InputError } from '../../core/index.ts';
import { userCodeOf, type ModelRecipe } from './model.ts';
import { printable } from '../sandbox/sandbox-messages.ts';

/** How much of the code a refusal shows. */
const SHOWN_CHARS = 160;

/** The code on one line, whitespace runs as one space, control characters gone, cut at SHOWN_CHARS. */
export function excerpt(source: string): string {
  const line = printable(source.replace(/\s+/g, ' '), Infinity);
  return line.length > SHOWN_CHARS ? `${line.slice(0, SHOWN_CHARS)}… (${line.length} characters)` : line;
}

/** Refuses, in one line naming `path`, a recipe that would run the file's code, unless `trusted`. */
export function admitFileCode(recipe: ModelRecipe, path: string, trusted: boolean): void {
  const user = userCodeOf(recipe);
  if (!user || trusted) return;
  const why = user.what === 'H' ? 'its H is JavaScript that does not translate to an expression' : 'its vector field is JavaScript';
  throw new InputError(`${path}: ${why}, so reproducing it would run its author's code: ${excerpt(user.source)} — pass --trust-code if you trust its author`);
}
