/**
 * The build's pass over a chapter's exercises (site/lib/remark-exercises.mjs),
 * run on chapters parsed as MDX: an exercise that cannot be read or graded is
 * reported with its file and line, so the build fails (fail-loudly.mjs), and
 * the page shows why in its place; a good one is rendered and reports nothing.
 * The cells' report of the same chapter is kept apart from it.
 */
import { beforeEach, describe, expect, it } from 'vitest';
import { unified } from 'unified';
import remarkParse from 'remark-parse';
import remarkMdx from 'remark-mdx';
import { VFile } from 'vfile';
import { remarkExercises } from '../../../site/lib/remark-exercises.mjs';
import { recordedProblems, reportChapter } from '../../../site/lib/cell-failures.ts';

const exerciseFence = (declaration: object) => ['```exercise', JSON.stringify(declaration), '```'].join('\n');

const periodExercise = (id: string, truth: { name: string; args: Record<string, number> }) => ({
  id, kind: 'predict', title: 'A period', prompt: 'Predict the period at $\\omega = 5$.', unit: 'time units',
  answer: { truth, tolerance: { relative: 0.01, why: 'T = 2π/ω is exact; 1 % allows for three digits.' }, mistakes: [{ value: 31.4, why: 'Divided, not multiplied.' }] },
  hints: ['Look at the cell period.'], solution: 'T = 2π/5.', source: 'Landau & Lifshitz §21',
});

/** Runs the build's exercise pass over `text` as the chapter file `path`; returns the tree and every problem recorded. */
async function build(path: string, text: string) {
  const file = new VFile({ path, value: text });
  const tree = unified().use(remarkParse).use(remarkMdx).parse(file);
  await (remarkExercises() as unknown as (tree: unknown, file: VFile) => Promise<void>)(tree, file);
  return { tree: tree as unknown as { children: { type: string; data?: { hProperties?: Record<string, unknown> } }[] }, problems: recordedProblems() };
}

beforeEach(() => {
  for (const file of ['good.mdx', 'bad.mdx']) {
    reportChapter(file, [], 'exercises');
    reportChapter(file, [], 'cells');
  }
});

describe('an exercise the build cannot grade fails the build, naming the file and the line', () => {
  it('reports nothing for a good exercise, and renders it', async () => {
    const { tree, problems } = await build('good.mdx', `# Good\n\n${exerciseFence(periodExercise('period', { name: 'harmonicPeriod', args: { omega: 5 } }))}\n`);
    expect(problems).toEqual([]);
    expect(tree.children.some((node) => node.type === 'exercise' && node.data?.hProperties?.dataExercise === 'period')).toBe(true);
  });

  it('reports a truth the book does not have, one missing an argument, a repeated id and a declaration that does not parse', async () => {
    const text = [
      '# Bad', '',
      exerciseFence(periodExercise('unknown-truth', { name: 'periodOfEverything', args: { omega: 5 } })), '',
      exerciseFence(periodExercise('no-omega', { name: 'harmonicPeriod', args: {} })), '',
      exerciseFence(periodExercise('no-omega', { name: 'harmonicPeriod', args: { omega: 5 } })), '',
      '```exercise', '{ "id": "broken", ', '```', '',
    ].join('\n');
    const { problems } = await build('bad.mdx', text);
    expect(problems).toHaveLength(4);
    expect(problems[0]).toMatch(/^bad\.mdx:3: exercise unknown-truth: no truth named “periodOfEverything”/);
    expect(problems[1]).toMatch(/^bad\.mdx:7: exercise no-omega: the truth harmonicPeriod needs the number omega/);
    expect(problems[2]).toMatch(/^bad\.mdx:11: exercise no-omega: the id no-omega is used twice/);
    expect(problems[3]).toMatch(/^bad\.mdx:15: exercise: an exercise is one JSON object/);
  });

  it('keeps the chapter\'s cell problems when its exercises report none, and the other way round', async () => {
    reportChapter('good.mdx', ['good.mdx:3: cell x: SyntaxError'], 'cells');
    const { problems } = await build('good.mdx', `# Good\n\n${exerciseFence(periodExercise('period', { name: 'harmonicPeriod', args: { omega: 5 } }))}\n`);
    expect(problems).toEqual(['good.mdx:3: cell x: SyntaxError']);
  });
});
