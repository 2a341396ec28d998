/**
 * The shape of the builtins' catalogue: what a cell can name without
 * defining it, with the documentation and option types the book's own
 * TypeScript declares. vscode/build/catalogue.ts writes it at build time
 * from widgets/catalogue.ts, so completion and hover never drift from the code.
 */

/** One option of an options object (a property of its type). */
export interface CatalogueOption {
  readonly name: string;
  /** The property's type as TypeScript prints it. */
  readonly type: string;
  readonly optional: boolean;
  /** The property's doc comment, or '' when it has none. */
  readonly doc: string;
  /** The options of an options-valued property (e.g. `timePlot`), when it is one. */
  readonly options?: readonly CatalogueOption[];
}

export interface CatalogueParameter {
  readonly name: string;
  readonly type: string;
  readonly optional: boolean;
  /** Set when the parameter is an options object: its properties. */
  readonly options?: readonly CatalogueOption[];
}

export interface CatalogueEntry {
  readonly name: string;
  /** The comment above the entry in widgets/catalogue.ts. */
  readonly doc: string;
  /** `function`: a cell calls it; `class`: a cell writes `new Name(…)`; `value`: anything else. */
  readonly kind: 'function' | 'class' | 'value';
  /** How it is called, e.g. `simulator(options: SimulatorOptions): Promise<SimulatorElement>`. */
  readonly signature: string;
  /** The parameters of its first (call or construct) signature. */
  readonly parameters: readonly CatalogueParameter[];
}

export interface Catalogue {
  readonly builtins: readonly CatalogueEntry[];
}

/** The options of argument `index` of `name`, following `path` into options-valued options. */
export function optionsAt(catalogue: Catalogue, name: string, index: number, path: readonly string[]): readonly CatalogueOption[] {
  const entry = catalogue.builtins.find((b) => b.name === name);
  let options = entry?.parameters[index]?.options ?? [];
  for (const key of path) options = options.find((o) => o.name === key)?.options ?? [];
  return options;
}
