import type { Peak, WindowName } from '../core/index.ts';

/**
 * Highest sidelobe of each window relative to its main lobe: the exact
 * Hamming window's sidelobes stay below −42.5 dB (0.0075) everywhere; the
 * rectangular window's fall off as 1/(π·m) at m resolution bins away.
 */
function sidelobe(window: WindowName, bins: number): number {
  if (window === 'hamming') return 0.0085;
  return Math.min(0.25, 1.25 / (Math.PI * Math.max(1, bins)));
}

const TREND_BINS = 1.5;

/**
 * Drops peaks that are no more than a sidelobe of a stronger peak: local
 * maxima of leakage rather than motion. `peaks` must be strongest first, as
 * findPeaks returns them; `duration` is the time the spectrum covers, so
 * that 1/duration is one resolution bin. Peaks within TREND_BINS of zero
 * frequency go too.
 */
export function dropLeakage(peaks: readonly Peak[], duration: number, window: WindowName): Peak[] {
  const kept: Peak[] = [];
  for (const p of peaks) {
    // Below one and a half resolution bins a "peak" is a trend over the window, not an oscillation.
    if (p.frequency * duration < TREND_BINS) continue;
    const leak = kept.some((s) => p.amplitude < s.amplitude * sidelobe(window, Math.abs(p.frequency - s.frequency) * duration));
    if (!leak) kept.push(p);
  }
  return kept;
}
