import { describe, expect, test, vi } from 'vitest';
import { createBuiltins, loadedDefinition, plainDefinition } from '../../../cells/builtins.ts';

describe('builtin definitions', () => {
  test('wrap a plain value, functions included, so the runtime does not call it', () => {
    const sin = Math.sin;
    expect(plainDefinition(sin)()).toBe(sin);
    expect(plainDefinition(3)()).toBe(3);
  });

  test('load a catalogue entry only when first defined, and only once', async () => {
    const load = vi.fn(async () => 'widget');
    const definition = loadedDefinition(load);
    expect(load).not.toHaveBeenCalled();
    await expect(definition()).resolves.toBe('widget');
    await expect(definition()).resolves.toBe('widget');
    expect(load).toHaveBeenCalledTimes(1);
  });

  test('a load that fails for a lost connection says so, and is tried again when next asked', async () => {
    const load = vi.fn(async () => {
      throw new TypeError('Failed to fetch dynamically imported module: https://book.test/_astro/table.js');
    });
    const definition = loadedDefinition(load, 'table');
    await expect(definition()).rejects.toThrow(/^The book's table could not be loaded: the connection to the book's site seems to be lost.*Reload the page when you are back online/);
    await expect(definition()).rejects.toThrow(/could not be loaded/);
    expect(load).toHaveBeenCalledTimes(2);
  });

  test('a catalogue entry wins over a standard builtin of the same name, and loads only when asked', async () => {
    const load = vi.fn(async () => 'the book’s html');
    const builtins = createBuiltins({} as Element, { html: load });
    expect(load).not.toHaveBeenCalled();
    await expect(builtins.html()).resolves.toBe('the book’s html');
    expect(typeof createBuiltins({} as Element, {}).html()).toBe('function');
  });
});
