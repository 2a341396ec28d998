import type { Simulation } from '../../core/index.ts';
import { h } from '../controls/dom.ts';
import { readoutNumber } from '../controls/format.ts';

/**
 * The two messages a simulator can show inside itself: the blow-up that
 * stopped it (an alert naming t and the component), and the note that the
 * record reached its memory cap and now keeps only the latest samples.
 */
export class Notices {
  readonly alert: HTMLElement;
  readonly note: HTMLElement;

  constructor() {
    this.alert = h('div', 'pb-alert', { role: 'alert' });
    this.alert.hidden = true;
    this.note = h('div', 'pb-note', { role: 'status' });
    this.note.hidden = true;
  }

  /** Shows the error that stopped the simulation, or hides the alert. */
  showError(error: Error | null): void {
    this.alert.hidden = !error;
    this.alert.textContent = error ? `Stopped: ${error.message}. Restart, or try a smaller dt.` : '';
  }

  /** Shows the capped-record note when the record has dropped rows. */
  showCap(simulation: Simulation): void {
    const { record } = simulation;
    const capped = record.dropped > 0 && record.length > 0;
    this.note.hidden = !capped;
    if (!capped) return;
    const text =
      `The record is full: it keeps the latest ${record.capacity.toLocaleString('en')} samples ` +
      `(from t = ${readoutNumber(record.time(0), 6)}) and has dropped ${record.dropped.toLocaleString('en')} older ones; ` +
      'scrolling back and downloads start there.';
    if (this.note.textContent !== text) this.note.textContent = text;
  }
}
