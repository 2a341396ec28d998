/**
 * The builtins' catalogue generated at build time (vscode/build/catalogue.ts)
 * and the set of names cells may read without defining them.
 */
import generated from '../../generated/catalogue.json';
import { builtinNames } from '../analyzer/builtin-names.ts';
import type { Catalogue } from '../analyzer/catalogue.ts';

export const catalogue: Catalogue = generated as Catalogue;

export const builtins: ReadonlySet<string> = builtinNames(catalogue);
