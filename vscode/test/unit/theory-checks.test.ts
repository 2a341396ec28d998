import { describe, expect, test } from 'vitest';
import { analyzeChapter } from '../../src/analyzer/analyze.ts';
import { checkCells, describeReading, staticLabel, verdictOf } from '../../src/analyzer/theory-checks.ts';
import type { CheckResult, TheoryCheckReading } from '../../src/shared/messages.ts';
import { readBook, readFixture } from './support.ts';

const reading = (overrides: Partial<TheoryCheckReading>): TheoryCheckReading => ({
  label: 'Period', measured: 3.2, predicted: 3.14, tolerance: 0.01, relative: true, error: 0.0191, verdict: 'disagrees', reason: '', text: '', ...overrides,
});
const fulfilled = (...checks: TheoryCheckReading[]): CheckResult => ({ id: 'a', state: 'fulfilled', checks });

describe('theory checks as tests', () => {
  test('checkCells(cells) finds the cells that read theoryCheck, labelled by their label', () => {
    const template = checkCells(analyzeChapter(readBook('templates/chapter.mdx'), new Set()).cells);
    expect(template.map((c) => [c.cell.id, c.label])).toEqual([['periodCheck', 'Period of the pendulum']]);
    const fixture = checkCells(analyzeChapter(readFixture('checks.mdx'), new Set()).cells);
    expect(fixture.map((c) => [c.cell.id, c.label])).toEqual([['passing', 'Two plus two'], ['failing', 'Pi, roughly']]);
  });

  test('a label written as a template literal keeps its static parts, each substitution shown as "…"', () => {
    expect(staticLabel('Order of ${method}')).toBe('Order of …');
    expect(staticLabel('${a} against ${f({ b: 1 })[0]}')).toBe('… against …');
    expect(staticLabel('Costs \\${5}')).toBe('Costs \\${5}');
    const cells = analyzeChapter(
      ['---', 'title: T', 'order: 1', '---', '', '```js cell', "orders = ['rk38', 'verlet'].map((method) => theoryCheck({label: `Order of ${method}`, measured: 4, predicted: 4, tolerance: 0.1}))", '```', ''].join('\n'),
      new Set(),
    ).cells;
    expect(checkCells(cells).map((c) => c.label)).toEqual(['Order of …']);
  });

  test("the book's order checks (a check per method, from one cell) are labelled by their static parts", () => {
    const chapter = checkCells(analyzeChapter(readBook('content/how-the-simulator-integrates.mdx'), new Set()).cells);
    const labels = chapter.map((c) => c.label);
    expect(labels).toContain('Order of …');
    expect(labels.filter((label) => label.includes('${'))).toEqual([]);
  });

  test('verdictOf(result): passed when every check agrees', () => {
    const verdict = verdictOf(fulfilled(reading({ verdict: 'agrees', error: 0.001 })), 60_000);
    expect(verdict.outcome).toBe('passed');
    expect(verdict.message).toBe('Period: measured 3.2, predicted 3.14; difference 0.1 %, allowed 1 %: agrees');
  });

  test('verdictOf(result): failed with the measured and predicted values', () => {
    const verdict = verdictOf(fulfilled(reading({ verdict: 'agrees', error: 0 }), reading({})), 60_000);
    expect(verdict).toMatchObject({ outcome: 'failed', expected: '3.14 ± 1 %', actual: '3.2' });
    expect(verdict.message.split('\n')[1]).toBe(describeReading(reading({})));
    expect(verdict.message).toMatch(/difference 1\.91 %, allowed 1 %: outside the expected error$/);
    const absolute = verdictOf(fulfilled(reading({ relative: false, tolerance: 0.05, error: 0.06 })), 1000);
    expect(absolute).toMatchObject({ expected: '3.14 ± 0.05', actual: '3.2' });
  });

  test("verdictOf(result): skipped outside the formula's validity, errored without a verdict", () => {
    const outside = verdictOf(fulfilled(reading({ verdict: 'outside', reason: 'the amplitude is small: 1.5 ≤ 0.5 fails' })), 1000);
    expect(outside).toEqual({ outcome: 'skipped', message: 'Period: measured 3.2, predicted 3.14; difference 1.91 %, allowed 1 %: outside the formula’s validity: the amplitude is small: 1.5 ≤ 0.5 fails' });
    const none = verdictOf(fulfilled(reading({ verdict: 'undefined', measured: NaN, error: NaN, reason: 'the pendulum goes over the top' })), 1000);
    expect(none).toEqual({ outcome: 'errored', message: 'Period: measured —, predicted 3.14; difference —, allowed 1 %: no verdict: the pendulum goes over the top' });
  });

  test('verdictOf(result): failed with a message when the check had no verdict within its time limit', () => {
    expect(verdictOf({ id: 'a', state: 'timeout', checks: [] }, 60_000)).toEqual({
      outcome: 'failed',
      message: 'The check had no verdict after 60 s, its time limit: its cell had not finished.',
    });
  });

  test('verdictOf(result): errored for a failed cell, a missing cell or no check', () => {
    expect(verdictOf({ id: 'a', state: 'rejected', error: 'RuntimeError: x is not defined', checks: [] }, 1000)).toEqual({ outcome: 'errored', message: 'RuntimeError: x is not defined' });
    expect(verdictOf({ id: 'a', state: 'missing', checks: [] }, 1000).outcome).toBe('errored');
    expect(verdictOf(fulfilled(), 1000).message).toMatch(/no theory check/);
  });
});
