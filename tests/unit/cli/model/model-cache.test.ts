import { chmodSync, mkdtempSync, readdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { beforeEach, describe, expect, it } from 'vitest';
import { diskModelStore, modelCacheDirectory, modelCacheFile, writtenByUserAlone } from '../../../../cli/model/model-cache.ts';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { modelKey } from '../../../../core/model/compiled-model.ts';

const home = () => '/home/reader';

describe('modelCacheDirectory(env, home)', () => {
  it('takes $PHASEBOOK_CACHE_DIR, else $XDG_CACHE_HOME/phasebook/models, else ~/.cache/phasebook/models', () => {
    expect(modelCacheDirectory({ PHASEBOOK_CACHE_DIR: '/c', XDG_CACHE_HOME: '/x' }, home)).toBe('/c');
    expect(modelCacheDirectory({ XDG_CACHE_HOME: '/x' }, home)).toBe('/x/phasebook/models');
    expect(modelCacheDirectory({}, home)).toBe('/home/reader/.cache/phasebook/models');
  });

  it('ignores a relative $XDG_CACHE_HOME, as the XDG base directory spec asks', () => {
    expect(modelCacheDirectory({ XDG_CACHE_HOME: 'cache' }, home)).toBe('/home/reader/.cache/phasebook/models');
  });
});

describe('diskModelStore(directory)', () => {
  let directory: string;
  beforeEach(() => {
    directory = join(mkdtempSync(join(tmpdir(), 'phasebook-store-')), 'models');
  });
  const spec = { dof: 1, hamiltonian: 'p^2/2 + k*q^2/2', params: { k: 4 } };

  it('keeps what canonicalEquations compiles, one file per model, and gives it back by key', async () => {
    const store = diskModelStore(directory);
    const model = await canonicalEquations(spec, { store });
    const key = modelKey(spec);
    expect(readdirSync(directory)).toEqual([modelCacheFile(directory, key).slice(directory.length + 1)]);
    const kept = await store.get(key);
    expect(kept?.key).toBe(key);
    // Built from the file alone, the model has the physics of H: q̇ = p, ṗ = −kq.
    const again = await canonicalEquations(spec, { store: { get: () => kept } });
    const rate = new Float64Array(2);
    again.field(0, Float64Array.of(0.5, 2), rate);
    expect(Array.from(rate)).toEqual([2, -2]);
    expect(again.route).toBe(model.route);
  });

  it('answers nothing for a missing or damaged file, and never throws', async () => {
    const store = diskModelStore(directory);
    expect(store.get('no such key')).toBeUndefined();
    await canonicalEquations(spec, { store });
    const file = modelCacheFile(directory, modelKey(spec));
    const text = readFileSync(file, 'utf8');
    writeFileSync(file, text.replace('"k"', '"K"'));
    expect(store.get(modelKey(spec))).toBeUndefined();
  });

  it('reads no file that another user wrote or could write: its code would run with the reader’s rights', async () => {
    const store = diskModelStore(directory);
    await canonicalEquations(spec, { store });
    const file = modelCacheFile(directory, modelKey(spec));
    expect(statSync(file).mode & 0o777).toBe(0o644);
    expect(store.get(modelKey(spec))).toBeDefined();
    for (const mode of [0o664, 0o646]) {
      chmodSync(file, mode);
      expect(store.get(modelKey(spec))).toBeUndefined();
    }
    chmodSync(file, 0o644);
    expect(store.get(modelKey(spec))).toBeDefined();
    expect(writtenByUserAlone({ uid: 1000, mode: 0o100644 }, 1000)).toBe(true);
    expect(writtenByUserAlone({ uid: 1001, mode: 0o100644 }, 1000)).toBe(false);
  });

  it('drops a write it cannot make', async () => {
    const blocker = join(directory, '..', 'blocker');
    writeFileSync(blocker, '');
    const store = diskModelStore(join(blocker, 'models'));
    const model = await canonicalEquations(spec, { store });
    expect(model.route).toBe('expression');
    expect(store.get(modelKey(spec))).toBeUndefined();
  });
});
