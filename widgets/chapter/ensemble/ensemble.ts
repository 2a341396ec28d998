/**
 * An ensemble in the phase plane: a disc of initial conditions of a
 * one-degree-of-freedom model, carried by its flow as a cloud of points
 * (tens of thousands, drawn as pixels) and as the disc's boundary, a
 * polygon refined where it stretches, whose area is read out against the
 * disc's. Under a Hamiltonian flow the blob shears into filaments at
 * constant area (Liouville's theorem); a non-Hamiltonian term such as a
 * damping shrinks it. It moves in a worker (ensemble-runner.ts), plays
 * while in view and stops at `until`; Play, Restart, Step, the speed and
 * dt are the simulators' own controls. A click, or the arrow keys and
 * Enter, put the disc's centre elsewhere and start again. The boundary
 * downloads as CSV: s (the vertex's place on the initial circle), q, p.
 *
 * The root's data attributes, for the end-to-end tests: data-t, data-area,
 * data-area-error, data-initial-area, data-vertices, data-points (drawn),
 * data-state ('playing', 'paused', 'done', 'failed', 'saturated') and
 * data-ready once the first frame is drawn.
 */
import { csvHeader, csvRows, type EnsembleSetup, InputError, type Model, MOST_POINTS } from '../../../core/index.ts';
import { button, h, prefersReducedMotion } from '../../controls/dom.ts';
import { Transport } from '../../controls/transport.ts';
import { downloadText } from '../../exports/download.ts';
import { MARGIN } from '../../plots/axes.ts';
import { drawPixels, markPoints, pixelArea, pixelWord } from '../../plots/pixel-image.ts';
import { PointPanel } from '../../plots/point-panel.ts';
import type { EnsembleFrame } from './ensemble-protocol.ts';
import { type EnsembleRunner, ensembleRunner } from './ensemble-runner.ts';
import { areaReading, ensembleSummary } from './ensemble-text.ts';

export interface EnsembleOptions {
  /** a model of one degree of freedom (canonicalEquations) */
  model: Model;
  /** the disc's centre (q, p) */
  center?: readonly [number, number];
  /** its radius, or its semi-axes along q and p */
  radius?: number | readonly [number, number];
  /** points in the cloud */
  points?: number;
  dt?: number;
  /** simulated time units per second */
  speed?: number;
  /** the time at which it stops */
  until?: number;
  /** the plane shown: [q0, q1] and [p0, p1]; by default five radii about the centre */
  view?: { q?: readonly [number, number]; p?: readonly [number, number] };
  height?: number;
  /** called with each frame drawn, for cells that read the ensemble */
  onFrame?: (frame: EnsembleFrame) => void;
}

/** The work a request may ask of the worker, in point-steps: a few milliseconds, so frames keep coming. */
const WORK_PER_FRAME = 400_000;
/** Steps of one press of Step. */
const STEP_PRESS = 10;
/** Arrow-key moves of the centre, in radii. */
const KEY_STEP = 0.25;

/** The widget described above. */
export function ensemble(options: EnsembleOptions): HTMLElement {
  const setting = settingOf(options);
  return new EnsembleFigure(setting).root;
}

interface Setting {
  model: Model;
  center: [number, number];
  radius: [number, number];
  points: number;
  dt: number;
  speed: number;
  until: number;
  view: { q: [number, number]; p: [number, number] };
  height: number;
  onFrame?: (frame: EnsembleFrame) => void;
}

