/**
 * The standard map's analyses (core/analysis/standard-map.ts) against
 * independent truths: Bessel functions against Abramowitz & Stegun's Table
 * 9.1 and their large-argument forms (A&S 9.2.5); Rechester & White's
 * diffusion (1980, Phys. Rev. Lett. 44, 1586) against simulations, one of
 * them written plainly here with its own random numbers; residues against
 * closed forms for the fixed points, the period-2 orbit and the accelerator
 * modes, worked out in the comments; Greene's sequence against MacKay's
 * critical K (1983, Physica D 7, 283) and Greene's criterion (1979,
 * J. Math. Phys. 20, 1183); an orbit's rotation number against the free
 * rotor's.
 */
import { describe, expect, test } from 'vitest';
import {
  acceleratorMode,
  besselJ,
  CHIRIKOV_OVERLAP,
  GREENE_K,
  greeneLevels,
  greeneOrbit,
  greeneResidueAt,
  measureDiffusion,
  nearAcceleratorMode,
  orbitReading,
  quasilinearDiffusion,
  rechesterWhiteDiffusion,
  rechesterWhiteRemainder,
  residue,
} from '../../../../core/analysis/standard-map.ts';

const TWO_PI = 2 * Math.PI;

describe('besselJ', () => {
  test('Abramowitz & Stegun Table 9.1, to 1e-9', () => {
    expect(Math.abs(besselJ(0, 1) - 0.7651976866)).toBeLessThan(1e-9);
    expect(Math.abs(besselJ(1, 1) - 0.4400505857)).toBeLessThan(1e-9);
    expect(Math.abs(besselJ(0, 10) - -0.2459357645)).toBeLessThan(1e-9);
    expect(Math.abs(besselJ(1, 10) - 0.0434727462)).toBeLessThan(1e-9);
    expect(Math.abs(besselJ(2, 10) - 0.2546303137)).toBeLessThan(1e-9);
  });

  test('J_n(0) is 1 for n = 0 and 0 otherwise; J_n(−x) = (−1)ⁿ J_n(x) (A&S 9.1.5)', () => {
    expect(besselJ(0, 0)).toBeCloseTo(1, 15);
    for (const n of [1, 2, 5]) expect(Math.abs(besselJ(n, 0))).toBeLessThan(1e-15);
    for (const n of [0, 1, 2, 3]) expect(besselJ(n, -7.3)).toBeCloseTo((-1) ** n * besselJ(n, 7.3), 14);
  });

  test('large arguments: within 1e-6 of the Hankel form with two terms (A&S 9.2.5) at x = 1000', () => {
    const x = 1000;
    for (const n of [0, 1, 2, 3]) {
      const omega = x - (n * Math.PI) / 2 - Math.PI / 4;
      const mu = 4 * n * n;
      const hankel = Math.sqrt(2 / (Math.PI * x)) * (Math.cos(omega) - ((mu - 1) / (8 * x)) * Math.sin(omega));
      expect(Math.abs(besselJ(n, x) - hankel)).toBeLessThan(1e-6);
    }
  });

  test('an order that is not a whole number ≥ 0 is refused', () => {
    expect(() => besselJ(-1, 1)).toThrow(RangeError);
    expect(() => besselJ(0.5, 1)).toThrow(RangeError);
    expect(() => besselJ(1, NaN)).toThrow(RangeError);
  });
});

