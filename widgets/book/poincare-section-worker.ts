/**
 * Computes surfaces of section, Lyapunov exponents and chaotic shares off
 * the main thread: a section of thirty orbits is a few million steps, which
 * would freeze the page it sits in. The systems are written in closed form
 * (core/analysis/henon-heiles.ts), so this worker needs no mathjs.
 *
 * Messages in: SectionRequest. Out, each tagged with the request's id:
 * {orbit, u, pu, progress} per orbit, then {done}; for a single launched
 * orbit {orbit: -1, u, pu, exponent}; for a share {progress} then {area};
 * {error} if anything fails. A section yields between orbits, so a
 * reader's launch is served before the rest of the section; cancelling is
 * terminating the worker.
 */
import { chaoticArea, henonHeiles, largestLyapunov, launchState, type Plane, section } from '../core/index.ts';

export type SectionRequest =
  | { id: number; kind: 'section'; energy: number; plane: Plane; launches: [number, number][]; crossings: number; dt: number }
  | { id: number; kind: 'orbit'; energy: number; plane: Plane; launch: [number, number]; crossings: number; dt: number; lyapunovTime: number }
  | { id: number; kind: 'area'; energy: number; plane: Plane; grid: number; time: number };

const pause = () => new Promise((resolve) => setTimeout(resolve, 0));

async function run(request: SectionRequest): Promise<void> {
  const { id, energy, plane } = request;
  if (request.kind === 'section') {
    for (let k = 0; k < request.launches.length; k++) {
      const [u0, pu0] = request.launches[k];
      const start = launchState(henonHeiles, energy, u0, pu0, plane);
      if (start) {
        const s = section(henonHeiles, start, { plane, count: request.crossings, dt: request.dt });
        const u = Float64Array.from(s.u);
        const pu = Float64Array.from(s.pu);
        postMessage({ id, orbit: k, u, pu, progress: (k + 1) / request.launches.length }, { transfer: [u.buffer, pu.buffer] });
      }
      await pause();
    }
    postMessage({ id, done: true });
  } else if (request.kind === 'orbit') {
    const start = launchState(henonHeiles, energy, request.launch[0], request.launch[1], plane);
    if (!start) throw new Error('the point lies outside the region the energy allows');
    const s = section(henonHeiles, start, { plane, count: request.crossings, dt: request.dt });
    const exponent = largestLyapunov(henonHeiles, start, { time: request.lyapunovTime, dt: 0.05 }).exponent;
    postMessage({ id, orbit: -1, u: Float64Array.from(s.u), pu: Float64Array.from(s.pu), exponent });
  } else {
    const area = chaoticArea(henonHeiles, energy, {
      plane,
      grid: request.grid,
      time: request.time,
      progress: (fraction) => postMessage({ id, progress: fraction }),
    });
    postMessage({ id, area: { fraction: area.fraction, chaotic: area.chaotic, total: area.total, samplingError: area.samplingError, undecided: area.undecided } });
  }
}

self.onmessage = (event: MessageEvent<SectionRequest>) => {
  run(event.data).catch((error: unknown) => postMessage({ id: event.data.id, error: (error as Error)?.message ?? String(error) }));
};
