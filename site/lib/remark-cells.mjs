/**
 * remark plugin: a fenced block marked ```` ```js cell ```` becomes a live cell.
 *
 * The cell is parsed HERE, at build time, and the parse result travels with
 * the page as `data-cell-spec`, so the first page load ships neither the
 * Observable parser nor the editor (see cells/boot.ts for the client
 * half). A cell the parser rejects still renders, with its error, and the
 * build reports it (see below).
 *
 * Emitted markup (the contract the client and the e2e tests rely on):
 *
 *   <figure class="cell" id="cell-<id>" data-cell="<id>" data-cell-name="<name>" [data-print-code]
 *           data-cell-hash="<sha256 of the source, 12 hex>" data-cell-spec="<CellSpec JSON>">
 *     <div class="cell-box">
 *       <div class="cell-editor"><pre class="cell-code"><code>…highlighted source…</code></pre></div>
 *       <div class="cell-toolbar">… [data-cell-add] [data-cell-reset] [data-cell-run]</div>
 *     </div>
 *     <div data-cell-notice hidden></div>
 *     <div data-cell-error hidden></div>
 *     <div data-cell-output></div>
 *     <noscript>…</noscript>
 *   </figure>
 *
 * The id is the cell's name, or `cell-N` for the N-th cell of the chapter when
 * it has no name: it survives edits to the source, so a reader's saved edit
 * can still be found (and offered) after the author changes the cell.
 *
 * A cell that fails at build time, a syntax error and a cell without a name
 * fail the build (cell-failures.ts, fail-loudly.mjs), unless the fence says
 * the failure is the lesson: ```` ```js cell fails ````.
 */
import { createHash } from 'node:crypto';
import { parseCell } from '@observablehq/parser';
import { fromHtmlIsomorphic } from 'hast-util-from-html-isomorphic';
import { describeCell, formatError } from '../../cells/index.ts';
import { highlightJs, tokenRuns } from './highlight-js.mjs';
import { precompileChapter } from './precompile.ts';
import { chapterProblems, reportChapter, FAILS_MARK } from './cell-failures.ts';
import { PAGE_DATA_ATTRIBUTE, WIDGET_NAMES } from '../../widgets/index.ts';

/** hast's name for the data attribute (`data-phasebook-page-data` → dataPhasebookPageData). */
const PAGE_DATA_PROPERTY = PAGE_DATA_ATTRIBUTE.replace(/-(\w)/g, (_, c) => c.toUpperCase());

/** The `language-*` class of cell code, which Shiki must leave alone. */
export const CELL_CODE_LANGUAGE = 'js-cell';

/**
 * The longest named cell whose code a printout shows (site/styles/print.css): a definition of the lesson's
 * inputs (H, parameters, the initial state) is a few lines; longer code computes something the printout shows.
 */
export const PRINTED_CODE_LINES = 8;

/**
 * The blocks of a chapter that are always laid out (the first sixteen, site/styles/global.css): a cell
 * among them has its code coloured in the HTML; a later one is coloured by the page as it comes near.
 */
const FIRST_VIEW_BLOCKS = 16;

/** @param {import('mdast').Code} node */
function isCellFence(node) {
  return node.lang === 'js' && typeof node.meta === 'string' && node.meta.split(/\s+/).includes('cell');
}

/**
 * @param {string} tagName
 * @param {import('hast').Properties} properties
 * @param {Array<import('hast').ElementContent>} [children]
 * @returns {import('hast').Element}
 */
function h(tagName, properties, children = []) {
  return { type: 'element', tagName, properties, children };
}

/** @param {string} value @returns {import('hast').Text} */
function text(value) {
  return { type: 'text', value };
}

/** @param {string} source */
export function hashSource(source) {
  return createHash('sha256').update(source).digest('hex').slice(0, 12);
}

/**
 * Parses one cell; a syntax error becomes part of the page (and of the build's report).
 * @param {string} source
 * @returns {{ spec: import('../../cells/spec.ts').CellSpec } | { error: string }}
 */
export function analyzeCell(source) {
  try {
    return { spec: describeCell(parseCell(source)) };
  } catch (error) {
    return { error: formatError(error) };
  }
}

/** The lines a cell's code shows: a final newline starts no line of its own in a <pre>. */
export function lineCount(source) {
  return source.replace(/\n$/, '').split('\n').length;
}

