/**
 * The book's named widgets and helpers, available to every code cell by bare
 * name (e.g. `simulator(...)` in a cell). Add entries here: each value is
 * handed to cells as is — a function stays a function the cell calls.
 *
 * widgets/cells/builtins.ts spreads this object over the standard builtins,
 * so an entry here wins over a standard builtin of the same name. A cell that
 * defines the same name wins over both.
 *
 * Every entry is lazy: its module loads when a cell first names it, so a page
 * ships only the widgets its cells use, and none before its cells run.
 */
import { lazy } from './cells/lazy-builtin.ts';

const core = () => import('./core/index.ts');
const analysis = () => import('./book/analysis.ts');

export const library: Record<string, unknown> = {
  // Widgets
  /** simulator({hamiltonian, initial, …}) → Promise of the widget's element */
  simulator: lazy(() => import('./simulator/simulator.ts').then((m) => m.simulator)),
  /** Views (each has an `.element`), for composing a simulator by hand */
  timePlot: lazy(() => import('./plots/time-plot.ts').then((m) => m.timePlot)),
  trajectoryView: lazy(() => import('./plots/trajectory-view.ts').then((m) => m.trajectoryView)),
  phasePortrait: lazy(() => import('./plots/phase-portrait.ts').then((m) => m.phasePortrait)),
  spectrumView: lazy(() => import('./plots/spectrum-view.ts').then((m) => m.spectrumView)),
  /** theoryCheck({label, measured, predicted, tolerance, relative, unit, method, formula}) → element */
  theoryCheck: lazy(() => import('./book/theory-check.ts').then((m) => m.theoryCheck)),
  /** equations(model) → H and Hamilton's equations, typeset */
  equations: lazy(() => import('./book/tex.ts').then((m) => m.equations)),
  /** tex(source, {display}) → typeset LaTeX */
  tex: lazy(() => import('./book/tex.ts').then((m) => m.tex)),
  /** stabilityChart({hamiltonian, params, x, y, frequencyParam, boundaries, onSelect}) → Floquet chart computed in a worker */
  stabilityChart: lazy(() => import('./book/stability-chart.ts').then((m) => m.stabilityChart)),

  // The simulation core
  /** canonicalEquations({dof, hamiltonian, params}) → Promise of a Model */
  canonicalEquations: lazy(() => core().then((m) => m.canonicalEquations)),
  /** new Simulation(model, {initial, dt, every, derived}): integrate off-screen, e.g. for a theory check */
  Simulation: lazy(() => core().then((m) => m.Simulation)),
  spectrum: lazy(() => core().then((m) => m.spectrum)),
  findPeaks: lazy(() => core().then((m) => m.findPeaks)),
  relativeDrift: lazy(() => core().then((m) => m.relativeDrift)),
  evaluateAlong: lazy(() => core().then((m) => m.evaluateAlong)),

  // Analysis for the chapters' theory checks
  crossings: lazy(() => analysis().then((m) => m.crossings)),
  meanPeriod: lazy(() => analysis().then((m) => m.meanPeriod)),
  floquet: lazy(() => analysis().then((m) => m.floquet)),
  keplerOrbit: lazy(() => analysis().then((m) => m.keplerOrbit)),
  rutherfordAngle: lazy(() => analysis().then((m) => m.rutherfordAngle)),
  deflectionFrom: lazy(() => analysis().then((m) => m.deflectionFrom)),
  outgoingDirection: lazy(() => analysis().then((m) => m.outgoingDirection)),
  angleBetween: lazy(() => analysis().then((m) => m.angleBetween)),
};
