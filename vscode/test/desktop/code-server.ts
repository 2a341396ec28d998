/**
 * The desktop VS Code the desktop test runs: code-server from the npm registry, a full VS Code
 * whose extensions run in a Node extension host, as in the desktop app. It is big (about 300 MB)
 * and slow to install (4 to 9 minutes here), so it is installed once into a cache folder
 * outside the tree, shared by every clone, and reused while its `installed` mark is there.
 *
 * As /work/shared/notes/vscode-testing.md found, it installs offline only with: npm run as root
 * allowed to run its install scripts (npm_config_unsafe_perm), npx allowed to fetch node-gyp
 * (npm_config_yes), Debian's libkrb5-dev (its `kerberos` module builds from source), and
 * Debian's ripgrep placed where @vscode/ripgrep looks for the download it cannot make.
 */
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { cp, mkdir, mkdtemp, rm, writeFile } from 'node:fs/promises';
import { homedir, tmpdir } from 'node:os';
import path from 'node:path';

/** The last code-server line that runs on Node 20, the book's Node. */
export const CODE_SERVER = 'code-server@4.100.3';
/** Where @vscode/ripgrep 1.15.11 (code-server 4.100's) looks for its download before fetching it. */
const RIPGREP_CACHE = path.join(tmpdir(), 'vscode-ripgrep-cache-1.15.11');
const RIPGREP_ARCHIVE = 'ripgrep-v13.0.0-10-x86_64-unknown-linux-musl.tar.gz';

export function codeServerDir(): string {
  const cache = process.env.XDG_CACHE_HOME ?? path.join(homedir(), '.cache');
  return process.env.PHASEBOOK_CODE_SERVER_DIR ?? path.join(cache, 'phasebook', CODE_SERVER.replace('@', '-'));
}

const has = (command: string) => {
  try {
    execFileSync('sh', ['-c', `command -v ${command}`], { stdio: 'ignore' });
    return true;
  } catch {
    return false;
  }
};

/** Debian's packages the install needs (krb5-config comes with libkrb5-dev), as `npm run setup:browser` installs Chromium. */
function installSystemPackages(): void {
  if (has('rg') && has('krb5-config')) return;
  const command = process.getuid?.() === 0 ? ['apt-get'] : ['sudo', 'apt-get'];
  const aptGet = (...args: string[]) => execFileSync(command[0], [...command.slice(1), ...args], { stdio: 'inherit' });
  aptGet('update', '-qq');
  aptGet('install', '-y', '-qq', 'ripgrep', 'libkrb5-dev');
}

/** Debian's rg, packed as the archive @vscode/ripgrep would have downloaded. */
async function plantRipgrep(): Promise<void> {
  if (existsSync(path.join(RIPGREP_CACHE, RIPGREP_ARCHIVE))) return;
  const staging = await mkdtemp(path.join(tmpdir(), 'phasebook-rg-'));
  try {
    const rg = execFileSync('sh', ['-c', 'command -v rg'], { encoding: 'utf8' }).trim();
    await cp(rg, path.join(staging, 'rg'));
    await mkdir(RIPGREP_CACHE, { recursive: true });
    execFileSync('tar', ['-czf', path.join(RIPGREP_CACHE, RIPGREP_ARCHIVE), '-C', staging, 'rg']);
  } finally {
    await rm(staging, { recursive: true, force: true });
  }
}

/** code-server's entry script, installed first if needed. */
export async function prepareCodeServer(log: (what: string) => void): Promise<string> {
  const dir = codeServerDir();
  const entry = path.join(dir, 'node_modules/code-server/out/node/entry.js');
  const mark = path.join(dir, 'installed');
  if (existsSync(mark) && existsSync(entry)) return entry;
  log(`installing ${CODE_SERVER} into ${dir} (once; several minutes)`);
  installSystemPackages();
  await plantRipgrep();
  // A half-finished install (an interrupted run) is started over, never used.
  await rm(dir, { recursive: true, force: true });
  await mkdir(dir, { recursive: true });
  await writeFile(path.join(dir, 'package.json'), '{ "private": true }\n');
  execFileSync('npm', ['install', '--no-audit', '--no-fund', '--no-save', CODE_SERVER], {
    cwd: dir,
    stdio: 'inherit',
    env: { ...process.env, npm_config_unsafe_perm: 'true', npm_config_yes: 'true' },
  });
  if (!existsSync(entry)) throw new Error(`npm installed ${CODE_SERVER} without ${entry}`);
  await writeFile(mark, `${CODE_SERVER}\n`);
  return entry;
}
