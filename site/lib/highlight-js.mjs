/**
 * Build-time JavaScript highlighting for cell sources.
 *
 * It uses the same Lezer grammar and the same `tok-*` class names as the
 * lazily loaded CodeMirror editor (cells/editor.ts), so nothing
 * changes colour when the static code is swapped for the editor. Like the
 * editor, it reads `name = { … }` as a block (cells/block-syntax.ts).
 *
 * Code in a chapter's first view comes as spans (`highlightJs`), so it is
 * coloured on the first paint, with or without JavaScript; code further
 * down comes as plain text with its runs as data (`tokenRuns`), which the
 * page turns into the same spans as it comes near (cells/code-tokens.ts).
 */
import { classHighlighter, highlightCode } from '@lezer/highlight';
import { parser } from '@lezer/javascript';
import { asParsableBlock } from '../../cells/index.ts';

/**
 * The source cut into runs of text, each with its `tok-*` classes ('' for none); a line break is a run of its own.
 * @param {string} source
 * @returns {Array<{ text: string, classes: string }>}
 */
function runsOf(source) {
  /** @type {Array<{ text: string, classes: string }>} */
  const runs = [];
  highlightCode(
    source,
    parser.parse(asParsableBlock(source)),
    classHighlighter,
    (text, classes) => runs.push({ text, classes }),
    () => runs.push({ text: '\n', classes: '' }),
  );
  return runs;
}

/**
 * @param {string} source
 * @returns {Array<import('hast').ElementContent>} hast text and `span.tok-*` nodes
 */
export function highlightJs(source) {
  return runsOf(source).map(({ text, classes }) => {
    /** @type {import('hast').Text} */
    const value = { type: 'text', value: text };
    return classes ? { type: 'element', tagName: 'span', properties: { className: classes.split(' ') }, children: [value] } : value;
  });
}

/**
 * The runs of `source` as cells/code-tokens.ts reads them from `data-tokens`:
 * space-separated lengths (UTF-16 units, as the page counts), a token's
 * followed by its classes, each after a `.`; neighbouring plain runs are one.
 * @param {string} source
 */
export function tokenRuns(source) {
  /** @type {string[]} */
  const out = [];
  let plain = 0;
  for (const { text, classes } of runsOf(source)) {
    if (!classes) {
      plain += text.length;
      continue;
    }
    if (plain) out.push(String(plain));
    plain = 0;
    out.push([text.length, ...classes.split(' ')].join('.'));
  }
  if (plain) out.push(String(plain));
  return out.join(' ');
}
