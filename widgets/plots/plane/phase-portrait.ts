import type { Simulation } from '../../../core/index.ts';
import type { View } from '../view.ts';
import type { SignedKind } from '../scale.ts';
import { axisTitle, batchTitle, phasePairs, toExtent, tracksOf, type ExtentOption, type Pair } from '../record-columns.ts';
import type { PanelSpec } from './plane-panels.ts';
import { PlaneView, type PlaneStyle } from './plane-view.ts';
import { heightAt, PHASE_MULTIPLE, PHASE_PANEL } from '../sizes.ts';

export interface PhasePortraitOptions extends PlaneStyle {
  /** degrees of freedom i to plot as (q_i, p_i), or explicit pairs of series; default all */
  pairs?: readonly (number | Pair)[];
  /** all pairs on one plane in their own colours (default), or one small panel each */
  layout?: 'overlay' | 'multiples';
  /**
   * 'symlog' maps y to sgn y·ln(1 + |y|/c) on both axes, as the paper draws
   * the exponentially growing phase path of parametric resonance (fig. 8)
   */
  scale?: SignedKind;
  /** the symlog constant c (default 1): the scale is nearly linear within ±c */
  constant?: number;
  /** legend labels, one per pair */
  labels?: readonly string[];
  /** a fixed extent for every panel; by default each grows to fit */
  extent?: ExtentOption;
  limit?: ExtentOption;
  /** one unit of q as long as one of p; default false */
  equal?: boolean;
}

/**
 * Phase paths, p_i against q_i, drawn as they are traced (the paper's §6.6),
 * the whole path kept by default.
 */
export function phasePortrait(options: PhasePortraitOptions = {}): View {
  const extent = toExtent(options.extent, 'extent');
  const limit = toExtent(options.limit, 'limit');
  const constant = options.constant ?? 1;
  if (!(constant > 0)) throw new Error(`the symlog constant must be positive, not ${options.constant}`);
  if (options.scale !== undefined && options.scale !== 'linear' && options.scale !== 'symlog') {
    throw new Error(`scale must be 'linear' or 'symlog', not ${JSON.stringify(options.scale)}`);
  }
  const multiples = options.layout === 'multiples';
  return new PlaneView({
    ...options,
    trail: options.trail ?? 'full',
    kind: 'phase-portrait',
    label: 'Phase portrait: momentum against coordinate',
    panelHeight: (width) => heightAt(multiples ? PHASE_MULTIPLE : PHASE_PANEL, width),
    resolve: (simulation) => {
      const pairs = phasePairs(simulation.model.names, simulation.model.dof, options.pairs);
      if (pairs.length === 0) throw new Error('no pairs to draw');
      const base = { xKind: options.scale ?? 'linear', yKind: options.scale ?? 'linear', constant, equal: options.equal ?? false, extent, limit };
      const label = (pair: Pair, i: number) => options.labels?.[i] ?? pair.join(', ');
      const tracks = (pair: Pair, i: number) => tracksOf(simulation.record, pair, () => i);
      const title = batchTitle(simulation.count);
      if (multiples) {
        return pairs.map((pair, i): PanelSpec => ({
          ...base,
          tracks: tracks(pair, i),
          legend: [{ label: label(pair, i), group: i }],
          title,
          xLabel: pair[0],
          yLabel: pair[1],
        }));
      }
      return [
        {
          ...base,
          tracks: pairs.flatMap(tracks),
          legend: pairs.length > 1 || options.labels ? pairs.map((pair, i) => ({ label: label(pair, i), group: i })) : [],
          title,
          xLabel: axisTitle(pairs.map((p) => p[0]), 'q'),
          yLabel: axisTitle(pairs.map((p) => p[1]), 'p'),
        },
      ];
    },
  });
}

