/**
 * The user's JavaScript runs in a sandbox, never in the CLI's own process
 * (issue 20): Node's permission model denies it the file system, processes,
 * threads and addons; it sees no environment, no `process`, no eval and no
 * import(); a sandbox that dies is said in one line naming the code; and
 * the sandbox changes nothing of what a run writes. Each case would fail if
 * the code ran in the CLI's process, as it used to: a marker file would be
 * written, a secret or exit status would come through.
 */
import { execFile } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeAll, beforeEach, describe, expect, it } from 'vitest';
import { ensureCli } from '../../../../bin/cli-bundle.mjs';
import { modelRecipe } from '../../../../cli/model/model.ts';
import { factsOfRecipe } from '../../../../cli/model/model-facts.ts';
import { hasStablePermissionFlag, sandboxFlags } from '../../../../cli/sandbox/sandbox-flags.ts';
import { checkReply, printable } from '../../../../cli/sandbox/sandbox-messages.ts';
import { userModelFromRecipe } from '../../../../cli/model/user-model.ts';
import { methodChoice, rowColumns } from '../../../../core/index.ts';
import { runCli, startCli, type CliExit } from '../../support/cli-harness.ts';


let scratch: string;
let marker: string;

beforeAll(async () => {
  await ensureCli();
});
beforeEach(() => {
  scratch = mkdtempSync(join(tmpdir(), 'phasebook-sandbox-'));
  marker = join(scratch, 'MARKER');
});
afterEach(() => rmSync(scratch, { recursive: true, force: true }));

type Exit = CliExit;

/** `phasebook …args` as a process, its cache and temporary files in the scratch folder, with `env` added. */
const phasebook = (args: string[], env: Record<string, string> = {}) => runCli(args, { PHASEBOOK_CACHE_DIR: join(scratch, 'cache'), TMPDIR: scratch, ...env });

const ONE_DOF = ['--dof', '1', '--initial', '1,0', '--t-end', '0.01'];
const oneLine = (exit: Exit) => expect(exit.stderr.trim().split('\n')).toHaveLength(1);
/** Nothing but the cache and the marker's absence: no output, no partial, no spill file. */
const leftovers = () => readdirSync(scratch).filter((name) => name !== 'cache');

describe('the permission model, as the sandbox starts Node', () => {
  it('denies file writes, reads outside the CLI, child processes, worker threads, and shows no environment', async () => {
    const code = join(scratch, 'code');
    mkdirSync(code);
    writeFileSync(
      join(code, 'probe.mjs'),
      `const tries = {
  write: async () => (await import('node:fs')).writeFileSync(${JSON.stringify(marker)}, 'x'),
  read: async () => (await import('node:fs')).readFileSync('/etc/passwd', 'utf8'),
  spawn: async () => (await import('node:child_process')).execFileSync('true'),
  worker: async () => new (await import('node:worker_threads')).Worker('1', { eval: true }),
  eval: async () => eval('1'),
};
const out = { env: Object.keys(process.env) };
for (const [name, attempt] of Object.entries(tries)) {
  try { await attempt(); out[name] = 'allowed'; } catch (error) { out[name] = error.code ?? error.name; }
}
process.stdout.write(JSON.stringify(out));`,
    );
    const seen = await new Promise<Record<string, unknown>>((resolve, reject) => {
      execFile(process.execPath, [...sandboxFlags([code]), join(code, 'probe.mjs')], { env: {}, cwd: '/' }, (error, stdout) =>
        error ? reject(error) : resolve(JSON.parse(stdout)),
      );
    });
    expect(seen).toEqual({ env: [], write: 'ERR_ACCESS_DENIED', read: 'ERR_ACCESS_DENIED', spawn: 'ERR_ACCESS_DENIED', worker: 'ERR_ACCESS_DENIED', eval: 'EvalError' });
    expect(existsSync(marker)).toBe(false);
  });

  it('names the flag by the version of Node, and never allows the network, writes, processes or threads', () => {
    expect(hasStablePermissionFlag('20.20.2')).toBe(false);
    expect(hasStablePermissionFlag('22.12.0')).toBe(false);
    expect(hasStablePermissionFlag('22.13.0')).toBe(true);
    expect(hasStablePermissionFlag('23.4.0')).toBe(false);
    expect(hasStablePermissionFlag('23.5.0')).toBe(true);
    expect(hasStablePermissionFlag('25.1.0')).toBe(true);
    for (const version of ['20.20.2', '22.13.0', '25.1.0']) {
      const flags = sandboxFlags(['/cli'], version);
      expect(flags.filter((f) => f.startsWith('--allow-'))).toEqual(['--allow-fs-read=/cli']);
    }
  });
});

