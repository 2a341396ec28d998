/**
 * Compiling H runs none of its code: what the source is, a function or not,
 * is decided from its parsed tree. A marker on globalThis shows whether any
 * of the source ran; each case would set it if it did.
 */
import { afterEach, describe, expect, it } from 'vitest';
import { compileModel } from '../../../../core/model/compile-model.ts';

const MARK = '__phasebookCompileRan';
const marker = () => (globalThis as Record<string, unknown>)[MARK];
afterEach(() => {
  delete (globalThis as Record<string, unknown>)[MARK];
});

describe('compileModel(spec)', () => {
  it.each([
    ['a call that returns a function', `(() => { globalThis.${MARK} = 1; return (t, x) => 1; })()`, /not a call that may make one/],
    ['a source that closes its parentheses and runs a statement', `1), (globalThis.${MARK} = 1), ((t, x) => 1`, /not a list of expressions/],
    ['statements after a function', `(t, x) => 1);globalThis.${MARK} = 1;(0`, /not statements/],
  ])('refuses %s without running it', async (_, hamiltonian, message) => {
    await expect(compileModel({ dof: 1, hamiltonian })).rejects.toThrow(message);
    expect(marker()).toBeUndefined();
  });

  it('leaves an untranslatable function opaque without calling it, or running its parameters’ defaults', async () => {
    const hamiltonian = `(t, x = (globalThis.${MARK} = 1)) => { globalThis.${MARK} = 2; return x[0] ** 2; }`;
    const compiled = await compileModel({ dof: 1, hamiltonian });
    expect(compiled.route).toBe('js-stencil');
    expect(compiled.code).toBeUndefined();
    expect(marker()).toBeUndefined();
  });

  it('says that an H too deep for the compiler is too deep, in one sentence, instead of a RangeError', async () => {
    // 20 000 terms: a sum mathjs parses into a tree that deep, well past the stack.
    const hamiltonian = Array.from({ length: 20_000 }, () => 'q^2').join('+');
    await expect(compileModel({ dof: 1, hamiltonian })).rejects.toThrow(/^H is too deeply nested for the compiler \(79999 characters\)/);
    const nested = `(t, x) => ${'('.repeat(50_000)}x[0]${')'.repeat(50_000)}`;
    await expect(compileModel({ dof: 1, hamiltonian: nested })).rejects.toThrow(/^H nests too deeply for the parser/);
  });
});