describe('Rechester & White’s diffusion coefficient', () => {
  test('at K = 10, from the tabulated J1(10), J2(10) and J3(10) = (4/10)·J2 − J1 (A&S Table 9.1 and 9.1.27)', () => {
    const [j1, j2] = [0.0434727462, 0.2546303137];
    const j3 = 0.4 * j2 - j1;
    const expected = 50 * (1 - 2 * j2 - 2 * j1 * j1 + 2 * j2 * j2 + 2 * j3 * j3);
    expect(Math.abs(rechesterWhiteDiffusion(10) - expected)).toBeLessThan(1e-7);
    expect(quasilinearDiffusion(10)).toBe(50);
  });

  test('tends to K²/2: within the stated remainder of its large-K form from A&S 9.2.5, which tends to 1', () => {
    // J_n(K) ≈ √(2/πK)(cos ω − ((4n² − 1)/8K) sin ω), ω = K − nπ/2 − π/4: the formula's ratio to K²/2 to O(K^{-3/2})
    const hankel = (n: number, K: number) => {
      const omega = K - (n * Math.PI) / 2 - Math.PI / 4;
      return Math.sqrt(2 / (Math.PI * K)) * (Math.cos(omega) - ((4 * n * n - 1) / (8 * K)) * Math.sin(omega));
    };
    let previous = Infinity;
    for (const K of [50, 100, 1000, 1e4, 1e5]) {
      const [j1, j2, j3] = [hankel(1, K), hankel(2, K), hankel(3, K)];
      const asymptotic = 1 - 2 * j2 - 2 * j1 * j1 + 2 * j2 * j2 + 2 * j3 * j3;
      const ratio = rechesterWhiteDiffusion(K) / quasilinearDiffusion(K);
      expect(Math.abs(ratio - asymptotic)).toBeLessThan(rechesterWhiteRemainder(K));
      // and the ratio's distance from 1 is bounded by the envelope 2√(2/πK) + 4·(2/πK) of its Bessel terms, which shrinks
      const envelope = 2 * Math.sqrt(2 / (Math.PI * K)) + 8 / (Math.PI * K);
      expect(Math.abs(ratio - 1)).toBeLessThan(envelope);
      expect(envelope).toBeLessThan(previous);
      previous = envelope;
    }
    expect(Math.abs(rechesterWhiteDiffusion(1e5) / quasilinearDiffusion(1e5) - 1)).toBeLessThan(6e-3);
  });
});

/** A linear congruential generator (Numerical Recipes' 32-bit constants): numbers of the test's own, independent of the core's Philox. */
function lcg(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(1664525, s) + 1013904223) >>> 0;
    return s / 4294967296;
  };
}

/** D = ⟨(p_n − p_0)²⟩/n by the plainest simulation: random starts on [0, 2π)², the map written out, p never reduced. */
function plainDiffusion(K: number, orbits: number, iterations: number, seed: number): { D: number; standardError: number } {
  const random = lcg(seed);
  const readings: number[] = [];
  for (let j = 0; j < orbits; j++) {
    let q = TWO_PI * random();
    let p = TWO_PI * random();
    const p0 = p;
    for (let n = 0; n < iterations; n++) {
      p += K * Math.sin(q);
      q += p;
    }
    readings.push((p - p0) ** 2 / iterations);
  }
  const mean = readings.reduce((a, b) => a + b, 0) / orbits;
  const variance = readings.reduce((a, b) => a + (b - mean) ** 2, 0) / (orbits - 1);
  return { D: mean, standardError: Math.sqrt(variance / orbits) };
}