describe('simulate runs the user’s JavaScript in the sandbox', () => {
  it.each([
    ['process.exit', '(t, x) => { process.exit(7); }'],
    ['process.getBuiltinModule', `(t, x) => { process.getBuiltinModule('fs').writeFileSync(${JSON.stringify('MARK')}, 'x'); return 1; }`],
    ['require', `(t, x) => { require('fs').writeFileSync(${JSON.stringify('MARK')}, 'x'); return 1; }`],
    ['eval', `(t, x) => { (0, eval)('process').getBuiltinModule('fs').writeFileSync(${JSON.stringify('MARK')}, 'x'); return 1; }`],
    ['the Function constructor', `(t, x) => { [].constructor.constructor('return process')().getBuiltinModule('fs').writeFileSync(${JSON.stringify('MARK')}, 'x'); return 1; }`],
  ])('contains an H that calls %s: one line, status 2 (not its own), no marker, no output', async (_, h) => {
    const out = join(scratch, 'out.csv');
    const exit = await phasebook(['simulate', '--hamiltonian', h.replaceAll('MARK', marker), ...ONE_DOF, '--output', out]);
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).toMatch(/^phasebook: H fails at t = 0: /);
    expect(existsSync(marker)).toBe(false);
    expect(leftovers()).toEqual([]);
  });

  it('hands the sandbox no environment: a secret in the CLI’s is not there', async () => {
    const h = `(t, x) => { throw new Error('seen: ' + JSON.stringify(globalThis.process?.env ?? (0, eval)('process.env'))); }`;
    const exit = await phasebook(['simulate', '--hamiltonian', h, ...ONE_DOF], { PHASEBOOK_SECRET: 'hunter2-secret' });
    expect(exit.code).toBe(2);
    oneLine(exit);
    // In the CLI's own process, as H used to run, the message would list the environment, the secret with it.
    expect(exit.stderr).toMatch(/^phasebook: H fails at t = 0: /);
    expect(exit.stderr).not.toContain('hunter2-secret');
  });

  it('says a sandbox that dies under the user’s code in one line naming the code, status 2, no partial left', async () => {
    // An exception thrown from a microtask reaches no caller: Node ends the process it is in.
    const h = '(t, x) => { queueMicrotask(() => { throw new Error("boom"); }); return x[1] ** 2 / 2 + x[0] ** 2 / 2; }';
    const out = join(scratch, 'out.csv');
    const exit = await phasebook(['simulate', '--hamiltonian', h, '--dof', '1', '--initial', '1,0', '--t-end', '1', '--output', out]);
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).toMatch(/^phasebook: H's code ended the sandboxed process it runs in \(exit status \d+\)\n$/);
    expect(leftovers()).toEqual([]);
  });

  it('prints the user code’s error as one line of printable text: no terminal escapes come through', async () => {
    const h = '(t, x) => { throw new Error("\\u001b]0;owned\\u0007\\u001b[2Jred\\nsecond line"); }';
    const exit = await phasebook(['simulate', '--hamiltonian', h, ...ONE_DOF]);
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).not.toMatch(/[\u0000-\u0009\u000b-\u001f]/);
    expect(exit.stderr).toMatch(/red second line/);
  });

  it('runs no source at compile time: an H that is a call making a function is refused unrun', async () => {
    const h = `(() => { process.getBuiltinModule('fs').writeFileSync(${JSON.stringify(marker)}, 'x'); return (t, x) => 1; })()`;
    const exit = await phasebook(['simulate', '--hamiltonian', h, ...ONE_DOF]);
    expect(exit.code).toBe(2);
    oneLine(exit);
    expect(exit.stderr).toMatch(/^phasebook: H must be one JS function, \(t, x\) => …, not a call/);
    expect(existsSync(marker)).toBe(false);
  });

  it.each([
    ['an opaque H', ['--hamiltonian', '(t, [q, p]) => { if (q > 10) return 0; return p * p / 2 + w * w * q * q / 2; }']],
    ['a vector field with an H', ['--vector-field', '(t, [q, p], dxdt) => { dxdt[0] = p; dxdt[1] = -w * w * q; }', '--hamiltonian', '(t, [q, p]) => p * p / 2 + w * w * q * q / 2']],
  ])('writes the same bytes for %s with 1, 2 or 3 sandboxes as workers', async (_, model) => {
    const args = ['simulate', ...model, '--param', 'w=2', '--dof', '1', '--sample', '7', '--seed', '3', '--box', 'q=-1:1,p=-1:1', '--t-end', '0.5', '--every', '50', '--derivatives'];
    const files = await Promise.all(
      [1, 2, 3].map(async (k) => {
        const out = join(scratch, `out-${k}.npz`);
        const exit = await phasebook([...args, '--workers', String(k), '--output', out]);
        expect(exit.stderr).toBe('');
        expect(exit.code).toBe(0);
        return readFileSync(out);
      }),
    );
    expect(files[1].equals(files[0])).toBe(true);
    expect(files[2].equals(files[0])).toBe(true);
  });

  it('stops a sandboxed run whose H never returns on SIGTERM: status 143, no partial, no sandbox left running', async () => {
    const out = join(scratch, 'out.csv');
    const { child, exited } = startCli(['simulate', '--hamiltonian', '(t, x) => { for (;;) {} }', ...ONE_DOF, '--output', out], { PHASEBOOK_CACHE_DIR: join(scratch, 'cache') });
    // The sandbox is up once it is a child of the CLI (Linux's /proc tells); the H then spins in its first evaluation.
    const sandboxes = () => childrenOf(child.pid!);
    await until(() => sandboxes().length > 0 || !existsSync('/proc'), 'the sandbox is running');
    const started = sandboxes();
    await new Promise((resolve) => setTimeout(resolve, 200));
    child.kill('SIGTERM');
    const exit = await exited;
    expect(exit.code).toBe(143);
    expect(exit.stderr).toMatch(/^phasebook: stopped by SIGTERM; \S+out\.csv was not written\n$/);
    expect(leftovers()).toEqual([]);
    for (const pid of started) expect(existsSync(`/proc/${pid}`)).toBe(false);
  });
});

