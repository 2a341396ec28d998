/**
 * Build-time JavaScript highlighting for cell sources.
 *
 * It uses the same Lezer grammar and the same `tok-*` class names as the
 * lazily loaded CodeMirror editor (cells/editor.ts), so nothing
 * changes colour when the static code is swapped for the editor, and the
 * no-JavaScript reader still gets highlighted code. Like the editor, it reads
 * `name = { … }` as a block (cells/block-syntax.ts).
 */
import { classHighlighter, highlightCode } from '@lezer/highlight';
import { parser } from '@lezer/javascript';
import { asParsableBlock } from '../../cells/index.ts';

/**
 * @param {string} source
 * @returns {Array<import('hast').ElementContent>} hast text and `span.tok-*` nodes
 */
export function highlightJs(source) {
  /** @type {Array<import('hast').ElementContent>} */
  const nodes = [];
  highlightCode(
    source,
    parser.parse(asParsableBlock(source)),
    classHighlighter,
    (text, classes) => {
      const value = { type: 'text', value: text };
      nodes.push(
        classes
          ? { type: 'element', tagName: 'span', properties: { className: classes.split(' ') }, children: [/** @type {import('hast').Text} */ (value)] }
          : /** @type {import('hast').Text} */ (value),
      );
    },
    () => nodes.push({ type: 'text', value: '\n' }),
  );
  return nodes;
}
