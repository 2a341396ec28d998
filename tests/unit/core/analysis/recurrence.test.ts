/**
 * Poincaré recurrence on the rotation by α (core/analysis/recurrence.ts)
 * against number theory worked here: the golden ratio's continued fraction
 * [1; 1, 1, …] and its convergents' denominators, the Fibonacci numbers;
 * the record returns of nα mod 1 at exactly those denominators (Khinchin,
 * *Continued Fractions*, theorems 16–17: the best approximations of the
 * second kind are the convergents); Kac's mean return time 1/ε (Kac 1947)
 * within the Denjoy–Koksma bound, checked here by a direct count; and the
 * section of two uncoupled oscillators (core/analysis/model-section.ts)
 * against their closed-form motion.
 */
import { describe, expect, test } from 'vitest';
import { canonicalEquations } from '../../../../core/index.ts';
import { modelSection } from '../../../../core/analysis/model-section.ts';
import { arcReturns, arcVisitBound, continuedFraction, convergentDenominators, kacMeasurement, ostrowskiDigitSum, periodicWithin, recordReturns, turnDistance } from '../../../../core/analysis/recurrence.ts';

const GOLDEN = (1 + Math.sqrt(5)) / 2;
const fibonacci = (count: number) => {
  const f = [1, 1];
  while (f.length < count) f.push(f[f.length - 1] + f[f.length - 2]);
  return f;
};

describe('continued fractions', () => {
  test('the golden ratio is [1; 1, 1, …] and √2 is [1; 2, 2, …]; a rational ends', () => {
    expect(continuedFraction(GOLDEN, 20)).toEqual(Array(20).fill(1));
    expect(continuedFraction(Math.SQRT2, 15)).toEqual([1, ...Array(14).fill(2)]);
    expect(continuedFraction(43 / 30)).toEqual([1, 2, 3, 4]);
  });

  test('the golden ratio’s denominators are the Fibonacci numbers', () => {
    const q = convergentDenominators(GOLDEN - 1, 10_000);
    // q₀ = q₁ = 1: the golden ratio's first two quotients are both 1.
    expect(q).toEqual(fibonacci(21).slice(0, q.length));
    expect(q[q.length - 1]).toBeGreaterThan(10_000);
  });

  test('Ostrowski’s digits rebuild T from the denominators', () => {
    const q = fibonacci(25).slice(1);
    // Zeckendorf: 100 = 89 + 8 + 3, three digits; a Fibonacci number is one.
    expect(ostrowskiDigitSum(100, q)).toBe(3);
    expect(ostrowskiDigitSum(987, q)).toBe(1);
    expect(ostrowskiDigitSum(0, q)).toBe(0);
  });
});

describe('returns of the rotation', () => {
  const rotation = (alpha: number, count: number, start = 0.2) => Float64Array.from({ length: count }, (_, n) => (start + n * alpha) % 1);

  test('the record returns come at the Fibonacci numbers, each closer by about the golden ratio', () => {
    const records = recordReturns(rotation(GOLDEN, 20_000));
    expect(records.map((r) => r.n)).toEqual(fibonacci(22).slice(1).filter((f) => f < 20_000));
    // ‖F_k α‖ = φ^(−k) exactly for the golden rotation (Binet): the ratio of successive distances is φ.
    for (let k = 3; k < records.length; k++) expect(records[k - 1].distance / records[k].distance).toBeCloseTo(GOLDEN, 3);
  });

  test.each([
    ['golden', GOLDEN - 1],
    ['√2', Math.SQRT2 - 1],
    ['e', Math.E - 2],
  ])('Kac: the mean return time to an arc of ε is 1/ε within the Denjoy–Koksma bound (%s)', (_, alpha) => {
    for (const width of [0.1, 0.03, 0.011]) {
      const phases = rotation(alpha, 30_000);
      const r = arcReturns(phases, width);
      const bound = arcVisitBound(alpha, r.span);
      // The count itself, against ε·T: the inequality the bound states.
      expect(Math.abs(r.returns - width * r.span)).toBeLessThanOrEqual(bound);
      expect(Math.abs(r.mean - 1 / width)).toBeLessThanOrEqual(bound / (width * r.returns));
      expect(Math.abs(r.mean - 1 / width) / (1 / width)).toBeLessThan(0.02);
    }
  });

  test('a rational rotation is not ergodic: its returns are all one period, far from Kac’s 1/ε for a narrow arc', () => {
    const r = arcReturns(rotation(2 / 7, 7000), 0.01);
    expect(new Set(r.visits.slice(1).map((v, i) => v - r.visits[i]))).toEqual(new Set([7]));
    expect(r.mean).toBe(7);
    expect(arcVisitBound(2 / 7, r.span)).toBeGreaterThan(Math.abs(r.returns - 0.01 * r.span) - 1e-9);
  });

  test('turnDistance is the distance on the circle', () => {
    expect(turnDistance(0.95, 0.05)).toBeCloseTo(0.1, 15);
    expect(turnDistance(0.3, 0.8)).toBeCloseTo(0.5, 15);
    expect(turnDistance(2.25, 0.25)).toBe(0);
  });
});

