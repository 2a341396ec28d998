/**
 * Readers of NPZ and Parquet that are not phasebook's: Python's numpy and
 * pyarrow, and always two maintained JavaScript ones, fflate + npyjs for NPZ
 * and parquet-wasm (the Rust Arrow project's Parquet reader, compiled to
 * WebAssembly) + apache-arrow for Parquet, so a fresh machine without
 * Python still checks both formats independently.
 *
 * The Python readers are what researchers load these files with, so CI must
 * run them: .ci/run installs them, pinned (.ci/python-requirements.txt), and
 * under CI a test that needs them runs whether or not python3 has them, and
 * so fails rather than skips when they are missing. Elsewhere it is skipped.
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { unzipSync } from 'fflate';
import { parse as parseNpy } from 'npyjs';
import * as parquetWasm from 'parquet-wasm';
import { tableFromIPC } from 'apache-arrow';

/** Whether python3 can import every module named. */
export function pythonHas(...modules: string[]): boolean {
  const run = spawnSync('python3', ['-c', modules.map((m) => `import ${m}`).join('; ')], { encoding: 'utf8' });
  return run.status === 0;
}

/** Whether this is a CI run (CI set, as .ci/run and every CI service set it), where nothing that needs Python may skip. */
export function inCI(): boolean {
  const ci = process.env.CI;
  return ci !== undefined && ci !== '' && ci !== '0' && ci.toLowerCase() !== 'false';
}

/** Whether a test that needs these Python modules runs: where python3 has them, and always under CI. */
export function runsWithPython(...modules: string[]): boolean {
  return inCI() || pythonHas(...modules);
}

function python(script: string, ...args: string[]): unknown {
  const run = spawnSync('python3', ['-c', script, ...args], { encoding: 'utf8', maxBuffer: 1 << 28 });
  if (run.error) throw new Error(`python3 cannot be run (${run.error.message}): .ci/run installs it with numpy and pyarrow`);
  if (/ModuleNotFoundError/.test(run.stderr)) throw new Error(`python3 lacks a reader: .ci/run installs numpy and pyarrow, pinned in .ci/python-requirements.txt (${run.stderr.trim().split('\n').pop()})`);
  if (run.status !== 0) throw new Error(`python3 failed: ${run.stderr}`);
  return JSON.parse(run.stdout);
}

export interface LoadedArrays {
  /** array name → shape and values in C order */
  arrays: Record<string, { shape: number[]; values: number[] }>;
  meta: Record<string, unknown>;
}

/** numpy.load, allow_pickle=False as a careful user loads it. */
export function numpyLoad(path: string): LoadedArrays {
  return python(
    `import json, sys, numpy as np
f = np.load(sys.argv[1], allow_pickle=False)
out = {'arrays': {}, 'meta': json.loads(f['meta'][()])}
for k in f.files:
    if k != 'meta':
        a = f[k]
        out['arrays'][k] = {'shape': list(a.shape), 'values': [float(v) for v in a.ravel()]}
print(json.dumps(out))`,
    path,
  ) as LoadedArrays;
}

/** fflate's unzip and npyjs's parser; the meta, a 0-d UTF-32 string, decoded by hand. */
export function npzJs(path: string): LoadedArrays {
  const files = unzipSync(new Uint8Array(readFileSync(path)));
  const out: LoadedArrays = { arrays: {}, meta: {} };
  for (const [name, bytes] of Object.entries(files)) {
    const key = name.replace(/\.npy$/, '');
    const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer;
    if (key === 'meta') {
      const headerLength = new DataView(buffer).getUint16(8, true);
      const body = new DataView(buffer, 10 + headerLength);
      let text = '';
      for (let i = 0; i + 4 <= body.byteLength; i += 4) text += String.fromCodePoint(body.getUint32(i, true));
      out.meta = JSON.parse(text.replace(/\0+$/, ''));
      continue;
    }
    const array = parseNpy(buffer);
    out.arrays[key] = { shape: array.shape, values: Array.from(array.data as Float64Array) };
  }
  return out;
}

export interface LoadedTable {
  columns: string[];
  /** column name → values */
  data: Record<string, number[]>;
  metadata: Record<string, string>;
  rowGroups?: number;
}

export function pyarrowRead(path: string): LoadedTable {
  return python(
    `import json, sys, pyarrow.parquet as pq
f = pq.ParquetFile(sys.argv[1])
t = f.read()
md = {k.decode(): v.decode() for k, v in (f.metadata.metadata or {}).items()}
print(json.dumps({'columns': t.column_names, 'data': {c: [float(v) for v in t.column(c).to_pylist()] for c in t.column_names}, 'metadata': md, 'rowGroups': f.metadata.num_row_groups}))`,
    path,
  ) as LoadedTable;
}

export function parquetJs(path: string): LoadedTable {
  const wasmTable = parquetWasm.readParquet(new Uint8Array(readFileSync(path)));
  const table = tableFromIPC(wasmTable.intoIPCStream());
  const columns = table.schema.fields.map((f) => f.name);
  const data: Record<string, number[]> = {};
  for (const name of columns) data[name] = Array.from(table.getChild(name)!.toArray() as ArrayLike<number>, Number);
  return { columns, data, metadata: Object.fromEntries(table.schema.metadata) };
}
