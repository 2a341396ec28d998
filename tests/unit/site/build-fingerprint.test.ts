/**
 * npm start's decision (site/lib/build-fingerprint.mjs): a build is up to
 * date exactly when no byte of its sources, nor its base path, has changed
 * since it was recorded — whatever the files' modification times say.
 */
import { mkdtempSync, mkdirSync, rmSync, utimesSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { fingerprintFile, isUpToDate, sourceFingerprint } from '../../../site/lib/build-fingerprint.mjs';

let root: string;

/** Writes `text` to `path` under the temporary project. */
function put(path: string, text: string) {
  mkdirSync(join(root, path, '..'), { recursive: true });
  writeFileSync(join(root, path), text);
}

/** Records the current sources as the build's in dist/, as a finished build does. */
async function recordBuild() {
  put('dist/index.html', '<!doctype html>');
  writeFileSync(fingerprintFile(join(root, 'dist')), JSON.stringify({ fingerprint: await sourceFingerprint(root) }));
}

beforeEach(() => {
  root = mkdtempSync(join(tmpdir(), 'phasebook-fingerprint-'));
  put('content/pendulum.mdx', '# The pendulum\n');
  put('core/index.ts', 'export const g = 9.81;\n');
  put('site/pages/index.astro', '<h1>Phasebook</h1>\n');
  put('astro.config.mjs', 'export default {};\n');
  put('package-lock.json', '{}\n');
});

afterEach(() => rmSync(root, { recursive: true, force: true }));

describe('the build fingerprint', () => {
  it('is the same for the same bytes, whatever their modification times', async () => {
    const before = await sourceFingerprint(root);
    const later = new Date(Date.UTC(2030, 0, 1));
    utimesSync(join(root, 'content/pendulum.mdx'), later, later);
    put('core/index.ts', 'export const g = 9.81;\n');
    expect(await sourceFingerprint(root)).toBe(before);
  });

  it('changes with one byte of a chapter, of the code, of the config or of the lock file', async () => {
    const before = await sourceFingerprint(root);
    for (const [path, text] of [
      ['content/pendulum.mdx', '# The pendulum!\n'],
      ['core/index.ts', 'export const g = 9.80;\n'],
      ['astro.config.mjs', 'export default { };\n'],
      ['package-lock.json', '{ }\n'],
    ]) {
      const original = await sourceFingerprint(root);
      put(path, text);
      expect(await sourceFingerprint(root), path).not.toBe(original);
    }
    expect(await sourceFingerprint(root)).not.toBe(before);
  });

  it('changes when a chapter is added, removed or renamed', async () => {
    const before = await sourceFingerprint(root);
    put('content/kepler.mdx', '# Kepler\n');
    const added = await sourceFingerprint(root);
    expect(added).not.toBe(before);
    rmSync(join(root, 'content/kepler.mdx'));
    expect(await sourceFingerprint(root)).toBe(before);
    rmSync(join(root, 'content/pendulum.mdx'));
    put('content/swing.mdx', '# The pendulum\n');
    expect(await sourceFingerprint(root)).not.toBe(before);
  });

  it('ignores what the build does not read', async () => {
    const before = await sourceFingerprint(root);
    put('tests/unit/new.test.ts', 'it();\n');
    put('README.md', '# Phasebook\n');
    expect(await sourceFingerprint(root)).toBe(before);
  });

  it('changes with the base path', async () => {
    expect(await sourceFingerprint(root, { base: '/course/' })).not.toBe(await sourceFingerprint(root));
  });
});

describe('isUpToDate', () => {
  it('is false with no build, or a build with no record', async () => {
    expect(await isUpToDate(root, join(root, 'dist'))).toBe(false);
    put('dist/index.html', '<!doctype html>');
    expect(await isUpToDate(root, join(root, 'dist'))).toBe(false);
  });

  it('is true for the recorded sources, and false once a chapter changes', async () => {
    await recordBuild();
    expect(await isUpToDate(root, join(root, 'dist'))).toBe(true);
    put('content/pendulum.mdx', '# The pendulum, edited\n');
    expect(await isUpToDate(root, join(root, 'dist'))).toBe(false);
  });

  it('is false for a build made for another base path', async () => {
    await recordBuild();
    expect(await isUpToDate(root, join(root, 'dist'), { base: '/course/' })).toBe(false);
  });
});
