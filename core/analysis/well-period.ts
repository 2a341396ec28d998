/**
 * The period of a bound motion in a one-dimensional well, by quadrature of
 * the period integral (Landau & Lifshitz, *Mechanics*, §11, eq. 11.5):
 *
 *     T = √2 ∫ dq / √(E − V(q))   from the left turning point to the right,
 *
 * for H = p²/2 + V(q). It needs no integration of the motion, so it is an
 * independent check of a simulation, and it holds at any amplitude, where a
 * perturbation series in the amplitude does not.
 *
 * The integrand is infinite at the turning points q± (E = V there). Near q₊,
 * E − V ≈ V'(q₊)(q₊ − q); with q = q₊ − u² the integrand 2u/√(E − V) tends
 * to 2/√V'(q₊), finite, and likewise q = q₋ + u² at the left. Split at the
 * well's bottom, each half is then a smooth integral that Gauss–Legendre
 * quadrature converges on quickly.
 */

/** Turning points beyond this distance from the bottom count as none: the motion is not bound. */
const SEARCH = 1e3;

/**
 * The turning point on one side (`side` ±1) of `bottom` where V reaches
 * `energy`, by bisection after a doubling search; NaN if V turns down first
 * (the particle goes over a barrier) or never reaches it.
 */
export function turningPoint(V: (q: number) => number, energy: number, bottom: number, side: 1 | -1): number {
  let inner = bottom;
  let step = 1e-3;
  let reached = NaN;
  while (Number.isNaN(reached)) {
    const outer = bottom + side * step;
    // Sampled finely, so that a step growing past a barrier still sees V rise to E, or fall back, before it.
    for (let k = 1; k <= 64; k++) {
      const q = inner + ((outer - inner) * k) / 64;
      const before = inner + ((outer - inner) * (k - 1)) / 64;
      if (V(q) >= energy) {
        [inner, reached] = [before, q];
        break;
      }
      // V falling again below E: a barrier lower than E, so no turning point on this side.
      if (V(q) < V(before)) return NaN;
    }
    if (Number.isNaN(reached)) {
      inner = outer;
      step *= 1.5;
      if (step > SEARCH) return NaN;
    }
  }
  let outer = reached;
  for (let i = 0; i < 200 && Math.abs(outer - inner) > 1e-15 * Math.max(1, Math.abs(outer)); i++) {
    const mid = (inner + outer) / 2;
    if (V(mid) < energy) inner = mid;
    else outer = mid;
  }
  return (inner + outer) / 2;
}

/** Nodes and weights of 64-point Gauss–Legendre quadrature on [0, 1], computed once by Newton's method on P₆₄. */
const GAUSS = (() => {
  const n = 64;
  const nodes: number[] = [];
  const weights: number[] = [];
  for (let i = 1; i <= n; i++) {
    let x = Math.cos((Math.PI * (i - 0.25)) / (n + 0.5));
    let derivative = 0;
    for (let iteration = 0; iteration < 100; iteration++) {
      let p0 = 1;
      let p1 = x;
      for (let k = 2; k <= n; k++) [p0, p1] = [p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k];
      derivative = (n * (x * p1 - p0)) / (x * x - 1);
      const dx = p1 / derivative;
      x -= dx;
      if (Math.abs(dx) < 1e-16) break;
    }
    nodes.push((1 + x) / 2);
    weights.push(1 / ((1 - x * x) * derivative * derivative));
  }
  return { nodes, weights };
})();

/** ∫₀^L f(u) du by composite Gauss–Legendre on `panels` equal panels. */
function integrate(f: (u: number) => number, length: number, panels = 8): number {
  let sum = 0;
  const width = length / panels;
  for (let panel = 0; panel < panels; panel++) {
    for (let i = 0; i < GAUSS.nodes.length; i++) sum += GAUSS.weights[i] * width * f((panel + GAUSS.nodes[i]) * width);
  }
  return sum;
}

/**
 * The period of H = p²/2 + V(q) released at rest from q = b, in a well whose
 * bottom is at `bottom` (V'(bottom) = 0); NaN when the motion is not bound
 * (b beyond a barrier) or b is the bottom itself.
 */
export function wellPeriod(V: (q: number) => number, b: number, bottom = 0): number {
  const energy = V(b);
  if (!Number.isFinite(energy) || b === bottom) return NaN;
  const side = b > bottom ? 1 : -1;
  const near = turningPoint(V, energy, bottom, side as 1 | -1);
  const far = turningPoint(V, energy, bottom, -side as 1 | -1);
  // Released beyond a barrier's top, V first reaches E short of b: the particle is outside the well.
  if (!Number.isFinite(near) || !Number.isFinite(far) || Math.abs(near - b) > 1e-9 * Math.max(1, Math.abs(b))) return NaN;
  // q = turn ∓ u², dq = 2u du: time from the bottom to a turning point and back is twice this.
  const half = (turn: number) => {
    const span = Math.sqrt(Math.abs(turn - bottom));
    const s = Math.sign(turn - bottom);
    return integrate((u) => {
      const gap = energy - V(turn - s * u * u);
      return u === 0 || gap <= 0 ? 2 / Math.sqrt(Math.max(Math.abs(slope(V, turn)), 1e-300)) : (2 * u) / Math.sqrt(gap);
    }, span);
  };
  return Math.SQRT2 * (half(near) + half(far));
}

/** V'(q) by a central difference, only for the integrand's finite limit at a turning point (never sampled: Gauss nodes avoid u = 0). */
function slope(V: (q: number) => number, q: number): number {
  const h = 1e-6 * Math.max(1, Math.abs(q));
  return (V(q + h) - V(q - h)) / (2 * h);
}
