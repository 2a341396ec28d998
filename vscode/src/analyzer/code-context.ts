/**
 * What the text before the cursor in a cell says about the cursor: inside
 * a string or comment, after a `.`, at a key of an options object passed to
 * a call (`simulator({ views: […], | })`, `new Simulation(model, { | })`,
 * nested as in `simulator({ timePlot: { | } })`), or at a place for a name.
 *
 * A small scanner rather than a parser, because the text being typed is
 * seldom valid JavaScript: it tracks brackets, strings, comments and the
 * last keys, and forgives the rest. Regular expression literals are not
 * recognised (a `/` is division), which can only cost a completion.
 */

/** The options object the cursor is in: argument `argument` of `callee`, then keys `path`. */
export interface OptionsOwner {
  readonly callee: string;
  readonly argument: number;
  readonly path: readonly string[];
}

export type CodeContext =
  | { readonly kind: 'none' }
  | { readonly kind: 'name'; readonly prefix: string }
  | { readonly kind: 'key'; readonly prefix: string; readonly owner: OptionsOwner; readonly present: readonly string[] };

interface Frame {
  readonly open: '(' | '{' | '[';
  /** For `(`: the function called, when the paren follows a name that is not a keyword. */
  readonly callee?: string;
  argument: number;
  /** For an object literal: whose options it holds. */
  readonly owner?: OptionsOwner;
  expectKey: boolean;
  lastKey?: string;
  readonly present: string[];
}

const KEYWORDS = new Set(['if', 'for', 'while', 'switch', 'catch', 'function', 'return', 'typeof', 'with', 'await', 'yield', 'new', 'in', 'of']);
const CLOSING: Record<string, Frame['open']> = { ')': '(', '}': '{', ']': '[' };

/** Scans `text` (the cell's source up to the cursor) and says where the cursor is. */
export function codeContext(text: string): CodeContext {
  const prefix = /[\w$]*$/.exec(text)?.[0] ?? '';
  const before = text.slice(0, text.length - prefix.length);
  const scan = scanBrackets(before);
  if (!scan) return { kind: 'none' };
  if (/\.\s*$/.test(before) && !/\.\.\.\s*$/.test(before)) return { kind: 'none' };
  const top = scan.at(-1);
  if (top?.open === '{' && top.owner && top.expectKey) return { kind: 'key', prefix, owner: top.owner, present: top.present };
  return { kind: 'name', prefix };
}

/**
 * The open brackets at the end of `text`, innermost last; null when the
 * text ends inside a string or a comment.
 */
function scanBrackets(text: string): Frame[] | null {
  const stack: Frame[] = [];
  let previous = '';
  let i = 0;
  while (i < text.length) {
    const c = text[i];
    if (c === '/' && text[i + 1] === '/') {
      const end = text.indexOf('\n', i);
      if (end === -1) return null;
      i = end + 1;
      continue;
    }
    if (c === '/' && text[i + 1] === '*') {
      const end = text.indexOf('*/', i + 2);
      if (end === -1) return null;
      i = end + 2;
      continue;
    }
    if (c === '"' || c === "'" || c === '`') {
      const end = stringEnd(text, i);
      if (end === -1) return null;
      const top = stack.at(-1);
      // A quoted key: `{ 'views': … }`.
      if (top?.open === '{' && top.expectKey && /^\s*:/.test(text.slice(end))) top.lastKey = text.slice(i + 1, end - 1);
      previous = 'string';
      i = end;
      continue;
    }
    const word = /^[A-Za-z_$][\w$]*/.exec(text.slice(i, i + 64))?.[0];
    if (word) {
      const top = stack.at(-1);
      if (top?.open === '{' && top.expectKey) {
        top.lastKey = word;
        top.present.push(word);
      }
      previous = word;
      i += word.length;
      continue;
    }
    if (!/\s/.test(c)) {
      punctuation(stack, c, previous);
      previous = c;
    }
    i++;
  }
  return stack;
}

/** The index just past the string that opens at `start`, or -1 when it is not closed. */
function stringEnd(text: string, start: number): number {
  const quote = text[start];
  for (let i = start + 1; i < text.length; i++) {
    if (text[i] === '\\') i++;
    else if (text[i] === quote) return i + 1;
    else if (text[i] === '\n' && quote !== '`') return -1;
  }
  return -1;
}

function punctuation(stack: Frame[], c: string, previous: string): void {
  const top = stack.at(-1);
  if (c === '(') {
    const callee = /^[A-Za-z_$]/.test(previous) && !KEYWORDS.has(previous) ? previous : undefined;
    stack.push({ open: '(', callee, argument: 0, expectKey: false, present: [] });
  } else if (c === '{') {
    stack.push({ open: '{', owner: objectOwner(top, previous), argument: 0, expectKey: true, present: [] });
  } else if (c === '[') {
    stack.push({ open: '[', argument: 0, expectKey: false, present: [] });
  } else if (c in CLOSING) {
    if (top?.open === CLOSING[c]) stack.pop();
  } else if (c === ',' && top) {
    top.argument++;
    top.expectKey = top.open === '{';
  } else if (c === ':' && top?.open === '{') {
    top.expectKey = false;
  }
}

/**
 * Whose options an object literal opening here holds: an argument of a
 * named call (`f(a, {`), or the value of a key of such an object (`timePlot: {`).
 * Any other brace (a block, `x = {`) holds no one's options.
 */
function objectOwner(top: Frame | undefined, previous: string): OptionsOwner | undefined {
  if (top?.open === '(' && top.callee && (previous === '(' || previous === ',')) {
    return { callee: top.callee, argument: top.argument, path: [] };
  }
  if (top?.open === '{' && top.owner && previous === ':' && top.lastKey) {
    return { ...top.owner, path: [...top.owner.path, top.lastKey] };
  }
  return undefined;
}
