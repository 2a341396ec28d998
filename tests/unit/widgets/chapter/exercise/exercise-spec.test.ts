import { describe, expect, test } from 'vitest';
import { exercisesInText, parseExercise, publicPart } from '../../../../../widgets/chapter/exercise/exercise-spec.ts';

const predict = {
  id: 'p', kind: 'predict', title: 'T', prompt: 'P', source: 'S', solution: 'X', hints: ['a'],
  answer: { truth: { name: 'harmonicPeriod', args: { omega: 2 } }, tolerance: { relative: 0.01, why: 'w' } },
};

describe('parseExercise', () => {
  test('a complete declaration parses; its public part carries no answer', () => {
    const parsed = parseExercise(JSON.stringify(predict));
    expect(parsed).toHaveProperty('exercise');
    if (!('exercise' in parsed)) return;
    const shown = JSON.stringify(publicPart(parsed.exercise));
    expect(shown).not.toContain('harmonicPeriod');
    expect(shown).not.toContain('"X"');
    expect(publicPart(parsed.exercise).hintCount).toBe(1);
  });
  test.each([
    ['not JSON', '{', /one JSON object/],
    ['a bad id', JSON.stringify({ ...predict, id: 'Bad Id' }), /"id"/],
    ['a bad kind', JSON.stringify({ ...predict, kind: 'quiz' }), /"kind"/],
    ['four hints', JSON.stringify({ ...predict, hints: ['a', 'b', 'c', 'd'] }), /at most three/],
    ['no solution', JSON.stringify({ ...predict, solution: undefined }), /"solution"/],
    ['no source', JSON.stringify({ ...predict, source: '' }), /"source"/],
    ['an unjustified tolerance', JSON.stringify({ ...predict, answer: { ...predict.answer, tolerance: { relative: 0.1 } } }), /why/],
    ['a code exercise without checks', JSON.stringify({ ...predict, kind: 'code', answer: undefined, code: { cell: 'h', reference: 'p^2/2', checks: [] } }), /at least one check/],
    ['an equationsInTime check without its times', JSON.stringify({ ...predict, kind: 'code', answer: undefined, code: { cell: 'h', reference: 'p^2/2', checks: [{ check: 'equationsInTime', box: [[0, 1], [0, 1]], time: [5, 1] }] } }), /"time"/],
    ['an equationsInTime check of the wrong size', JSON.stringify({ ...predict, kind: 'code', answer: undefined, code: { cell: 'h', reference: 'p^2/2', checks: [{ check: 'equationsInTime', box: [[0, 1]], time: [0, 1] }] } }), /2 components/],
    ['a check of the wrong size', JSON.stringify({ ...predict, kind: 'code', answer: undefined, code: { cell: 'h', reference: 'p^2/2', checks: [{ check: 'equations', box: [[0, 1]] }] } }), /2 components/],
  ])('%s is refused with a message naming it', (_, text, message) => {
    const parsed = parseExercise(text);
    expect(parsed).toHaveProperty('error');
    expect('error' in parsed && parsed.error).toMatch(message);
  });
});

test('exercisesInText finds every ```exercise block of an MDX text', () => {
  const mdx = `Text\n\n\`\`\`exercise\n${JSON.stringify(predict)}\n\`\`\`\n\n\`\`\`js cell\nx = 1\n\`\`\`\n\n\`\`\`exercise\n{"id": 1}\n\`\`\`\n`;
  const found = exercisesInText(mdx);
  expect(found).toHaveLength(2);
  expect(found[0]).toHaveProperty('exercise');
  expect(found[1]).toHaveProperty('error');
});
