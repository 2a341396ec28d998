/**
 * The standard map p' = p + K sin q, q' = q + p' as a phase portrait that
 * answers its K at once: a slider and a number field for K, about a
 * thousand orbits from a lattice of starts redrawn on every change (on the
 * page: a frame's worth of iterates costs a few milliseconds, so no worker
 * is needed), and a click, or the arrow keys and Enter, to launch a long
 * orbit from a point, read out as its rotation number, its Lyapunov
 * exponent and whether its p crossed a band an invariant circle would bar.
 * The last launched orbit downloads as CSV, its n in the t column.
 *
 * The root's data attributes, for the end-to-end tests: data-k, data-points
 * (iterates drawn), data-launched (orbits the reader launched),
 * data-rotation, data-exponent and data-crossed of the last one, and
 * data-ready once the portrait is drawn.
 */
import { GREENE_K, iterateMap, mapRecord, orbitReading, standardMap as standardMapOf, wrapAngle } from '../../../core/index.ts';
import { button, field, h, setFieldError } from '../../controls/dom.ts';
import { csvParts } from '../../exports/export.ts';
import { downloadText } from '../../exports/download.ts';
import { MARGIN } from '../../plots/axes.ts';
import { PointPanel } from '../../plots/point-panel.ts';
import { drawPixels, pixelArea, type PixelMapping, pixelWord } from '../../plots/pixel-image.ts';
import { markOrbits, P_DOMAIN, Q_DOMAIN, startGrid, torusP } from './standard-map-orbits.ts';
import { cursorReading, LAUNCH_ITERATIONS, type LaunchedReading, launchReading, mapSummary } from './standard-map-text.ts';

export interface StandardMapOptions {
  /** the kick strength, Greene's critical 0.9716 by default */
  K?: number;
  /** the slider's largest K */
  kMax?: number;
  /** orbits drawn, from a lattice of starts over the torus */
  orbits?: number;
  /** iterates of each */
  iterations?: number;
  height?: number;
  /** called when the reader launches an orbit */
  onLaunch?: (orbit: LaunchedReading & { K: number }) => void;
}

/** Launch steps of the keys: a fiftieth of the torus, five times that with Shift. */
const KEY_STEP = (2 * Math.PI) / 50;
const LARGER_STEP = 5;
/**
 * Iterates of every orbit drawn per frame: about 100 000 steps with the
 * default lattice, a third of a frame on a phone-class core, so the slider
 * moves at 60 fps and the portrait fills in over three frames once it stops.
 */
const PART = 100;
/** The most orbits and iterates a portrait may ask for: beyond, it would take seconds to fill in. */
const MOST_POINTS = 2_000_000;

/** The widget described above. */
export function standardMap(options: StandardMapOptions = {}): HTMLElement {
  const { K = GREENE_K, kMax = 3, orbits = 1024, iterations = 300, height = 600, onLaunch } = options;
  checkOptions(K, kMax, orbits, iterations);
  return new MapFigure({ K, kMax, orbits, iterations, height, onLaunch }).root;
}

function checkOptions(K: number, kMax: number, orbits: number, iterations: number): void {
  if (!(Number.isFinite(kMax) && kMax > 0)) throw new RangeError(`standardMap: kMax must be a positive number, not ${String(kMax)}`);
  if (!(Number.isFinite(K) && K >= 0 && K <= kMax)) throw new RangeError(`standardMap: K must be a number from 0 to kMax = ${kMax}, not ${String(K)}`);
  for (const [name, value] of [['orbits', orbits], ['iterations', iterations]] as const) {
    if (!(Number.isInteger(value) && value >= 1)) throw new RangeError(`standardMap: ${name} must be a whole number ≥ 1, not ${String(value)}`);
  }
  if (orbits * iterations > MOST_POINTS) throw new RangeError(`standardMap: orbits × iterations is ${orbits * iterations}; at most ${MOST_POINTS} fill in within a second`);
}

type Setting = Required<Omit<StandardMapOptions, 'onLaunch'>> & Pick<StandardMapOptions, 'onLaunch'>;

