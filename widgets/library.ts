/**
 * The book's named widgets and helpers, available to every code cell by bare
 * name (e.g. `simulator(...)` in a cell). Add entries here: each value is
 * handed to cells as is — a function stays a function the cell calls.
 *
 * widgets/cells/builtins.ts spreads this object over the standard builtins,
 * so an entry here wins over a standard builtin of the same name. A cell that
 * defines the same name wins over both.
 */
import { canonicalEquations } from './core/canonical-equations.ts';
import { phasePortrait } from './plots/phase-portrait.ts';
import { spectrumView } from './plots/spectrum-view.ts';
import { timePlot } from './plots/time-plot.ts';
import { trajectoryView } from './plots/trajectory-view.ts';
import { simulator } from './simulator/simulator.ts';

export const library: Record<string, unknown> = {
  /** simulator({hamiltonian, initial, …}) → Promise of the widget's element */
  simulator,
  /** canonicalEquations({dof, hamiltonian, params}) → Promise of a Model */
  canonicalEquations,
  /** Views (each has an `.element`), for composing a simulator by hand */
  timePlot,
  trajectoryView,
  phasePortrait,
  spectrumView,
};
