/**
 * truths.ts gathers the truths of every subject's module by name: two modules
 * giving one name would let the later silently replace the earlier, and an
 * exercise would be graded against another subject's truth. Each name is
 * given once, and each truth names its method.
 */
import { readdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { expect, test } from 'vitest';
import { TRUTHS } from '../../../../../widgets/chapter/exercise/truths.ts';

const FOLDER = resolve(__dirname, '../../../../../widgets/chapter/exercise/truths');

test('every subject module is gathered, and no truth name is given twice', async () => {
  const names: string[] = [];
  for (const file of readdirSync(FOLDER).filter((f) => f.endsWith('.ts'))) {
    const module = (await import(join(FOLDER, file))) as Record<string, unknown>;
    const [truths] = Object.entries(module).filter(([name]) => name.endsWith('_TRUTHS')).map(([, value]) => value as Record<string, unknown>);
    expect(truths, `${file} exports no …_TRUTHS`).toBeDefined();
    names.push(...Object.keys(truths));
  }
  expect(names.filter((name, i) => names.indexOf(name) !== i)).toEqual([]);
  expect(Object.keys(TRUTHS).sort()).toEqual([...names].sort());
});

test('each truth names its method, and computes a number from its arguments alone', () => {
  for (const [name, truth] of Object.entries(TRUTHS)) {
    expect(truth.method.length, name).toBeGreaterThan(20);
    // Its arguments are distinct names (a constant, such as Routh's μ, has none).
    expect(new Set(truth.args).size, name).toBe(truth.args.length);
  }
});
