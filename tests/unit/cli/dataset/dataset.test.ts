/**
 * `phasebook simulate` over many initial conditions, every input mode and
 * format, checked against the harmonic oscillator's closed form
 * (q = q0 cos t + p0 sin t, p = p0 cos t − q0 sin t; RK 3/8 at dt = 5e-4
 * errs by ~1e-14 over a few time units) and read back by readers that are
 * not phasebook's (support/dataset-readers.ts).
 */
import { execFile, spawnSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { ROOT } from '../../../../bin/cli-bundle.mjs';
import { main } from '../../../../cli/main.ts';
import { parseCSV } from '../../../../core/tables/csv-read.ts';
import { parseJSON, toJSON } from '../../../../core/index.ts';
import { npzJs, numpyLoad, parquetJs, pyarrowRead, runsWithPython, type LoadedArrays, type LoadedTable } from '../../support/dataset-readers.ts';
import { captureWrites, useScratchCache } from '../../support/cli-harness.ts';

const BIN = join(ROOT, 'bin/phasebook.mjs');
const OSCILLATOR = ['--hamiltonian', 'p^2/2 + q^2/2', '--dof', '1'];
// Where python3 has them, and always under CI, which installs them (.ci/run): there, without them, these tests fail.
const HAS_NUMPY = runsWithPython('numpy');
const HAS_PYARROW = runsWithPython('pyarrow');
const TOLERANCE = 1e-12;

let dir: string;
let stderr: string[];
let stdout: string[];
useScratchCache();
beforeEach(() => {
  dir = mkdtempSync(join(tmpdir(), 'phasebook-dataset-'));
  stderr = captureWrites(process.stderr);
  stdout = captureWrites(process.stdout);
});
afterEach(() => vi.restoreAllMocks());

/** The closed form at t from (q0, p0). */
const exact = (q0: number, p0: number, t: number) => [q0 * Math.cos(t) + p0 * Math.sin(t), p0 * Math.cos(t) - q0 * Math.sin(t)];

/** Runs the command in this process; returns its status. */
const simulate = (...args: string[]) => main(['simulate', ...args, '--workers', '1']);

/** Runs the compiled CLI as a process. */
function spawn(args: string[]): Promise<{ code: number; stdout: string; stderr: string }> {
  return new Promise((resolve) => {
    execFile('node', [BIN, ...args], { maxBuffer: 1 << 28 }, (error, out, err) => {
      resolve({ code: error ? Number((error as { code?: unknown }).code ?? 1) : 0, stdout: out, stderr: err });
    });
  });
}

/** Checks rows `trajectory, t, q, p, …` of a long table against the closed form from each trajectory's first row. */
function checkLong(rows: number[][], trajectories: number, samples: number): void {
  expect(rows).toHaveLength(trajectories * samples);
  for (let j = 0; j < trajectories; j++) {
    const first = rows[j * samples];
    expect(first[0]).toBe(j);
    for (let r = 0; r < samples; r++) {
      const [id, t, q, p] = rows[j * samples + r];
      expect(id).toBe(j);
      const [qe, pe] = exact(first[2], first[3], t);
      expect(Math.abs(q - qe)).toBeLessThan(TOLERANCE);
      expect(Math.abs(p - pe)).toBeLessThan(TOLERANCE);
    }
  }
}

function rowsOf(table: { columns: readonly string[]; rows: number; data: Float64Array }): number[][] {
  const w = table.columns.length;
  return Array.from({ length: table.rows }, (_, r) => Array.from(table.data.subarray(r * w, (r + 1) * w)));
}

/** The rows of a long Parquet table read by another reader. */
function longRows(table: LoadedTable): number[][] {
  const n = table.data[table.columns[0]].length;
  return Array.from({ length: n }, (_, r) => table.columns.map((c) => table.data[c][r]));
}

/** NPZ arrays checked against the closed form; returns x's initial states. */
function checkNpz(loaded: LoadedArrays, trajectories: number, samples: number, derivatives: boolean): void {
  const { t, x, H, dxdt } = loaded.arrays;
  expect(t.shape).toEqual([samples]);
  expect(x.shape).toEqual([trajectories, samples, 2]);
  expect(H.shape).toEqual([trajectories, samples]);
  expect(loaded.meta).toMatchObject({ count: trajectories, samples, names: ['q', 'p'] });
  if (derivatives) expect(dxdt.shape).toEqual([trajectories, samples, 2]);
  else expect(dxdt).toBeUndefined();
  for (let j = 0; j < trajectories; j++) {
    const at = (r: number) => 2 * (j * samples + r);
    const [q0, p0] = [x.values[at(0)], x.values[at(0) + 1]];
    for (let r = 0; r < samples; r++) {
      const [qe, pe] = exact(q0, p0, t.values[r]);
      expect(Math.abs(x.values[at(r)] - qe)).toBeLessThan(TOLERANCE);
      expect(Math.abs(x.values[at(r) + 1] - pe)).toBeLessThan(TOLERANCE);
      expect(Math.abs(H.values[j * samples + r] - (q0 * q0 + p0 * p0) / 2)).toBeLessThan(TOLERANCE);
      // ẋ = (p, −q), exactly as the canonical equations give it.
      if (derivatives) {
        expect(dxdt.values[at(r)]).toBe(x.values[at(r) + 1]);
        expect(dxdt.values[at(r) + 1]).toBe(-x.values[at(r)]);
      }
    }
  }
}

describe('initial states of many trajectories', () => {
  it('reads --initial-file as CSV with its columns in any order, and writes a long CSV numbered by trajectory', async () => {
    const file = join(dir, 'initial.csv');
    writeFileSync(file, 'p,q\n0,1\n0.5,-2\n-1,0.25\n');
    const out = join(dir, 'out.csv');
    expect(await simulate(...OSCILLATOR, '--initial-file', file, '--t-end', '3', '--every', '1000', '--output', out)).toBe(0);
    const table = parseCSV(readFileSync(out, 'utf8'));
    expect(table.columns).toEqual(['trajectory', 't', 'q', 'p', 'H']);
    const rows = rowsOf(table);
    checkLong(rows, 3, 7);
    expect([0, 7, 14].map((r) => rows[r].slice(2, 4))).toEqual([[1, 0], [-2, 0.5], [0.25, -1]]);
  });

  it('reads --initial-file as NPY (float64, C order) and as JSON rows by name', async () => {
    const states = [[1, 0], [0, 1], [-0.5, 0.5]];
    // An NPY v1.0 file written by hand after numpy's format.py: magic, version, header length, dict, data.
    const dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2), }";
    const header = dict + ' '.repeat(64 - ((10 + dict.length + 1) % 64)) + '\n';
    const npy = Buffer.alloc(10 + header.length + 48);
    Buffer.from([0x93, 0x4e, 0x55, 0x4d, 0x50, 0x59, 1, 0]).copy(npy);
    npy.writeUInt16LE(header.length, 8);
    npy.write(header, 10, 'latin1');
    states.flat().forEach((v, i) => npy.writeDoubleLE(v, 10 + header.length + 8 * i));
    writeFileSync(join(dir, 'initial.npy'), npy);
    writeFileSync(join(dir, 'initial.json'), JSON.stringify(states.map(([q, p]) => ({ q, p }))));
    for (const name of ['initial.npy', 'initial.json']) {
      const out = join(dir, `${name}.json`);
      expect(await simulate(...OSCILLATOR, '--initial-file', join(dir, name), '--t-end', '1', '--every', '500', '--format', 'json', '--output', out)).toBe(0);
      const { meta, table } = parseJSON(readFileSync(out, 'utf8'));
      expect(meta).toMatchObject({ initial: states.flat(), initialSet: { kind: 'given', file: name }, count: 3, trajectories: 3 });
      const rows = rowsOf(table);
      checkLong(rows, 3, 5);
      expect(rows.filter((row) => row[1] === 0).map((row) => row.slice(2, 4))).toEqual(states);
    }
  });

  it.skipIf(!HAS_NUMPY)('reads an initial NPY that numpy.save wrote, and a CSV that numpy.savetxt wrote (needs python3 with numpy)', async () => {
    // An independent writer: numpy's own format.py, float64 in C order, and savetxt's header line.
    const py = spawnSync('python3', ['-c', `import numpy as np, sys
x = np.array([[1.0, 0.0], [0.1, -0.3], [-2.0, 0.75], [0.0, 1e-3]])
np.save(sys.argv[1], x)
np.savetxt(sys.argv[2], x, delimiter=',', header='q,p', comments='', fmt='%.17g')`, join(dir, 'initial.npy'), join(dir, 'initial.csv')], { encoding: 'utf8' });
    expect(py.stderr).toBe('');
    for (const name of ['initial.npy', 'initial.csv']) {
      const out = join(dir, `${name}.json`);
      expect(await simulate(...OSCILLATOR, '--initial-file', join(dir, name), '--t-end', '2', '--every', '500', '--format', 'json', '--output', out)).toBe(0);
      const { meta, table } = parseJSON(readFileSync(out, 'utf8'));
      expect(meta).toMatchObject({ initial: [1, 0, 0.1, -0.3, -2, 0.75, 0, 1e-3], count: 4 });
      checkLong(rowsOf(table), 4, 9);
    }
  });

  it('samples a box from a seed: the same set for the same seed, another for another', async () => {
    const run = async (seed: string) => {
      const out = join(dir, `s${seed}.csv`);
      expect(await simulate(...OSCILLATOR, '--sample', '50', '--seed', seed, '--box', 'q=-1:1,p=2', '--t-end', '0.5', '--every', '500', '--output', out)).toBe(0);
      return rowsOf(parseCSV(readFileSync(out, 'utf8')));
    };
    const a = await run('11');
    checkLong(a, 50, 3);
    const starts = a.filter((row) => row[1] === 0);
    expect(starts.every(([, , q, p]) => q >= -1 && q < 1 && p === 2)).toBe(true);
    expect(await run('11')).toEqual(a);
    expect((await run('12')).filter((row) => row[1] === 0)).not.toEqual(starts);
  });

  it('projects onto an energy surface by solving for p, named in the meta: H = E at every start (E = q²/2 + p²/2)', async () => {
    const out = join(dir, 'energy.json');
    expect(await simulate(...OSCILLATOR, '--sample', '40', '--seed', '2', '--box', 'q=-1:1,p=-2:2', '--energy', '0.5', '--t-end', '1', '--every', '1000', '--format', 'json', '--output', out)).toBe(0);
    const { meta, table } = parseJSON(readFileSync(out, 'utf8'));
    expect(meta.initialSet).toEqual({ kind: 'sample', count: 40, seed: 2, box: { q: [-1, 1], p: [-2, 2] }, energy: { value: 0.5, solveFor: 'p' } });
    for (const [, t, q, p] of rowsOf(table)) if (t === 0) expect(Math.abs(Math.abs(p) - Math.sqrt(1 - q * q))).toBeLessThan(1e-15);
  });

  it('lays a grid in C order', async () => {
    const out = join(dir, 'grid.csv');
    expect(await simulate(...OSCILLATOR, '--grid', 'q=-1:1:3,p=0:1:2', '--t-end', '0', '--output', out)).toBe(0);
    const rows = rowsOf(parseCSV(readFileSync(out, 'utf8')));
    expect(rows.map((r) => r.slice(2, 4))).toEqual([[-1, 0], [-1, 1], [0, 0], [0, 1], [1, 0], [1, 1]]);
  });
});

