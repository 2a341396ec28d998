/**
 * The write-code checks (code-checks.ts) on models built by the core: a
 * correct H passes however it is written (reordered, a constant added, as a
 * JS function), and wrong ones fail with a sentence naming the state.
 */
import { describe, expect, test } from 'vitest';
import { canonicalEquations } from '../../../../../core/model/canonical-equations.ts';
import { equationsCheck, returnsCheck, runCheck } from '../../../../../widgets/chapter/exercise/code-checks.ts';

const model = (hamiltonian: string | ((t: number, x: Float64Array) => number), dof = 1) => canonicalEquations({ dof, hamiltonian });
const box = [[-2, 2], [-3, 3]] as const;

describe('equationsCheck', () => {
  test('the same dynamics written otherwise passes: reordered, plus a constant, as a JS function', async () => {
    const reference = await model('p^2/4 + 9*q^2');
    for (const h of ['9*q^2 + p^2/4', 'p^2/4 + 9*q^2 + 7', (_t: number, x: Float64Array) => x[1] ** 2 / 4 + 9 * x[0] ** 2]) {
      expect(equationsCheck(await model(h), reference, box).passed).toBe(true);
    }
  });
  test('a wrong coefficient or sign fails, naming the state and the rate that differs', async () => {
    const reference = await model('p^2/4 + 9*q^2');
    const halfMass = equationsCheck(await model('p^2/2 + 9*q^2/2'), reference, box);
    expect(halfMass.passed).toBe(false);
    expect(halfMass.message).toMatch(/differ at \(q, p\) = \(.*\): your H gives/);
    expect(equationsCheck(await model('p^2/4 - 9*q^2'), reference, box).passed).toBe(false);
  });
});

describe('returnsCheck', () => {
  test('an oscillator of frequency 3 returns after 2π/3; one of frequency √3 does not', async () => {
    expect(returnsCheck(await model('p^2/4 + 9*q^2'), [1, 0], (2 * Math.PI) / 3).passed).toBe(true);
    const wrong = returnsCheck(await model('p^2/4 + 3*q^2'), [1, 0], (2 * Math.PI) / 3);
    expect(wrong.passed).toBe(false);
    expect(wrong.message).toContain('not back where it began');
  });
  test('a motion that blows up says so', async () => {
    expect(returnsCheck(await model('p^2/2 - q^4'), [3, 0], 5).message).toContain('blows up');
  });
});

test('a reader H with the wrong number of degrees of freedom is told so', async () => {
  const verdict = runCheck({ check: 'equations', box: [...box] }, await model('(p0^2 + p1^2)/2 + (q0^2 + q1^2)/2', 2), await model('p^2/2 + q^2/2'));
  expect(verdict.passed).toBe(false);
  expect(verdict.message).toContain('degrees of freedom');
});

describe('equationsInTime', () => {
  // ω(t) = 6 − 0.05t: the frozen H and the ramp of ω² instead of ω agree with it at t = 0 and nowhere later.
  const ramp = 'p^2/2 + (6 - 0.05*t)^2*q^2/2';
  const check = { check: 'equationsInTime', box: [...box], time: [0, 60] } as const;
  test('the same time-dependent H written otherwise passes, naming the times', async () => {
    const verdict = runCheck(check, await model('p^2/2 + (36 - 0.6*t + 0.0025*t^2)*q^2/2 + t'), await model(ramp));
    expect(verdict).toMatchObject({ passed: true });
    expect(verdict.message).toContain('times 0 ≤ t ≤ 60');
  });
  test('an H right at t = 0 but wrong later fails, naming the time, which the check at t = 0 alone misses', async () => {
    const reference = await model(ramp);
    for (const wrong of ['p^2/2 + 18*q^2', 'p^2/2 + (36 - 0.05*t)*q^2/2']) {
      expect(runCheck({ check: 'equations', box: [...box] }, await model(wrong), reference).passed).toBe(true);
      const verdict = runCheck(check, await model(wrong), reference);
      expect(verdict.passed).toBe(false);
      expect(verdict.message).toMatch(/differ at t = [\d.]+, \(q, p\) = /);
    }
  });
});
