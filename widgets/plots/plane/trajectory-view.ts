import type { Simulation } from '../../../core/index.ts';
import type { View } from '../view.ts';
import { axisTitle, batchTitle, defaultBodies, toExtent, tracksOf, type ExtentOption, type Pair } from '../record-columns.ts';
import type { PanelSpec } from './plane-panels.ts';
import { PlaneView, type PlaneStyle } from './plane-view.ts';
import { heightAt, TRAJECTORY_PANEL } from '../sizes.ts';

export interface TrajectoryOptions extends PlaneStyle {
  /**
   * The bodies as (x, y) pairs of state components, e.g. the two Kepler
   * stars [['q0', 'q1'], ['q2', 'q3']]; by default consecutive coordinates
   * are paired. In a batch every trajectory's body is drawn.
   */
  bodies?: readonly Pair[];
  /** legend labels, one per body */
  labels?: readonly string[];
  /** a fixed extent; by default the extent grows to fit the motion */
  extent?: ExtentOption;
  /** the largest extent the auto-extent may grow to (e.g. for particles that escape to infinity) */
  limit?: ExtentOption;
  /** keep one data unit as long across as up, so a circle looks round; default true */
  equal?: boolean;
  /** colour by body (default), or by trajectory in a batch */
  colorBy?: 'body' | 'trajectory';
  xLabel?: string;
  yLabel?: string;
}

/**
 * Motion in configuration space: each body a dot with a fading trail (or the
 * whole path), in equal aspect, as in the paper's Kepler stars (§7.1) and
 * scattered beam (§7.3).
 */
export function trajectoryView(options: TrajectoryOptions = {}): View {
  const extent = toExtent(options.extent, 'extent');
  const limit = toExtent(options.limit, 'limit');
  return new PlaneView({
    ...options,
    trail: options.trail ?? 'fade',
    kind: 'trajectory',
    label: 'Trajectory in configuration space',
    panelHeight: (width) => heightAt(TRAJECTORY_PANEL, width),
    resolve: (simulation) => [trajectoryPanel(simulation, options, extent, limit)],
  });
}

function trajectoryPanel(
  simulation: Simulation,
  options: TrajectoryOptions,
  extent: PanelSpec['extent'],
  limit: PanelSpec['limit'],
): PanelSpec {
  const { model, count } = simulation;
  const bodies = options.bodies ?? defaultBodies(model.names, model.dof);
  if (bodies.length === 0) throw new Error('no bodies to draw');
  const byTrajectory = options.colorBy === 'trajectory' && count > 1;
  const tracks = bodies.flatMap((body, b) => tracksOf(simulation.record, body, (j) => (byTrajectory ? j % 8 : b)));
  const legend = byTrajectory ? [] : bodies.map((body, b) => ({ label: options.labels?.[b] ?? body.join(', '), group: b }));
  return {
    tracks,
    legend: bodies.length > 1 || options.labels ? legend : [],
    title: batchTitle(count),
    xLabel: options.xLabel ?? axisTitle(bodies.map((b) => b[0]), 'x'),
    yLabel: options.yLabel ?? axisTitle(bodies.map((b) => b[1]), 'y'),
    xKind: 'linear',
    yKind: 'linear',
    constant: 1,
    equal: options.equal ?? true,
    extent,
    limit,
  };
}
