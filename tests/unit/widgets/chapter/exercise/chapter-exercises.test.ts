/**
 * Every exercise the book declares (content/*.mdx and the template), run as
 * the reader would meet it: its declaration parses; a number's truth is a
 * finite number, and every known mistake is graded wrong with its own
 * explanation; a code exercise's reference H passes all its checks and every
 * listed wrong H fails at least one. The chapters that have exercises have
 * four or more, with every kind among them.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { describe, expect, test } from 'vitest';
import { canonicalEquations } from '../../../../../core/model/canonical-equations.ts';
import { runCheck } from '../../../../../widgets/chapter/exercise/code-checks.ts';
import { type Exercise, exercisesInText } from '../../../../../widgets/chapter/exercise/exercise-spec.ts';
import { allowance, gradeNumber } from '../../../../../widgets/chapter/exercise/grade.ts';
import { computeTruth } from '../../../../../widgets/chapter/exercise/truths.ts';

const ROOT = resolve(__dirname, '../../../../..');
const files = [...readdirSync(join(ROOT, 'content')).filter((f) => f.endsWith('.mdx')).map((f) => join('content', f)), 'templates/chapter.mdx'];
const declared = files.map((file) => ({ file, parsed: exercisesInText(readFileSync(join(ROOT, file), 'utf8')) }));
const all = declared.flatMap(({ file, parsed }) => parsed.map((p) => ({ file, p })));

test('every declaration parses', () => {
  expect(all.filter(({ p }) => 'error' in p).map(({ file, p }) => `${file}: ${'error' in p ? p.error : ''}`)).toEqual([]);
});

const exercises = all.flatMap(({ file, p }) => ('exercise' in p ? [{ file, exercise: p.exercise }] : []));

test.each(['content/introduction.mdx', 'content/nonlinear-oscillator.mdx', 'content/restricted-three-body.mdx', 'templates/chapter.mdx'])('%s has four exercises or more (the template one of each kind), every kind among them', (file) => {
  const kinds = exercises.filter((e) => e.file === file).map((e) => e.exercise.kind);
  expect(kinds.length).toBeGreaterThanOrEqual(file.startsWith('templates') ? 3 : 4);
  expect(new Set(kinds)).toEqual(new Set(['predict', 'find', 'code']));
});

const numeric = exercises.filter(({ exercise }) => exercise.answer);
describe.each(numeric.map(({ file, exercise }) => [`${file} ${exercise.id}`, exercise] as [string, Exercise]))('%s', (_, exercise) => {
  const answer = exercise.answer!;
  const truth = computeTruth(answer.truth.name, answer.truth.args);
  test('its truth is a finite number', () => {
    expect(truth).toHaveProperty('value');
    expect(Number.isFinite('value' in truth ? truth.value : NaN)).toBe(true);
  });
  test('it has two wrong answers or more, each graded wrong with its own explanation', () => {
    if (!('value' in truth)) return;
    expect(answer.mistakes.length).toBeGreaterThanOrEqual(2);
    for (const mistake of answer.mistakes) {
      // A mistake inside the tolerance would be graded right: the tolerance would be too loose to teach anything.
      expect(Math.abs(mistake.value - truth.value)).toBeGreaterThan(allowance(truth.value, answer.tolerance));
      const verdict = gradeNumber(mistake.value, truth.value, answer.tolerance, answer.mistakes, exercise.unit);
      expect(verdict.passed).toBe(false);
      expect(verdict.message).toContain(mistake.why);
    }
  });
  test('an answer at the edge of the tolerance passes, one just beyond fails', () => {
    if (!('value' in truth)) return;
    const edge = allowance(truth.value, answer.tolerance);
    expect(gradeNumber(truth.value + 0.99 * edge, truth.value, answer.tolerance, answer.mistakes).passed).toBe(true);
    expect(gradeNumber(truth.value - 1.01 * edge, truth.value, answer.tolerance, answer.mistakes).passed).toBe(false);
  });
});

const coded = exercises.filter(({ exercise }) => exercise.code);
describe.each(coded.map(({ file, exercise }) => [`${file} ${exercise.id}`, exercise] as [string, Exercise]))('%s', (_, exercise) => {
  const code = exercise.code!;
  const build = (hamiltonian: string) => canonicalEquations({ dof: code.dof, hamiltonian, params: code.params });
  test('the reference H passes every check', async () => {
    const reference = await build(code.reference);
    for (const [i, check] of code.checks.entries()) expect(runCheck(check, await build(code.reference), reference, i + 1)).toMatchObject({ passed: true });
  });
  test('every listed wrong H fails a check, with a sentence', async () => {
    const reference = await build(code.reference);
    expect(code.mistakes.length).toBeGreaterThanOrEqual(2);
    for (const wrong of code.mistakes) {
      const reader = await build(wrong);
      const failed = code.checks.map((check, i) => runCheck(check, reader, reference, i + 1)).filter((v) => !v.passed);
      expect(failed.length, wrong).toBeGreaterThan(0);
      expect(failed[0].message.length).toBeGreaterThan(20);
    }
  });
});
