import type { Peak, Simulation, Spectrum, WindowName } from '../../../core/index.ts';
import type { View } from '../view.ts';
import { drawAxes, fontOf, type AxisReadout } from '../axes.ts';
import { PlotTable } from '../plot-table.ts';
import { show, type TableData } from '../table-data.ts';
import { analyse, chooseMaxFrequency, displaySpectrum, largestShown, steadyLimit, theoryOf } from './spectrum-analysis.ts';
import { basisLine, compareWithTheory, fixed, frequencyDecimals, nearestPeak, peakLine, significant, SpectrumReadout } from './spectrum-readout.ts';
import { columnsOf } from '../record-columns.ts';
import { controlRow, selectControl, seriesChoices, type SelectControl } from './spectrum-controls.ts';
import { drawSpectrum, lastBin, spectrumMappings, type SpectrumPicture, type SpectrumShow } from './spectrum-plot.ts';
import { checkSpectrumOptions, chooseRows, gatherSamples, MIN_SAMPLES, type RowChoice, rowsInSpan, type SpanOption } from './spectrum-rows.ts';
import { heightAt, SPECTRUM_PLOT } from '../sizes.ts';
import { ViewFrame } from '../view-frame.ts';

export interface SpectrumViewOptions {
  /** the record series to transform (a state name such as 'q', or a column such as 'q0[3]'); default the first coordinate */
  series?: string;
  /** default 'hamming', the paper's eq. 6 */
  window?: WindowName;
  /** the latest `span` time units of the record, or [t0, t1]; default the whole record */
  span?: SpanOption;
  /** |X|, Re and Im (the paper's: Re in colour, Im grey), or both; default 'magnitude' */
  show?: SpectrumShow;
  /** end of the frequency axis, cycles per time unit; default: a little past the significant peaks */
  maxFrequency?: number;
  /** a predicted frequency (cycles per time unit) to mark, as a number or with a label */
  theory?: number | { frequency: number; label?: string };
  /** how many peaks to read out; default 3 */
  peaks?: number;
  /** milliseconds between recomputations while the simulation runs; default 250 */
  refresh?: number;
  /** more samples than this are thinned by block means (which lowers only the Nyquist frequency, not the resolution); default 8192 */
  maxSamples?: number;
  /** show the series, window and Re/Im selectors; default true */
  controls?: boolean;
  height?: number | ((width: number) => number);
}

/** The spectrum view, with its latest result for readouts and tests. */
export interface SpectrumView extends View {
  /** the strongest peaks of the latest spectrum, strongest first */
  readonly peaks: readonly Peak[];
  readonly spectrum: Spectrum | null;
  /** recompute now rather than at the next refresh */
  update(): void;
}

/**
 * The frequency domain of one series (the paper's §3.4 and §5.2): the
 * Hamming-windowed FFT over a window of the record, recomputed a few times a
 * second, with refined peak readouts and an optional theoretical marker.
 */
export function spectrumView(options: SpectrumViewOptions = {}): SpectrumView {
  checkSpectrumOptions(options);
  return new SpectrumViewImpl(options);
}

class SpectrumViewImpl implements SpectrumView {
  private readonly frame: ViewFrame;
  private readonly readout: SpectrumReadout;
  private readonly seriesSelect: SelectControl;
  private simulation: Simulation | null = null;
  private columns: readonly string[] = [];
  private series = '';
  private window: WindowName;
  private show: SpectrumShow;
  private buffer = new Float64Array(0);
  private computedAt = -Infinity;
  private computedTotal = -1;
  /** milliseconds the last update took */
  private cost = 0;
  /** a recompute due when the refresh interval ends */
  private timer: ReturnType<typeof setTimeout> | undefined;
  private picture: SpectrumPicture | null = null;
  private waiting = `Not enough samples yet`;
  private maxFrequency: number | undefined;
  private yMax: number | undefined;
  private readonly table: PlotTable;
  /** the axes as last drawn */
  private axes: { x: AxisReadout; y: AxisReadout } | null = null;
  /** what the spectrum was computed from, for the table's caption */
  private basis = '';
  peaks: readonly Peak[] = [];
  spectrum: Spectrum | null = null;