describe('formats researchers load', () => {
  const SET = ['--sample', '5', '--seed', '4', '--box', 'q=-1:1,p=-1:1', '--t-end', '2', '--every', '400'];

  it.each([true, false])('writes NPZ that fflate + npyjs read (derivatives %s)', async (derivatives) => {
    const out = join(dir, 'set.npz');
    expect(await simulate(...OSCILLATOR, ...SET, ...(derivatives ? ['--derivatives'] : []), '--output', out)).toBe(0);
    checkNpz(npzJs(out), 5, 11, derivatives);
    expect(readdirSync(dir)).toEqual(['set.npz']);
  });

  it.skipIf(!HAS_NUMPY)('writes NPZ that numpy.load opens, allow_pickle=False (needs python3 with numpy)', async () => {
    const out = join(dir, 'set.npz');
    expect(await simulate(...OSCILLATOR, ...SET, '--derivatives', '--output', out)).toBe(0);
    const loaded = numpyLoad(out);
    checkNpz(loaded, 5, 11, true);
    expect(loaded).toEqual(npzJs(out));
  });

  it('writes ZIP64 fields that numpy and fflate still read', async () => {
    const { NpzDatasetWriter } = await import('../../../../cli/formats/npz-dataset.ts');
    const chunks: Uint8Array[] = [];
    const sink = { write: (d: string | Uint8Array) => chunks.push(typeof d === 'string' ? Buffer.from(d) : d), commit: () => {}, abandon: () => {} };
    const shape = { columns: ['t', 'q', 'p'], names: ['q', 'p'], count: 1, first: 0, total: 1, samples: 2 };
    const writer = new NpzDatasetWriter(sink, shape, { count: 1 } as never, Float64Array.of(0, 1), join(dir, 'z.npz'), { forceZip64: true });
    writer.write({ first: 0, count: 1, rowFrom: 0, rowTo: 2, data: Float64Array.of(0, 1, 2, 1, 3, 4) });
    writer.finish();
    writeFileSync(join(dir, 'z.npz'), Buffer.concat(chunks));
    const js = npzJs(join(dir, 'z.npz'));
    expect(js.arrays.x.values).toEqual([1, 2, 3, 4]);
    if (HAS_NUMPY) expect(numpyLoad(join(dir, 'z.npz')).arrays.x.values).toEqual([1, 2, 3, 4]);
  });

  it.each(['long', 'wide'])('writes %s Parquet that parquet-wasm reads, with the meta in the key-value metadata', async (layout) => {
    const out = join(dir, 'set.parquet');
    expect(await simulate(...OSCILLATOR, ...SET, '--derivatives', '--layout', layout, '--output', out)).toBe(0);
    const table = parquetJs(out);
    const meta = JSON.parse(table.metadata.phasebook);
    expect(meta).toMatchObject({ count: 5, samples: 11, layout, derivatives: true });
    if (layout === 'long') {
      expect(table.columns).toEqual(['trajectory', 't', 'q', 'p', 'H', 'dq/dt', 'dp/dt']);
      checkLong(longRows(table), 5, 11);
    } else {
      expect(table.columns.slice(0, 7)).toEqual(['t', 'q[0]', 'p[0]', 'H[0]', 'dq/dt[0]', 'dp/dt[0]', 'q[1]']);
      const t = table.data.t;
      for (let j = 0; j < 5; j++) {
        const q = table.data[`q[${j}]`];
        const p = table.data[`p[${j}]`];
        t.forEach((time, r) => expect(Math.abs(q[r] - exact(q[0], p[0], time)[0])).toBeLessThan(TOLERANCE));
      }
    }
  });

  it.skipIf(!HAS_PYARROW)('writes Parquet that pyarrow reads as parquet-wasm does (needs python3 with pyarrow)', async () => {
    const out = join(dir, 'set.parquet');
    expect(await simulate(...OSCILLATOR, ...SET, '--output', out)).toBe(0);
    const py = pyarrowRead(out);
    const js = parquetJs(out);
    expect(py.columns).toEqual(js.columns);
    expect(py.data).toEqual(js.data);
    expect(JSON.parse(py.metadata.phasebook)).toEqual(JSON.parse(js.metadata.phasebook));
  });

  it.skipIf(!HAS_PYARROW)('writes wide Parquet that pyarrow reads, every trajectory on the closed form (needs python3 with pyarrow)', async () => {
    const out = join(dir, 'wide.parquet');
    expect(await simulate(...OSCILLATOR, ...SET, '--derivatives', '--layout', 'wide', '--output', out)).toBe(0);
    const table = pyarrowRead(out);
    expect(table.columns).toHaveLength(1 + 5 * 5);
    expect(JSON.parse(table.metadata.phasebook)).toMatchObject({ layout: 'wide', count: 5, samples: 11, derivatives: true });
    const t = table.data.t;
    expect(t).toHaveLength(11);
    for (let j = 0; j < 5; j++) {
      const [q, p, H, dq, dp] = ['q', 'p', 'H', 'dq/dt', 'dp/dt'].map((c) => table.data[`${c}[${j}]`]);
      t.forEach((time, r) => {
        const [qe, pe] = exact(q[0], p[0], time);
        expect(Math.abs(q[r] - qe)).toBeLessThan(TOLERANCE);
        expect(Math.abs(p[r] - pe)).toBeLessThan(TOLERANCE);
        expect(Math.abs(H[r] - (q[0] ** 2 + p[0] ** 2) / 2)).toBeLessThan(TOLERANCE);
        expect([dq[r], dp[r]]).toEqual([p[r], -q[r]]);
      });
    }
  });

  it('writes a long JSON table numbered by trajectory when there are many, each on the closed form', async () => {
    const out = join(dir, 'set.json');
    expect(await simulate(...OSCILLATOR, ...SET, '--output', out)).toBe(0);
    const { meta, table } = parseJSON(readFileSync(out, 'utf8'));
    expect(table.columns).toEqual(['trajectory', 't', 'q', 'p', 'H']);
    expect(meta).toMatchObject({ format: 'json', count: 5, trajectories: 5, samples: 11, tEnd: 2 });
    checkLong(rowsOf(table), 5, 11);
  });

  it('keeps the single-trajectory CSV as it was: t, q, p, H and no trajectory column', async () => {
    const out = join(dir, 'one.csv');
    expect(await simulate(...OSCILLATOR, '--initial', '1,0', '--t-end', '1', '--every', '1000', '--derivatives', '--output', out)).toBe(0);
    const table = parseCSV(readFileSync(out, 'utf8'));
    expect(table.columns).toEqual(['t', 'q', 'p', 'H', 'dq/dt', 'dp/dt']);
    expect(table.rows).toBe(3);
  });
});