/**
 * @param {string} source
 * @param {string} id
 * @param {ReturnType<typeof analyzeCell>} analysis
 * @param {string} [output] HTML of the cell's value when the build could compute it (a typeset formula)
 * @param {{ colourLater?: boolean }} [options] `colourLater`: plain code with its runs as data (cells/code-tokens.ts),
 *   for a cell far from the chapter's first view
 * @returns {import('hast').Element}
 */
export function renderCell(source, id, analysis, output, { colourLater = false } = {}) {
  const name = 'spec' in analysis ? analysis.spec.name : null;
  const label = name ? `Code cell ${name}` : 'Code cell';
  /** @type {import('hast').Properties} */
  // The element id makes a cell linkable (`/kepler/#cell-stars`); the prefix keeps it apart from headings' ids.
  const properties = { className: ['cell'], id: `cell-${id}`, dataCell: id, dataCellHash: hashSource(source) };
  if (name) properties.dataCellName = name;
  if (name && lineCount(source) <= PRINTED_CODE_LINES) properties.dataPrintCode = '';
  if ('spec' in analysis) properties.dataCellSpec = JSON.stringify(analysis.spec);
  else properties.dataCellBuildError = analysis.error;

  return h('figure', properties, [
    h('div', { className: ['cell-box'] }, [
      h('div', { className: ['cell-editor'] }, [
        // Its number of lines keeps its place while it is not laid out (global.css).
        h('pre', { className: ['cell-code'], tabIndex: 0, ariaLabel: label, style: `--lines: ${lineCount(source)}` }, [
          colourLater
            ? h('code', { className: [`language-${CELL_CODE_LANGUAGE}`], dataTokens: tokenRuns(source) }, [text(source)])
            : h('code', { className: [`language-${CELL_CODE_LANGUAGE}`] }, highlightJs(source)),
        ]),
      ]),
      h('div', { className: ['cell-toolbar'] }, [
        h('span', { className: ['cell-status'], dataCellStatus: '' }),
        h('span', { className: ['cell-activity'], dataCellActivity: '', ariaLive: 'polite' }),
        // The way to run that the device has: a key on a desk, the Run button under a finger (site/styles/cells.css).
        h('span', { className: ['cell-hint'] }, [
          h('span', { className: ['cell-hint-keys'] }, [text('Shift+Enter runs')]),
          h('span', { className: ['cell-hint-touch'] }, [text('Edit, then tap Run')]),
        ]),
        h('button', { type: 'button', className: ['cell-button'], dataCellAdd: '', title: 'Add a cell of your own below this one' }, [text('+ Cell')]),
        h('button', { type: 'button', className: ['cell-button'], dataCellReset: '', disabled: true }, [text('Reset')]),
        h('button', { type: 'button', className: ['cell-button', 'cell-run'], dataCellRun: '' }, [text('Run')]),
      ]),
    ]),
    h('div', { className: ['cell-notice'], dataCellNotice: '', hidden: true }),
    h('div', { className: ['cell-error'], dataCellError: '', ariaLive: 'polite', hidden: true }),
    h('div', { className: ['cell-output'], dataCellOutput: '' }, output ? /** @type {import('hast').ElementContent[]} */ (fromHtmlIsomorphic(output, { fragment: true }).children) : []),
    h('noscript', {}, [
      h('p', { className: ['cell-noscript'] }, [text('This is a live code cell: turn on JavaScript to run and edit it.')]),
    ]),
  ]);
}

/**
 * Gives every cell of a chapter its id: its name, `name-dupN` for a repeated
 * name (the runtime then reports the duplicate), or `cell-N` by position.
 * @param {Array<{ name: string | null }>} cells
 */
export function assignCellIds(cells) {
  /** @type {Map<string, number>} */
  const seen = new Map();
  return cells.map(({ name }, index) => {
    if (!name) return `cell-${index + 1}`;
    const count = (seen.get(name) ?? 0) + 1;
    seen.set(name, count);
    return count === 1 ? name : `${name}-dup${count}`;
  });
}

/**
 * The plugin. It runs the chapter's cells once at build time (precompile.ts)
 * to compile their models and typeset their formulas, puts a formula that
 * is a cell's value into the cell's output, and hands the rest to the page
 * in a `<template data-phasebook-page-data>` at the end of the file's markup
 * (see pageDataNode). It also records the cell count as `cells`, so a
 * chapter without cells loads no cell script.
 */
