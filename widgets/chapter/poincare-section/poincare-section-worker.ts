/**
 * Computes surfaces of section, Lyapunov exponents and chaotic shares off
 * the main thread: a section of thirty orbits is a few million steps, which
 * would freeze the page it sits in. The systems are written in closed form
 * (core/analysis/henon-heiles.ts, core/analysis/anisotropic-kepler.ts), so
 * this worker needs no mathjs. A request names its system
 * (section-systems.ts); without one it is Hénon–Heiles.
 *
 * Messages in: SectionRequest. Out, each tagged with the request's id:
 * {orbit, u, pu, progress} per orbit, then {done}; for a single launched
 * orbit {orbit: -1, u, pu, exponent}; for a share {progress} then {area};
 * {error} if anything fails. For the anisotropic Kepler problem's checks,
 * {run: KeplerRun} (kepler-run.ts). A section yields between orbits, so a
 * reader's launch is served before the rest of the section; cancelling is
 * terminating the worker.
 */
import { chaoticArea, henonHeiles, keplerLyapunov, keplerSection, largestLyapunov, launchState, type Plane, section, sectionLaunch } from '../../../core/index.ts';
import { keplerRun } from '../analysis/kepler-run.ts';
import { keplerSetting, type SectionSystem } from './section-systems.ts';

export type SectionRequest =
  | { id: number; kind: 'section'; system?: SectionSystem; energy: number; plane: Plane; launches: [number, number][]; crossings: number; dt: number }
  | { id: number; kind: 'orbit'; system?: SectionSystem; energy: number; plane: Plane; launch: [number, number]; crossings: number; dt: number; lyapunovTime: number }
  | { id: number; kind: 'area'; energy: number; plane: Plane; grid: number; time: number }
  | { id: number; kind: 'kepler-run'; factor: number; time: number };

/** The crossings of one orbit from (u0, pu0), in the section's coordinates; null where no orbit starts there. */
function crossingsFrom(request: { system?: SectionSystem; energy: number; plane: Plane; dt: number }, u0: number, pu0: number, count: number) {
  const { system, energy, plane, dt } = request;
  if (system?.kind === 'anisotropic-kepler') {
    const setting = keplerSetting(system.factor);
    const start = sectionLaunch(setting.system, setting.energy, u0, pu0);
    if (!start) return null;
    const run = keplerSection(setting.system, setting.energy, start, { count });
    return { u: run.sigma, pu: run.pi, start, setting };
  }
  const start = launchState(henonHeiles, energy, u0, pu0, plane);
  if (!start) return null;
  const run = section(henonHeiles, start, { plane, count, dt });
  return { u: run.u, pu: run.pu, start, setting: null };
}

const pause = () => new Promise((resolve) => setTimeout(resolve, 0));

async function run(request: SectionRequest): Promise<void> {
  const { id } = request;
  if (request.kind === 'kepler-run') {
    postMessage({ id, run: keplerRun(request.factor, request.time) });
  } else if (request.kind === 'section') {
    for (let k = 0; k < request.launches.length; k++) {
      const [u0, pu0] = request.launches[k];
      const s = crossingsFrom(request, u0, pu0, request.crossings);
      if (s) {
        const u = Float64Array.from(s.u);
        const pu = Float64Array.from(s.pu);
        postMessage({ id, orbit: k, u, pu, progress: (k + 1) / request.launches.length }, { transfer: [u.buffer, pu.buffer] });
      }
      await pause();
    }
    postMessage({ id, done: true });
  } else if (request.kind === 'orbit') {
    const s = crossingsFrom(request, request.launch[0], request.launch[1], request.crossings);
    if (!s) throw new Error('the point lies outside the region the energy allows');
    const exponent = s.setting
      ? keplerLyapunov(s.setting.system, s.setting.energy, s.start, { time: request.lyapunovTime }).exponent
      : largestLyapunov(henonHeiles, s.start, { time: request.lyapunovTime, dt: 0.05 }).exponent;
    postMessage({ id, orbit: -1, u: Float64Array.from(s.u), pu: Float64Array.from(s.pu), exponent });
  } else {
    const area = chaoticArea(henonHeiles, request.energy, {
      plane: request.plane,
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