function settingOf(options: EnsembleOptions): Setting {
  const { model, center = [0, 0], radius = 0.5, points = 20_000, dt = 0.01, speed = 1, until = 100, height = 440, onFrame } = options ?? ({} as EnsembleOptions);
  if (!model || typeof model.stepper?.advance !== 'function') throw new InputError('ensemble: model must be a model from canonicalEquations');
  if (model.dof !== 1) throw new InputError(`ensemble: the phase plane holds a model of one degree of freedom, not ${model.dof}`);
  const pair = (value: unknown, name: string): [number, number] => {
    if (!(Array.isArray(value) && value.length === 2 && value.every(Number.isFinite))) throw new InputError(`ensemble: ${name} must be two finite numbers`);
    return [value[0], value[1]];
  };
  const c = pair(center, 'center, [q, p],');
  const r = typeof radius === 'number' ? ([radius, radius] as [number, number]) : pair(radius, 'radius, a number or [along q, along p],');
  if (!(r[0] > 0 && r[1] > 0)) throw new InputError(`ensemble: radius must be positive, not ${String(radius)}`);
  if (!(Number.isInteger(points) && points >= 1 && points <= MOST_POINTS)) throw new InputError(`ensemble: points must be a whole number from 1 to ${MOST_POINTS}, not ${String(points)}`);
  for (const [name, value] of [['dt', dt], ['speed', speed], ['until', until]] as const) {
    if (!(typeof value === 'number' && value > 0 && Number.isFinite(value))) throw new InputError(`ensemble: ${name} must be a positive number, not ${String(value)}`);
  }
  const q = options.view?.q ? pair(options.view.q, 'view.q') : ([c[0] - 5 * r[0], c[0] + 5 * r[0]] as [number, number]);
  const p = options.view?.p ? pair(options.view.p, 'view.p') : ([c[1] - 5 * r[1], c[1] + 5 * r[1]] as [number, number]);
  if (!(q[1] > q[0] && p[1] > p[0])) throw new InputError('ensemble: each range of view must be increasing, [from, to]');
  return { model, center: c, radius: r, points, dt, speed, until, view: { q, p }, height, onFrame };
}

type State = 'playing' | 'paused' | 'done' | 'failed' | 'saturated';

class EnsembleFigure {
  readonly root = h('figure', 'pb-ensemble');
  readonly #setting: Setting;
  readonly #panel: PointPanel;
  readonly #transport: Transport;
  readonly #runner: EnsembleRunner;
  readonly #reading = h('p', 'pb-stability-reading', { 'aria-live': 'off' });
  readonly #summary = h('p', 'pb-poincare-summary');
  readonly #download = button('Download boundary (CSV)', 'The boundary now: its vertices’ s on the initial circle, q and p');
  readonly #layer = document.createElement('canvas');
  /** the cloud's image, kept from frame to frame and cleared, not allocated anew: a megabyte a frame otherwise */
  #image: { pixels: Uint32Array; data: ImageData } | null = null;
  /** when the reading's words were last written: a few times a second while playing, since each write lays the text out again */
  #worded = 0;
  #center: [number, number];
  #dt: number;
  #speed: number;
  #frame: EnsembleFrame | null = null;
  #state: State = 'paused';
  #wanted = false;
  #visible = true;
  #busy = false;
  #generation = 0;
  #last = 0;
  #owed = 0;
  #drawPending = false;

