/**
 * Whose code is calling: a cell's, or the book's. The sandbox's guarded
 * globals (setTimeout, Function, window.open, …) are the page's, called by
 * the book's widgets as much as by cells, and only a cell's call is to be
 * charged to it or refused. Each cell's code is named `cell:<id>` in stack
 * traces (cell-definition.ts), so the stack says it, in every engine that
 * gives one.
 */
import { cellOfSource } from '../cell-errors.ts';

/**
 * Frames of the sandbox itself, skipped when looking for the caller: its
 * chunk in the built book, its folder when the modules are served one by
 * one (development, tests).
 */
const OWN = ((here: string) => {
  const path = here.split(/[?#]/)[0];
  return /\.ts$/.test(path) ? path.slice(0, path.lastIndexOf('/') + 1) : path;
})(import.meta.url);

interface CallSite {
  getFileName(): string | null | undefined;
  getEvalOrigin(): string | undefined;
}

type V8Error = ErrorConstructor & { stackTraceLimit?: number; prepareStackTrace?: (error: Error, sites: CallSite[]) => unknown };

/**
 * Where each frame of the current stack comes from, innermost first: its
 * script's address (`cell:<id>` for a cell's code, empty for the browser's
 * own functions). V8 hands the frames over as objects, without formatting
 * a stack trace, which keeps this cheap enough for every setTimeout the
 * page makes; other engines' stack text is read line by line.
 */
function frames(depth: number): string[] {
  const E = Error as V8Error;
  const { stackTraceLimit: limit, prepareStackTrace: prepare } = E;
  // As many frames as asked, whatever a cell has set the limit to: each frame taken costs time.
  E.stackTraceLimit = depth;
  E.prepareStackTrace = (_, sites) => sites;
  let stack: unknown;
  try {
    stack = new Error().stack;
  } finally {
    E.stackTraceLimit = limit;
    E.prepareStackTrace = prepare;
  }
  if (Array.isArray(stack)) return (stack as CallSite[]).map((site) => site.getFileName() ?? site.getEvalOrigin() ?? '');
  return String(stack ?? '').split('\n').filter((line) => /\bat\b|@/.test(line));
}

/** A frame of the browser's own code (`Array.map`, `new Promise`), which has no address. */
function isNative(frame: string): boolean {
  return !/(https?|file|cell):/.test(frame);
}

/**
 * The id of the cell whose code called the guarded function, or null when
 * the book's own code did (or no cell's code is on the stack). Frames of the
 * sandbox and of the browser's built-ins are looked through: `[…].map(f)`
 * is `f` called by the cell that called `map`.
 */
export function callerCell(): string | null {
  // The sandbox's own frames, a built-in or two, then the caller: a dozen is plenty, and cheap.
  for (const frame of frames(12)) {
    const cell = cellOfSource(frame);
    if (cell !== null) return cell;
    if (frame.includes(OWN) || isNative(frame)) continue;
    return null;
  }
  return null;
}

/**
 * The innermost cell anywhere on the stack, or null: for what the book
 * itself never does (navigate away, open a window, write the document), a
 * cell that did it through the book's code did it all the same.
 */
export function cellOnStack(): string | null {
  // Asked rarely (a navigation, a window, a dialog), and the cell may be far out.
  for (const frame of frames(40)) {
    const cell = cellOfSource(frame);
    if (cell !== null) return cell;
  }
  return null;
}
