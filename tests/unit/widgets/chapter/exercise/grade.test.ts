import { describe, expect, test } from 'vitest';
import { allowance, gradeNumber, readNumber } from '../../../../../widgets/chapter/exercise/grade.ts';

const tolerance = { relative: 0.01, why: 'Because.' };

describe('readNumber', () => {
  test('decimals with sign, point and exponent; a minus sign as typeset', () => {
    expect(readNumber(' 0.63 ')).toEqual({ value: 0.63 });
    expect(readNumber('-1.5e-3')).toEqual({ value: -0.0015 });
    expect(readNumber('\u22122')).toEqual({ value: -2 });
    expect(readNumber('.5')).toEqual({ value: 0.5 });
  });
  test('a comma, units, words or nothing are refused with a sentence', () => {
    expect(readNumber('1,25')).toEqual({ error: expect.stringContaining('1.25') });
    expect(readNumber('1.2 s')).toEqual({ error: expect.stringContaining('without units') });
    expect(readNumber('')).toEqual({ error: expect.stringContaining('number') });
    expect(readNumber('2*pi')).toHaveProperty('error');
  });
});

describe('gradeNumber', () => {
  test('within the tolerance passes and repeats why that much', () => {
    const v = gradeNumber(1.005, 1, tolerance, [], 's');
    expect(v.passed).toBe(true);
    expect(v.message).toMatch(/^Right: 1\.005 s is within 0\.01 of the true 1 s\. Because\./);
  });
  test('outside it fails, says how far and which way, and never the truth', () => {
    const v = gradeNumber(1.03, 1, tolerance, []);
    expect(v.passed).toBe(false);
    expect(v.message).toContain('3.0 % high');
    expect(gradeNumber(2, 1, tolerance, []).message).toContain('2.0 times too large');
    expect(gradeNumber(-1, 1, tolerance, []).message).toContain('wrong sign');
  });
  test('an answer at a known mistake is told what the mistake is', () => {
    const v = gradeNumber(2.001, 1, tolerance, [{ value: 2, why: 'A factor of 2.' }]);
    expect(v.passed).toBe(false);
    expect(v.message).toContain('A factor of 2.');
  });
  test('the allowance is the larger of absolute and relative', () => {
    expect(allowance(10, { absolute: 0.5, relative: 0.01, why: '' })).toBe(0.5);
    expect(allowance(100, { absolute: 0.5, relative: 0.01, why: '' })).toBe(1);
  });
  test('a truth that is not a number grades nothing', () => {
    expect(gradeNumber(1, NaN, tolerance, []).passed).toBe(false);
  });
});