describe('what the CLI knows of a sandboxed model', () => {
  it.each([
    ['an opaque H', { hamiltonian: '(t, [q, p]) => { if (q > 9) return 0; return p * p / 2 + k * q * q / 2; }' }, undefined],
    ['an opaque H run by the adaptive method', { hamiltonian: '(t, [q, p]) => { if (q > 9) return 0; return p * p / 2 + k * q * q / 2; }' }, 'adaptive'],
    ['a vector field run by the midpoint rule', { vectorField: '(t, x, dxdt) => { dxdt[0] = x[1]; dxdt[1] = -k * x[0]; }' }, 'midpoint'],
    ['a vector field with an H', { vectorField: '(t, x, dxdt) => { dxdt[0] = x[1]; dxdt[1] = -k * x[0]; }', hamiltonian: '(t, x) => x[1] ** 2 / 2' }, undefined],
  ])('reads off the recipe of %s what the model built from it says: the file’s meta and columns come from these', async (_, code, methodName) => {
    const method = methodName ? methodChoice(methodName) : undefined;
    const recipe = await modelRecipe({ ...code, dof: 1, params: { k: 3 }, method, cache: false });
    const facts = factsOfRecipe(recipe);
    // Built here, in the test, to compare: the CLI builds it only in the sandbox.
    const model = await userModelFromRecipe(recipe);
    expect(facts.names).toEqual(model.names);
    expect(facts.paramNames).toEqual(model.paramNames);
    expect(Array.from(facts.params)).toEqual(Array.from(model.params));
    expect(facts.route).toBe(model.route);
    expect(facts.method).toEqual(model.method);
    expect(facts.hasHamiltonian).toBe(model.hamiltonian !== undefined);
    if (recipe.kind === 'compiled') expect(facts.source).toBe(model.source);
    expect(rowColumns({ names: facts.names, hamiltonian: facts.hasHamiltonian || undefined }, true)).toEqual(rowColumns(model, true));
  });
});

describe('the sandbox’s replies, read as a stranger’s', () => {
  it('takes only replies of the protocol’s form, and errors as printable lines', () => {
    expect(checkReply({ kind: 'result', id: 1, data: new Float64Array(2), steps: 3 })).toMatchObject({ kind: 'result', id: 1, steps: 3 });
    expect(checkReply({ kind: 'result', id: 1, data: [1, 2], steps: 3 })).toBeUndefined();
    expect(checkReply({ kind: 'result', id: -1, data: new Float64Array(2), steps: 3 })).toBeUndefined();
    expect(checkReply({ kind: 'progress', steps: Infinity })).toBeUndefined();
    expect(checkReply({ kind: 'error', error: { kind: 'input' } })).toBeUndefined();
    expect(checkReply('done')).toBeUndefined();
    const error = checkReply({ kind: 'error', error: { kind: 'input', message: '\u001b[2Jcleared\r\nand more' } });
    // The escape character goes, and with it the sequence's power; what is left is plain text.
    expect(error?.kind === 'error' && error.error.message).toBe('[2Jcleared and more');
    expect(printable('x'.repeat(1000)).length).toBeLessThan(410);
    // Marks that reorder text on screen, as "Trojan source" uses them, go too.
    expect(printable('H fails\u202e txt.exe\u2066')).toBe('H fails  txt.exe');
  });
});

/** The processes whose parent is `pid`, from Linux's /proc; none elsewhere. */
function childrenOf(pid: number): number[] {
  if (!existsSync('/proc')) return [];
  return readdirSync('/proc')
    .filter((name) => /^\d+$/.test(name))
    .filter((name) => {
      try {
        // The fields after the command's name (which is in parentheses and may hold spaces): state, then the parent's pid.
        const stat = readFileSync(`/proc/${name}/stat`, 'utf8');
        return Number(stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1]) === pid;
      } catch {
        return false;
      }
    })
    .map(Number);
}

/** Resolves once `condition` holds, checking every 10 ms. */
async function until(condition: () => boolean, what: string, timeoutMs = 20_000): Promise<void> {
  const deadline = performance.now() + timeoutMs;
  while (!condition()) {
    if (performance.now() > deadline) throw new Error(`timed out waiting until ${what}`);
    await new Promise((resolve) => setTimeout(resolve, 10));
  }
}
