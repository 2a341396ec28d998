/**
 * The build's report on a chapter's cells (site/lib/cell-failures.ts), from
 * chapters run through the real plugin (site/lib/remark-cells.mjs), parsed
 * as MDX, so the cells run as the build runs them and the lines are the
 * chapter file's own.
 */
import { beforeEach, describe, expect, it } from 'vitest';
import { unified } from 'unified';
import remarkParse from 'remark-parse';
import remarkMdx from 'remark-mdx';
import { VFile } from 'vfile';
import { remarkCells } from '../../../site/lib/remark-cells.mjs';
import { chapterProblems, recordedProblems, reportChapter } from '../../../site/lib/cell-failures.ts';

/** Runs the build's cell pass over `text` as the chapter file `path`; returns every problem recorded. */
async function build(path: string, text: string): Promise<string[]> {
  const file = new VFile({ path, value: text });
  const tree = unified().use(remarkParse).use(remarkMdx).parse(file);
  await (remarkCells() as unknown as (tree: unknown, file: VFile) => Promise<void>)(tree, file);
  return recordedProblems();
}

/** A chapter whose parameter is named E, the crossed-fields chapter in small. */
const CROSSED_FIELDS = [
  '# Crossed fields', //                                                          1
  '', //                                                                          2
  '```js cell', //                                                                3
  'params = ({E: 1, B: 2})', //                                                   4
  '```', //                                                                       5
  '', //                                                                          6
  '```js cell', //                                                                7
  "model = canonicalEquations({dof: 1, hamiltonian: 'p^2/2 - E*q', params})", //  8
  '```', //                                                                       9
  '', //                                                                          10
  '```js cell', //                                                                11
  'drift = params.E / params.B', //                                               12
  '```', //                                                                       13
  '',
].join('\n');

beforeEach(() => {
  for (const file of ['crossed-fields.mdx', 'lesson.mdx', 'fine.mdx', 'unnamed.mdx']) reportChapter(file, []);
});

describe('a chapter whose cells fail at build time', () => {
  it('names the file, the cell, its line and the message, with what the reserved name means', async () => {
    expect(await build('crossed-fields.mdx', CROSSED_FIELDS)).toEqual([
      "crossed-fields.mdx:7: cell model: InputError: E is Euler's number, 2.71828…; name the parameter something else, e.g. E0",
    ]);
  });

  it('lists every failing cell, not just the first, and not the cells that fail only through an input', async () => {
    const text = ['```js cell', 'a = undefinedName + 1', '```', '', '```js cell', 'b = a * 2', '```', '', '```js cell', 'c = (() => { throw new RangeError("too far"); })()', '```', ''].join('\n');
    expect(await build('fine.mdx', text)).toEqual([
      'fine.mdx:1: cell a: RuntimeError: undefinedName is not defined',
      'fine.mdx:9: cell c: RangeError: too far',
    ]);
  });

  it('passes over a cell marked "fails" that fails, and its dependents', async () => {
    const marked = CROSSED_FIELDS.replace('```js cell\nmodel', '```js cell fails\nmodel');
    expect(await build('lesson.mdx', marked)).toEqual([]);
  });

  it('reports a cell marked "fails" that runs without an error', async () => {
    expect(await build('lesson.mdx', '```js cell fails\nomega = 2\n```\n')).toEqual(['lesson.mdx:1: cell omega is marked "fails" but ran without an error']);
  });

  it('reports a cell marked "fails" that only the page runs, since the build cannot see it fail', async () => {
    expect(await build('lesson.mdx', '```js cell fails\nplot = chart({})\n```\n')).toEqual([
      'lesson.mdx:1: cell plot is marked "fails" but runs only in the page, so the build cannot see it fail',
    ]);
  });

  it('reports a cell without a name', async () => {
    expect(await build('unnamed.mdx', '```js cell\nomega = 2\n```\n\n```js cell\nomega * 2\n```\n')).toEqual([
      "unnamed.mdx:5: cell cell-2 has no name; start it with one (`name = …`), under which a reader's edit is saved",
    ]);
  });

  it('has nothing to say about a chapter whose cells run, or need the page', async () => {
    const text = ['```js cell', 'params = ({omega: 3})', '```', '', '```js cell', "model = canonicalEquations({dof: 1, hamiltonian: 'p^2/2 + omega^2*q^2/2', params})", '```', '', '```js cell', 'sim = simulator({model, initial: [1, 0]})', '```', ''].join('\n');
    expect(await build('fine.mdx', text)).toEqual([]);
  });

  it('forgets a chapter\'s problems once it is compiled again without them', async () => {
    await build('crossed-fields.mdx', CROSSED_FIELDS);
    expect(recordedProblems()).toHaveLength(1);
    await build('crossed-fields.mdx', CROSSED_FIELDS.replace(/\bE\b/g, 'E0'));
    expect(recordedProblems()).toEqual([]);
  });
});

describe('chapterProblems', () => {
  it('treats a syntax error as a failure unless the cell is marked', () => {
    const cell = { id: 'cell-1', line: 3, named: false, failureIsTheLesson: true, syntaxError: 'SyntaxError: Unexpected token (1:4)' };
    expect(chapterProblems('x.mdx', [cell], new Map())).toEqual(["x.mdx:3: cell cell-1 has no name; start it with one (`name = …`), under which a reader's edit is saved"]);
    expect(chapterProblems('x.mdx', [{ ...cell, named: true, failureIsTheLesson: false }], new Map())).toEqual(['x.mdx:3: cell cell-1: SyntaxError: Unexpected token (1:4)']);
  });
});