describe("the README's dataset", () => {
  it.skipIf(!HAS_NUMPY)('is made by its one command and loaded by its three lines of Python, ẋ = (p, −sin q) at every sample (needs python3 with numpy)', async () => {
    const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');
    const section = readme.slice(readme.indexOf('## Datasets of many trajectories'));
    const [command, load] = [/```sh\n([\s\S]*?)```/, /```python\n([\s\S]*?)```/].map((re) => re.exec(section)![1]);
    expect(load.trim().split('\n')).toHaveLength(3);
    // The command as a shell runs it, with the CLI of this tree for `npx phasebook`.
    const shell = spawnSync('sh', ['-c', command.replace(/^npx phasebook /, `node ${JSON.stringify(BIN)} `)], { cwd: dir, encoding: 'utf8' });
    expect(shell.stderr).toBe('');
    expect(shell.status).toBe(0);
    const py = spawnSync('python3', ['-c', `${load}
import sys
p, q = x[..., 1], x[..., 0]
# Hamilton's equations of H = p^2/2 - cos q: q' = p, p' = -sin q (numpy's sin; phasebook's may differ in the last bit).
print(json.dumps({'t': t.shape, 'x': x.shape, 'dxdt': dxdt.shape, 'H': f['H'].shape, 'count': meta['count'],
  'dq': float(np.max(np.abs(dxdt[..., 0] - p))), 'dp': float(np.max(np.abs(dxdt[..., 1] + np.sin(q)))),
  'energy': float(np.max(np.abs(f['H'] - f['H'][:, :1]))), 'dt': float(np.max(np.abs(np.diff(t) - 0.1)))}))`], { cwd: dir, encoding: 'utf8' });
    expect(py.stderr).toBe('');
    const got = JSON.parse(py.stdout);
    expect(got).toMatchObject({ t: [101], x: [1000, 101, 2], dxdt: [1000, 101, 2], H: [1000, 101], count: 1000 });
    expect(got.dq).toBe(0);
    expect(got.dp).toBeLessThan(1e-15);
    // RK 3/8 at dt = 5e-4 keeps H to ~1e-12 over 10 time units on these orbits (its error is O(dt⁴)).
    expect(got.energy).toBeLessThan(1e-10);
    expect(got.dt).toBeLessThan(1e-14);
  });
});

