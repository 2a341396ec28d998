/**
 * The three-body truths (widgets/chapter/exercise/truths/three-body.ts),
 * against independent values: the Earth–Moon L1 as tabulated (0.836915 at
 * μ = 0.012150585), the libration period's small-μ limit 2π/√(27μ/4)
 * (Murray & Dermott §3.8), and Routh's 0.0385209.
 */
import { expect, test } from 'vitest';
import { computeTruth } from '../../../../../../widgets/chapter/exercise/truths.ts';

const value = (name: string, args: Record<string, number>) => {
  const truth = computeTruth(name, args);
  if (!('value' in truth)) throw new Error(truth.error);
  return truth.value;
};

test('collinearPoint gives the Earth–Moon L1 and L2, and NaN for a point that is not 1, 2 or 3', () => {
  expect(value('collinearPoint', { mu: 0.012150585, point: 1 })).toBeCloseTo(0.836915, 5);
  expect(value('collinearPoint', { mu: 0.012150585, point: 2 })).toBeCloseTo(1.155682, 5);
  expect(value('collinearPoint', { mu: 0.01, point: 4 })).toBeNaN();
});

test('librationPeriod tends to 2π/√(27μ/4) as μ → 0, and is NaN above Routh’s value', () => {
  const mu = 1e-7;
  expect(value('librationPeriod', { mu }) / ((2 * Math.PI) / Math.sqrt((27 * mu) / 4))).toBeCloseTo(1, 6);
  expect(value('librationPeriod', { mu: 0.1 })).toBeNaN();
});

test('routhMu is 0.0385209', () => {
  expect(value('routhMu', {})).toBeCloseTo(0.0385209, 7);
});
