/**
 * Scattering in a repulsive Coulomb field U = α/r of a particle of mass m.
 * The paper's beam (section 7.3) is H = px² + py² + 30/r: m = 1/2, α = 30.
 */

/** Rutherford's deflection for impact parameter b at energy E: tan(θ/2) = α/(2Eb) (Landau & Lifshitz, Mechanics §19). */
export function rutherfordAngle(b: number, energy: number, alpha: number): number {
  return 2 * Math.atan(alpha / (2 * energy * Math.abs(b)));
}

/** The angle between the momentum (px0, py0) and a direction given by its angle φ, in [0, π]. */
export function angleBetween(px0: number, py0: number, phi: number): number {
  return Math.abs(Math.atan2(px0 * Math.sin(phi) - py0 * Math.cos(phi), px0 * Math.cos(phi) + py0 * Math.sin(phi)));
}

/**
 * The direction (polar angle) in which a particle in U = α/r finally leaves,
 * from any one state on its orbit, exactly. The orbit is a hyperbola
 * r = L²/(mα) / (e cos(φ − φ_A) − 1) whose axis points along the
 * Laplace–Runge–Lenz vector A = p × L + mα r̂ (conserved; Goldstein §3.9),
 * so the asymptotes lie at φ_A ± arccos(1/e), and the particle leaves along
 * the one ahead of it in the sense of L.
 */
export function outgoingDirection(x: number, y: number, px: number, py: number, alpha: number, mass: number): number {
  const r = Math.hypot(x, y);
  const l = x * py - y * px;
  const ax = py * l + (mass * alpha * x) / r;
  const ay = -px * l + (mass * alpha * y) / r;
  const e = Math.hypot(ax, ay) / (mass * alpha);
  return Math.atan2(ay, ax) + Math.sign(l) * Math.acos(1 / e);
}

/**
 * The deflection of a particle started at (x, y) with momentum (px, py): the
 * angle from its initial momentum to its final one. Started at a finite
 * distance, it differs from Rutherford's θ(b, E) with E the initial kinetic
 * energy, because the start already holds potential energy α/r0 (so the
 * asymptotic speed is higher) and the initial momentum is not yet along the
 * incoming asymptote.
 */
export function deflectionFrom(x: number, y: number, px: number, py: number, alpha: number, mass: number): number {
  return angleBetween(px, py, outgoingDirection(x, y, px, py, alpha, mass));
}
