import { expect, test } from 'vitest';
import { seal, unseal } from '../../../../../widgets/chapter/exercise/seal.ts';

test('sealed parts round-trip, hide their text, and need the same id', async () => {
  const value = { solution: 'T = 2π/ω = 1.2566', mistakes: [{ value: 0.6283 }] };
  const sealed = await seal(value, 'period-at-omega-5');
  expect(await unseal(sealed, 'period-at-omega-5')).toEqual(value);
  expect(sealed).not.toContain('1.2566');
  expect(atob(sealed)).not.toContain('1.2566');
  await expect(unseal(sealed, 'another-id')).rejects.toThrow();
  await expect(unseal(sealed.slice(0, -8), 'period-at-omega-5')).rejects.toThrow();
});

test('a seal is compressed: a solution of repetitive typeset HTML seals to a small part of its size', async () => {
  // KaTeX's HTML for one formula, many times over, as a worked solution carries it.
  const formula = '<span class="katex"><span class="katex-html" aria-hidden="true"><span class="base"><span class="strut" style="height:0.6833em;"></span><span class="mord mathnormal">T</span></span></span></span>';
  const value = { solution: Array.from({ length: 200 }, (_, i) => `<p>Step ${i}: ${formula}</p>`).join('') };
  const plain = JSON.stringify(value).length;
  const sealed = await seal(value, 'long-solution');
  expect(sealed.length).toBeLessThan(plain / 10);
  expect(await unseal(sealed, 'long-solution')).toEqual(value);
});
