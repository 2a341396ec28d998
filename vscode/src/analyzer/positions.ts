/**
 * Offsets ↔ line and character (both from 0, as VS Code counts them) in a
 * text that is not open in an editor, such as a chapter read from disk for
 * the workspace's diagnostics.
 */
export interface LineCharacter {
  readonly line: number;
  readonly character: number;
}

export class LineIndex {
  /** Offset at which each line starts. */
  readonly #starts: number[] = [0];
  readonly #length: number;

  constructor(text: string) {
    for (let i = 0; i < text.length; i++) if (text.charCodeAt(i) === 10) this.#starts.push(i + 1);
    this.#length = text.length;
  }

  get lineCount(): number {
    return this.#starts.length;
  }

  position(offset: number): LineCharacter {
    const at = Math.max(0, Math.min(offset, this.#length));
    let low = 0;
    let high = this.#starts.length - 1;
    while (low < high) {
      const middle = (low + high + 1) >> 1;
      if (this.#starts[middle] <= at) low = middle;
      else high = middle - 1;
    }
    return { line: low, character: at - this.#starts[low] };
  }

  /** The offset of a line and character, clamped to the text (a character past the line's end stays on it). */
  offset(line: number, character: number): number {
    if (line < 0) return 0;
    if (line >= this.#starts.length) return this.#length;
    const end = line + 1 < this.#starts.length ? this.#starts[line + 1] - 1 : this.#length;
    return Math.min(this.#starts[line] + Math.max(0, character), end);
  }

  /** The offset just past the end of `line`'s text (before its newline). */
  lineEnd(line: number): number {
    return this.offset(line, Number.MAX_SAFE_INTEGER);
  }
}
