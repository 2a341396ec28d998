/**
 * `--param name=value`, repeated: a number, or arithmetic over constants
 * and the parameters given before it (param-expression.ts). Names are those
 * a generated stepper can use: ASCII letters, digits and _.
 */
import { checkName, InputError } from '../../core/index.ts';
import { evaluateParameter } from './param-expression.ts';

export interface Parameters {
  values: Record<string, number>;
  /** the parameters given as arithmetic rather than a plain number, as written */
  expressions: Record<string, string>;
}

const PLAIN_NUMBER = /^\s*[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\s*$/;

export function parameters(pairs: readonly string[], stateNames: readonly string[] = []): Parameters {
  const values: Record<string, number> = {};
  const expressions: Record<string, string> = {};
  for (const pair of pairs) {
    const eq = pair.indexOf('=');
    if (eq <= 0) throw new InputError(`--param takes name=value, not "${pair}"`);
    const name = pair.slice(0, eq).trim();
    const text = pair.slice(eq + 1);
    try {
      checkName(name, 'parameter');
    } catch (error) {
      const ascii = /^[\x20-\x7e]*$/.test(name) ? '' : ' (a name is ASCII letters, digits and _: write omega, not ω)';
      throw new InputError(`the parameter name ${(error as Error).message.replace(/^"[^"]*" /, `"${name}" `)}${ascii}`);
    }
    if (name in values) throw new InputError(`the parameter ${name} is given twice`);
    if (stateNames.includes(name)) throw new InputError(`the parameter ${name} has the name of a component of the state`);
    const value = PLAIN_NUMBER.test(text) ? Number(text) : evaluateParameter(text, values, `the parameter ${name}`);
    if (!Number.isFinite(value)) throw new InputError(`the parameter ${name} must be a finite number, not ${text} = ${value}`);
    values[name] = value;
    if (!PLAIN_NUMBER.test(text)) expressions[name] = text.trim();
  }
  return { values, expressions };
}