describe('measureDiffusion', () => {
  test('at K = 10, 20, 30, 50, away from accelerator modes, agrees with Rechester & White within 3 standard errors and the stated remainder', () => {
    for (const K of [10, 20, 30, 50]) {
      expect(acceleratorMode(K)).toBe(0);
      expect(nearAcceleratorMode(K)).toBe(false);
      const measured = measureDiffusion(K);
      expect(measured.orbits).toBe(400);
      expect(measured.iterations).toBe(400);
      const allowed = 3 * measured.standardError + rechesterWhiteRemainder(K) * quasilinearDiffusion(K);
      expect(Math.abs(measured.D - rechesterWhiteDiffusion(K))).toBeLessThan(allowed);
      // each orbit's reading is D times a χ² of one degree of freedom, of relative spread √2: the standard error is about √(2/400)·D
      expect(measured.standardError / measured.D).toBeGreaterThan(0.5 * Math.sqrt(2 / 400));
      expect(measured.standardError / measured.D).toBeLessThan(1.5 * Math.sqrt(2 / 400));
      // diffusive: the spread grows like n, so the reading at the half run agrees (its errors are correlated with D's; 5 standard errors)
      expect(Math.abs(measured.halfRunD - measured.D)).toBeLessThan(5 * measured.standardError);
    }
  });

  test('agrees with a simulation written plainly here, with its own random numbers, within 3 combined standard errors', () => {
    for (const K of [10, 30]) {
      const core = measureDiffusion(K, { orbits: 400, iterations: 400, seed: 3 });
      const plain = plainDiffusion(K, 400, 400, 12345);
      expect(Math.abs(core.D - plain.D)).toBeLessThan(3 * Math.hypot(core.standardError, plain.standardError));
    }
  });

  test('at K = 10 the measured D sits well below K²/2, as Rechester & White’s −2J₂(10) ≈ −0.51 predicts, not at the quasilinear value', () => {
    const measured = measureDiffusion(10, { orbits: 1600, iterations: 200 });
    expect(measured.D / quasilinearDiffusion(10)).toBeLessThan(0.8);
    expect(measured.D / quasilinearDiffusion(10)).toBeGreaterThan(0.45);
  });

  test('is reproducible from its seed, and another seed gives other orbits', () => {
    expect(measureDiffusion(15, { orbits: 50, iterations: 50, seed: 9 })).toEqual(measureDiffusion(15, { orbits: 50, iterations: 50, seed: 9 }));
    expect(measureDiffusion(15, { orbits: 50, iterations: 50, seed: 9 }).D).not.toBe(measureDiffusion(15, { orbits: 50, iterations: 50, seed: 10 }).D);
  });

  test('refuses too few orbits or iterations, and a K that is not a finite number', () => {
    expect(() => measureDiffusion(10, { orbits: 1 })).toThrow(RangeError);
    expect(() => measureDiffusion(10, { iterations: 2.5 })).toThrow(RangeError);
    expect(() => measureDiffusion(NaN)).toThrow(/finite number/);
  });
});

