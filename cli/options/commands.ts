/**
 * The command line's four commands and their options, each declared once:
 * the parser reads the arguments by these declarations (args.ts), and the
 * synopsis, `--help` and the README's synopsis are written from them
 * (usage.ts; a unit test holds the README to it), so that what the CLI
 * accepts and what it says it accepts cannot drift apart.
 *
 * The order is the synopsis's: options appear on their line in the order
 * declared here, and lines in the order of their first option.
 */
import type { CommandSpec } from './args.ts';

export const SIMULATE: CommandSpec = {
  name: 'simulate',
  summary: 'integrates Hamilton’s equations from one initial state or many, into CSV, JSON, NPZ or Parquet',
  headings: {
    field: 'equations of motion instead of H (a JS H beside them only fills the H column):',
    file: 'many trajectories instead of --initial:',
  },
  options: [
    { name: 'hamiltonian', kind: 'value', value: 'H', line: 'model', required: true, help: 'H(t, q, p) as a math expression, or a JS arrow function (t, x) => …' },
    { name: 'dof', kind: 'value', value: 'N', line: 'model', required: true, help: 'degrees of freedom: the state is N coordinates, then N momenta' },
    { name: 'initial', kind: 'value', value: 'v1,…,v2N', line: 'model', required: true, help: 'the initial state, coordinates then momenta' },
    { name: 'param', kind: 'list', value: 'name=value', line: 'model', help: 'a parameter H can use; the value may be arithmetic (w=2*pi)' },
    { name: 'dt', kind: 'value', value: '5e-4', line: 'time', help: 'the time step (with --method adaptive, the interval between samples)' },
    { name: 't0', kind: 'value', value: '0', line: 'time', help: 'the time of the initial state' },
    { name: 't-end', kind: 'value', value: '10', line: 'time', help: 'the last time (by default 10 after --t0)' },
    { name: 'every', kind: 'value', value: '1', line: 'time', help: 'a row every K steps, from --t0' },
    { name: 'times', kind: 'value', value: 't1,t2,…', line: 'time', joins: { option: 'every', as: 'or' }, help: 'rows at these times only, instead of --t-end and --every' },
    { name: 'derivatives', kind: 'flag', line: 'time', help: 'add the columns dq/dt, dp/dt, from Hamilton’s equations' },
    { name: 'format', kind: 'value', value: 'csv|json|npz|parquet', line: 'output', help: 'the output’s format (by default its extension’s, else csv)' },
    { name: 'layout', kind: 'value', value: 'long|wide', line: 'output', help: 'Parquet’s rows: one per sample (long), or one per time for every trajectory (wide)' },
    { name: 'output', kind: 'value', value: 'FILE', line: 'output', help: 'the file to write, complete or not at all (by default stdout)' },
    { name: 'coordinates', kind: 'value', value: 'x,y', line: 'run', help: 'the coordinates’ names, instead of q or q0, q1, …' },
    { name: 'momenta', kind: 'value', value: 'px,py', line: 'run', joins: { option: 'coordinates', as: 'and' }, help: 'the momenta’s names, instead of p or p0, p1, …' },
    { name: 'workers', kind: 'value', value: 'K', line: 'run', help: 'threads (by default every core, once a run has over 5e6 steps to share)' },
    { name: 'shard', kind: 'value', value: 'i/n', line: 'run', help: 'only the i-th of n slices of a sampled or gridded set, for phasebook merge' },
    { name: 'no-cache', kind: 'flag', line: 'run', help: 'neither read nor write the compiled models’ cache' },
    { name: 'force', kind: 'flag', line: 'run', help: 'run even past 1e9 steps or an estimated 1 GiB of output' },
    { name: 'method', kind: 'value', value: 'rk38|verlet|yoshida4|midpoint|adaptive', line: 'method', help: 'the integrator (by default rk38, Runge–Kutta 3/8 as in the paper)' },
    { name: 'rtol', kind: 'value', value: 'R', line: 'method', joins: { option: 'method', as: 'nested' }, help: 'the relative tolerance of --method adaptive' },
    { name: 'atol', kind: 'value', value: 'A', line: 'method', joins: { option: 'rtol', as: 'and' }, help: 'the absolute tolerance of --method adaptive' },
    { name: 'vector-field', kind: 'value', value: "'(t, x, dxdt) => { … }'", line: 'field', required: true, help: 'Hamilton’s equations as a JS function that fills dxdt, instead of H' },
    { name: 'initial-file', kind: 'value', value: 'FILE', line: 'file', required: true, help: 'initial states from a .csv, .npy or .json file, a row per trajectory' },
    { name: 'sample', kind: 'value', value: 'N', line: 'sample', required: true, help: 'N initial states drawn uniformly in --box' },
    { name: 'seed', kind: 'value', value: 'S', line: 'sample', joins: { option: 'sample', as: 'nested' }, help: 'the draw’s seed (by default 0): the same states for the same seed' },
    { name: 'box', kind: 'value', value: 'q=lo:hi,p=lo:hi', line: 'sample', joins: { option: 'sample', as: 'and' }, help: 'the box drawn in, a range per component; q=c fixes one' },
    { name: 'energy', kind: 'value', value: 'E', line: 'sample', joins: { option: 'sample', as: 'nested' }, help: 'each drawn state moved onto H = E by solving for one momentum' },
    { name: 'solve-for', kind: 'value', value: 'p', line: 'sample', joins: { option: 'energy', as: 'nested' }, help: 'the momentum --energy solves for (by default the first)' },
    { name: 'grid', kind: 'value', value: 'q=lo:hi:n,p=lo:hi:n', line: 'grid', required: true, help: 'initial states on a grid in C order, numpy.linspace’s points on each axis' },
  ],
};

