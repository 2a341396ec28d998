import type { Simulation } from '../../core/index.ts';
import { askProvenance } from './provenance.ts';
import { button, field, h, setFieldError } from '../controls/dom.ts';
import { parseBound } from '../controls/field-values.ts';
import { readTheme } from '../plots/theme.ts';
import { exportName, selectRows, type Selection } from './interval.ts';

/**
 * The writers and the download helpers, loaded when the reader first points
 * at the panel or asks for a file: a simulator that is only watched never
 * loads them.
 */
const loadExporters = () =>
  Promise.all([import('./export.ts'), import('./download.ts'), import('../../core/tables/export-meta.ts')]).then(
    ([exporters, download, meta]) => ({ ...exporters, ...download, ...meta }),
  );
let exporters: ReturnType<typeof loadExporters> | undefined;
const exportersReady = () => (exporters ??= loadExporters());

/** A plot a PNG can be made of. */
export interface PlotSource {
  name: string;
  canvas(): HTMLCanvasElement;
}

/**
 * Downloads: CSV or JSON of the rows with t0 ≤ t ≤ t1 (empty bounds: all that
 * is recorded), in exactly the CLI's formats, and a PNG of any plot.
 */
export class DataPanel {
  readonly element: HTMLElement;
  private readonly t0: { input: HTMLInputElement; message: HTMLElement };
  private readonly t1: { input: HTMLInputElement; message: HTMLElement };
  private readonly summary: HTMLElement;
  private readonly message: HTMLElement;
  private readonly plotSelect: HTMLSelectElement;
  private simulation: Simulation | null = null;
  private last = -Infinity;

  constructor(private readonly plots: () => PlotSource[]) {
    const t0 = field('t0', '', { placeholder: 'start', size: '6', 'aria-label': 'Export from time t0 (empty: from the start)' });
    const t1 = field('t1', '', { placeholder: 'end', size: '6', 'aria-label': 'Export to time t1 (empty: to the end)' });
    this.t0 = t0;
    this.t1 = t1;
    this.summary = h('span', 'pb-data-summary', { 'aria-live': 'polite' });
    this.message = h('span', 'pb-data-message', { role: 'status' });
    const csv = button('Download CSV', 'Download the selected samples as CSV', '⤓');
    const json = button('Download JSON', 'Download the selected samples and their metadata as JSON', '⤓');
    const png = button('Download PNG', 'Download the chosen plot as a PNG image', '⤓');
    this.plotSelect = h('select', 'pb-select', { 'aria-label': 'Plot to download' });
    this.element = h('div', 'pb-data', { role: 'group', 'aria-label': 'Data' },
      h('span', 'pb-data-title', {}, 'Data'), t0.wrapper, t1.wrapper, this.summary,
      h('span', 'pb-data-actions', {}, csv, json, this.plotSelect, png), this.message);

    this.element.addEventListener('pointerenter', () => void exportersReady().catch(() => undefined), { once: true });
    this.element.addEventListener('focusin', () => void exportersReady().catch(() => undefined), { once: true });
    csv.addEventListener('click', () => void this.exportRows('csv'));
    json.addEventListener('click', () => void this.exportRows('json'));
    png.addEventListener('click', () => void this.exportPng());
    for (const f of [t0, t1]) f.input.addEventListener('input', () => this.update(this.simulation, true));
    this.listPlots();
  }

  /** Lists the plots offered for PNG; hides the choice when there is one. */
  listPlots(): void {
    const plots = this.plots();
    this.plotSelect.replaceChildren(...plots.map((p, i) => new Option(p.name, String(i))));
    this.plotSelect.hidden = plots.length < 2;
  }

  /** Refreshes the row count of the selection, at most once a second unless forced. */
  update(simulation: Simulation | null, force = false): void {
    this.simulation = simulation;
    const now = performance.now();
    if (!simulation || (!force && now - this.last < 1000)) return;
    this.last = now;
    const selection = this.select(false);
    if (selection) this.summary.textContent = `${selection.rows.toLocaleString('en')} rows, t ${short(selection.first)} – ${short(selection.last)}`;
  }

  /** The chosen rows, or null with the reason shown. */
  private select(report: boolean): Selection | null {
    const simulation = this.simulation;
    if (!simulation) return null;
    const a = parseBound(this.t0.input.value, 't0');
    const b = parseBound(this.t1.input.value, 't1');
    setFieldError(this.t0.input, this.t0.message, a.error ?? null);
    setFieldError(this.t1.input, this.t1.message, b.error ?? null);
    if (a.error !== undefined || b.error !== undefined) {
      this.summary.textContent = '';
      return null;
    }
    const selection = selectRows(simulation.record, a.value, b.value);
    if ('error' in selection) {
      this.summary.textContent = selection.error;
      if (report) this.say(`Nothing to download: ${selection.error}`);
      return null;
    }
    return selection;
  }

  private async exportRows(format: 'csv' | 'json'): Promise<void> {
    let tools: Awaited<ReturnType<typeof loadExporters>>;
    try {
      tools = await exportersReady();
    } catch (error) {
      exporters = undefined;
      return this.say(`The download could not start: ${error instanceof Error ? error.message : String(error)}`);
    }
    // Selected after the wait, so the rows are those recorded now.
    const simulation = this.simulation;
    const selection = this.select(true);
    if (!simulation || !selection) return;
    const { csvParts, jsonParts, downloadText, exportMeta } = tools;
    const { record } = simulation;
    const name = exportName(selection.first, selection.last, format);
    if (format === 'csv') downloadText(csvParts(record, selection.from, selection.to), 'text/csv', name);
    else {
      // A file made from a chapter the reader changed says so: which cells, and the code that ran.
      const provenance = askProvenance(this.element);
      const meta = provenance && provenance.cells.length ? { ...exportMeta(simulation), provenance } : exportMeta(simulation);
      downloadText(jsonParts(record, meta, selection.from, selection.to), 'application/json', name);
    }
    const dropped = record.dropped > 0 && selection.from === 0 ? ' (the record had already dropped its oldest rows)' : '';
    this.say(`Saved ${name}: ${selection.rows.toLocaleString('en')} rows${dropped}.`);
  }

  private async exportPng(): Promise<void> {
    const plot = this.plots()[Number(this.plotSelect.value) || 0];
    if (!plot) return this.say('There is no plot to save.');
    try {
      const { onBackground, downloadBlob, pngBlob } = await exportersReady();
      const canvas = onBackground(plot.canvas(), readTheme(this.element).bg);
      const name = `phasebook-${plot.name.replace(/[^a-z0-9]+/gi, '-').toLowerCase()}.png`;
      downloadBlob(await pngBlob(canvas), name);
      this.say(`Saved ${name}.`);
    } catch (error) {
      this.say(error instanceof Error ? error.message : String(error));
    }
  }

  private say(text: string): void {
    this.message.textContent = text;
  }
}

function short(t: number): string {
  return String(Number(t.toPrecision(6)));
}
