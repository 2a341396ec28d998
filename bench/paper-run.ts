/**
 * The paper's algorithm as a process of its own, for bench/cli.ts to time
 * against `phasebook simulate`:
 *
 *   node paper-run.mjs DOF STEPS DT INITIAL PARAMS_JSON H_SOURCE
 *
 * H is the same JS function source the CLI is given, with the parameters and
 * Math's functions in scope by name, as in the paper's examples; the
 * gradient is paper-reference.ts's 2-point difference. Prints the final
 * state. bench/cli.ts bundles this file with esbuild into a temporary .mjs.
 */
import { canonicalEquation, plainRk38, type PlainHamiltonian } from './paper-reference.ts';

const [dof, steps, dt, initial, paramsJson, source] = process.argv.slice(2);
const params = JSON.parse(paramsJson) as Record<string, number>;
const mathNames = Object.getOwnPropertyNames(Math).filter((name) => !(name in params));
const math = Math as unknown as Record<string, unknown>;
const H = new Function(...Object.keys(params), ...mathNames, `return (${source});`)(
  ...Object.values(params),
  ...mathNames.map((name) => math[name]),
) as PlainHamiltonian;
const x = plainRk38(canonicalEquation(Number(dof), H), initial.split(',').map(Number), Number(dt), Number(steps));
process.stdout.write(`${x.join(' ')}\n`);