export function remarkCells() {
  /**
   * @param {import('mdast').Root} tree
   * @param {import('vfile').VFile} file
   */
  return async (tree, file) => {
    /** @type {Array<{ parent: import('mdast').Parent, index: number, source: string, analysis: ReturnType<typeof analyzeCell>, failureIsTheLesson: boolean }>} */
    const found = [];
    collectCells(tree, found);

    const ids = assignCellIds(found.map(({ analysis }) => ({ name: 'spec' in analysis ? analysis.spec.name : null })));
    const work = await precompileChapter(
      found.flatMap(({ source, analysis }, i) => ('spec' in analysis ? [{ id: ids[i], source, spec: analysis.spec }] : [])),
    );
    const cells = found.map(({ parent, index, analysis, failureIsTheLesson }, i) => ({
      id: ids[i],
      line: parent.children[index].position?.start.line ?? 0,
      named: 'spec' in analysis && !!analysis.spec.name,
      failureIsTheLesson,
      ...('error' in analysis ? { syntaxError: analysis.error } : {}),
    }));
    const chapter = file.path ? shownPath(file.path) : '(chapter)';
    reportChapter(chapter, chapterProblems(chapter, cells, work.outcomes));
    found.forEach(({ parent, index, source, analysis }, i) => {
      const colourLater = parent !== tree || index >= FIRST_VIEW_BLOCKS;
      const cell = renderCell(source, ids[i], analysis, work.outputs.get(ids[i]), { colourLater });
      // An unknown mdast node with hName/hProperties/hChildren becomes exactly this element.
      parent.children[index] = /** @type {import('mdast').RootContent} */ (/** @type {unknown} */ ({
        type: 'liveCell',
        data: { hName: cell.tagName, hProperties: cell.properties, hChildren: cell.children },
      }));
    });

    const data = /** @type {{ astro?: { frontmatter?: Record<string, unknown> } }} */ (file.data);
    data.astro ??= {};
    data.astro.frontmatter ??= {};
    data.astro.frontmatter.cells = found.length;
    // Which cell reads which, for the embed pages (site/lib/embeds.ts): one per cell that draws a widget.
    data.astro.frontmatter.cellGraph = found.map(({ analysis }, i) => cellNode(ids[i], analysis));
    // Carried by the chapter's own markup, so an MDX file that imports another
    // (for-teachers imports the template) brings that file's data along too.
    if (work.data) tree.children.push(/** @type {import('mdast').RootContent} */ (/** @type {unknown} */ (pageDataNode(work.data))));
  };
}

/**
 * A cell as the embed pages see it: its id, the name it defines, what it
 * reads, and whether it draws a widget.
 * @param {string} id
 * @param {ReturnType<typeof analyzeCell>} analysis
 */
function cellNode(id, analysis) {
  const spec = 'spec' in analysis ? analysis.spec : null;
  const inputs = spec ? [...spec.inputs] : [];
  return { id, name: spec?.name ?? null, inputs, widget: inputs.some((name) => WIDGET_NAMES.includes(name)) };
}

/**
 * The build's data for the page (widgets/chapter/models/page-data.ts) as an inert
 * element: JSON in an attribute, which the HTML parser gives back exactly.
 * @param {import('../../widgets/chapter/models/page-data.ts').PageData} data
 */
function pageDataNode(data) {
  return { type: 'phasebookPageData', data: { hName: 'template', hProperties: { [PAGE_DATA_PROPERTY]: JSON.stringify(data) } } };
}

/**
 * A chapter's path as the build's report names it: from the project's root when it is inside.
 * @param {string} path
 */
export function shownPath(path) {
  // No node:path here: the VS Code extension bundles this module for the browser (vscode/build/book-modules.ts).
  const root = `${process.cwd().replace(/[\\/]+$/, '')}/`;
  return path.replace(/\\/g, '/').startsWith(root.replace(/\\/g, '/')) ? path.slice(root.length) : path;
}

/**
 * Every cell fence under `parent`, in document order, with its source as the
 * page gets it, its parse, and whether its fence marks its failure as the
 * lesson. Exported for the VS Code extension (vscode/), which finds and
 * checks a chapter's cells exactly as the build does.
 * @param {import('mdast').Parent} parent
 * @param {Array<{ parent: import('mdast').Parent, index: number, source: string, analysis: ReturnType<typeof analyzeCell>, failureIsTheLesson: boolean }>} found
 */
export function collectCells(parent, found) {
  parent.children.forEach((child, index) => {
    if (child.type === 'code' && isCellFence(child)) {
      const source = child.value.replace(/^\n+/, '').trimEnd();
      const failureIsTheLesson = /** @type {string} */ (child.meta).split(/\s+/).includes(FAILS_MARK);
      found.push({ parent, index, source, analysis: analyzeCell(source), failureIsTheLesson });
    } else if ('children' in child) {
      collectCells(child, found);
    }
  });
}
