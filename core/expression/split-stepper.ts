/**
 * Generated steppers of the splitting methods for a separable
 * H = T(p) + V(q, t), fused per model like the RK 3/8 stepper
 * (fused-stepper.ts): the state in scalar locals, every derivative written
 * out in line, parameters read live from the array.
 *
 * Both are compositions of a kick p ← p − c·h·∂V/∂q(q, t) at fixed q and
 * t, and a drift q ← q + d·h·∂T/∂p(p) at fixed p that also moves t by d·h:
 * the exact flows of V and of T + E in the extended phase space (t, E), so
 * a time-dependent V keeps the methods symplectic there (Hairer, Lubich &
 * Wanner, *Geometric Numerical Integration*, §II.5 and §VI.1).
 *
 * - Störmer–Verlet (leapfrog), kick–drift–kick: c = ½, 1, … d = 1; order 2
 *   (HLW §I.3, eq. (3.4)).
 * - Yoshida's 4th-order composition of three Verlet steps of fractions
 *   w₁, w₀, w₁ with w₁ = 1/(2 − 2^⅓), w₀ = −2^⅓/(2 − 2^⅓) (Yoshida 1990,
 *   Phys. Lett. A 150, 262; HLW §II.4, eq. (4.4)): kicks c = w₁/2,
 *   (w₀ + w₁)/2, (w₀ + w₁)/2, w₁/2, drifts d = w₁, w₀, w₁.
 *
 * A step's last kick and the next step's first are evaluated at the same q
 * and t, so the force is carried over ("first same as last"): Verlet
 * costs one ∂V/∂q and one ∂T/∂p per step, Yoshida three of each.
 */
import type { MathNode } from 'mathjs';
import { Emitter } from './emit.ts';
import { symbolReader, type RateExpressions } from './fused-stepper.ts';

export type SplittingName = 'verlet' | 'yoshida4';

const CBRT2 = Math.cbrt(2);
const W1 = 1 / (2 - CBRT2);
const W0 = -CBRT2 / (2 - CBRT2);

/** Kick fractions (one more than drifts) and drift fractions of one step. */
export const SPLITTING_COEFFICIENTS: Record<SplittingName, { kicks: number[]; drifts: number[] }> = {
  verlet: { kicks: [0.5, 0.5], drifts: [1] },
  yoshida4: { kicks: [W1 / 2, (W0 + W1) / 2, (W0 + W1) / 2, W1 / 2], drifts: [W1, W0, W1] },
};

/** A number as JS source that reads back as the same double. */
const literal = (v: number) => (Object.is(v, -0) ? '-0' : String(v));

/**
 * The code of one evaluation of some rates: a block computing them from the
 * locals the state reader names, at time `time`, into `targets`.
 */
function evaluation(
  model: RateExpressions,
  rates: readonly { node: MathNode; negate: boolean }[],
  read: (i: number) => string,
  time: string,
  targets: readonly string[],
  prefix: string,
): string[] {
  const emitter = new Emitter(symbolReader(model, read), prefix);
  const codes = rates.map(({ node, negate }) => {
    const code = emitter.emit(node);
    return negate ? `(-${code})` : code;
  });
  return ['{', `const $time = ${time};`, ...emitter.temps, ...codes.map((c, i) => `${targets[i]} = ${c};`), '}'];
}

/**
 * The source of `return function advance($x, $count, $P, $t0, $k0, $dt, $steps)`
 * for a splitting method; `model.rates` must be those of a separable H
 * (expression/separable.ts checks it before this is called).
 */
export function splitStepperSource(model: RateExpressions, method: SplittingName): string {
  const dim = model.names.length;
  const dof = dim / 2;
  const { kicks, drifts } = SPLITTING_COEFFICIENTS[method];
  const qs = Array.from({ length: dof }, (_, i) => i);
  const y = (i: number) => `$y${i}`;
  const force = (i: number) => `$f${i}`;
  const velocity = (i: number) => `$v${i}`;
  const kickRates = qs.map((i) => model.rates[dof + i]);
  const driftRates = qs.map((i) => model.rates[i]);
  const onlyMomenta = (i: number) => {
    if (i < dof) throw new Error('a drift read a coordinate: H does not separate');
    return y(i);
  };
  const onlyCoordinates = (i: number) => {
    if (i >= dof) throw new Error('a kick read a momentum: H does not separate');
    return y(i);
  };
  const forceAt = (time: string, label: string) => evaluation(model, kickRates, onlyCoordinates, time, qs.map(force), `$${label}`);

  const out: string[] = [];
  out.push(`"use strict";`);
  out.push(`return function advance($x, $count, $P, $t0, $k0, $dt, $steps) {`);
  model.paramNames.forEach((name, j) => out.push(`const ${name} = $P[${j}];`));
  kicks.forEach((c, j) => out.push(`const $c${j} = ${literal(c)} * $dt;`));
  drifts.forEach((d, j) => out.push(`const $d${j} = ${literal(d)} * $dt;`));
  out.push(`for (let $m = 0; $m < $count; $m++) {`);
  out.push(`const $o = $m * ${dim};`);
  out.push(`let ${Array.from({ length: dim }, (_, i) => `${y(i)} = $x[$o + ${i}]`).join(', ')};`);
  out.push(`let ${qs.map(force).join(', ')};`);
  out.push(`let ${qs.map(velocity).join(', ')};`);
  // The force at the start of the call; later steps carry it from the step before.
  out.push(...forceAt('$t0 + $k0 * $dt', 'i'));
  out.push(`for (let $k = 0; $k < $steps; $k++) {`);
  out.push(`const $tk = $t0 + ($k0 + $k) * $dt;`);
  drifts.forEach((_, j) => {
    qs.forEach((i) => out.push(`${y(dof + i)} += $c${j} * ${force(i)};`));
    out.push(...evaluation(model, driftRates, onlyMomenta, '$tk', qs.map(velocity), `$u${j}_`));
    qs.forEach((i) => out.push(`${y(i)} += $d${j} * ${velocity(i)};`));
    const last = j === drifts.length - 1;
    // The last kick's time is written as the next step's start, so the carried force is exactly that step's.
    const time = last ? '$t0 + ($k0 + $k + 1) * $dt' : `$tk + ${literal(drifts.slice(0, j + 1).reduce((a, b) => a + b, 0))} * $dt`;
    out.push(...forceAt(time, `k${j}_`));
  });
  qs.forEach((i) => out.push(`${y(dof + i)} += $c${kicks.length - 1} * ${force(i)};`));
  out.push(`const $sum = ${Array.from({ length: dim }, (_, i) => y(i)).join(' + ')};`);
  out.push(`if ($sum - $sum !== 0) {`);
  for (let i = 0; i < dim; i++) out.push(`$x[$o + ${i}] = ${y(i)};`);
  out.push(`return $k;`, `}`);
  out.push(`}`);
  for (let i = 0; i < dim; i++) out.push(`$x[$o + ${i}] = ${y(i)};`);
  out.push(`}`, `return $steps;`, `};`);
  return out.join('\n');
}
