/**
 * The book's named widgets and helpers, available to every code cell by bare
 * name (e.g. `simulator(...)` in a cell). Add entries here: each value is
 * handed to cells as is — a function stays a function the cell calls.
 *
 * widgets/cells/builtins.ts spreads this object over the standard builtins,
 * so an entry here wins over a standard builtin of the same name. A cell that
 * defines the same name wins over both.
 */
export const library: Record<string, unknown> = {};