export const SPECTRUM: CommandSpec = {
  name: 'spectrum',
  summary: 'the strongest lines of one column’s spectrum, from a file simulate wrote',
  options: [
    { name: 'input', kind: 'value', value: 'FILE', line: 'input', required: true, help: 'a file phasebook wrote: CSV, JSON, NPZ or Parquet, of one trajectory or several' },
    { name: 'column', kind: 'value', value: 'NAME', line: 'input', required: true, help: 'the column to analyse, e.g. q' },
    { name: 'trajectory', kind: 'value', value: 'J', line: 'input', help: 'the trajectory to analyse, in a file of several' },
    { name: 'from', kind: 'value', value: 'T0', line: 'input', help: 'analyse the samples from this time on' },
    { name: 'to', kind: 'value', value: 'T1', line: 'input', help: 'analyse the samples up to this time' },
    { name: 'window', kind: 'value', value: 'hamming|none', line: 'analysis', help: 'the window the samples are weighted by (by default hamming)' },
    { name: 'top', kind: 'value', value: 'K', line: 'analysis', help: 'how many lines to list (by default 5)' },
    { name: 'format', kind: 'value', value: 'text|json', line: 'analysis', help: 'the output’s format (by default text)' },
  ],
};

export const MERGE: CommandSpec = {
  name: 'merge',
  summary: 'joins the shards of one run into the file the whole run writes',
  operands: { text: 'SHARD…', at: 'end', many: true },
  options: [{ name: 'output', kind: 'value', value: 'FILE', line: 'merge', required: true, help: 'the merged file, written complete or not at all' }],
};

export const REPRODUCE: CommandSpec = {
  name: 'reproduce',
  summary: 'runs a JSON, NPZ or Parquet file again from its meta and compares every number, bit for bit',
  operands: { text: 'FILE', at: 'start', many: false },
  options: [
    { name: 'workers', kind: 'value', value: 'K', line: 'run', help: 'threads (by default every core, once a run has over 5e6 steps to share)' },
    { name: 'no-cache', kind: 'flag', line: 'run', help: 'neither read nor write the compiled models’ cache' },
    { name: 'trust-code', kind: 'flag', line: 'run', help: 'run the file’s JavaScript, in the sandbox, if it has any that does not translate' },
  ],
};

/** Every command, in the order the synopsis lists them. */
export const COMMANDS: readonly CommandSpec[] = [SIMULATE, SPECTRUM, MERGE, REPRODUCE];