class MapFigure {
  readonly root = h('figure', 'pb-stability pb-standard-map');
  readonly #setting: Setting;
  readonly #panel: PointPanel;
  readonly #slider: HTMLInputElement;
  readonly #k = field('K', '');
  readonly #reading = h('p', 'pb-stability-reading', { 'aria-live': 'polite' });
  readonly #summary = h('p', 'pb-poincare-summary');
  readonly #download = button('Download orbit (CSV)', 'The last launched orbit, one row per iterate n');
  /** the lattice's starts, the pairs q, p */
  readonly #starts: Float64Array;
  /** The canvas the iterates are drawn on before they are laid over the portrait's background and grid. */
  readonly #layer = document.createElement('canvas');
  #K: number;
  #cursor: [number, number] = [Math.PI, 0];
  #launched: { q: Float64Array; p: Float64Array; reading: LaunchedReading; K: number } | null = null;
  #launches = 0;
  /** the portrait being drawn: for which K, mapping and colours (its key), its pixels, and how far its orbits have come */
  #portrait: { key: string; to: PixelMapping; pixels: Uint32Array; states: Float64Array; done: number; marked: number } | null = null;
  #pending = false;

  constructor(setting: Setting) {
    this.#setting = setting;
    this.#K = setting.K;
    this.#starts = startGrid(setting.orbits);
    this.root.dataset.widget = 'standard-map';
    this.#panel = new PointPanel(this.root, 'phase portrait of the standard map', 'Standard map on the torus q, p: arrow keys move the launch point (Shift for larger steps), Enter or Space launches an orbit from it; or click', { sameUnits: true });
    this.#panel.followWidth(() => this.draw());
    this.#slider = h('input', 'pb-standard-map-slider', { type: 'range', min: '0', max: String(setting.kMax), step: '0.0001', 'aria-label': 'K, the kick strength' });
    this.#slider.value = String(this.#K);
    this.#k.input.value = String(this.#K);
    this.#download.disabled = true;
    const controls = h('div', 'pb-standard-map-k', {}, this.#slider, this.#k.wrapper, this.#download);
    this.root.append(controls, this.#panel.canvas, this.#reading, this.#summary);
    this.#listen();
    this.#redraw();
  }

  /**
   * Draws the portrait as it stands at the current K: the lattice's orbits as
   * pixels, carried on by a part of their iterates each frame until all are
   * drawn (a new K, size or theme starts them again), the reader's orbit over
   * them, then the launch point and the axes.
   */
  draw(): void {
    const { height, iterations } = this.#setting;
    // The torus is square: the plotting area as tall as it is wide, up to `height`.
    const f = this.#panel.frame((width) => Math.min(height, width - MARGIN.left - MARGIN.right + MARGIN.top + MARGIN.bottom), Q_DOMAIN, P_DOMAIN);
    if (!f) return;
    const { g, dpr, rect, mx, my, theme } = f;
    const area = pixelArea(rect, dpr, mx, my);
    const { to } = area;
    const key = `${this.#K} ${JSON.stringify(to)} ${theme.series.join()}`;
    let portrait = this.#portrait;
    if (portrait?.key !== key) {
      portrait = { key, to, pixels: new Uint32Array(to.width * to.height), states: this.#starts.slice(), done: 0, marked: 0 };
      this.#portrait = portrait;
      delete this.root.dataset.ready;
    }
    if (portrait.done < iterations) {
      const part = Math.min(PART, iterations - portrait.done);
      portrait.marked += markOrbits(portrait.pixels, to, standardMapOf(this.#K), portrait.states, part, Uint32Array.from(theme.series, pixelWord));
      portrait.done += part;
    }
    drawPixels(g, this.#layer, area, new ImageData(new Uint8ClampedArray(portrait.pixels.buffer as ArrayBuffer), to.width, to.height), dpr);
    const launched = this.#launched;
    if (launched && launched.K === this.#K) {
      // Larger marks in the accent colour: the reader's orbit stands out from the lattice's.
      g.fillStyle = theme.accent;
      for (let n = 0; n < launched.q.length; n++) g.fillRect(mx.scale(launched.q[n]) - 1, my.scale(launched.p[n]) - 1, 2, 2);
    }
    this.#panel.finish(f, this.#cursor, { xLabel: 'q', yLabel: 'p' });
    this.#describe();
    if (portrait.done < iterations) this.#redraw();
    else this.root.dataset.ready = '';
  }

  /** A redraw at the next frame, once however often it is asked for before then. */
  #redraw(): void {
    if (this.#pending) return;
    this.#pending = true;
    requestAnimationFrame(() => {
      this.#pending = false;
      this.draw();
    });
  }

  /** K from the slider or the field: the portrait redrawn at the next frame, however fast the slider moves. */
  #setK(K: number): void {
    this.#K = K;
    this.root.dataset.k = String(K);
    this.#redraw();
  }

  /** The orbit from (q, p), long enough to read; kept for drawing and download, and told to the chapter. */
  #launch(q: number, p: number): void {
    this.#cursor = [q, torusP(p)];
    const start: [number, number] = [q, this.#cursor[1]];
    const map = standardMapOf(this.#K);
    const orbit = iterateMap(map, start, LAUNCH_ITERATIONS, { reduceP: true });
    const reading: LaunchedReading = { q: start[0], p: start[1], ...orbitReading(this.#K, start, LAUNCH_ITERATIONS) };
    this.#launched = { ...orbit, reading, K: this.#K };
    this.#launches++;
    Object.assign(this.root.dataset, { rotation: String(reading.rotation), exponent: String(reading.lyapunov), crossed: String(reading.crossed) });
    this.#reading.textContent = launchReading(reading);
    this.#download.disabled = false;
    this.#setting.onLaunch?.({ ...reading, K: this.#K });
    this.draw();
  }

  /** The last launched orbit as CSV: n, q, p with p unreduced, as the map made it. */
  #save(): void {
    const launched = this.#launched;
    if (!launched) return;
    const record = mapRecord(standardMapOf(launched.K), [launched.reading.q, launched.reading.p], LAUNCH_ITERATIONS);
    downloadText(csvParts(record), 'text/csv', `standard-map-K${launched.K}.csv`);
  }

  /** What the canvas and the root's data attributes say now. */
  #describe(): void {
    this.root.dataset.k = String(this.#K);
    this.root.dataset.points = String(this.#portrait?.marked ?? 0);
    this.root.dataset.launched = String(this.#launches);
    const last = this.#launched && this.#launched.K === this.#K ? this.#launched.reading : null;
    this.#summary.textContent = mapSummary(this.#K, this.#starts.length / 2, this.#portrait?.marked ?? 0, last);
  }

  /** The slider and the field move together; a field that is no K in range says so under itself and leaves K as it was. */
  #listen(): void {
    const { kMax } = this.#setting;
    this.#slider.addEventListener('input', () => {
      const K = Number(this.#slider.value);
      this.#k.input.value = String(K);
      setFieldError(this.#k.input, this.#k.message, null);
      this.#setK(K);
    });
    this.#k.input.addEventListener('change', () => {
      const K = Number(this.#k.input.value.trim().replace('−', '-'));
      if (this.#k.input.value.trim() === '' || !(K >= 0 && K <= kMax)) {
        setFieldError(this.#k.input, this.#k.message, `K must be a number from 0 to ${kMax}`);
        return;
      }
      setFieldError(this.#k.input, this.#k.message, null);
      this.#slider.value = String(K);
      this.#setK(K);
    });
    this.#download.addEventListener('click', () => this.#save());
    this.#panel.onClick((q, p) => this.#launch(q, p));
    this.#panel.onKeys(
      () => [KEY_STEP, KEY_STEP],
      LARGER_STEP,
      (dq, dp) => {
        this.#cursor = [wrapAngle(this.#cursor[0] + dq), torusP(this.#cursor[1] + dp)];
        this.#reading.textContent = cursorReading(this.#cursor);
        this.draw();
      },
      () => this.#launch(this.#cursor[0], this.#cursor[1]),
    );
  }
}
