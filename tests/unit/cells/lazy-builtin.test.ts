import { describe, expect, test, vi } from 'vitest';
import { builtinDefinition, lazy } from '../../../widgets/cells/lazy-builtin.ts';

describe('builtinDefinition(value)', () => {
  test('wraps a plain value, functions included, so the runtime does not call it', () => {
    const sin = Math.sin;
    expect(builtinDefinition(sin)()).toBe(sin);
    expect(builtinDefinition(3)()).toBe(3);
  });

  test('loads a lazy(…) value only when first defined, and only once', async () => {
    const load = vi.fn(async () => 'widget');
    const definition = builtinDefinition(lazy(load));
    expect(load).not.toHaveBeenCalled();
    await expect(definition()).resolves.toBe('widget');
    await expect(definition()).resolves.toBe('widget');
    expect(load).toHaveBeenCalledTimes(1);
  });
});
