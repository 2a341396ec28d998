/**
 * The records of CSV text as RFC 4180 defines them: fields separated by
 * commas, records by CRLF or LF, and a field in double quotes may hold
 * commas, line breaks and doubled quotes (`""` for one). Spreadsheets and
 * pandas quote a header (`"q","p"`) as readily as not, and an initial file
 * written so is as good as any.
 *
 * A quote inside an unquoted field, or text after a closing quote, is
 * refused rather than guessed at; spaces around a quoted field are padding.
 */
import { InputError } from '../core/index.ts';

/** The records of `text`, each its fields unquoted; `what` names the file in messages. A last empty line ends the text, as usual. */
export function csvRecords(text: string, what: string): string[][] {
  const records: string[][] = [];
  let record: string[] = [];
  let field = '';
  let line = 1;
  let i = 0;
  const endField = () => {
    record.push(field);
    field = '';
  };
  const endRecord = () => {
    endField();
    records.push(record);
    record = [];
    line++;
  };
  while (i < text.length) {
    const c = text[i];
    if (c === '"') {
      // Spaces before a quoted field (`q, "p"`) are taken as padding, as they are around unquoted ones.
      if (field.trim() !== '') throw new InputError(`${what}: line ${line} has a quote inside a field; a field with quotes must be quoted whole ("a ""b""")`);
      field = '';
      const start = line;
      i++;
      for (;;) {
        if (i >= text.length) throw new InputError(`${what}: the quoted field that starts on line ${start} is never closed`);
        if (text[i] === '"') {
          if (text[i + 1] === '"') {
            field += '"';
            i += 2;
            continue;
          }
          i++;
          break;
        }
        if (text[i] === '\n') line++;
        field += text[i++];
      }
      while (text[i] === ' ' || text[i] === '\t') i++;
      const next = text[i];
      if (next !== undefined && next !== ',' && next !== '\n' && !(next === '\r' && text[i + 1] === '\n')) {
        throw new InputError(`${what}: line ${line} has text after a closing quote`);
      }
      continue;
    }
    if (c === ',') endField();
    else if (c === '\n') endRecord();
    else if (c === '\r' && text[i + 1] === '\n') {
      endRecord();
      i++;
    } else field += c;
    i++;
  }
  // A last record without its line break; an empty last line adds none.
  if (field !== '' || record.length > 0) endRecord();
  return records;
}
