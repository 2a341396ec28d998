import type { Simulation } from '../../core/index.ts';

/**
 * What every plot of a running simulation implements. The driver calls
 * `draw` once per animation frame after integrating; a view draws only what
 * is new since its last call (the record's `dropped + length` is the count of
 * samples ever taken, so a view remembers how many it has seen), which keeps
 * drawing work per frame proportional to the new samples.
 */
export interface View {
  /** the root element, carrying data-widget="<kind>" and, after its first frame, data-ready */
  readonly element: HTMLElement;
  /** draw what is new in `simulation.record` */
  draw(simulation: Simulation): void;
  /** the simulation restarted (or was replaced): forget what was drawn */
  reset(simulation: Simulation): void;
  /** canvases a PNG download may offer, with a name for each */
  canvases?(): { name: string; canvas: HTMLCanvasElement }[];
  /** the driver started or stopped integrating */
  setPlaying?(playing: boolean): void;
  dispose(): void;
}

/** Index range, in the record's current indices, of the samples a view has not drawn yet. */
export function unseen(simulation: Simulation, seen: number): { from: number; to: number; total: number } {
  const { record } = simulation;
  const total = record.dropped + record.length;
  const from = Math.max(0, seen - record.dropped);
  return { from, to: record.length, total };
}
