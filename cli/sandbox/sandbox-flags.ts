/**
 * The options Node starts the sandbox with (sandbox-process.ts): its
 * permission model, which is the boundary, and V8's ban on making code from
 * strings, which is defence in depth.
 *
 * The permission model denies what it is not told to allow. The sandbox is
 * allowed to read the files of the compiled CLI it loads, and nothing else:
 * no file write, no child process, no worker thread, no native addon, no
 * WASI, no inspector, and from Node 25 on, when the model covers it, no
 * network (`--allow-net` is never given). The flag that turns it on was
 * `--experimental-permission` until it became stable as `--permission`
 * (Node 23.5, and 22.13 on the 22 line).
 */

/** Whether `version` (process.versions.node, e.g. "22.13.1") names the stable `--permission` flag. */
export function hasStablePermissionFlag(version: string): boolean {
  const [major, minor] = version.split('.').map(Number);
  if (major === 22) return minor >= 13;
  if (major === 23) return minor >= 5;
  return major > 23;
}

/**
 * Node's options for a sandbox that may read the folders or files in
 * `readable` (the compiled CLI) and nothing more.
 */
export function sandboxFlags(readable: readonly string[], version: string = process.versions.node): string[] {
  return [
    hasStablePermissionFlag(version) ? '--permission' : '--experimental-permission',
    ...readable.map((path) => `--allow-fs-read=${path}`),
    // eval, new Function and string timers fail in the sandbox: the user's code is compiled by the sandbox through
    // node:vm, which this does not stop, and then cannot make more code, whose dynamic import() could load Node's modules.
    '--disallow-code-generation-from-strings',
    // Native addons refused by Node's own switch too, whichever permissions a version of Node checks.
    '--no-addons',
    // The permission model's "experimental" warning is not the user's business, and would reach them as the sandbox's stderr.
    '--no-warnings',
  ];
}