describe('residues', () => {
  test('the fixed points: R = K/4 at the elliptic (π, 0), R = −K/4 at the hyperbolic (0, 0)', () => {
    // M = [[1 + K cos q, 1], [K cos q, 1]] has trace 2 + K cos q, so R = (2 − tr M)/4 = −K cos q/4
    for (const K of [0.3, 1, 2.5, 3.9]) {
      expect(residue(K, Math.PI, 0, 1)).toBeCloseTo(K / 4, 14);
      expect(residue(K, 0, 0, 1)).toBeCloseTo(-K / 4, 14);
      expect(greeneResidueAt(K, 1)).toBeCloseTo(K / 4, 14);
    }
  });

  test('the period-2 orbit (π, π) → (0, π): R = K²/4', () => {
    // J(0)·J(π) = [[1 + K, 1], [K, 1]]·[[1 − K, 1], [−K, 1]] has trace (1 − K²) − K + K + 1 = 2 − K²
    for (const K of [0.5, 0.97, 2]) {
      expect(residue(K, Math.PI, Math.PI, 2)).toBeCloseTo((K * K) / 4, 13);
      expect(greeneResidueAt(K, 2)).toBeCloseTo((K * K) / 4, 13);
    }
  });

  test('at K = 0 every orbit is a shear, M = [[1, n], [0, 1]], and every residue is 0', () => {
    for (const level of [1, 3, 6, 10]) expect(greeneResidueAt(0, level)).toBe(0);
  });

  test('Greene’s orbits are periodic with rotation number F_k/F_{k+1}, checked by iterating the map written out here', () => {
    for (const [K, level] of [
      [0.5, 6],
      [0.9, 10],
      [0.97, 8],
    ]) {
      const orbit = greeneOrbit(K, level);
      expect([orbit.m, orbit.n]).toEqual([[8, 13], [55, 89], [21, 34]][[6, 10, 8].indexOf(level)]);
      let [q, p] = [orbit.q0, orbit.p0];
      for (let t = 0; t < orbit.n; t++) {
        p += K * Math.sin(q);
        q += p;
      }
      expect(Math.abs(q - orbit.q0 - TWO_PI * orbit.m)).toBeLessThan(1e-9);
      expect(Math.abs(p - orbit.p0)).toBeLessThan(1e-9);
      // the residue by iterating (residue()) agrees with the one from the solved angles
      expect(residue(K, orbit.q0, orbit.p0, orbit.n)).toBeCloseTo(orbit.residue, 8);
    }
  });

  test('Greene’s criterion: at K = 0.95 the residues of levels 8 → 12 shrink toward 0, at K = 1.0 they grow without bound', () => {
    const below = [8, 9, 10, 11, 12].map((level) => greeneResidueAt(0.95, level));
    const above = [8, 9, 10, 11, 12].map((level) => greeneResidueAt(1.0, level));
    for (let i = 1; i < 5; i++) {
      expect(below[i]).toBeLessThan(below[i - 1]);
      expect(above[i]).toBeGreaterThan(above[i - 1]);
    }
    expect(below[4]).toBeGreaterThan(0);
    expect(below[4]).toBeLessThan(0.01);
    expect(above[4]).toBeGreaterThan(10);
  });

  test('the K of residue 1/4 converge to MacKay’s 0.971635406: level 14 within 1e-4, each level closer than the one two above it', () => {
    // Greene 1979 quotes 0.971635; MacKay 1983, by renormalisation, 0.971635406
    expect(Math.abs(GREENE_K - 0.971635)).toBeLessThan(1e-6);
    const levels = greeneLevels(14);
    expect(levels.map((l) => l.level)).toEqual([5, 6, 7, 8, 9, 10, 11, 12, 13, 14]);
    expect(levels[0]).toMatchObject({ m: 5, n: 8 });
    expect(levels[9]).toMatchObject({ m: 377, n: 610 });
    const gaps = levels.map((l) => Math.abs(l.K - 0.971635406));
    expect(gaps[9]).toBeLessThan(1e-4);
    for (let i = 2; i < gaps.length; i++) expect(gaps[i]).toBeLessThan(gaps[i - 2]);
    // each K is a root: the residue crosses 1/4 there
    const { level, K } = levels[5];
    expect(greeneResidueAt(K - 1e-9, level)).toBeLessThan(0.25);
    expect(greeneResidueAt(K + 1e-9, level)).toBeGreaterThan(0.25);
  });

  test('the overlap estimates: the primary half-widths 2√K meet at 4√K = 2π; with the 1:2 resonance’s K/2, 4√K + K = 2π, Chirikov’s 1.46; both above Greene’s K', () => {
    expect(4 * Math.sqrt(CHIRIKOV_OVERLAP.primary)).toBeCloseTo(TWO_PI, 14);
    expect(4 * Math.sqrt(CHIRIKOV_OVERLAP.withSecondary) + CHIRIKOV_OVERLAP.withSecondary).toBeCloseTo(TWO_PI, 14);
    expect(Math.abs(CHIRIKOV_OVERLAP.withSecondary - 1.46)).toBeLessThan(0.005);
    expect(CHIRIKOV_OVERLAP.withSecondary).toBeGreaterThan(GREENE_K);
  });

  test('bad arguments are refused', () => {
    expect(() => residue(1, 0, 0, 0)).toThrow(RangeError);
    expect(() => greeneOrbit(1, 0)).toThrow(RangeError);
    expect(() => greeneLevels(4)).toThrow(RangeError);
    expect(() => greeneResidueAt(Infinity, 3)).toThrow(/finite number/);
  });
});