  constructor(setting: Setting) {
    this.#setting = setting;
    this.#center = setting.center;
    this.#dt = setting.dt;
    this.#speed = setting.speed;
    this.root.dataset.widget = 'ensemble';
    this.#panel = new PointPanel(this.root, 'phase plane of an ensemble', 'The ensemble in the phase plane q, p: arrow keys move the disc’s centre (Shift for larger steps), Enter starts it there; or click', { sameUnits: true });
    this.#panel.followWidth(() => this.#draw());
    this.#transport = new Transport(
      {
        toggle: () => (this.#state === 'playing' ? this.#pause() : this.#play()),
        restart: () => this.#restart(),
        step: () => {
          this.#pause();
          void this.#advance(STEP_PRESS);
        },
        setSpeed: (speed) => (this.#speed = speed),
        setDt: (dt) => {
          this.#dt = dt;
          this.#restart();
        },
      },
      setting.speed,
      setting.dt,
    );
    this.#download.disabled = true;
    this.root.append(this.#transport.element, this.#panel.canvas, this.#reading, h('div', 'pb-ensemble-actions', {}, this.#download), this.#summary);
    this.#runner = ensembleRunner(setting.model);
    this.#listen();
    this.#wanted = !prefersReducedMotion();
    void this.#restart();
  }

  /** Starts again from the disc at the current centre and dt; plays if the reader had it playing. */
  async #restart(): Promise<void> {
    const generation = ++this.#generation;
    this.#busy = true;
    const { radius, points } = this.#setting;
    const setup: EnsembleSetup = { center: this.#center, radius, points, dt: this.#dt };
    try {
      const frame = await this.#runner.start(setup);
      if (generation !== this.#generation) return;
      this.#show(frame);
      this.#busy = false;
      this.#state = 'paused';
      if (this.#wanted) this.#play();
      else this.#describe();
    } catch (error) {
      if (generation === this.#generation) this.#fail(error);
    }
  }

  #play(): void {
    if (this.#state === 'failed' || this.#state === 'saturated') return;
    this.#wanted = true;
    if ((this.#frame?.t ?? 0) >= this.#setting.until - this.#dt / 2) return this.#finish();
    this.#state = 'playing';
    this.#last = 0;
    this.#owed = 0;
    this.#describe();
    this.#tick();
  }

  #pause(): void {
    this.#wanted = false;
    if (this.#state === 'playing') this.#state = 'paused';
    this.#describe();
  }

  #finish(): void {
    this.#state = 'done';
    this.#wanted = false;
    this.#describe();
  }

  /** One animation frame while playing: the steps real time asks for since the last, at most a frame's work. */
  #tick(): void {
    requestAnimationFrame((now) => {
      if (this.#state !== 'playing') return;
      if (!this.#visible || !this.root.isConnected) {
        // Out of view, nothing is computed; the clock starts afresh when it is seen again.
        this.#last = 0;
        return this.root.isConnected ? this.#tick() : this.#runner.stop();
      }
      if (this.#last > 0 && !this.#busy) {
        this.#owed += (this.#speed * Math.min(now - this.#last, 100)) / 1000 / this.#dt;
        const frame = this.#frame!;
        const most = Math.max(1, Math.floor(WORK_PER_FRAME / (this.#setting.points + frame.q.length)));
        const left = Math.max(0, Math.round((this.#setting.until - frame.t) / this.#dt));
        const steps = Math.min(Math.floor(this.#owed), most, left);
        if (steps >= 1) {
          this.#owed -= steps;
          void this.#advance(steps);
        }
      }
      this.#last = now;
      this.#tick();
    });
  }

  async #advance(steps: number): Promise<void> {
    if (this.#busy || !this.#frame) return;
    const generation = this.#generation;
    this.#busy = true;
    try {
      const frame = await this.#runner.advance(steps);
      if (generation !== this.#generation) return;
      this.#busy = false;
      this.#show(frame);
      if (frame.failed) this.#state = 'failed';
      else if (frame.saturated) this.#state = 'saturated';
      else if (frame.t >= this.#setting.until - this.#dt / 2) this.#finish();
      this.#describe();
    } catch (error) {
      if (generation === this.#generation) this.#fail(error);
    }
  }

  #show(frame: EnsembleFrame): void {
    this.#frame = frame;
    this.#download.disabled = false;
    this.#setting.onFrame?.(frame);
    this.#scheduleDraw();
  }

  #fail(error: unknown): void {
    this.#busy = false;
    this.#state = 'failed';
    this.#reading.textContent = `The ensemble stopped: ${(error as Error)?.message ?? String(error)}`;
    this.root.dataset.state = this.#state;
    this.#transport.setPlaying(false, true);
  }

  #scheduleDraw(): void {
    if (this.#drawPending) return;
    this.#drawPending = true;
    requestAnimationFrame(() => {
      this.#drawPending = false;
      this.#draw();
    });
  }

  /** The plane: the background, the cloud as pixels, the initial disc dashed, the boundary now, the axes. */
  #draw(): void {
    const frame = this.#frame;
    const { height, view, radius } = this.#setting;
    const f = this.#panel.frame((width) => Math.min(height, Math.round(width * 0.75)), view.q, view.p);
    if (!f || !frame) return;
    const { g, dpr, rect, mx, my, theme } = f;
    const area = pixelArea(rect, dpr, mx, my);
    const { width, height: tall } = area.to;
    let image = this.#image;
    if (image?.data.width !== width || image.data.height !== tall) {
      const pixels = new Uint32Array(width * tall);
      image = this.#image = { pixels, data: new ImageData(new Uint8ClampedArray(pixels.buffer), width, tall) };
    } else image.pixels.fill(0);
    const marked = markPoints(image.pixels, area.to, frame.cloud, pixelWord(theme.series[0]));
    drawPixels(g, this.#layer, area, image.data, dpr);
    g.save();
    g.beginPath();
    g.rect(rect.left, rect.top, rect.width, rect.height);
    g.clip();
    // The disc it started as, dashed: the area the boundary's must match.
    g.strokeStyle = theme.muted;
    g.setLineDash([4, 4]);
    g.lineWidth = 1;
    g.beginPath();
    g.ellipse(mx.scale(this.#center[0]), my.scale(this.#center[1]), Math.abs(mx.scale(radius[0]) - mx.scale(0)), Math.abs(my.scale(radius[1]) - my.scale(0)), 0, 0, 2 * Math.PI);
    g.stroke();
    g.setLineDash([]);
    g.strokeStyle = theme.accent;
    g.lineWidth = 1.5;
    g.beginPath();
    for (let i = 0; i < frame.q.length; i++) {
      const x = mx.scale(frame.q[i]);
      const y = my.scale(frame.p[i]);
      if (i === 0) g.moveTo(x, y);
      else g.lineTo(x, y);
    }
    g.closePath();
    g.stroke();
    g.restore();
    this.#panel.finish(f, null, { xLabel: 'q', yLabel: 'p' });
    this.root.dataset.points = String(marked);
    this.root.dataset.ready = '';
  }

  /** The reading, the summary, the buttons and the data attributes as they stand. */
  #describe(): void {
    const frame = this.#frame;
    this.#transport.setPlaying(this.#state === 'playing', this.#state === 'failed' || this.#state === 'saturated');
    this.root.dataset.state = this.#state;
    if (!frame) return;
    const now = performance.now();
    if (this.#state !== 'playing' || now - this.#worded > 250) {
      this.#worded = now;
      this.#reading.textContent = areaReading(frame) + (this.#state === 'done' ? ` · stopped at t = ${this.#setting.until}; Restart to watch again` : '');
      if (this.#state !== 'playing') this.#summary.textContent = ensembleSummary(frame, this.#setting.points);
    }
    Object.assign(this.root.dataset, {
      t: String(frame.t),
      area: String(frame.area),
      areaError: String(frame.areaError),
      initialArea: String(frame.initialArea),
      vertices: String(frame.q.length),
    });
  }

  /** The boundary now as CSV: s, q, p, one vertex a row in their order along the curve. */
  #save(): void {
    const frame = this.#frame;
    if (!frame) return;
    const n = frame.q.length;
    const rows = new Float64Array(3 * n);
    for (let i = 0; i < n; i++) rows.set([frame.s[i], frame.q[i], frame.p[i]], 3 * i);
    downloadText([csvHeader(['s', 'q', 'p']), csvRows(rows, 3, 0, n)], 'text/csv', `ensemble-boundary-t${frame.t.toFixed(2)}.csv`);
  }

  #listen(): void {
    this.#download.addEventListener('click', () => this.#save());
    const moveTo = (q: number, p: number) => {
      this.#center = [q, p];
      void this.#restart();
    };
    this.#panel.onClick(moveTo);
    this.#panel.onKeys(
      () => [KEY_STEP * this.#setting.radius[0], KEY_STEP * this.#setting.radius[1]],
      4,
      (dq, dp) => moveTo(this.#center[0] + dq, this.#center[1] + dp),
      () => void this.#restart(),
    );
    if (typeof IntersectionObserver !== 'undefined') {
      new IntersectionObserver((entries) => {
        this.#visible = entries[entries.length - 1].isIntersecting;
      }, { rootMargin: '20% 0px' }).observe(this.root);
    }
  }
}
