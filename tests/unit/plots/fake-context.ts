/** A recorded call on the fake context: the method name and its arguments. */
export interface Call {
  name: string;
  args: unknown[];
}

/**
 * A stand-in for CanvasRenderingContext2D that records every method call
 * and accepts any property, so drawing code runs in Node and tests can
 * read what was drawn. measureText says each character is 6 px wide.
 */
export function fakeContext(): { context: CanvasRenderingContext2D; calls: Call[]; state: Record<string, unknown> } {
  const calls: Call[] = [];
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