describe('accelerator modes', () => {
  test('the bands 2πm ≤ |K| ≤ √((2πm)² + 16)', () => {
    expect(acceleratorMode(6.5)).toBe(1);
    expect(acceleratorMode(-6.5)).toBe(1);
    expect(acceleratorMode(10)).toBe(0);
    expect(acceleratorMode(6.2)).toBe(0);
    expect(acceleratorMode(4 * Math.PI + 0.1)).toBe(2);
    expect(nearAcceleratorMode(6.2)).toBe(true);
    expect(nearAcceleratorMode(7.9)).toBe(true);
    expect(nearAcceleratorMode(10)).toBe(false);
  });

  test('inside a band the map has a stable orbit gaining 2πm per iterate; outside, the same orbit is unstable', () => {
    // sin q* = 2πm/K gives p' = p + 2πm and q' = q* + 2πm ≡ q*: with cos q* < 0 the residue −K cos q*/4 lies in (0, 1)
    // exactly when K²cos²q* = K² − (2πm)² < 16, the band's top
    const accelerator = (K: number, m: number) => Math.PI - Math.asin((TWO_PI * m) / K);
    for (const [K, m, inside] of [
      [6.5, 1, true],
      [7.6, 1, false],
      [13, 2, true],
      [13.3, 2, false],
    ] as const) {
      expect(acceleratorMode(K) === m).toBe(inside);
      const q = accelerator(K, m);
      const R = residue(K, q, 0, 1);
      expect(R > 0 && R < 1).toBe(inside);
      const reading = orbitReading(K, [q, 0], 20);
      expect(reading.pMax).toBeCloseTo(20 * TWO_PI * m, 6);
    }
  });
});

describe('orbitReading', () => {
  test('at K = 0 the rotation number is p0/(2π), and nothing crosses', () => {
    for (const p0 of [0.3, 2.5, -1.7]) {
      const reading = orbitReading(0, [1, p0], 1000);
      expect(reading.rotation).toBeCloseTo(p0 / TWO_PI, 12);
      expect(reading.crossed).toBe(false);
      expect([reading.pMin, reading.pMax]).toEqual([p0, p0]);
    }
  });

  test('at K = 0.5 from (π, 1), inside the main island: no crossing, rotation 0, Lyapunov exponent near 0', () => {
    const reading = orbitReading(0.5, [Math.PI, 1], 5000);
    expect(reading.crossed).toBe(false);
    expect(Math.abs(reading.rotation)).toBeLessThan(1e-3);
    expect(reading.lyapunov).toBeLessThan(0.01);
    expect(reading.pMax - reading.pMin).toBeLessThan(2 * 2 * Math.sqrt(0.5) + 0.5);
  });

  test('at K = 0.9 from (π, 1.5), near the edge of the main island: p swings by more than π but not 2π, and that is no crossing', () => {
    // the island, a pendulum of half-width 2√K ≈ 1.9, is wider than π: its orbits go from p to about −p and back
    const reading = orbitReading(0.9, [Math.PI, 1.5], 20_000);
    expect(1.5 - reading.pMin).toBeGreaterThan(Math.PI);
    expect(reading.crossed).toBe(false);
    expect(Math.abs(reading.rotation)).toBeLessThan(1e-3);
  });

  test('at K = 0.95, below Greene’s K, the chaotic orbit by the hyperbolic point is barred by the surviving circles', () => {
    const reading = orbitReading(0.95, [0.1, 0.1], 100_000);
    expect(reading.lyapunov).toBeGreaterThan(0.03);
    expect(reading.crossed).toBe(false);
    expect(reading.pMax - reading.pMin).toBeLessThan(TWO_PI);
  });

  test('at K = 2, above Greene’s K, the orbit from (0.1, 0.1) crosses within 5000 iterates and is chaotic', () => {
    const reading = orbitReading(2, [0.1, 0.1], 5000);
    expect(reading.crossed).toBe(true);
    expect(reading.lyapunov).toBeGreaterThan(0.1);
    expect(reading.pMax - reading.pMin).toBeGreaterThan(TWO_PI);
  });
});
