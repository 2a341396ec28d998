/**
 * The verdict of a theory check (widgets/chapter/theory-check/check-verdict.ts): it agrees
 * exactly when the difference is inside the sum of the errors it names; a
 * failed condition of the formula's regime gives "outside", a missing number
 * "undefined" with its reason; and the error terms are checked as sizes.
 */
import { describe, expect, it } from 'vitest';
import { allowedTerms, judge, SMALL } from '../../../../../widgets/chapter/theory-check/check-verdict.ts';
import { verdictNumber } from '../../../../../widgets/chapter/theory-check/theory-check.ts';

const errors = {
  formula: { value: 0.03, why: 'the b³ term' },
  integration: { value: 0.001, why: 'RK 3/8 phase error' },
  measurement: { value: 0.009, why: 'leakage' },
};

describe('judge: agrees exactly when the difference is inside the sum of the errors', () => {
  it('sums the three terms, in the order formula, integration, measurement', () => {
    const j = judge({ measured: 1.02, predicted: 1, errors });
    expect(j.terms.map((t) => t.source)).toEqual(['formula', 'integration', 'measurement']);
    expect(j.allowed).toBeCloseTo(0.04, 15);
    expect(j.difference).toBeCloseTo(0.02, 15);
    expect(j.verdict).toBe('agrees');
  });

  it('at the boundary: equal agrees, one ulp more disagrees', () => {
    const allowed = 0.25;
    expect(judge({ measured: 1.25, predicted: 1, errors: { formula: allowed } }).verdict).toBe('agrees');
    expect(judge({ measured: 1.25 + 2.3e-16, predicted: 1, errors: { formula: allowed } }).verdict).toBe('disagrees');
  });

  it('needs every term: leaving one out can turn ✓ into ✗ (the spectral peak at b = 0.1)', () => {
    // The nonlinear oscillator at b = 0.1: the peak is 6.6e-5 from the formula, whose own error is 2.1e-5;
    // only with the peak's leakage (1.25e-4) is the difference inside the errors.
    const formula = { value: 2.1e-5, why: 'b³ and b⁴ terms' };
    expect(judge({ measured: 9.995366, predicted: 9.9953, errors: { formula } }).verdict).toBe('disagrees');
    expect(judge({ measured: 9.995366, predicted: 9.9953, errors: { formula, measurement: 1.25e-4 } }).verdict).toBe('agrees');
  });

  it('divides by |predicted| for a relative check, and the terms are then fractions', () => {
    const j = judge({ measured: -10.3, predicted: -10, relative: true, errors: { formula: 0.02, measurement: 0.011 } });
    expect(j.error).toBeCloseTo(0.03, 12);
    expect(j.verdict).toBe('agrees');
    expect(judge({ measured: -10.4, predicted: -10, relative: true, errors: { formula: 0.02, measurement: 0.011 } }).verdict).toBe('disagrees');
  });
});

describe('judge: outside the formula’s validity, before any comparison', () => {
  it('says outside, with the failed condition, however small the difference', () => {
    const j = judge({
      measured: 0.25,
      predicted: 0.25,
      errors,
      validity: [
        { holds: true, condition: 'ω stays positive' },
        { holds: false, condition: 'the ramp is short: c₂τ² = 2.9 is not ≤ S/3 = 0.083' },
      ],
    });
    expect(j.verdict).toBe('outside');
    expect(j.reason).toBe('the ramp is short: c₂τ² = 2.9 is not ≤ S/3 = 0.083');
  });

  it('accepts a single condition, and judges normally when it holds', () => {
    expect(judge({ measured: 1, predicted: 1, errors, validity: { holds: true, condition: 'bound' } }).verdict).toBe('agrees');
    expect(judge({ measured: 1, predicted: 5, errors, validity: { holds: true, condition: 'bound' } }).verdict).toBe('disagrees');
  });

  it('takes precedence over a missing value: the pendulum over the top is outside, not NaN', () => {
    const j = judge({ measured: NaN, predicted: 3.5, errors, validity: { holds: false, condition: 'the pendulum swings: E < ω₀²' } });
    expect(j.verdict).toBe('outside');
  });
});

describe('judge: a missing number gives no verdict, and says why', () => {
  it('uses the chapter’s reason when the measurement is not a number', () => {
    const j = judge({ measured: NaN, predicted: 1, errors, missing: 'the particle left the well at t = 3.2' });
    expect(j.verdict).toBe('undefined');
    expect(j.reason).toBe('the particle left the well at t = 3.2');
  });

  it('names what is missing when the chapter gives no reason', () => {
    expect(judge({ measured: 1, predicted: Infinity, errors }).reason).toBe('the formula gave no number');
    expect(judge({ measured: NaN, predicted: 1, errors }).reason).toBe('the measurement gave no number');
  });

  it('refuses a relative difference from a prediction of 0', () => {
    expect(judge({ measured: 0.001, predicted: 0, relative: true, errors }).verdict).toBe('undefined');
  });

  it('takes a null size as one that could not be estimated', () => {
    expect(judge({ measured: 1, predicted: 1, errors: { formula: 0, integration: { value: null, why: 'the orbit never closes' } } }).reason).toBe(
      'the integration error could not be estimated: the orbit never closes',
    );
  });

  it('gives no verdict when an error could not be estimated, naming it', () => {
    const j = judge({ measured: 1, predicted: 1, errors: { ...errors, measurement: { value: NaN, why: 'no line near κ/2π' } } });
    expect(j.verdict).toBe('undefined');
    expect(j.reason).toBe('the measurement error could not be estimated: no line near κ/2π');
  });
});

describe('allowedTerms: the error model is stated, and its terms are sizes', () => {
  it('rejects a negative term, an unknown source, both errors and tolerance, and neither', () => {
    expect(() => allowedTerms({ errors: { formula: -1 } })).toThrow(/cannot be negative/);
    expect(() => allowedTerms({ errors: { rounding: 1 } as never })).toThrow(/unknown source of error "rounding"/);
    expect(() => allowedTerms({ errors, tolerance: 1 })).toThrow(/not both/);
    expect(() => allowedTerms({})).toThrow(/state the errors allowed/);
    expect(() => allowedTerms({ errors: {} })).toThrow(/names no source/);
  });

  it('keeps an old cell’s single tolerance as one allowance', () => {
    expect(allowedTerms({ tolerance: 0.1 })).toEqual([{ source: 'allowance', value: 0.1, why: 'an allowance without a stated error model' }]);
  });

  it('reads ≪ as at most a third', () => {
    expect(SMALL).toBe(1 / 3);
  });
});

describe('verdictNumber: never NaN on the page', () => {
  it('writes a dash for values that are not numbers, and keeps the digits asked for', () => {
    expect(verdictNumber(NaN, 3)).toBe('—');
    expect(verdictNumber(Infinity, 3)).toBe('—');
    expect(verdictNumber(0.25, 2)).toBe('0.25');
    expect(verdictNumber(0, 2)).toBe('0');
    expect(verdictNumber(6.6e-5, 2)).toBe('6.6e-5');
    expect(verdictNumber(2.5e6, 3)).toBe('2.50e+6');
  });
});
