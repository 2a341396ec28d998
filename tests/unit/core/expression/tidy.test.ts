/**
 * The linear clean-up of unsimplified derivatives (expression/tidy.ts):
 * values against derivatives worked by hand, evaluated by the full mathjs
 * (not the code this project generates), and the rewrites themselves.
 */
import { evaluate, type MathNode } from 'mathjs';
import { describe, expect, it } from 'vitest';
import { loadMathjs } from '../../../../core/expression/mathjs.ts';
import { Tidy } from '../../../../core/expression/tidy.ts';

const math = await loadMathjs();
const STATE = new Set(['q', 'p', 'q0', 'q1', 'q2', 'q3']);

function tidier(): Tidy {
  return new Tidy(math, (name) => STATE.has(name));
}

/** ∂H/∂x as the compiler takes it: mathjs's derivative, unsimplified, then tidied. */
function partial(h: string, x: string): MathNode {
  return tidier().tidy(math.derivative(math.parse(h), x, { simplify: false }));
}

type Scope = Record<string, number>;

const SCOPES: Scope[] = [
  { q: 0.7, p: -1.3, q0: 0.3, q1: -1.2, q2: 2.5, q3: 0.7, t: 0.4, omega: 10, omega0: 3, u: 0.3, gamma: 21.7, f: 20, kappa: 8, beta: 0.2, alpha: -2, m: 1.5 },
  { q: 2.1, p: 0.4, q0: -3, q1: -3, q2: 3, q3: 3.5, t: 1.9, omega: 2, omega0: 0.5, u: -0.7, gamma: 1.1, f: -1, kappa: 3, beta: -3, alpha: 5, m: 0.2 },
];

/** H, the variable, and ∂H/∂x worked by hand. */
const CASES: [string, string, (s: Scope) => number][] = [
  [
    'p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t + beta)',
    'q',
    (s) => s.omega ** 2 * (1 + s.u * Math.cos(s.gamma * s.t)) * s.q - s.f * Math.cos(s.kappa * s.t + s.beta),
  ],
  [
    'p0^2 + p1^2 - 500/sqrt((q0-q2)^2 + (q1-q3)^2)',
    'q0',
    (s) => (500 * (s.q0 - s.q2)) / Math.hypot(s.q0 - s.q2, s.q1 - s.q3) ** 3,
  ],
  [
    'p0^2 + p1^2 - 500/sqrt((q0-q2)^2 + (q1-q3)^2)',
    'q3',
    (s) => (-500 * (s.q1 - s.q3)) / Math.hypot(s.q0 - s.q2, s.q1 - s.q3) ** 3,
  ],
  ['p^2/2 - omega0^2 * cos(q)', 'q', (s) => s.omega0 ** 2 * Math.sin(s.q)],
  ['p^2/2 + omega0^2*q^2/2 + alpha*q^3 + beta*q^4', 'q', (s) => s.omega0 ** 2 * s.q + 3 * s.alpha * s.q ** 2 + 4 * s.beta * s.q ** 3],
  ['sqrt(p^2 + m^2) - f*q', 'p', (s) => s.p / Math.sqrt(s.p ** 2 + s.m ** 2)],
  ['q^-2 + 1/(1 + q^2)', 'q', (s) => -2 / s.q ** 3 - (2 * s.q) / (1 + s.q ** 2) ** 2],
  ['exp(-q^2/2) * p^3/3', 'q', (s) => (-s.q * Math.exp(-(s.q ** 2) / 2) * s.p ** 3) / 3],
  ['exp(-q^2/2) * p^3/3', 'p', (s) => Math.exp(-(s.q ** 2) / 2) * s.p ** 2],
  ['(q - p)^2 * (q + 1)/4 - -q', 'q', (s) => ((s.q - s.p) * (s.q + 1)) / 2 + (s.q - s.p) ** 2 / 4 + 1],
  ['sqrt(q)^3 * sqrt(q)', 'q', (s) => 2 * s.q],
  ['q*0 + 0*p + 1*q*1 - (0 - q)', 'q', () => 2],
  ['(omega0 + beta*t)^2 * q^2/2', 'q', (s) => (s.omega0 + s.beta * s.t) ** 2 * s.q],
];

describe('tidy(∂H/∂x)', () => {
  it.each(CASES)('keeps the value of ∂/∂%s… (%s)', (h, x, truth) => {
    const text = partial(h, x).toString();
    for (const scope of SCOPES) {
      const value = evaluate(text, { ...scope }) as number;
      const expected = truth(scope);
      expect(Math.abs(value - expected)).toBeLessThanOrEqual(1e-12 * Math.max(1, Math.abs(expected)));
    }
  });

  it.each([
    ['2 * 1 * q ^ (2 - 1) / 2', 'q'],
    ['0 + q * 0 - 0', '0'],
    ['0 - -500 * q', '500 * q'],
    ['3 * q / 6', 'q / 2'],
    ['-q0 + q2', 'q2 - q0'],
    ['1 + omega * 0 + q ^ 1 + 2', '3 + q'],
    ['sqrt(q) * sqrt(q) ^ 2 / 2', 'sqrt(q) ^ 3 / 2'],
    ['q * omega ^ 2 * 2 / 2', 'omega ^ 2 * q'],
    ['(0 - 1) * omega0 ^ 2 * sin(q)', '-(omega0 ^ 2 * sin(q))'],
    ['a * (b * (c / d)) / (e / f)', 'a * b * c * f / (d * e)'],
  ])('rewrites %s as %s', (input, output) => {
    expect(tidier().tidy(math.parse(input)).toString()).toBe(output);
  });

  it('writes a negation for reading: a sum with its signs turned, a difference in a product turned round', () => {
    const tidy = tidier();
    const negated = (text: string) => tidy.negated(tidy.tidy(math.parse(text))).toString();
    expect(negated('q0 - q2')).toBe('q2 - q0');
    expect(negated('500 * (q0 - q2) / r ^ 3')).toBe('500 * (q2 - q0) / r ^ 3');
    expect(negated('omega0 ^ 2 * sin(q)')).toBe('-(omega0 ^ 2 * sin(q))');
    expect(negated('-(omega0 ^ 2 * q)')).toBe('omega0 ^ 2 * q');
    expect(negated('3')).toBe('-3');
  });

  it('tidies a sum of thousands of zero terms to its one live term', () => {
    const terms = Array.from({ length: 3000 }, (_, i) => `0 * q${i % 4}`);
    expect(tidier().tidy(math.parse([...terms, '2 * q / 2'].join(' + '))).toString()).toBe('q');
  });
});
