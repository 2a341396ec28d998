import type { BuildOptions } from '../../core/index.ts';
import type { View } from '../plots/view.ts';
import { mount, type SimulatorElement } from './mount.ts';
import { parseSimulatorOptions, type SimulatorOptions, type ViewName, type ViewOptions } from './options.ts';
import { VIEW_MODULES } from './view-modules.ts';

export type { SimulatorElement, SimulatorHandle } from './mount.ts';
export type { SimulatorOptions } from './options.ts';

/** Each view's module loads only when a simulator shows that view. */
const FACTORIES: Record<ViewName, (o: ViewOptions) => Promise<View>> = {
  time: (o) => VIEW_MODULES.time().then((m) => m.timePlot(o.timePlot)),
  trajectory: (o) => VIEW_MODULES.trajectory().then((m) => m.trajectoryView(o.trajectory)),
  phase: (o) => VIEW_MODULES.phase().then((m) => m.phasePortrait(o.phase)),
  spectrum: (o) => VIEW_MODULES.spectrum().then((m) => m.spectrumView(o.spectrum)),
};

/**
 * A running simulation with its controls, readouts, views and data panel:
 * the paper's simulator as one widget. Resolves to the root element
 * (data-widget="simulator", data-ready once every view has drawn); rejects
 * with a one-line InputError when the options are wrong (options.ts says
 * which). `build` passes on how models are built (the page's compiled
 * models, see canonicalEquations).
 */
export async function simulator(options: SimulatorOptions, build: BuildOptions = {}): Promise<SimulatorElement> {
  let loading: Promise<View[]> | undefined;
  // The views' modules load while the model is built.
  const settings = await parseSimulatorOptions(options, build, (names, viewOptions) => {
    loading = Promise.all(names.map((name) => FACTORIES[name](viewOptions)));
    loading.catch(() => undefined);
  });
  const views = await loading!;
  return mount(settings, settings.model, settings.simulation, views, settings.withDt);
}
