/**
 * The Liouville truths (widgets/chapter/exercise/truths/liouville.ts)
 * against computations written here: the damped blob's area from the
 * determinant of the damped oscillator's exact flow map, a 2×2 matrix in
 * closed form (its determinant is e^(−γt), Liouville's formula); Kac's
 * mean return time from a direct count of the golden rotation's visits to
 * an arc; and the first close return by searching n·φ mod 1 directly.
 */
import { expect, test } from 'vitest';
import { computeTruth } from '../../../../../../widgets/chapter/exercise/truths.ts';

const value = (name: string, args: Record<string, number>) => {
  const truth = computeTruth(name, args);
  if (!('value' in truth)) throw new Error(truth.error);
  return truth.value;
};
const GOLDEN = (1 + Math.sqrt(5)) / 2;
const turnDistance = (x: number) => Math.min(x - Math.floor(x), Math.ceil(x) - x);

test('dampedArea is πr² times the determinant of the damped oscillator’s flow map q̈ + γq̇ + q = 0', () => {
  for (const [radius, gamma, t] of [[0.5, 0.2, 5], [1, 0.05, 30], [0.3, 1, 2]]) {
    const Omega = Math.sqrt(1 - (gamma * gamma) / 4);
    const decay = Math.exp((-gamma * t) / 2);
    const [c, s] = [Math.cos(Omega * t), Math.sin(Omega * t)];
    // columns: the motion from (1, 0) and from (0, 1), written out from q = e^(−γt/2)(A cos Ωt + B sin Ωt)
    const fromQ = [decay * (c + (gamma / (2 * Omega)) * s), decay * (-s / Omega)];
    const fromP = [decay * (s / Omega), decay * (c - (gamma / (2 * Omega)) * s)];
    const det = fromQ[0] * fromP[1] - fromP[0] * fromQ[1];
    expect(value('dampedArea', { radius, gamma, t }) / (Math.PI * radius * radius * det)).toBeCloseTo(1, 12);
  }
});

test('kacMeanReturn is the golden rotation’s mean return time to an arc, counted', () => {
  for (const width of [0.1, 0.02]) {
    const visits: number[] = [];
    for (let n = 0; n < 200_000; n++) if (turnDistance(n * GOLDEN) < width / 2) visits.push(n);
    const mean = (visits[visits.length - 1] - visits[0]) / (visits.length - 1);
    expect(Math.abs(mean - value('kacMeanReturn', { width })) / (1 / width)).toBeLessThan(0.002);
  }
});

test('goldenFirstReturn is the first n whose nφ comes within the distance of a whole number', () => {
  for (const distance of [0.1, 0.01, 0.003, 0.0005]) {
    let n = 1;
    while (turnDistance(n * GOLDEN) >= distance) n++;
    expect(value('goldenFirstReturn', { distance })).toBe(n);
  }
});

test('areaHalvingTime is where the damped flow map’s determinant, written out above, is 1/2: found here by bisection', () => {
  for (const gamma of [0.1, 0.37]) {
    const det = (t: number) => value('dampedArea', { radius: 1, gamma, t }) / Math.PI;
    let [lo, hi] = [0, 100 / gamma];
    for (let i = 0; i < 200; i++) [lo, hi] = det((lo + hi) / 2) > 0.5 ? [(lo + hi) / 2, hi] : [lo, (lo + hi) / 2];
    expect(value('areaHalvingTime', { gamma })).toBeCloseTo(lo, 9);
  }
});
