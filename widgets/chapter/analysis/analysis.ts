/** The core's analysis functions, gathered into one module that the catalogue loads when a chapter's check first needs one. */
export {
  angleBetween,
  crossings,
  deflectionFrom,
  floquet,
  keplerOrbit,
  meanPeriod,
  outgoingDirection,
  peakError,
  rutherfordAngle,
} from '../../../core/index.ts';
