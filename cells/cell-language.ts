/**
 * JavaScript for the cell editor, parsed the way block-syntax.ts describes so
 * `name = { … }` highlights as a block, exactly as the build highlighted it.
 * Part of the lazily loaded `editor` chunk.
 */
import { Language, LanguageSupport } from '@codemirror/language';
import { javascriptLanguage } from '@codemirror/lang-javascript';
import { Parser, type Input, type PartialParse, type TreeFragment } from '@lezer/common';
import { BLOCK_HEADER_WINDOW, blockAssignmentAt } from './block-syntax.ts';

/** The document with one character replaced; same length, so positions map one to one. */
class PatchedInput implements Input {
  readonly #inner: Input;
  readonly #at: number;
  readonly #char: string;

  constructor(inner: Input, at: number, char: string) {
    this.#inner = inner;
    this.#at = at;
    this.#char = char;
  }

  get length(): number {
    return this.#inner.length;
  }

  get lineChunks(): boolean {
    return this.#inner.lineChunks;
  }

  #patch(text: string, from: number): string {
    const i = this.#at - from;
    return i >= 0 && i < text.length ? text.slice(0, i) + this.#char + text.slice(i + 1) : text;
  }

  chunk(from: number): string {
    return this.#patch(this.#inner.chunk(from), from);
  }

  read(from: number, to: number): string {
    return this.#patch(this.#inner.read(from, to), from);
  }
}

class CellParser extends Parser {
  readonly #inner: Parser;

  constructor(inner: Parser) {
    super();
    this.#inner = inner;
  }

  /**
   * Cells are a few lines long, so every parse starts afresh: reusing old
   * fragments could keep a tree built before the `=` was (or stopped being)
   * patched.
   */
  createParse(input: Input, _fragments: readonly TreeFragment[], ranges: readonly { from: number; to: number }[]): PartialParse {
    const at = blockAssignmentAt(input.read(0, Math.min(input.length, BLOCK_HEADER_WINDOW)));
    return this.#inner.startParse(at < 0 ? input : new PatchedInput(input, at, ';'), [], ranges);
  }
}

const cellLanguage = new Language(javascriptLanguage.data, new CellParser(javascriptLanguage.parser), [], 'observable-javascript');

export function cellJavascript(): LanguageSupport {
  return new LanguageSupport(cellLanguage);
}
