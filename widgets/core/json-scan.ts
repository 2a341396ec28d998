import { ParseError } from './parse-error.ts';

/**
 * A JSON reader that knows where it is. `JSON.parse` in Node 20 reports
 * errors without a position, and cannot say which line a structurally wrong
 * row sits on, so the table reader walks the text itself with this cursor and
 * reads the (possibly huge) data array without building nested JS arrays.
 * Numbers go through `Number()` on the exact token, which rounds identically
 * to `JSON.parse`.
 */

/** A JSON value as produced by JSON.parse. */
export type JsonValue = null | boolean | number | string | JsonValue[] | { [key: string]: JsonValue };

const MAX_DEPTH = 256;
const NUMBER = /-?(?:0|[1-9]\d*)(?:\.\d+)?(?:[eE][+-]?\d+)?/y;
const LITERALS: ReadonlyArray<[string, JsonValue]> = [['true', true], ['false', false], ['null', null]];
const ESCAPES: Readonly<Record<string, string>> = { '"': '"', '\\': '\\', '/': '/', b: '\b', f: '\f', n: '\n', r: '\r', t: '\t' };

export class JsonCursor {
  pos = 0;
  constructor(readonly text: string) {}

  /** 1-based line of a position (default: the current one); computed only when needed. */
  lineAt(pos = this.pos): number {
    let line = 1;
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
    const s = this.text;
    let c = s.charCodeAt(this.pos);
    while (c === 0x20 || c === 0x0a || c === 0x0d || c === 0x09) c = s.charCodeAt(++this.pos);
    return this.pos < s.length ? s[this.pos] : '';
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

  number(): number {
    this.peek();
    NUMBER.lastIndex = this.pos;
    const m = NUMBER.exec(this.text);
    if (m === null) this.fail('expected a number');
    this.pos += m[0].length;
    return Number(m[0]);
  }

  string(): string {
    this.expect('"', 'a string');
    const s = this.text;
    let out = '';
    let run = this.pos;
    for (;;) {
      const c = s.charCodeAt(this.pos);
      if (c === 0x22) break;
      if (Number.isNaN(c)) this.fail('unterminated string');
      if (c < 0x20) this.fail('control character in string');
      if (c === 0x5c) {
        out += s.slice(run, this.pos);
        const e = s[this.pos + 1];
        if (e === 'u' && /^[0-9a-fA-F]{4}$/.test(s.slice(this.pos + 2, this.pos + 6))) {
          out += String.fromCharCode(parseInt(s.slice(this.pos + 2, this.pos + 6), 16));
          this.pos += 6;
        } else if (e !== undefined && Object.hasOwn(ESCAPES, e)) {
          out += ESCAPES[e];
          this.pos += 2;
        } else this.fail('invalid escape in string');
        run = this.pos;
      } else this.pos++;
    }
    out += s.slice(run, this.pos++);
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
    for (const [word, v] of LITERALS) {
      if (this.text.startsWith(word, this.pos)) {
        this.pos += word.length;
        return v;
      }
    }
    if (c === '-' || (c >= '0' && c <= '9')) return this.number();
    return this.fail(c === '' ? 'unexpected end of input' : `unexpected "${c}"`);
  }

  /** Fails unless only whitespace remains. */
  end(): void {
    if (this.peek() !== '') this.fail(`unexpected "${this.text[this.pos]}" after the end of the JSON value`);
  }
}
