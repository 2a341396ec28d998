/**
 * Exercises as tests: the items the Test Explorer lists (from the analysis
 * of a chapter's ```exercise fences) and what running one says. The answer
 * keys are judged by the book's own grading and checks; the truths behind
 * them are closed forms (harmonicPeriod: T = 2π/ω, Landau & Lifshitz §21;
 * pendulumPeriod: T = 4K(sin(θ₀/2))/ω, §11), so a passing key here is one
 * whose truth and mistakes sit where physics puts them.
 */
import { describe, expect, test } from 'vitest';
import { analyzeChapter, type ChapterAnalysis } from '../../src/analyzer/analyze.ts';
import { LEAST_MISTAKES, testDeclaration } from '../../src/analyzer/exercise-tests.ts';
import { LineIndex } from '../../src/analyzer/positions.ts';
import { readBook, readFixture } from './support.ts';

const analyze = (text: string) => analyzeChapter(text, new Set());
const template = analyze(readBook('templates/chapter.mdx'));
const fixtureText = readFixture('exercises.mdx');
const fixture = analyze(fixtureText);

/** The (0-based) line of an offset in the text. */
const lineOf = (text: string, offset: number) => new LineIndex(text).position(offset).line;
const exercise = (analysis: ChapterAnalysis, key: string) => analysis.exercises.find((e) => e.key === key)!;

