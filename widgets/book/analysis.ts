/** The core's analysis functions, gathered for the chapters' cells. */
export { crossings, meanPeriod } from '../core/analysis/crossings.ts';
export { floquet } from '../core/analysis/floquet.ts';
export { keplerOrbit } from '../core/analysis/kepler.ts';
export { peakError } from '../core/analysis/leakage.ts';
export { angleBetween, deflectionFrom, outgoingDirection, rutherfordAngle } from '../core/analysis/scattering.ts';
