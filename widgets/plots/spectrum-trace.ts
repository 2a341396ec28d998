import { toPixel, type Mapping } from './axis-scale.ts';
import type { PathSink } from './trace.ts';

/**
 * Traces y against x for indices [0, end] as one polyline, connecting
 * adjacent points (the paper's §5.2). Where several points fall in one pixel
 * column, as when a long series is shown up to Nyquist, the column is drawn
 * as its first value, its range and its last value: the same picture as
 * every point, at a few segments per pixel.
 */
export function traceSeries(sink: PathSink, x: ArrayLike<number>, y: ArrayLike<number>, end: number, mx: Mapping, my: Mapping): number {
  let segments = 0;
  let started = false;
  let column = NaN;
  let cx = 0;
  let first = 0;
  let last = 0;
  let min = 0;
  let max = 0;
  const emit = (px: number, py: number): void => {
    if (started) {
      sink.lineTo(px, py);
      segments++;
    } else {
      sink.moveTo(px, py);
      started = true;
    }
  };
  const flush = (): void => {
    if (Number.isNaN(column)) return;
    emit(cx, first);
    if (min !== max) {
      emit(cx, min);
      emit(cx, max);
      emit(cx, last);
    }
  };
  const n = Math.min(end + 1, x.length, y.length);
  for (let k = 0; k < n; k++) {
    const px = toPixel(mx, x[k]);
    const py = toPixel(my, y[k]);
    if (!Number.isFinite(px) || !Number.isFinite(py)) continue;
    const c = Math.floor(px);
    if (c !== column) {
      flush();
      column = c;
      cx = px;
      first = last = min = max = py;
    } else {
      last = py;
      if (py < min) min = py;
      if (py > max) max = py;
    }
  }
  flush();
  return segments;
}
