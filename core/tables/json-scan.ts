import { ParseError } from './parse-error.ts';

/**
 * A JSON reader that knows where it is. `JSON.parse` in Node 20 reports
 * errors without a position, and cannot say which line a structurally wrong
 * row sits on, so the table reader walks the text itself with this cursor and
 * reads the (possibly huge) data array without building nested JS arrays.
 * Numbers go through `Number()` on the exact token, which rounds identically
 * to `JSON.parse`.
 *
 * The text may come in pieces (`more`), so that a file of any size reads in
 * flat memory: the cursor asks for the next piece when it reaches the end of
 * what it has, and forgets what lies before the point its reader last
 * released (`release`), keeping count of the lines it forgot.
 */

/** A JSON value as produced by JSON.parse. */
export type JsonValue = null | boolean | number | string | JsonValue[] | { [key: string]: JsonValue };

const MAX_DEPTH = 256;
/** Characters read past before release() forgets them. */
const RELEASE_AFTER = 1 << 16;
const NUMBER = /-?(?:0|[1-9]\d*)(?:\.\d+)?(?:[eE][+-]?\d+)?/y;
const LITERALS: ReadonlyArray<[string, JsonValue]> = [['true', true], ['false', false], ['null', null]];
const ESCAPES: Readonly<Record<string, string>> = { '"': '"', '\\': '\\', '/': '/', b: '\b', f: '\f', n: '\n', r: '\r', t: '\t' };

export class JsonCursor {
  /** where the cursor is in `text` */
  pos = 0;
  /** the text read and not yet released */
  text: string;
  /** lines wholly before `text`, released */
  private linesBefore = 0;

  /**
   * @param text the whole text, or its first piece
   * @param more the next piece, or undefined at the end; absent when `text` is all
   */
  constructor(
    text: string,
    private more?: () => string | undefined,
  ) {
    this.text = text;
  }

  /** Appends the next piece; false at the end of the input. */
  private refill(): boolean {
    const piece = this.more?.();
    if (piece === undefined) {
      this.more = undefined;
      return false;
    }
    this.text += piece;
    return true;
  }

  /** Makes at least `n` characters from `pos` present, unless the input ends first. */
  private ensure(n: number): void {
    while (this.text.length - this.pos < n && this.refill());
  }

  /**
   * Lets the cursor forget the text before it, once that is long enough to
   * be worth the copy: positions saved before this are no longer valid.
   */
  release(): void {
    if (this.pos < RELEASE_AFTER) return;
    const gone = this.text.slice(0, this.pos);
    for (let i = gone.indexOf('\n'); i !== -1; i = gone.indexOf('\n', i + 1)) this.linesBefore++;
    this.text = this.text.slice(this.pos);
    this.pos = 0;
  }

  /** 1-based line of a position (default: the current one); computed only when needed. */
  lineAt(pos = this.pos): number {
    let line = 1 + this.linesBefore;
    for (let i = this.text.indexOf('\n'); i !== -1 && i < pos; i = this.text.indexOf('\n', i + 1)) line++;
    return line;
  }

  /** Throws a ParseError; at the end of input it names the last line with content, where the cut is. */
  fail(detail: string, pos = this.pos): never {
    if (pos >= this.text.length) pos = Math.max(0, this.text.trimEnd().length - 1);
    throw new ParseError(detail, this.lineAt(pos));
  }

  /** Skips whitespace and returns the next character ('' at the end). */
  peek(): string {
    for (;;) {
      const s = this.text;
      let c = s.charCodeAt(this.pos);
      while (c === 0x20 || c === 0x0a || c === 0x0d || c === 0x09) c = s.charCodeAt(++this.pos);
      if (this.pos < s.length) return s[this.pos];
      if (!this.refill()) return '';
    }
  }

  /** Consumes `ch` (after whitespace) or fails saying what was expected. */
  expect(ch: string, what = `"${ch}"`): void {
    const got = this.peek();
    if (got !== ch) this.fail(`expected ${what}, found ${got === '' ? 'end of input' : `"${got}"`}`);
    this.pos++;
  }