describe('workers and shards', () => {
  const SET = [...OSCILLATOR, '--sample', '37', '--seed', '9', '--box', 'q=-1:1,p=-1:1', '--t-end', '40', '--every', '197', '--derivatives'];

  it.each(['csv', 'json', 'npz', 'parquet'])('writes the same %s bytes with 1, 2 or 3 worker threads', async (format) => {
    const files = await Promise.all(
      [1, 2, 3].map(async (k) => {
        const out = join(dir, `w${k}.${format}`);
        // --workers K is obeyed whatever the size of the run.
        const run = await spawn(['simulate', ...SET, '--workers', String(k), '--output', out]);
        expect(run.stderr).toBe('');
        return readFileSync(out);
      }),
    );
    expect(files[1].equals(files[0])).toBe(true);
    expect(files[2].equals(files[0])).toBe(true);
  });

  it('hands each task to worker threads, which give the numbers this thread gives', async () => {
    // The worker code path itself, in this process (tsx compiles the worker's TypeScript), against the local executor.
    const { prepareRun } = await import('../../../../cli/dataset/prepare.ts');
    const { modelFromRecipe, modelRecipe } = await import('../../../../cli/model/model.ts');
    const { parseSimulate } = await import('../../../../cli/commands/simulate.ts');
    const { localExecutor, workerExecutor } = await import('../../../../cli/dataset/executors.ts');
    const { planTasks } = await import('../../../../cli/dataset/plan-tasks.ts');
    const { schedule } = await import('../../../../cli/dataset/dispatch.ts');
    const { spec } = parseSimulate([...OSCILLATOR, '--sample', '9', '--seed', '1', '--box', 'q=-1:1,p=-1:1', '--t-end', '2', '--every', '100', '--derivatives']);
    const run = await prepareRun(spec, await modelRecipe({ ...spec, cache: true }), { force: false });
    const setup = { times: run.times, set: run.set, derivatives: true, numberTrajectories: true };
    const collect = async (executors: Parameters<typeof schedule>[1]) => {
      const plan = planTasks({ ...run.shape, width: run.shape.columns.length }, 'trajectory', 3, 0);
      const out: number[] = [];
      await schedule(plan, executors, { order: 'trajectory', ahead: 2, write: (_, result) => out.push(...result.data!) });
      await Promise.all(executors.map((e) => e.close()));
      return out;
    };
    const here = await collect([localExecutor(modelFromRecipe(run.recipe), setup, undefined, () => {})]);
    const threads = await collect([0, 1, 2].map(() => workerExecutor({ recipe: run.recipe, setup })));
    expect(here).toHaveLength(9 * 41 * 6);
    expect(threads).toEqual(here);
  });

  it.each(['json', 'npz', 'parquet'])('merges %s shards into exactly the unsharded file, whatever order they are given in', async (format) => {
    const whole = join(dir, `whole.${format}`);
    expect(await simulate(...SET, '--output', whole)).toBe(0);
    for (const i of [1, 2, 3, 4]) expect(await simulate(...SET, '--shard', `${i}/4`, '--output', join(dir, `s${i}.${format}`))).toBe(0);
    const merged = join(dir, `merged.${format}`);
    expect(await main(['merge', '--output', merged, ...[3, 1, 4, 2].map((i) => join(dir, `s${i}.${format}`))])).toBe(0);
    expect(readFileSync(merged).equals(readFileSync(whole))).toBe(true);
  });

  it('merges the shards of a grid into the unsharded file, each grid point where the whole run puts it', async () => {
    const grid = [...OSCILLATOR, '--grid', 'q=-1:1:5,p=-0.5:0.5:3', '--t-end', '3', '--every', '300', '--derivatives'];
    const whole = join(dir, 'whole.npz');
    expect(await simulate(...grid, '--output', whole)).toBe(0);
    for (const i of [1, 2, 3]) expect(await simulate(...grid, '--shard', `${i}/3`, '--output', join(dir, `g${i}.npz`))).toBe(0);
    expect(await main(['merge', '--output', join(dir, 'm.npz'), join(dir, 'g2.npz'), join(dir, 'g3.npz'), join(dir, 'g1.npz')])).toBe(0);
    expect(readFileSync(join(dir, 'm.npz')).equals(readFileSync(whole))).toBe(true);
    checkNpz(npzJs(whole), 15, 21, true);
  });

  it('merges wide Parquet shards into the unsharded file', async () => {
    const whole = join(dir, 'whole.parquet');
    expect(await simulate(...SET, '--layout', 'wide', '--output', whole)).toBe(0);
    for (const i of [1, 2]) expect(await simulate(...SET, '--layout', 'wide', '--shard', `${i}/2`, '--output', join(dir, `s${i}.parquet`))).toBe(0);
    expect(await main(['merge', '--output', join(dir, 'm.parquet'), join(dir, 's1.parquet'), join(dir, 's2.parquet')])).toBe(0);
    expect(readFileSync(join(dir, 'm.parquet')).equals(readFileSync(whole))).toBe(true);
  });
});