  constructor(private readonly options: SpectrumViewOptions) {
    const { height } = options;
    this.readout = new SpectrumReadout(options.peaks ?? 3);
    this.frame = new ViewFrame({
      kind: 'spectrum',
      label: 'Frequency spectrum',
      height: (w) => (typeof height === 'number' ? height : height ? height(w) : heightAt(SPECTRUM_PLOT, w)),
    });
    this.window = options.window ?? 'hamming';
    this.show = options.show ?? 'magnitude';
    this.seriesSelect = selectControl('Series', 'series', [], '', (v) => this.choose(() => (this.series = v)));
    const windowSelect = selectControl('Window', 'window', [{ value: 'hamming', label: 'Hamming' }, { value: 'none', label: 'none (rectangular)' }], this.window, (v) =>
      this.choose(() => (this.window = v as WindowName)),
    );
    const choices = [
      { value: 'magnitude', label: '|X|' },
      { value: 'reim', label: 'Re and Im' },
      { value: 'both', label: '|X|, Re and Im' },
    ];
    const showSelect = selectControl('Show', 'show', choices, this.show, (v) => this.choose(() => (this.show = v as SpectrumShow)));
    const element = this.frame.element;
    if (options.controls !== false) element.prepend(controlRow(this.seriesSelect, windowSelect, showSelect));
    element.append(this.readout.element);
    Object.defineProperty(element, 'peaks', { get: () => this.peaks, configurable: true });
    Object.defineProperty(element, 'axes', { get: () => (this.axes ? [this.axes] : []), configurable: true });
    this.table = this.frame.addTable('spectrum', () => this.tableData());
    this.frame.onChange = () => this.simulation && this.render();
  }

  get element(): HTMLElement {
    return this.frame.element;
  }

  draw(simulation: Simulation): void {
    const { record } = simulation;
    const total = record.dropped + record.length;
    // a different simulation, or this one restarted (its record holds fewer samples than were transformed)
    if (simulation !== this.simulation || record.columns !== this.columns || total < this.computedTotal) this.reset(simulation);
    if (this.frame.measure()) this.render();
    const now = performance.now();
    // at most a few times a second, and never more than about 5% of the time however long a compute takes
    const interval = Math.max(this.options.refresh ?? 250, 20 * this.cost);
    if (total === this.computedTotal) return;
    const wait = this.computedAt + interval - now;
    if (wait <= 0) this.update();
    // If the frames stop (the simulation paused) before the next recompute, the last samples still get one.
    else this.timer ??= setTimeout(() => this.update(), wait);
  }

  reset(simulation: Simulation): void {
    this.simulation = simulation;
    this.columns = simulation.record.columns;
    this.maxFrequency = this.yMax = undefined;
    try {
      // A series the reader chose survives a restart; otherwise the chapter's choice, or the first coordinate.
      const kept = this.series !== '' && this.columns.includes(this.series) ? this.series : undefined;
      const wanted = kept ?? this.options.series ?? simulation.model.names[0];
      this.series = this.columns[columnsOf(simulation.record, wanted)[0]];
      this.frame.say(null);
    } catch (error) {
      this.series = '';
      this.frame.say(error instanceof Error ? error.message : String(error));
    }
    this.update();
  }

  update(): void {
    if (this.timer !== undefined) clearTimeout(this.timer);
    this.timer = undefined;
    const simulation = this.simulation;
    if (!simulation) return;
    const { record } = simulation;
    this.computedAt = performance.now();
    this.computedTotal = record.dropped + record.length;
    this.seriesSelect.setChoices(seriesChoices(this.columns, this.series), this.series);
    const column = record.columnIndex(this.series);
    const choice = column > 0 ? chooseRows(record, this.options.span, this.options.maxSamples ?? 8192) : null;
    if (!choice || column <= 0) {
      const [from, to] = rowsInSpan(record, this.options.span);
      if (column > 0) this.clearResult(`Not enough samples yet: ${to - from} of the ${MIN_SAMPLES} needed`);
      else this.clearResult('Choose a series from the list above.', false);
    } else {
      try {
        this.computeFrom(column, choice);
      } catch (error) {
        this.clearResult(error instanceof Error ? error.message : String(error));
      }
    }
    this.render();
    this.table.refresh(true);
    this.cost = performance.now() - this.computedAt;
  }

  canvases(): { name: string; canvas: HTMLCanvasElement }[] {
    return [{ name: 'spectrum', canvas: this.frame.canvas }];
  }

  dispose(): void {
    if (this.timer !== undefined) clearTimeout(this.timer);
    this.timer = undefined;
    this.frame.dispose();
    this.simulation = null;
  }

  private choose(change: () => void): void {
    change();
    this.frame.say(null);
    this.maxFrequency = this.yMax = undefined;
    this.update();
  }

