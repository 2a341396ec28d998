/**
 * Pause and Play for a chart updated frame after frame (a cell fed by a
 * generator), offered while it moves and while it is paused, as the
 * simulators offer them; a reader whose system asks for reduced motion
 * sees the picture held from the first frame-on-frame update, until Play.
 */
import { prefersReducedMotion } from '../../controls/dom.ts';
import { MotionSense, STILL_AFTER_MS } from './chart-reuse.ts';
import { button } from './chart-tools.ts';

export class PauseControl<T> {
  readonly #motion = new MotionSense();
  readonly #calm = new MotionSense(1);
  readonly #toggle: HTMLButtonElement;
  #paused = false;
  /** while paused, the latest update, shown on Play */
  #pending: T | null = null;
  #stillTimer: ReturnType<typeof setTimeout> | undefined;
  readonly #tools: HTMLElement;
  readonly #show: (next: T) => void;

  /** `tools` is where the button appears; `show` shows an update. */
  constructor(tools: HTMLElement, show: (next: T) => void) {
    this.#tools = tools;
    this.#show = show;
    this.#motion.update(performance.now());
    this.#calm.update(performance.now());
    this.#toggle = button('Pause', 'Pause or resume the animation', () => this.#flip());
    this.#toggle.dataset.motion = '';
  }

  /** An update of the chart: shown, or kept while paused; offers the button once the updates come frame on frame. */
  update(next: T): void {
    const now = performance.now();
    const moving = this.#motion.update(now);
    const hold = this.#calm.update(now) && prefersReducedMotion() && !this.#offered();
    if ((moving || hold) && !this.#offered()) this.#offer(hold);
    if (this.#offered()) this.#settle();
    if (this.#paused) this.#pending = next;
    else this.#show(next);
  }

  /** Puts the button before the other tools; `hold` starts it paused, for a reader who asks for reduced motion. */
  #offer(hold: boolean): void {
    this.#tools.prepend(this.#toggle);
    if (hold) {
      this.#paused = true;
      this.#toggle.textContent = 'Play';
    }
  }

  #flip(): void {
    this.#paused = !this.#paused;
    this.#toggle.textContent = this.#paused ? 'Play' : 'Pause';
    if (!this.#paused && this.#pending) this.#show(this.#pending);
    this.#pending = null;
    this.#settle();
  }

  #offered(): boolean {
    return this.#toggle.parentNode !== null;
  }

  /** Takes the button away once the chart is still and running (and the reader is not on the button). */
  #settle(): void {
    clearTimeout(this.#stillTimer);
    this.#stillTimer = setTimeout(() => {
      if (!this.#paused && !this.#motion.moving(performance.now()) && document.activeElement !== this.#toggle) this.#toggle.remove();
    }, STILL_AFTER_MS);
  }
}
