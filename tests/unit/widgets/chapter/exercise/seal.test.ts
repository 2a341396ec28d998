import { expect, test } from 'vitest';
import { seal, unseal } from '../../../../../widgets/chapter/exercise/seal.ts';

test('sealed parts round-trip, hide their text, and need the same id', () => {
  const value = { solution: 'T = 2π/ω = 1.2566', mistakes: [{ value: 0.6283 }] };
  const sealed = seal(value, 'period-at-omega-5');
  expect(unseal(sealed, 'period-at-omega-5')).toEqual(value);
  expect(sealed).not.toContain('1.2566');
  expect(atob(sealed)).not.toContain('1.2566');
  expect(() => unseal(sealed, 'another-id')).toThrow();
});
