/**
 * Ensembles of initial conditions carried by a flow: a blob's boundary
 * tracked as a refined polygon, and the area it encloses (Liouville's theorem).
 */
export { type BoundaryCurve, discArea, discBoundary } from './boundary-curve.ts';
export { polygonArea, polygonAreaError, polygonAreaShortfall } from './polygon-area.ts';
export { markSplits, type SplitLimits } from './side-splits.ts';
export { MIN_PARAMETER_GAP, TrackedBoundary, type TrackedBoundaryOptions } from './tracked-boundary.ts';
export { discCloud, Ensemble, type EnsembleSetup, type EnsembleState, MOST_POINTS } from './ensemble.ts';
export { type FlowArea, flowArea, type FlowAreaOptions } from './flow-area.ts';
