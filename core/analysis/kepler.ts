/**
 * The two-body problem of the paper's section 7.1, H = Σ p²/(2m) − k/|r1 − r2|
 * with the state [x1, y1, x2, y2, px1, py1, px2, py2], reduced to its
 * relative motion (Landau & Lifshitz, Mechanics §13–15; Goldstein §3.7–3.9).
 */
export interface KeplerOrbit {
  /** energy of the relative motion (all of H when the total momentum is 0) */
  energy: number;
  /** angular momentum of both bodies about the origin */
  angularMomentum: number;
  /** Laplace–Runge–Lenz vector of the relative motion, pointing to the pericentre */
  lenz: [number, number];
  eccentricity: number;
  /** semi-major axis (negative for a hyperbola) */
  semiMajorAxis: number;
  /** 2π√(μa³/k), Kepler's third law (NaN for an unbound orbit) */
  period: number;
}

/** Orbit of two bodies of masses m1, m2 (the paper's H = Σp² means m = 1/2) attracting with −k/r. */
export function keplerOrbit(x: ArrayLike<number>, k = 500, m1 = 0.5, m2 = 0.5, offset = 0): KeplerOrbit {
  const o = offset;
  const mu = (m1 * m2) / (m1 + m2);
  const rx = x[o] - x[o + 2];
  const ry = x[o + 1] - x[o + 3];
  // Relative momentum p = μ·ṙ = μ(p1/m1 − p2/m2).
  const px = mu * (x[o + 4] / m1 - x[o + 6] / m2);
  const py = mu * (x[o + 5] / m1 - x[o + 7] / m2);
  const r = Math.hypot(rx, ry);
  const energy = (px * px + py * py) / (2 * mu) - k / r;
  const l = rx * py - ry * px;
  // A = p × L − μk r̂, with L along z: p × L = (py·L, −px·L).
  const lenz: [number, number] = [py * l - (mu * k * rx) / r, -px * l - (mu * k * ry) / r];
  const eccentricity = Math.hypot(lenz[0], lenz[1]) / (mu * k);
  const semiMajorAxis = -k / (2 * energy);
  const period = energy < 0 ? 2 * Math.PI * Math.sqrt((mu * semiMajorAxis ** 3) / k) : NaN;
  const angularMomentum =
    x[o] * x[o + 5] - x[o + 1] * x[o + 4] + x[o + 2] * x[o + 7] - x[o + 3] * x[o + 6];
  return { energy, angularMomentum, lenz, eccentricity, semiMajorAxis, period };
}
