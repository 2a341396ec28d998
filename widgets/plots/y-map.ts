import { scaleLinear, scaleSymlog, type NumberScale } from './scale.ts';

/**
 * The vertical mapping m_y of the paper (§5): linear, or the symmetric
 * logarithm of §6.4, m_y(y) = 20 ln(1 + |y|) sgn y + h/2, which is d3's
 * scaleSymlog with constant 1 once the factor 20 and the offset h/2 are
 * fitted to the domain.
 */
export type YScaleKind = 'linear' | 'symlog';

export type Domain = readonly [number, number];

/** sgn y · ln(1 + |y|), the symlog transform with constant 1. */
export function symlog(y: number): number {
  return y < 0 ? -Math.log1p(-y) : Math.log1p(y);
}

/** The inverse of symlog. */
export function symexp(u: number): number {
  return u < 0 ? -Math.expm1(-u) : Math.expm1(u);
}

/** The transform of a scale kind: identity or symlog. */
export function transformOf(kind: YScaleKind): (y: number) => number {
  return kind === 'symlog' ? symlog : (y) => y;
}

/**
 * A mapping reduced to coefficients, pixel = a·T(y) + b with T the identity
 * or symlog, so the per-sample drawing loop evaluates it inline with no
 * function objects and no allocation.
 */
export interface YMap {
  readonly log: boolean;
  readonly a: number;
  readonly b: number;
}

/** The mapping of `domain` onto `range` ([bottom, top] in pixels) for a scale kind. */
export function yMap(kind: YScaleKind, domain: Domain, range: Domain): YMap {
  const log = kind === 'symlog';
  const u0 = log ? symlog(domain[0]) : domain[0];
  const u1 = log ? symlog(domain[1]) : domain[1];
  const a = u1 === u0 ? 0 : (range[1] - range[0]) / (u1 - u0);
  return { log, a, b: range[0] - a * u0 + (u1 === u0 ? (range[1] - range[0]) / 2 : 0) };
}

/** m_y(y) for a reduced mapping; equal to the d3 scale of the same kind, domain and range. */
export function mapY(m: YMap, y: number): number {
  return m.a * (m.log ? (y < 0 ? -Math.log1p(-y) : Math.log1p(y)) : y) + m.b;
}

/** The d3 scale with the same mapping, for axes and ticks. */
export function yScale(kind: YScaleKind, domain: Domain, range: Domain): NumberScale {
  const scale = kind === 'symlog' ? scaleSymlog().constant(1) : scaleLinear();
  return scale.domain(domain).range(range);
}
