/**
 * The systems a surface-of-section widget can show, described for drawing
 * (the allowed region, its rim, the axes' names) and for the worker (where
 * a launch point starts): Hénon–Heiles at an energy, on the plane y = 0 or
 * x = 0; and the anisotropic Kepler problem of the paper's chaotic two-body
 * variant, at the energy of the paper's initial state, on the line v = 0
 * drawn in the scaled Levi-Civita coordinates (σ̂, π̂) whose allowed region
 * is the unit disk (core/analysis/anisotropic-kepler-flow.ts). DOM-free, so
 * that the page and the worker share it.
 */
import {
  allowed,
  type AnisotropicKepler,
  henonHeiles,
  keplerEnergy,
  massRatio,
  type Plane,
  planeIndices,
  relativeMotion,
  sectionBox,
  sectionLaunch,
} from '../../../core/index.ts';

export type SectionSystem = { kind: 'henon-heiles'; plane: Plane } | { kind: 'anisotropic-kepler'; factor: number };

export interface SectionView {
  /** the box holding the allowed region */
  box: { uMin: number; uMax: number; puMax: number };
  /** whether a launch from (u, pu) is possible */
  allowed(u: number, pu: number): boolean;
  /** the rim's momentum |p| at u (the region is symmetric in p) */
  rim(u: number): number;
  labels: { u: string; pu: string };
  /** e.g. "y = 0 with p_y > 0" */
  plane: string;
  /** e.g. "E = 1/12" or "μ = 1.625" */
  setting: string;
}

const FRACTIONS: Record<string, string> = { [String(1 / 12)]: '1/12', [String(1 / 8)]: '1/8', [String(1 / 6)]: '1/6' };
export const energyName = (E: number) => FRACTIONS[String(E)] ?? E.toPrecision(3);

export function henonHeilesView(energy: number, plane: Plane): SectionView {
  const names = planeIndices(plane).names;
  const V = (u: number) => (plane === 'y' ? henonHeiles.potential(u, 0) : henonHeiles.potential(0, u));
  return {
    box: sectionBox(henonHeiles, energy, plane),
    allowed: (u, pu) => allowed(henonHeiles, energy, u, pu, plane),
    rim: (u) => Math.sqrt(Math.max(0, 2 * (energy - V(u)))),
    labels: { u: names[0] === 'x' ? 'x' : 'y', pu: names[1] === 'px' ? 'pₓ' : 'p_y' },
    plane: `${plane} = 0 with p${plane} > 0`,
    setting: `E = ${energyName(energy)}`,
  };
}

export interface KeplerSetting {
  factor: number;
  system: AnisotropicKepler;
  /** the relative state of the paper's initial condition, [u, v, p_u, p_v] */
  state: Float64Array;
  energy: number;
  /** m_heavy/m_light */
  mu: number;
}

/**
 * The anisotropic Kepler problem of H = Σp² − 500/hypot(factor·x1 − x2, y1 − y2)
 * from the paper's initial state; throws, with the reason, for a factor that
 * is not a finite number or that leaves that state unbound (E ≥ 0).
 */
export function keplerSetting(factor: number): KeplerSetting {
  if (typeof factor !== 'number' || !Number.isFinite(factor)) throw new TypeError(`the anisotropy factor must be a finite number, not ${String(factor)}`);
  const { system, state } = relativeMotion(factor);
  const energy = keplerEnergy(system, state);
  if (!(energy < 0)) {
    throw new RangeError(
      `with factor ${factor} the paper's initial state is unbound (E = ${energy.toPrecision(3)} ≥ 0): the relative orbit escapes and has no surface of section; try a factor between −5 and 5`,
    );
  }
  return { factor, system, state, energy, mu: massRatio(system) };
}

export function keplerView(setting: KeplerSetting): SectionView {
  const { system, energy, mu } = setting;
  return {
    box: { uMin: -1, uMax: 1, puMax: 1 },
    allowed: (u, pu) => sectionLaunch(system, energy, u, pu) !== null,
    rim: (u) => Math.sqrt(Math.max(0, 1 - u * u)),
    labels: { u: 'σ = ±√|u|, scaled', pu: 'π = 2√|u|·p_u, scaled' },
    plane: 'v = 0 with p_v > 0',
    setting: `μ = ${Number(mu.toPrecision(4))}`,
  };
}

/** Launch points spread over the section: most along its horizontal axis, the rest along a vertical line off the centre. */
export function launchGrid(view: SectionView, orbits: number, across: number): [number, number][] {
  const { box } = view;
  const along = Math.ceil(orbits * 0.6);
  const rest = orbits - along;
  const out: [number, number][] = [];
  for (let i = 0; i < along; i++) out.push([box.uMin + ((i + 0.5) / along) * (box.uMax - box.uMin), 0]);
  for (let j = 0; j < rest; j++) out.push([across, -box.puMax + ((j + 0.5) / rest) * 2 * box.puMax]);
  return out.filter(([u, pu]) => view.allowed(u, pu));
}
