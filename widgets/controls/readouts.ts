import type { Simulation } from '../../core/index.ts';
import { h } from './dom.ts';
import { DriftTracker } from './drift.ts';
import { formatDrift, formatTime, readoutNumber } from './format.ts';

/** Readouts refresh at most this often, ms: faster numbers cannot be read and cost layout. */
const INTERVAL_MS = 100;

/**
 * Live readouts: t, H and the relative energy drift |H − H₀| / |H₀|. H is
 * left out when the model has none; for a batch, H is not shown (there is
 * one per trajectory) and the drift is the worst of the batch.
 */
export class Readouts {
  readonly element: HTMLElement;
  private readonly t: HTMLElement;
  private readonly h: HTMLElement;
  private readonly drift: HTMLElement;
  private readonly hItem: HTMLElement;
  private readonly driftItem: HTMLElement;
  private readonly driftLabel: HTMLElement;
  /** after the value, for a batch: "worst of 9", so the count does not run into the number */
  private readonly driftNote: HTMLElement;
  private tracker: DriftTracker | null = null;
  private last = -Infinity;

  constructor() {
    this.t = h('output', 'pb-readout-value');
    this.h = h('output', 'pb-readout-value');
    this.drift = h('output', 'pb-readout-value');
    this.driftLabel = h('span', 'pb-readout-label', { title: 'Relative energy drift |H − H₀| / |H₀|' }, '|ΔH/H₀|');
    const item = (label: HTMLElement | string, value: HTMLElement): HTMLElement =>
      h('span', 'pb-readout', {}, typeof label === 'string' ? h('span', 'pb-readout-label', {}, label) : label, value);
    this.hItem = item('H', this.h);
    this.driftItem = item(this.driftLabel, this.drift);
    this.driftNote = h('span', 'pb-readout-note');
    this.driftItem.append(this.driftNote);
    this.element = h('div', 'pb-readouts', { 'aria-label': 'Readouts' }, item('t', this.t), this.hItem, this.driftItem);
  }

  /** Starts over for a restarted or new simulation. */
  reset(simulation: Simulation): void {
    this.tracker = new DriftTracker(simulation.record);
    this.tracker.start(simulation.record);
    const batch = simulation.count > 1;
    this.hItem.hidden = !this.tracker.hasEnergy || batch;
    this.driftItem.hidden = !this.tracker.hasEnergy;
    this.driftLabel.textContent = '|ΔH/H₀|';
    this.driftNote.textContent = batch ? `(worst of ${simulation.count})` : '';
    this.update(simulation, true);
  }

  /** Refreshes the numbers, at most every 100 ms unless forced. */
  update(simulation: Simulation, force = false): void {
    const now = performance.now();
    if (!force && now - this.last < INTERVAL_MS) return;
    this.last = now;
    this.t.textContent = formatTime(simulation.t, simulation.dt);
    const energy = this.tracker?.latest(simulation.record);
    if (!energy) return;
    this.h.textContent = readoutNumber(energy.h, 8);
    this.drift.textContent = formatDrift(simulation.count > 1 ? energy.worst : energy.drift);
  }
}
