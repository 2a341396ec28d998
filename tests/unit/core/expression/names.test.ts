/**
 * The names a model cannot use (core/expression/names.ts): each is refused
 * with what it already means and a name to use instead, and the list the
 * teachers' page shows is that same list.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { canonicalEquations, checkName, RESERVED_NAMES } from '../../../../core/index.ts';
import { reservedNameRows } from '../../../../site/lib/reserved-names.ts';

describe('reserved names', () => {
  it("refuses E as a parameter with what E means: Euler's number", async () => {
    await expect(canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 - E*q', params: { E: 1 } })).rejects.toThrow(
      "E is Euler's number, 2.71828…; name the parameter something else, e.g. E0",
    );
  });

  it('refuses every reserved name, saying what it means, and accepts the name it suggests', () => {
    for (const { name, meaning } of RESERVED_NAMES) {
      expect(() => checkName(name, 'parameter')).toThrow(`${name} is ${meaning}; name the parameter something else, e.g. ${name}0`);
      expect(() => checkName(`${name}0`, 'parameter')).not.toThrow();
    }
  });

  it('gives each constant the value it stands for', () => {
    // The meanings quote the first digits of the true values.
    const digits = (meaning: string) => Number(/(\d+\.\d+)…/.exec(meaning)?.[1]);
    const meaningOf = (name: string) => RESERVED_NAMES.find((r) => r.name === name)?.meaning ?? '';
    for (const [name, value] of [['pi', Math.PI], ['PI', Math.PI], ['e', Math.E], ['E', Math.E], ['tau', 2 * Math.PI]] as const) {
      expect(Math.abs(digits(meaningOf(name)) - value)).toBeLessThan(1e-5);
    }
  });

  it("reserves every word JavaScript itself refuses as a parameter's name", () => {
    const candidates = ['if', 'while', 'class', 'const', 'let', 'yield', 'await', 'enum', 'static', 'eval', 'arguments', 'interface', 'package', 'delete', 'typeof'];
    for (const word of candidates) {
      let refused = false;
      try {
        new Function(`"use strict"; return function (${word}) {}`)();
      } catch {
        refused = true;
      }
      if (refused) expect(RESERVED_NAMES.map((r) => r.name)).toContain(word);
    }
  });

  it("the teachers' page's table holds exactly the core's list, and the page shows that table", () => {
    expect(reservedNameRows().flatMap((row) => row.names)).toEqual(RESERVED_NAMES.map((r) => r.name));
    const page = readFileSync(new URL('../../../../content/for-teachers.mdx', import.meta.url), 'utf8');
    expect(page).toMatch(/^import ReservedNames from '..\/site\/components\/ReservedNames.astro';$/m);
    expect(page).toMatch(/^<ReservedNames \/>$/m);
  });
});