describe('phasebook reproduce', () => {
  it.each(['json', 'npz', 'parquet'])('re-runs a %s file from its meta and finds every number the same', async (format) => {
    const out = join(dir, `r.${format}`);
    expect(await simulate(...OSCILLATOR, '--sample', '4', '--seed', '5', '--box', 'q=-1:1,p=-1:1', '--t-end', '1', '--every', '200', '--output', out)).toBe(0);
    expect(await main(['reproduce', out, '--workers', '1'])).toBe(0);
    expect(stdout.join('')).toMatch(/reproduced, 4 trajectories × 11 samples, all 176 numbers identical/);
    expect(readdirSync(dir)).toEqual([`r.${format}`]);
  });

  it('says where a file differs from its re-run, with status 1', async () => {
    const out = join(dir, 'r.json');
    expect(await simulate(...OSCILLATOR, '--grid', 'q=0:1:2,p=0', '--t-end', '1', '--every', '1000', '--format', 'json', '--output', out)).toBe(0);
    const text = readFileSync(out, 'utf8');
    writeFileSync(out, text.replace('\n[1,0.5,', '\n[1,0.4999,'));
    expect(await main(['reproduce', out, '--workers', '1'])).toBe(1);
    expect(stdout.join('')).toMatch(/differs at trajectory 1, sample 1, t: the file has 0\.4999, the run gives 0\.5/);
  });

  it('finds a number changed by one ulp, or 0 turned to -0: bit for bit, status 1, naming trajectory, sample and column', async () => {
    const out = join(dir, 'r.json');
    expect(await simulate(...OSCILLATOR, '--grid', 'q=0:1:3,p=0', '--t-end', '1', '--every', '250', '--format', 'json', '--output', out)).toBe(0);
    const { meta, table } = parseJSON(readFileSync(out, 'utf8'));
    const w = table.columns.length;
    // Columns trajectory, t, q, p, H, trajectory after trajectory.
    const samples = (meta as unknown as { samples: number }).samples;
    const at = (j: number, sample: number, column: string) => (j * samples + sample) * w + table.columns.indexOf(column);
    const original = table.data[at(1, 3, 'q')];
    const bits = new DataView(new ArrayBuffer(8));
    bits.setFloat64(0, original);
    bits.setBigUint64(0, bits.getBigUint64(0) + 1n);
    const nextUp = bits.getFloat64(0);
    expect(nextUp - original).toBeLessThan(1e-15);
    const changed = Float64Array.from(table.data);
    changed[at(1, 3, 'q')] = nextUp;
    writeFileSync(out, toJSON({ ...table, data: changed }, meta));
    expect(await main(['reproduce', out, '--workers', '1'])).toBe(1);
    expect(stdout.join('')).toBe(`${out}: differs at trajectory 1, sample 3, q: the file has ${nextUp}, the run gives ${original}\n`);

    stdout.length = 0;
    // p starts at 0 in every trajectory: the file's -0 is another double.
    const signed = Float64Array.from(table.data);
    expect(Object.is(signed[at(2, 0, 'p')], 0)).toBe(true);
    signed[at(2, 0, 'p')] = -0;
    writeFileSync(out, toJSON({ ...table, data: signed }, meta));
    expect(await main(['reproduce', out, '--workers', '1'])).toBe(1);
    expect(stdout.join('')).toBe(`${out}: differs at trajectory 2, sample 0, p: the file has -0, the run gives 0\n`);
  });

  it('rebuilds a file with its own rows from its meta: t-end is in it (3.65 every 100 steps: 74 rows)', async () => {
    const out = join(dir, 'one.json');
    expect(await simulate(...OSCILLATOR, '--initial', '1,0', '--t-end', '3.65', '--every', '100', '--format', 'json', '--output', out)).toBe(0);
    const { meta, table } = parseJSON(readFileSync(out, 'utf8'));
    expect(table.rows).toBe(74);
    expect(meta).toMatchObject({ tEnd: 3.65, steps: 7300, samples: 74 });
    expect(await main(['reproduce', out, '--workers', '1'])).toBe(0);
  });
});

