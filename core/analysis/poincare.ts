/**
 * Surfaces of section of a planar system (henon-heiles.ts): the points where
 * an orbit pierces a plane q = 0 with p > 0 (Poincaré 1892; Hénon & Heiles
 * 1964). The brief's plane is y = 0 with py > 0, drawn in (x, px); Hénon &
 * Heiles drew x = 0 with px > 0 in (y, py). Both are offered.
 *
 * Locating a crossing: Hénon's trick (Hénon 1982, Physica D 5, 412). Once a
 * time step has carried q through 0, the equations are rewritten with q as
 * the independent variable, dS/dq = f(S)/f_q(S) where f_q = dq/dt = p, and
 * one RK 3/8 step of length −q lands exactly on the plane. Chosen over
 * Hermite interpolation plus a secant step because it needs no iteration, it
 * is as accurate as the integrator itself (order 4 in the step), and the
 * plane coordinate comes out 0 to rounding, with no tolerance to pick.
 * The division by p is harmless: we keep only crossings with p > 0, and the
 * endpoint nearer the plane is the one used.
 */
import { rk38 } from '../integrators/rk38.ts';
import type { PlanarSystem } from './henon-heiles.ts';

export type Plane = 'y' | 'x';

/** Indices into [x, y, px, py]: the plane's coordinate and momentum, and the section's two coordinates. */
export function planeIndices(plane: Plane) {
  return plane === 'y'
    ? { q: 1, p: 3, u: 0, pu: 2, names: ['x', 'px'] as const }
    : { q: 0, p: 2, u: 1, pu: 3, names: ['y', 'py'] as const };
}

/**
 * The state on the plane at (u, pu) with energy E, its momentum across the
 * plane solved from the energy, p = +√(2(E − V) − pu²); null where the point
 * lies outside the energy's allowed region (p² < 0).
 */
export function launchState(system: PlanarSystem, energy: number, u: number, pu: number, plane: Plane = 'y'): Float64Array | null {
  const ix = planeIndices(plane);
  const s = new Float64Array(4);
  s[ix.u] = u;
  s[ix.pu] = pu;
  const V = plane === 'y' ? system.potential(u, 0) : system.potential(0, u);
  const p2 = 2 * (energy - V) - pu * pu;
  if (!(p2 > 0)) return null;
  s[ix.p] = Math.sqrt(p2);
  return s;
}

/** Whether (u, pu) lies inside the section's allowed region at energy E. */
export function allowed(system: PlanarSystem, energy: number, u: number, pu: number, plane: Plane = 'y'): boolean {
  return launchState(system, energy, u, pu, plane) !== null;
}

export interface SectionOptions {
  plane?: Plane;
  /** time step of the RK 3/8 integration */
  dt?: number;
  /** stop after this many crossings */
  count?: number;
  /** or after this much time */
  maxTime?: number;
  /** leave when |s| exceeds this (an orbit escaping above E = 1/6) */
  escape?: number;
}

export interface Section {
  /** the section's coordinates of each crossing: (x, px) for plane y, (y, py) for plane x */
  u: number[];
  pu: number[];
  /** the full state at each crossing, 4 numbers each */
  states: number[];
  /** time integrated */
  time: number;
  escaped: boolean;
}

/** Integrates from `start` and records its crossings of the plane with p > 0. */
export function section(system: PlanarSystem, start: ArrayLike<number>, options: SectionOptions = {}): Section {
  const { plane = 'y', dt = 0.02, count = 500, maxTime = 1e5, escape = 10 } = options;
  const ix = planeIndices(plane);
  const step = rk38(system.field, 4);
  const fieldOut = new Float64Array(4);
  // dS/dq = f/f_q: the same field, divided through by the rate of the plane's coordinate.
  const byPlane = rk38((t, s, out) => {
    system.field(t, s, out);
    const rate = out[ix.q];
    for (let i = 0; i < 4; i++) out[i] /= rate;
  }, 4);
  const none = new Float64Array(0);
  const s = Float64Array.from(start);
  const before = new Float64Array(4);
  const hit = new Float64Array(4);
  const out: Section = { u: [], pu: [], states: [], time: 0, escaped: false };
  const steps = Math.ceil(maxTime / dt);
  let k = 0;
  for (; k < steps && out.u.length < count; k++) {
    before.set(s);
    if (step.advance(s, 1, none, 0, k, dt, 1) < 1 || Math.abs(s[0]) + Math.abs(s[1]) + Math.abs(s[2]) + Math.abs(s[3]) > escape) {
      out.escaped = true;
      out.time = k * dt;
      return out;
    }
    const a = before[ix.q];
    const b = s[ix.q];
    if (a < 0 && b >= 0) {
      // Start from the endpoint nearer the plane, with a positive rate across it.
      hit.set(-a < b && before[ix.p] > 0 ? before : s);
      system.field(0, hit, fieldOut);
      if (!(fieldOut[ix.q] > 0)) continue;
      byPlane.advance(hit, 1, none, 0, 0, -hit[ix.q], 1);
      out.u.push(hit[ix.u]);
      out.pu.push(hit[ix.pu]);
      for (let i = 0; i < 4; i++) out.states.push(hit[i]);
    }
  }
  out.time = k * dt;
  return out;
}
