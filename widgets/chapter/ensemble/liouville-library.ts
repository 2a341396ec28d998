/**
 * What the Liouville chapter's cells name, from one module: the catalogue
 * then loads them through one import, which its boot chunk, on every page,
 * carries once rather than once a name.
 */
export { ensemble } from './ensemble.ts';
export { flowArea, kacMeasurement, modelSection, recordReturns } from '../../../core/index.ts';
