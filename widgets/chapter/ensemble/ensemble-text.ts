/**
 * What the ensemble widget says in words: the reading under the plane (the
 * time, the boundary's area against the disc's, the vertices it took) and
 * the summary for those who cannot see the cloud.
 */
import { fixedNumber, minusSign } from '../../controls/format.ts';
import type { EnsembleFrame } from './ensemble-protocol.ts';

const exp = (x: number, digits = 1) => minusSign(x.toExponential(digits));

/**
 * The area's reading: the boundary's shoelace area, its polygon error, and
 * its ratio to the disc's πab at the start (which a Hamiltonian flow keeps
 * at 1 and a damping γ shrinks as e^(−γt)).
 */
export function areaReading(frame: EnsembleFrame): string {
  const vertices = frame.q.length;
  if (frame.failed) return `t = ${fixedNumber(frame.t, 2)}: a point of the ensemble left the finite numbers; Restart, or try a smaller dt.`;
  if (frame.saturated) return `t = ${fixedNumber(frame.t, 2)}: the boundary has stretched past ${vertices} vertices, the most it may hold; its area is no longer measured. Restart to watch again.`;
  const ratio = frame.area / frame.initialArea;
  return (
    `t = ${fixedNumber(frame.t, 2)} · area ${frame.area.toPrecision(7)} ± ${exp(frame.areaError)} ` +
    `(${ratio.toFixed(6)} × the disc's ${frame.initialArea.toPrecision(5)}) · boundary of ${vertices} vertices`
  );
}

/** The plane in words: what is drawn and what the area does. */
export function ensembleSummary(frame: EnsembleFrame, points: number): string {
  return (
    `A cloud of ${points} points that started as a disc of area ${frame.initialArea.toPrecision(4)} in the phase plane, ` +
    `and the boundary of that disc carried by the same flow, drawn as a closed line. ${areaReading(frame)}`
  );
}