  /** Consumes `ch` if it is next; for the separators of arrays and objects. */
  accept(ch: string): boolean {
    if (this.peek() !== ch) return false;
    this.pos++;
    return true;
  }

  /** Consumes `word` if it is next (after whitespace). */
  acceptWord(word: string): boolean {
    this.peek();
    this.ensure(word.length);
    if (!this.text.startsWith(word, this.pos)) return false;
    this.pos += word.length;
    return true;
  }

  number(): number {
    this.peek();
    for (;;) {
      NUMBER.lastIndex = this.pos;
      const m = NUMBER.exec(this.text);
      const end = this.pos + (m === null ? 0 : m[0].length);
      // A token near the end of the text read so far may go on in the next piece ("1." then "5", "1e" then "-9").
      if (this.text.length - end < 3 && this.refill()) continue;
      if (m === null) this.fail('expected a number');
      this.pos = end;
      return Number(m[0]);
    }
  }

  string(): string {
    this.expect('"', 'a string');
    let out = '';
    let run = this.pos;
    for (;;) {
      const s = this.text;
      const c = s.charCodeAt(this.pos);
      if (c === 0x22) break;
      if (Number.isNaN(c)) {
        out += s.slice(run, this.pos);
        if (!this.refill()) this.fail('unterminated string');
        run = this.pos;
        continue;
      }
      if (c < 0x20) this.fail('control character in string');
      if (c === 0x5c) {
        out += s.slice(run, this.pos);
        this.ensure(6);
        const t = this.text;
        const e = t[this.pos + 1];
        if (e === 'u' && /^[0-9a-fA-F]{4}$/.test(t.slice(this.pos + 2, this.pos + 6))) {
          out += String.fromCharCode(parseInt(t.slice(this.pos + 2, this.pos + 6), 16));
          this.pos += 6;
        } else if (e !== undefined && Object.hasOwn(ESCAPES, e)) {
          out += ESCAPES[e];
          this.pos += 2;
        } else this.fail('invalid escape in string');
        run = this.pos;
      } else this.pos++;
    }
    out += this.text.slice(run, this.pos++);
    return out;
  }

  /** Any JSON value, as JSON.parse would return it. */
  value(depth = 0): JsonValue {
    if (depth > MAX_DEPTH) this.fail(`nesting deeper than ${MAX_DEPTH}`);
    const c = this.peek();
    if (c === '"') return this.string();
    if (c === '[') {
      this.pos++;
      const out: JsonValue[] = [];
      if (this.accept(']')) return out;
      do out.push(this.value(depth + 1));
      while (this.accept(','));
      this.expect(']', '"," or "]"');
      return out;
    }
    if (c === '{') {
      this.pos++;
      const out: { [key: string]: JsonValue } = {};
      if (this.accept('}')) return out;
      do {
        const key = this.string();
        this.expect(':');
        // defineProperty, so that a "__proto__" key stays data as in JSON.parse
        Object.defineProperty(out, key, { value: this.value(depth + 1), enumerable: true, writable: true, configurable: true });
      } while (this.accept(','));
      this.expect('}', '"," or "}"');
      return out;
    }
    for (const [word, v] of LITERALS) if (this.acceptWord(word)) return v;
    if (c === '-' || (c >= '0' && c <= '9')) return this.number();
    return this.fail(c === '' ? 'unexpected end of input' : `unexpected "${c}"`);
  }

  /** Fails unless only whitespace remains. */
  end(): void {
    if (this.peek() !== '') this.fail(`unexpected "${this.text[this.pos]}" after the end of the JSON value`);
  }
}

/** The value of a whole JSON text, as JSON.parse gives it, or a ParseError that names the line. */
export function parseJsonValue(text: string): JsonValue {
  const cur = new JsonCursor(text);
  if (cur.peek() === '\ufeff') cur.pos++; // byte-order mark
  const value = cur.value();
  cur.end();
  return value;
}
