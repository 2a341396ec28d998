/**
 * Where each view of a simulator lives. A simulator loads the modules of
 * the views it shows; the page may ask for them earlier, as soon as it knows
 * a simulator is coming (catalogue.ts, prefetchWidgets), so that they arrive
 * together with the simulator's own module rather than after it.
 */
import type { ViewName } from './options.ts';

export const VIEW_MODULES = {
  time: () => import('../plots/time/time-plot.ts'),
  trajectory: () => import('../plots/plane/trajectory-view.ts'),
  phase: () => import('../plots/plane/phase-portrait.ts'),
  spectrum: () => import('../plots/spectrum/spectrum-view.ts'),
} satisfies Record<ViewName, () => Promise<unknown>>;
