import { button, field, h, relabel, setFieldError } from './dom.ts';
import { formatRate, formatSpeed } from './format.ts';
import { parseDt } from './field-values.ts';

/** What the transport controls ask of a running simulation. */
export interface TransportActions {
  toggle(): void;
  restart(): void;
  step(): void;
  setSpeed(speed: number): void;
  /** a new time step; the simulation restarts with it */
  setDt(dt: number): void;
}

/** Speeds offered, in simulated time units per real second. */
export const SPEEDS = [0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500];

/** The speed list with `speed` in it, sorted. */
export function speedsWith(speed: number): number[] {
  return [...new Set([...SPEEDS, speed])].sort((a, b) => a - b);
}

/**
 * Play/pause, restart and step buttons, a speed slider with the step rate it
 * asks for (and a note when the model cannot keep up), and the dt field,
 * which keeps the old step and says why when the entry is not a valid dt.
 */
export class Transport {
  readonly element: HTMLElement;
  readonly playButton: HTMLButtonElement;
  private readonly restartButton: HTMLButtonElement;
  private readonly stepButton: HTMLButtonElement;
  private readonly speedInput: HTMLInputElement;
  private readonly speedText: HTMLElement;
  private readonly dtInput: HTMLInputElement;
  private readonly dtMessage: HTMLElement;
  private readonly speeds: number[];
  private dt: number;

  constructor(actions: TransportActions, speed: number, dt: number) {
    this.dt = dt;
    this.speeds = speedsWith(speed);
    this.playButton = button('Play', 'Play or pause (Space)', '▶');
    this.playButton.setAttribute('aria-keyshortcuts', 'Space');
    this.playButton.classList.add('pb-primary');
    this.restartButton = button('Restart', 'Back to the initial state', '↺');
    this.stepButton = button('Step', 'Pause and advance by one sample', '⇥');
    this.speedInput = h('input', 'pb-range', {
      type: 'range', min: '0', max: String(this.speeds.length - 1), step: '1',
      value: String(this.speeds.indexOf(speed)), 'aria-label': 'Speed',
    });
    this.speedText = h('output', 'pb-speed-text', { 'aria-live': 'off' });
    const speedGroup = h('label', 'pb-speed', {}, h('span', 'pb-field-label', {}, 'speed'), this.speedInput, this.speedText);
    const dtField = field('dt', String(dt), { size: '7', 'aria-label': 'Time step dt' });
    this.dtInput = dtField.input;
    this.dtMessage = dtField.message;
    this.element = h('div', 'pb-transport', { role: 'toolbar', 'aria-label': 'Simulation controls' },
      h('span', 'pb-group', {}, this.playButton, this.restartButton, this.stepButton), dtField.wrapper, speedGroup);

    this.playButton.addEventListener('click', () => actions.toggle());
    this.restartButton.addEventListener('click', () => actions.restart());
    this.stepButton.addEventListener('click', () => actions.step());
    this.speedInput.addEventListener('input', () => {
      actions.setSpeed(this.speed);
      this.showRate(this.speed / this.dt, null);
    });
    const commitDt = (): void => {
      const parsed = parseDt(this.dtInput.value);
      if (parsed.error !== undefined) return setFieldError(this.dtInput, this.dtMessage, `${parsed.error}; keeping dt = ${this.dt}`);
      setFieldError(this.dtInput, this.dtMessage, null);
      if (parsed.value === this.dt) return;
      this.dt = parsed.value;
      actions.setDt(parsed.value);
      this.showRate(this.speed / this.dt, null);
    };
    this.dtInput.addEventListener('change', commitDt);
    this.dtInput.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') commitDt();
      if (e.key === 'Escape') {
        this.dtInput.value = String(this.dt);
        setFieldError(this.dtInput, this.dtMessage, null);
      }
    });
    this.showRate(speed / dt, null);
  }

  get speed(): number {
    return this.speeds[Number(this.speedInput.value)] ?? 1;
  }

  /** Shows a dt set from elsewhere (a script), clearing any message. */
  showDt(dt: number): void {
    this.dt = dt;
    if (document.activeElement !== this.dtInput) this.dtInput.value = String(dt);
    setFieldError(this.dtInput, this.dtMessage, null);
  }

  /** Shows play or pause; a blow-up disables play and step until a restart. */
  setPlaying(playing: boolean, error: boolean): void {
    relabel(this.playButton, playing ? 'Pause' : 'Play', playing ? '❚❚' : '▶');
    this.playButton.setAttribute('aria-pressed', String(playing));
    this.playButton.disabled = error;
    this.stepButton.disabled = error;
    this.restartButton.classList.toggle('pb-primary', error);
  }

  /**
   * The requested step rate, and `behind`, the share of it the model
   * achieves when it has been judged to fall behind real time (null
   * otherwise). Said plainly, not as an alarm: a slow model is not a fault.
   */
  showRate(target: number, behind: number | null): void {
    const note = behind === null ? '' : ` · behind real time, ${Math.round(behind * 100)}%`;
    this.speedText.textContent = `${formatSpeed(this.speed)} t/s · ${formatRate(target)} steps/s${note}`;
    this.speedText.classList.toggle('pb-behind', behind !== null);
  }
}
