/** The simulation core: DOM-free, shared by the widgets, the CLI and the tests. */
export { canonicalEquations, type HamiltonianSpec, type BuildOptions } from './canonical-equations.ts';
export { abortError, type BuildControl } from './build-control.ts';
export { rk38 } from './rk38.ts';
export { Simulation, DEFAULT_DT, type DerivedSeries, type SimulationOptions } from './simulation.ts';
export { TrajectoryRecord, capacityFor, bytesFor, type Table } from './record.ts';
export { csvHeader, csvRows, toCSV, parseCSV } from './csv.ts';
export { jsonHead, jsonRows, jsonTail, toJSON, parseJSON, type ExportMeta } from './json.ts';
export { readTable } from './read-table.ts';
export { spectrum, findPeaks, hamming, type Spectrum, type Peak, type WindowName } from './spectrum.ts';
export { evaluateAlong, relativeDrift, type StateFunction } from './invariants.ts';
export { InputError, BlowUpError } from './errors.ts';
export { VERSION } from './version.ts';
export type { Model, Route, Stepper, VectorField, HamiltonianFunction } from './types.ts';
