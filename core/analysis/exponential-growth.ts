/**
 * The rate a of a motion whose size grows as e^{at} times a bounded
 * oscillation (a complex pair of roots a ± ib, as about an unstable
 * equilibrium), from the least-squares line through ln(size) against time.
 * The oscillation leaves the logarithm off any straight line by a bounded
 * amount R, the largest residual; the fit's weights carry that to the slope
 * exactly, to at most R·Σ|∂slope/∂yᵢ| (line-fit.ts), which is the bound it
 * reports. A longer span shrinks it as 1/span.
 */
import { fitLine } from './line-fit.ts';

export interface ExponentialGrowth {
  /** the slope of ln(size) against time */
  rate: number;
  /** how far the rate can be from the envelope's: the largest residual times Σ|weights| */
  bound: number;
  /** the time from the first sample used to the last */
  span: number;
  /** the samples used */
  samples: number;
}

/**
 * Fits ln(size) at the samples whose size lies between `from` and `to`, and
 * only those before the first that exceeds `to`: `from` so that the decaying
 * solutions have died out, `to` so that the motion is still linear. Fewer
 * than three samples give NaN.
 */
export function exponentialGrowth(t: ArrayLike<number>, size: ArrayLike<number>, from: number, to: number): ExponentialGrowth {
  const times: number[] = [];
  const logs: number[] = [];
  for (let i = 0; i < size.length && !(size[i] > to); i++) {
    if (size[i] >= from) {
      times.push(t[i]);
      logs.push(Math.log(size[i]));
    }
  }
  if (times.length < 3) return { rate: NaN, bound: NaN, span: NaN, samples: times.length };
  const line = fitLine(times, logs);
  const residual = Math.max(...logs.map((y, i) => Math.abs(y - line.intercept - line.slope * times[i])));
  const bound = residual * line.weights.reduce((sum, w) => sum + Math.abs(w), 0);
  return { rate: line.slope, bound, span: times[times.length - 1] - times[0], samples: times.length };
}
