/**
 * Stand-ins for a canvas in Node: FakeContext, a typed context that records
 * the drawing calls of the plots' protocol (with FakeSurface and a factory),
 * and fakeContext(), a proxy that records any call and property set, for
 * drawing code that uses more of CanvasRenderingContext2D.
 */
import type { Context, Surface, SurfaceFactory } from '../../../widgets/plots/canvas.ts';

/** One recorded call on a FakeContext: the method name and its arguments. */
export type Call = [string, ...unknown[]];

/**
 * A 2D context that records the drawing calls made on it (and the style at
 * each stroke), so drawing code can be tested in Node without a canvas.
 */
export class FakeContext {
  calls: Call[] = [];
  strokeStyle: string = '#000';
  fillStyle: string = '#000';
  lineWidth = 1;
  lineJoin: CanvasLineJoin = 'miter';
  lineCap: CanvasLineCap = 'butt';
  globalAlpha = 1;
  font = '10px sans-serif';
  textAlign: CanvasTextAlign = 'start';
  textBaseline: CanvasTextBaseline = 'alphabetic';

  private record(name: string, ...args: unknown[]): void {
    this.calls.push([name, ...args]);
  }

  beginPath(): void { this.record('beginPath'); }
  moveTo(x: number, y: number): void { this.record('moveTo', x, y); }
  lineTo(x: number, y: number): void { this.record('lineTo', x, y); }
  stroke(): void { this.record('stroke', this.strokeStyle, this.globalAlpha); }
  fill(): void { this.record('fill'); }
  arc(...args: number[]): void { this.record('arc', ...args); }
  rect(...args: number[]): void { this.record('rect', ...args); }
  fillRect(...args: number[]): void { this.record('fillRect', ...args); }
  clearRect(...args: number[]): void { this.record('clearRect', ...args); }
  fillText(text: string, x: number, y: number): void { this.record('fillText', text, x, y); }
  measureText(text: string): TextMetrics { return { width: text.length * 6 } as TextMetrics; }
  drawImage(image: unknown, x: number, y: number): void { this.record('drawImage', image, x, y); }
  save(): void { this.record('save'); }
  restore(): void { this.record('restore'); }
  setTransform(...args: number[]): void { this.record('setTransform', ...args); }

  /** Calls of one kind. */
  named(name: string): Call[] {
    return this.calls.filter((c) => c[0] === name);
  }

  /** The context typed as the plots' drawing protocol. */
  get ctx(): Context {
    return this as unknown as Context;
  }
}

/** A surface whose context is a FakeContext. */
export class FakeSurface implements Surface {
  readonly context = new FakeContext();
  constructor(
    public width: number,
    public height: number,
  ) {}
  getContext(): Context {
    return this.context.ctx;
  }
}

/** A factory that remembers every surface it made. */
export function fakeFactory(): { create: SurfaceFactory; made: FakeSurface[] } {
  const made: FakeSurface[] = [];
  return {
    made,
    create: (w, h) => {
      const s = new FakeSurface(w, h);
      made.push(s);
      return s;
    },
  };
}

/** A recorded call on the fake context: the method name and its arguments. */
export interface ProxyCall {
  name: string;
  args: unknown[];
}

/**
 * A stand-in for CanvasRenderingContext2D that records every method call
 * and accepts any property, so drawing code runs in Node and tests can
 * read what was drawn. measureText says each character is 6 px wide.
 */
export function fakeContext(): { context: CanvasRenderingContext2D; calls: ProxyCall[]; state: Record<string, unknown> } {
  const calls: ProxyCall[] = [];
  const state: Record<string, unknown> = {};
  const handler: ProxyHandler<Record<string, unknown>> = {
    get(_target, key) {
      if (typeof key !== 'string') return undefined;
      if (key === 'measureText') return (text: string) => ({ width: 6 * text.length });
      if (key in state) return state[key];
      return (...args: unknown[]) => {
        calls.push({ name: key, args });
      };
    },
    set(_target, key, value) {
      if (typeof key === 'string') {
        state[key] = value;
        calls.push({ name: `set ${key}`, args: [value] });
      }
      return true;
    },
  };
  return { context: new Proxy({}, handler) as unknown as CanvasRenderingContext2D, calls, state };
}

/** A PathSink that records its calls as [name, x, y]. */
export function recordingSink(): { sink: { moveTo(x: number, y: number): void; lineTo(x: number, y: number): void }; calls: [string, number, number][] } {
  const calls: [string, number, number][] = [];
  return {
    calls,
    sink: {
      moveTo: (x, y) => calls.push(['moveTo', x, y]),
      lineTo: (x, y) => calls.push(['lineTo', x, y]),
    },
  };
}