describe('the section of a model', () => {
  test('two uncoupled oscillators: crossings of q1 = 0 upward every 2π, the second turned by 2πω each time (closed form)', async () => {
    const omega = GOLDEN;
    const model = await canonicalEquations({ dof: 2, hamiltonian: '(p1^2 + q1^2)/2 + (p2^2 + w^2*q2^2)/2', params: { w: omega }, coordinates: ['q1', 'q2'], momenta: ['p1', 'p2'] });
    // q1 = −cos t crosses 0 upward at t = π/2 + 2πn; q2 = A cos(ωt), p2 = −Aω sin(ωt).
    const section = modelSection(model, [-1, 0.5, 0, 0], { dt: 0.01, count: 50 });
    expect(section.count).toBe(50);
    for (let n = 0; n < 50; n++) {
      const t = Math.PI / 2 + 2 * Math.PI * n;
      // The first oscillator's phase lags by (Δt)⁵/120 a step: its crossing comes that much late.
      expect(Math.abs(section.times[n] - t)).toBeLessThan(2 * (Math.pow(0.01, 5) / 120) * (t / 0.01) + 1e-10);
      const [q1, q2, p1, p2] = section.states.subarray(4 * n, 4 * n + 4);
      expect(Math.abs(q1)).toBeLessThan(1e-12);
      expect(p1).toBeCloseTo(1, 9);
      // RK 3/8's phase error on an oscillator, (ωΔt)⁵/120 a step (its stability function is RK4's), twice over, times the amplitude.
      const phase = 2 * (Math.pow(omega * 0.01, 5) / 120) * (t / 0.01);
      expect(Math.abs(q2 - 0.5 * Math.cos(omega * t))).toBeLessThan(0.5 * phase + 1e-10);
      expect(Math.abs(p2 + 0.5 * omega * Math.sin(omega * t))).toBeLessThan(0.5 * omega * phase + 1e-10);
    }
  });

  test('a model whose H depends on t: the crossing times of q̇ = 1 + cos t… follow the closed form', async () => {
    // H = p·(1 + 0.5 cos t): q = t + 0.5 sin t − 3 from q = −3, crossing 0 once, upward, where t + 0.5 sin t = 3.
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p*(1 + 0.5*cos(t))' });
    const section = modelSection(model, [-3, 0], { dt: 0.05, count: 1, maxSteps: 200 });
    expect(section.count).toBe(1);
    let t = 3;
    for (let i = 0; i < 50; i++) t -= (t + 0.5 * Math.sin(t) - 3) / (1 + 0.5 * Math.cos(t));
    expect(section.times[0]).toBeCloseTo(t, 8);
  });

  test('bad options are refused in words; a blow-up is reported as failed', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 - q^4' });
    expect(() => modelSection(model, [0, 1], { dt: 0, count: 1 })).toThrow(/step must be a positive number/);
    expect(() => modelSection(model, [0, 1], { dt: 0.1, count: 1, index: 2 })).toThrow(/index must be a state component/);
    const run = modelSection(model, [1, 10], { dt: 0.1, count: 5, maxSteps: 10_000 });
    expect(run.failed).toBe(true);
  });
});

describe('Kac’s measurement', () => {
  const rotation = (alpha: number, count: number, start = 0.2) => Float64Array.from({ length: count }, (_, n) => (start + n * alpha) % 1);

  test('of an exact golden rotation: no phase error, no spread, not periodic, the mean within its bound of 1/ε', () => {
    const phases = rotation(GOLDEN - 1, 5000);
    const m = kacMeasurement(phases, phases, GOLDEN - 1, 0.02);
    expect(m.phaseError).toBe(0);
    // a phase exactly on an end is ambiguous even with no error; none is, for this irrational start
    expect(m.ambiguous).toBe(0);
    expect(m.rotationSpread).toBeLessThan(1e-12);
    expect(m.periodic).toBe(false);
    expect(Math.abs(m.mean - 50)).toBeLessThanOrEqual(m.visitBound / (0.02 * m.returns));
  });

  test('a rational turn is periodic within the run; a perturbed rotation has a spread; a shifted run has a phase error', () => {
    expect(kacMeasurement(rotation(0.5, 100), rotation(0.5, 100), 0.5, 0.02).periodic).toBe(true);
    expect(periodicWithin(3 / 1000, 500)).toBe(false);
    expect(periodicWithin(3 / 1000, 1000)).toBe(true);
    const wobbly = Float64Array.from(rotation(GOLDEN - 1, 1000), (x, n) => (x + 1e-4 * Math.sin(n)) % 1);
    expect(kacMeasurement(wobbly, wobbly, GOLDEN - 1, 0.02).rotationSpread).toBeGreaterThan(5e-5);
    const shifted = Float64Array.from(rotation(GOLDEN - 1, 1000), (x) => (x + 3e-7) % 1);
    const shiftedRun = kacMeasurement(rotation(GOLDEN - 1, 1000), shifted, GOLDEN - 1, 0.02);
    expect(shiftedRun.phaseError).toBeCloseTo((16 / 15) * 3e-7, 12);
    // counted here: the crossings within twice that of the arc's ends
    const ends = Array.from(rotation(GOLDEN - 1, 1000)).filter((x, n) => n > 0 && Math.abs(turnDistance(x, 0.2) - 0.01) <= 2 * (16 / 15) * 3e-7).length;
    expect(shiftedRun.ambiguous).toBe(ends);
    const wide = kacMeasurement(rotation(GOLDEN - 1, 1000), Float64Array.from(rotation(GOLDEN - 1, 1000), (x) => (x + 3e-3) % 1), GOLDEN - 1, 0.02);
    expect(wide.ambiguous).toBeGreaterThan(0);
  });
});
