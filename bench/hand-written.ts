/**
 * RK 3/8 loops written by hand with analytic gradients and the state in
 * locals: the fastest JS can be for each model, the yardstick for the
 * generated steppers (measured here within 0.8–1.3× of gcc -O2).
 */

/** The paper's default model, eq. 7: H = p²/2 + ω²(1 + u cos γt)q²/2 − f q cos(κt + β). */
export function defaultModel(x: Float64Array, dt: number, steps: number): void {
  const u = 0.3, gamma = 21.7, beta = 0.2, kappa = 8, omega = 10, f = 20;
  const w2 = omega * omega;
  const rate = (t: number, q: number) => -w2 * (1 + u * Math.cos(gamma * t)) * q + f * Math.cos(kappa * t + beta);
  let q = x[0], p = x[1];
  for (let k = 0; k < steps; k++) {
    const t = k * dt;
    const aq = p, ap = rate(t, q);
    const bq = p + (dt / 3) * ap, bp = rate(t + dt / 3, q + (dt / 3) * aq);
    const cq = p + dt * (bp - ap / 3), cp = rate(t + (2 * dt) / 3, q + dt * (bq - aq / 3));
    const dq = p + dt * (ap - bp + cp), dp = rate(t + dt, q + dt * (aq - bq + cq));
    q += (dt / 8) * (aq + 3 * (bq + cq) + dq);
    p += (dt / 8) * (ap + 3 * (bp + cp) + dp);
  }
  x[0] = q;
  x[1] = p;
}

/** Paper 7.1: H = Σp² − k/|r1 − r2| with k = 500; q̇ = 2p, ṗ1 = −k(r1 − r2)/r³ = −ṗ2. */
export function kepler(x: Float64Array, dt: number, steps: number): void {
  const k = 500, h3 = dt / 3, h8 = dt / 8;
  let x1 = x[0], y1 = x[1], x2 = x[2], y2 = x[3], a1 = x[4], b1 = x[5], a2 = x[6], b2 = x[7];
  for (let n = 0; n < steps; n++) {
    // Stage 1
    let dx = x1 - x2, dy = y1 - y2, r2 = dx * dx + dy * dy, s = k / (r2 * Math.sqrt(r2));
    const ka1 = -s * dx, kb1 = -s * dy;
    // Stage 2: positions move with q̇ = 2p, momenta with ṗ.
    const pa1 = a1 + h3 * ka1, pb1 = b1 + h3 * kb1, pa2 = a2 - h3 * ka1, pb2 = b2 - h3 * kb1;
    dx = x1 - x2 + h3 * 2 * (a1 - a2); dy = y1 - y2 + h3 * 2 * (b1 - b2);
    r2 = dx * dx + dy * dy; s = k / (r2 * Math.sqrt(r2));
    const ka2 = -s * dx, kb2 = -s * dy;
    // Stage 3
    const qa1 = a1 + dt * (ka2 - ka1 / 3), qb1 = b1 + dt * (kb2 - kb1 / 3), qa2 = a2 - dt * (ka2 - ka1 / 3), qb2 = b2 - dt * (kb2 - kb1 / 3);
    dx = x1 - x2 + dt * 2 * (pa1 - pa2 - (a1 - a2) / 3); dy = y1 - y2 + dt * 2 * (pb1 - pb2 - (b1 - b2) / 3);
    r2 = dx * dx + dy * dy; s = k / (r2 * Math.sqrt(r2));
    const ka3 = -s * dx, kb3 = -s * dy;
    // Stage 4
    const ra1 = a1 + dt * (ka1 - ka2 + ka3), rb1 = b1 + dt * (kb1 - kb2 + kb3), ra2 = a2 - dt * (ka1 - ka2 + ka3), rb2 = b2 - dt * (kb1 - kb2 + kb3);
    dx = x1 - x2 + dt * 2 * (a1 - a2 - (pa1 - pa2) + (qa1 - qa2)); dy = y1 - y2 + dt * 2 * (b1 - b2 - (pb1 - pb2) + (qb1 - qb2));
    r2 = dx * dx + dy * dy; s = k / (r2 * Math.sqrt(r2));
    const ka4 = -s * dx, kb4 = -s * dy;
    x1 += h8 * 2 * (a1 + 3 * (pa1 + qa1) + ra1); y1 += h8 * 2 * (b1 + 3 * (pb1 + qb1) + rb1);
    x2 += h8 * 2 * (a2 + 3 * (pa2 + qa2) + ra2); y2 += h8 * 2 * (b2 + 3 * (pb2 + qb2) + rb2);
    const fa = h8 * (ka1 + 3 * (ka2 + ka3) + ka4), fb = h8 * (kb1 + 3 * (kb2 + kb3) + kb4);
    a1 += fa; b1 += fb; a2 -= fa; b2 -= fb;
  }
  x.set([x1, y1, x2, y2, a1, b1, a2, b2]);
}

/** Paper 7.3, one particle of the beam: H = px² + py² + 30/r, for each of `count` particles. */
export function beam(x: Float64Array, count: number, dt: number, steps: number): void {
  const g = 30;
  for (let m = 0; m < count; m++) {
    const o = 4 * m;
    let X = x[o], Y = x[o + 1], A = x[o + 2], B = x[o + 3];
    for (let n = 0; n < steps; n++) {
      // ṗ = g r/|r|³ (repulsive), q̇ = 2p.
      let r2 = X * X + Y * Y, s = g / (r2 * Math.sqrt(r2));
      const aX = 2 * A, aY = 2 * B, aA = s * X, aB = s * Y;
      let sx = X + (dt / 3) * aX, sy = Y + (dt / 3) * aY;
      r2 = sx * sx + sy * sy; s = g / (r2 * Math.sqrt(r2));
      const bX = 2 * (A + (dt / 3) * aA), bY = 2 * (B + (dt / 3) * aB), bA = s * sx, bB = s * sy;
      sx = X + dt * (bX - aX / 3); sy = Y + dt * (bY - aY / 3);
      r2 = sx * sx + sy * sy; s = g / (r2 * Math.sqrt(r2));
      const cX = 2 * (A + dt * (bA - aA / 3)), cY = 2 * (B + dt * (bB - aB / 3)), cA = s * sx, cB = s * sy;
      sx = X + dt * (aX - bX + cX); sy = Y + dt * (aY - bY + cY);
      r2 = sx * sx + sy * sy; s = g / (r2 * Math.sqrt(r2));
      const dX = 2 * (A + dt * (aA - bA + cA)), dY = 2 * (B + dt * (aB - bB + cB)), dA = s * sx, dB = s * sy;
      X += (dt / 8) * (aX + 3 * (bX + cX) + dX); Y += (dt / 8) * (aY + 3 * (bY + cY) + dY);
      A += (dt / 8) * (aA + 3 * (bA + cA) + dA); B += (dt / 8) * (aB + 3 * (bB + cB) + dB);
    }
    x[o] = X; x[o + 1] = Y; x[o + 2] = A; x[o + 3] = B;
  }
}
