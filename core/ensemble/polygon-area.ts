/**
 * The area of a closed polygon in the (q, p) plane, and the error of that
 * area as a measure of the smooth closed curve through its vertices.
 *
 * The area, by the shoelace formula, is written with one product per vertex,
 *
 *     2A = Σ_i X_i·(p_{i+1} − p_{i−1}),   X_i = q_i − q_0,
 *
 * (the cross-product form Σ X_i Y_{i+1} − X_{i+1} Y_i regrouped, indices
 * cyclic). Measuring q from a vertex keeps the digits of a polygon that sits
 * far from the origin: its coordinates agree in their leading digits, and
 * those cancel exactly in the differences instead of in a sum of products of
 * size |q|·|p|. Adjacent vertices nearly agree, so p_{i+1} − p_{i−1} is
 * formed with almost no rounding, and each term is rounded once; the cross
 * form would round two products of size D² (D the polygon's size) to leave
 * one of size D·ℓ (ℓ a side), losing a factor D/ℓ — about the vertex count —
 * more. The terms are summed with Neumaier's compensated summation, so the
 * rounding of the sum is that of its largest terms, not of their number.
 */

/**
 * The signed area of the polygon of vertices (q_i, p_i), i < n, closed from
 * the last vertex back to the first: positive when they run counter-clockwise
 * with q across and p up. Fewer than three vertices enclose nothing.
 */
export function polygonArea(q: ArrayLike<number>, p: ArrayLike<number>, n: number = q.length): number {
  if (n < 3) return 0;
  const q0 = q[0];
  const last = n - 1;
  // Neumaier's compensated sum (Neumaier 1974, an improved Kahan–Babuška
  // sum) of the terms; X_0 = 0, so it starts at vertex 1, and vertex n wraps to 0.
  let twice = 0;
  let compensation = 0;
  for (let i = 1; i < n; i++) {
    const next = i === last ? p[0] : p[i + 1];
    const term = (q[i] - q0) * (next - p[i - 1]);
    const sum = twice + term;
    compensation += Math.abs(twice) >= Math.abs(term) ? twice - sum + term : term - sum + twice;
    twice = sum;
  }
  return (twice + compensation) / 2;
}

/**
 * How much more the estimate below claims than its leading order: for the
 * regular n-gon inscribed in a circle the leading order falls short of the
 * true error by a fraction θ²/5 (θ = 2π/n, the next terms of the series
 * below), and where the curvature varies along a side it is off by a like
 * amount either way, so the bound leaves a quarter's room.
 */
const SAFETY = 1.25;

/**
 * A bound on |A_curve − A_polygon|, the area between the polygon of
 * vertices (q_i, p_i), i < n, and the smooth closed curve through them, when
 * the vertices resolve the curve (each side turns through a small angle).
 * It is positive whatever the orientation.
 *
 * The error model. The side of length ℓ between two vertices cuts off the
 * curve's segment of area κℓ³/12 to leading order in κℓ, κ the curvature
 * there: the arc lies at height κx(ℓ − x)/2 above the chord, whose integral
 * over 0 < x < ℓ is κℓ³/12. With n evenly spread vertices the error is
 * therefore E_n ≈ c/n² (n sides, each ∝ (1/n)³), and dropping every other
 * vertex gives E_{n/2} ≈ 4E_n. The difference A_n − A_{n/2} is exactly the
 * sum of the triangles (v_{i−1}, v_i, v_{i+1}) the coarser polygon leaves
 * out, and it is E_{n/2} − E_n ≈ 3E_n: Richardson's E_n ≈ (A_n − A_{n/2})/3,
 * which is a third of the dropped triangles' area.
 *
 * Per triangle, with sides ℓ₁, ℓ₂ about v_i: the polygon turns there through
 * φ ≈ κ(ℓ₁ + ℓ₂)/2, so the triangle's area is ½ℓ₁ℓ₂ sin φ ≈ κℓ₁ℓ₂(ℓ₁ + ℓ₂)/4,
 * while its two sides' own error is κ(ℓ₁³ + ℓ₂³)/12: the triangle times
 * w = (ℓ₁² − ℓ₁ℓ₂ + ℓ₂²)/(3ℓ₁ℓ₂). That is the ⅓ above for even sides, and
 * more for uneven ones — which a refined boundary has, where one side was
 * halved and its neighbour not (sides in ratio 2 take w = ½) — so the weight
 * keeps the estimate true there. Each side belongs to two triangles, one of
 * each choice of the vertices dropped (the odd or the even ones); both are
 * taken, at half weight each, so neither choice is favoured and an odd n
 * needs no special case.
 *
 * The triangles enter by absolute value, so that the error of a side that
 * bulges out and one that bulges in cannot cancel: the result bounds the
 * error instead of estimating its sum. It is multiplied by SAFETY (above).
 * It does not include rounding, of the vertices or of the area, nor any error
 * in the vertices themselves (an integrator's): only the polygon's own. For
 * the regular n-gon the result is 1.25·(1 − θ²/5 + …) times the true error.
 * A side with a vertex repeated (zero length) adds nothing.
 */
export function polygonAreaError(q: ArrayLike<number>, p: ArrayLike<number>, n: number = q.length): number {
  return SAFETY * chordErrors(q, p, n, true);
}

/**
 * The signed estimate of A_curve − A_polygon by the same error model as
 * polygonAreaError, without absolute values and without SAFETY: positive
 * where the polygon cuts inside a convex (counter-clockwise, left-turning)
 * curve, negative where it cuts outside a concave stretch. The two sides of
 * a thin filament bend opposite ways, so their errors nearly cancel: on a
 * disc sheared into a spiral the bound above can exceed the actual error a
 * hundredfold while this estimate comes within a few percent of it. Added to
 * the polygon's area it gives the curve's to higher order (Richardson's
 * extrapolation); it is an estimate, not a bound.
 */
export function polygonAreaShortfall(q: ArrayLike<number>, p: ArrayLike<number>, n: number = q.length): number {
  return chordErrors(q, p, n, false);
}

/** Σ over the sides of the error model's κℓ³/12, each side's by absolute value or signed. */
function chordErrors(q: ArrayLike<number>, p: ArrayLike<number>, n: number, absolute: boolean): number {
  if (n < 3) return 0;
  let sum = 0;
  // The side into vertex i is (aq, ap), the side out of it (bq, bp).
  let aq = q[0] - q[n - 1];
  let ap = p[0] - p[n - 1];
  let la = Math.sqrt(aq * aq + ap * ap);
  for (let i = 0; i < n; i++) {
    const next = i + 1 === n ? 0 : i + 1;
    const bq = q[next] - q[i];
    const bp = p[next] - p[i];
    const lb = Math.sqrt(bq * bq + bp * bp);
    const product = la * lb;
    // a × b = 2·(triangle), positive for a left turn; times (ℓ₁² − ℓ₁ℓ₂ + ℓ₂²)/(ℓ₁ℓ₂) it is 6·(the two sides' error).
    if (product > 0) {
      const cross = aq * bp - ap * bq;
      sum += ((absolute ? Math.abs(cross) : cross) * (la * la - product + lb * lb)) / product;
    }
    aq = bq;
    ap = bp;
    la = lb;
  }
  // Half of Σ over both choices of the dropped vertices, of 6·(error) each.
  return sum / 12;
}
