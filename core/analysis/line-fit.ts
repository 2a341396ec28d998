/**
 * The least-squares straight line through points (x, y), with what the
 * order study and the drift law need of it: the slope, its standard error,
 * and the weights by which each y moves the slope, so that a known error in
 * one y can be carried to the slope exactly (to first order).
 */
export interface LineFit {
  slope: number;
  intercept: number;
  /** the slope's standard error from the residuals (0 for two points, or points on a line) */
  slopeError: number;
  /** ∂slope/∂y_i = (x_i − x̄)/Σ(x − x̄)²: a change δ_i in y_i moves the slope by Σ w_i δ_i */
  weights: number[];
}

/** The least-squares line y ≈ intercept + slope·x; NaN throughout with fewer than two distinct x. */
export function fitLine(x: ArrayLike<number>, y: ArrayLike<number>): LineFit {
  const n = Math.min(x.length, y.length);
  let mx = 0;
  let my = 0;
  for (let i = 0; i < n; i++) {
    mx += x[i] / n;
    my += y[i] / n;
  }
  let sxx = 0;
  let sxy = 0;
  for (let i = 0; i < n; i++) {
    sxx += (x[i] - mx) ** 2;
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (!(sxx > 0)) return { slope: NaN, intercept: NaN, slopeError: NaN, weights: [] };
  const slope = sxy / sxx;
  const intercept = my - slope * mx;
  let rss = 0;
  for (let i = 0; i < n; i++) rss += (y[i] - intercept - slope * x[i]) ** 2;
  const slopeError = n > 2 ? Math.sqrt(rss / (n - 2) / sxx) : 0;
  const weights = Array.from({ length: n }, (_, i) => (x[i] - mx) / sxx);
  return { slope, intercept, slopeError, weights };
}