describe('the items: one per ```exercise fence', () => {
  test("the template's exercises, by title, kind and the fence's lines", () => {
    const text = readBook('templates/chapter.mdx');
    const fences = [...text.matchAll(/^```exercise$/gm)].map((m) => lineOf(text, m.index!));
    expect(template.exercises.map((e) => [e.key, e.label, e.description, lineOf(text, e.start)])).toEqual([
      ['pendulum-period-2rad', 'The period at a large swing', 'Predict, then check', fences[0]],
      ['pendulum-over-the-top', 'Just over the top', 'Find it', fences[1]],
      ['pendulum-hamiltonian', 'A faster pendulum', 'Write code', fences[2]],
    ]);
    // Each range ends on the closing fence.
    for (const e of template.exercises) expect(text.slice(e.start, e.end)).toMatch(/^```exercise\n[\s\S]*\n```$/);
  });

  test('a declaration that does not parse is listed by its place, with the parser’s message', () => {
    const broken = fixture.exercises[3];
    expect([broken.key, broken.label, broken.description]).toEqual(['@4', 'Exercise 4', 'not readable']);
    expect(broken.parsed).toEqual({ error: '"solution", the worked solution, is needed' });
  });

  test('items follow edits: an exercise added, renamed or removed', () => {
    const text = readBook('templates/chapter.mdx');
    const renamed = analyze(text.replace('"title": "Just over the top"', '"title": "Over the top"'));
    expect(renamed.exercises.map((e) => e.label)).toEqual(['The period at a large swing', 'Over the top', 'A faster pendulum']);
    const fence = text.slice(template.exercises[1].start, template.exercises[1].end);
    const removed = analyze(text.replace(fence, ''));
    expect(removed.exercises.map((e) => e.key)).toEqual(['pendulum-period-2rad', 'pendulum-hamiltonian']);
    const added = analyze(`${text}\n${fence.replace('pendulum-over-the-top', 'over-the-top-again')}\n`);
    expect(added.exercises.map((e) => e.key)).toEqual(['pendulum-period-2rad', 'pendulum-over-the-top', 'pendulum-hamiltonian', 'over-the-top-again']);
  });

  test('a fence inside a list item is found (the book finds it), and an id used twice is refused as the build refuses it', () => {
    const text = readBook('templates/chapter.mdx');
    const fence = text.slice(template.exercises[0].start, template.exercises[0].end);
    const nested = analyze(`${text}\n1. Try this:\n\n   ${fence.split('\n').join('\n   ')}\n`);
    expect(nested.exercises).toHaveLength(4);
    expect(nested.exercises[3].parsed).toEqual({ error: 'the id pendulum-period-2rad is used twice in this chapter: progress is kept by id' });
    expect(nested.exercises[3].key).toBe('@4');
  });
});

describe('running an exercise: its answer key against the book’s grading', () => {
  test.each(template.exercises.map((e) => [e.key, e] as const))('the template’s %s passes: the truth is right, every wrong answer is wrong', async (_, found) => {
    const verdict = await testDeclaration(found);
    expect(verdict.failures).toEqual([]);
    expect(verdict.outcome).toBe('passed');
  });

  test('a passing number exercise reports the truth and each mistake graded wrong with its own sentence', async () => {
    const verdict = await testDeclaration(exercise(fixture, 'harmonic-period'));
    expect(verdict.outcome).toBe('passed');
    // T = 2π/ω at ω = 2 is π (Landau & Lifshitz §21).
    expect(verdict.report[0]).toMatch(/^The truth, 3\.14159 time units ± 0\.0314159 \(closed form T = 2π\/ω .*\): graded right\.$/);
    expect(verdict.report[1]).toMatch(/^Wrong answer 6\.2832 time units: graded wrong: Not yet: .* That is 2π, the period for ω = 1: divide by ω = 2\.$/);
    expect(verdict.report[2]).toMatch(/That is half the period: a swing there and back takes 2π\/ω\.$/);
  });

  test('a mistake inside the tolerance fails, said at the mistake’s line', async () => {
    const found = exercise(fixture, 'loose-tolerance');
    const verdict = await testDeclaration(found);
    expect(verdict.outcome).toBe('failed');
    expect(verdict.failures).toHaveLength(1);
    expect(verdict.failures[0].message).toBe('The wrong answer 6 is within the tolerance of the truth 6.28319 (± 0.628319): the page would call it right. Tighten the tolerance, or drop this mistake.');
    const place = found.locate(verdict.failures[0].about!)!;
    expect(fixtureText.split('\n')[lineOf(fixtureText, place.start)]).toContain('"value": 6, "why"');
  });

  test('a wrong H that passes every check fails, said at that H', async () => {
    const found = exercise(fixture, 'blind-checks');
    const verdict = await testDeclaration(found);
    expect(verdict.outcome).toBe('failed');
    expect(verdict.failures.map((f) => f.message)).toEqual([
      'The wrong H “p^2/2 + q^2/2 + 1” passes every check: the checks cannot tell it from the reference “p^2/2 + q^2/2”. Add a check that does.',
    ]);
    expect(verdict.report).toContain('Reference H, check 1 (equations): passed: Hamilton’s equations of your H equal the reference’s at 8 random states (largest relative difference 0.0e+0).');
    expect(verdict.report.find((line) => line.startsWith('Wrong H “p^2/2 + 2*q^2”'))).toMatch(/^Wrong H “p\^2\/2 \+ 2\*q\^2”: fails check 1 \(equations\): Hamilton’s equations differ/);
    const place = found.locate(verdict.failures[0].about!)!;
    expect(fixtureText.slice(place.start, place.end)).toBe('"p^2/2 + q^2/2 + 1"');
  });

  test('a declaration that does not parse fails with the parser’s message, at the fence', async () => {
    const verdict = await testDeclaration(fixture.exercises[3]);
    expect(verdict).toEqual({
      outcome: 'failed',
      report: ['The declaration does not parse: "solution", the worked solution, is needed.'],
      failures: [{ message: 'The declaration does not parse: "solution", the worked solution, is needed.' }],
    });
  });

  test('the reference H must pass every check, and the key must list two wrong answers or more', async () => {
    const found = exercise(template, 'pendulum-hamiltonian');
    const exerciseOf = (e: typeof found) => ('exercise' in e.parsed ? e.parsed.exercise : null)!;
    const original = exerciseOf(found);
    // ω₀ = 2 where the checks' period is that of ω₀ = 3: the reference H would fail its own "returns" check.
    const wrongReference = { ...found, parsed: { exercise: { ...original, code: { ...original.code!, reference: 'p^2/2 - 4*cos(q)', mistakes: [original.code!.mistakes[0]] } } } };
    const verdict = await testDeclaration(wrongReference);
    expect(verdict.outcome).toBe('failed');
    expect(verdict.failures.map((f) => f.message)).toEqual([
      expect.stringMatching(/^The reference H “p\^2\/2 - 4\*cos\(q\)” fails check 2 \(returns\): Released from \(q, p\) = \(2, 0\), your system is at/),
      expect.stringMatching(new RegExp(`^The exercise lists 1 wrong H: give ${LEAST_MISTAKES} or more`)),
    ]);
  });

  test('a mistake graded wrong with another mistake’s sentence fails: the reader would be told the wrong reason', async () => {
    const found = exercise(fixture, 'harmonic-period');
    const original = 'exercise' in found.parsed ? found.parsed.exercise : null;
    const answer = original!.answer!;
    // 1.5700 lies within 1 % of 1.5708, so the page names the first of the two for either.
    const mistakes = [...answer.mistakes, { value: 1.57, why: 'That is π/2, a quarter of a period written as a number.' }];
    const verdict = await testDeclaration({ ...found, parsed: { exercise: { ...original!, answer: { ...answer, mistakes } } } });
    expect(verdict.failures.map((f) => [f.message, f.about])).toEqual([
      [expect.stringMatching(/^The wrong answer 1\.57 time units is graded wrong, but without its own explanation .*That is half the period/), 'That is π/2, a quarter of a period written as a number.'],
    ]);
  });

  test('a truth the book does not have fails with the book’s own message', async () => {
    const found = exercise(fixture, 'harmonic-period');
    const original = 'exercise' in found.parsed ? found.parsed.exercise : null;
    const unknown = { ...found, parsed: { exercise: { ...original!, answer: { ...original!.answer!, truth: { name: 'noSuchTruth', args: {} } } } } };
    const verdict = await testDeclaration(unknown);
    expect(verdict.failures[0].message).toMatch(/^The truth cannot be computed: no truth named “noSuchTruth”: the book has .*harmonicPeriod/);
    expect(verdict.failures[0].about).toBe('noSuchTruth');
  });
});