describe('bad input: one line on stderr, status 2, no file left', () => {
  const out = () => join(dir, 'out.npz');
  it.each([
    ['an initial file with a column the state lacks', () => ['--initial-file', write('i.csv', 'q,x\n1,0\n')], /has a column "x", which is not a component of the state \(q, p\)/],
    ['an initial file with NaN', () => ['--initial-file', write('i.csv', 'q,p\n1,0\n2,NaN\n')], /--initial-file i\.csv line 3: p is "NaN", not a finite number/],
    ['an initial NPY of the wrong shape', () => ['--initial-file', write('i.json', '[[1, 2, 3]]')], /row 1 has 3 values; the state q, p needs 2/],
    ['an energy with no solution', () => ['--sample', '3', '--box', 'q=-1:1,p=-1:1', '--energy', '-1'], /no point of the box reaches H = -1 with p in \[-1, 1\]/],
    ['a shard index out of range', () => ['--sample', '3', '--box', 'q=-1:1,p=-1:1', '--shard', '5/4'], /--shard 5\/4: the shard number runs from 1 to 4/],
    ['a box that misses a component', () => ['--sample', '3', '--box', 'q=-1:1'], /--box gives no range for p/],
    ['two sets at once', () => ['--initial', '1,0', '--grid', 'q=0:1:2,p=0'], /give one of --initial, --initial-file, --sample and --grid, not --initial and --grid/],
    ['a shard index of 0', () => ['--grid', 'q=0:1:4,p=0', '--shard', '0/4'], /--shard 0\/4: the shard number runs from 1 to 4/],
    ['a CSV shard, which merge could not check', () => ['--grid', 'q=0:1:4,p=0', '--shard', '1/4', '--format', 'csv'], /--shard writes a part for phasebook merge, .*give --format npz, parquet or json/],
    ['an initial file that is missing', () => ['--initial-file', join(dir, 'none.csv')], /none\.csv/],
  ])('%s', async (_, extra, message) => {
    const args = extra();
    expect(await simulate(...OSCILLATOR, ...args, '--t-end', '1', '--output', out())).toBe(2);
    expect(stderr.join('')).toMatch(message);
    expect(stderr.join('').trim().split('\n')).toHaveLength(1);
    expect(readdirSync(dir).filter((n) => !n.startsWith('i.'))).toEqual([]);
  });

  it('refuses to merge shards of different specs, or an incomplete set', async () => {
    const base = [...OSCILLATOR, '--sample', '6', '--box', 'q=-1:1,p=-1:1', '--t-end', '1', '--every', '100'];
    expect(await simulate(...base, '--seed', '1', '--shard', '1/2', '--output', join(dir, 'a.npz'))).toBe(0);
    expect(await simulate(...base, '--seed', '2', '--shard', '2/2', '--output', join(dir, 'b.npz'))).toBe(0);
    expect(await main(['merge', '--output', join(dir, 'm.npz'), join(dir, 'a.npz'), join(dir, 'b.npz')])).toBe(2);
    expect(stderr.join('')).toMatch(/b\.npz and \S*a\.npz come from different runs: their meta differs in initialSet\n$/);
    stderr.length = 0;
    expect(await main(['merge', '--output', join(dir, 'm.npz'), join(dir, 'a.npz')])).toBe(2);
    expect(stderr.join('')).toMatch(/^phasebook: shard 2\/2 of the run is missing\n$/);
    expect(readdirSync(dir).sort()).toEqual(['a.npz', 'b.npz']);
  });
});

/** Writes a file in the test's folder; returns its path. */
function write(name: string, text: string): string {
  const path = join(dir, name);
  writeFileSync(path, text);
  return path;
}