  private computeFrom(column: number, choice: RowChoice): void {
    const record = this.simulation!.record;
    if (this.buffer.length < choice.samples) this.buffer = new Float64Array(Math.max(choice.samples, 2 * this.buffer.length));
    const samples = gatherSamples(record, column, choice, this.buffer);
    const { spectrum: s, peaks } = analyse(samples, choice.interval, this.window, this.options.peaks ?? 3);
    const theory = theoryOf(this.options.theory, (f) => fixed(f, 3));
    const nyquist = 0.5 / choice.interval;
    this.maxFrequency = Math.min(nyquist, this.options.maxFrequency ?? chooseMaxFrequency(peaks, nyquist, theory?.frequency, this.maxFrequency, choice.duration));
    const shown = displaySpectrum(samples, choice.interval, this.window, this.maxFrequency);
    this.yMax = steadyLimit(largestShown(shown, this.show !== 'magnitude', lastBin(shown, this.maxFrequency)), this.yMax);
    this.spectrum = s;
    this.peaks = peaks;
    this.picture = { spectrum: shown, peaks, show: this.show, maxFrequency: this.maxFrequency, yMax: this.yMax, theory, series: this.series };
    if (peaks.length) this.element.dataset.peak = String(peaks[0].frequency);
    else delete this.element.dataset.peak;
    const strongest = peaks.length ? `; strongest peak at f = ${fixed(peaks[0].frequency, frequencyDecimals(choice.duration))}` : '';
    this.frame.canvas.setAttribute('aria-label', `Frequency spectrum of ${this.series}${strongest}${markerText(theory)}`);
    const t0 = record.time(choice.from);
    this.basis = `${this.window === 'hamming' ? 'Hamming window' : 'no window'}, t = ${fixed(t0, 2)} … ${fixed(t0 + choice.duration, 2)}`;
    const near = theory && peaks.length ? nearestPeak(peaks, theory.frequency) : 0;
    this.readout.show(
      peaks.map((p) => peakLine(p, choice.duration)),
      basisLine(this.window, t0, choice.duration, choice.samples, choice.stride),
      theory && peaks.length ? compareWithTheory(peaks[near], theory, choice.duration, near === 0 ? 'strongest peak' : `peak ${near + 1}`) : undefined,
      peaks.length ? undefined : `No peaks: nothing completes 1.5 periods within the window (T = ${significant(choice.duration, 3)}).`,
    );
  }

  private clearResult(message: string, onCanvas = true): void {
    this.picture = null;
    this.spectrum = null;
    this.peaks = [];
    this.waiting = onCanvas ? message : '';
    delete this.element.dataset.peak;
    this.frame.canvas.setAttribute('aria-label', `Frequency spectrum of ${this.series}: ${message}${markerText(theoryOf(this.options.theory, (f) => fixed(f, 3)))}`);
    this.readout.show([], '', undefined, message);
  }

  /** The data-table view: the peaks read out, strongest first, and the theory's line when there is one. */
  private tableData(): TableData | null {
    if (!this.picture || this.peaks.length === 0) return null;
    const theory = this.picture.theory;
    const rows = this.peaks.map((p, i) => [String(i + 1), show(p.frequency), show(2 * Math.PI * p.frequency), show(p.amplitude)]);
    if (theory) rows.push([`dashed line: ${theory.label}`, show(theory.frequency), show(2 * Math.PI * theory.frequency), '']);
    return {
      caption: `Peaks of the spectrum of ${this.series} (${this.basis})`,
      head: ['peak', 'f (cycles per time unit)', 'ω = 2πf', 'amplitude'],
      rows,
    };
  }

  private render(): void {
    const { frame } = this;
    frame.clear();
    const g = frame.context;
    if (this.picture) {
      this.axes = drawSpectrum(g, frame.width, frame.height, this.picture, frame.theme, frame.dpr);
    } else {
      const empty = { maxFrequency: this.options.maxFrequency ?? 1, yMax: 1, show: 'magnitude' as const };
      const { rect, mx, my } = spectrumMappings(frame.width, frame.height, empty);
      this.axes = drawAxes(g, rect, mx, my, frame.theme, { xLabel: 'frequency f (cycles per time unit)', yLabel: 'amplitude' }, frame.dpr);
      g.save();
      g.fillStyle = frame.theme.muted;
      g.font = fontOf(frame.theme, 13);
      g.textAlign = 'center';
      g.textBaseline = 'middle';
      g.fillText(this.waiting, rect.left + rect.width / 2, rect.top + rect.height / 2);
      g.restore();
    }
    frame.markReady();
  }
}

/** The dashed marker, said in the plot's text alternative (it is drawn only on the canvas). */
function markerText(theory: { frequency: number; label: string } | undefined): string {
  return theory ? `; dashed line: ${theory.label} at f = ${fixed(theory.frequency, 3)}` : '';
}
