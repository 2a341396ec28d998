/**
 * `phasebook reproduce FILE`: runs again the run whose meta FILE carries
 * (JSON, NPZ or Parquet), into a temporary file of the same format, and
 * compares every number with FILE's, bit for bit. Prints what it found;
 * the status is 0 when every number is the same, 1 when one differs.
 *
 * The file's meta is data: it is checked field by field (meta-spec.ts), and
 * the JavaScript it may carry runs only if it translates to an expression
 * or the user passes --trust-code, and then in the sandbox (trust-code.ts).
 * Every message names the file; a signal stops the run and the comparison
 * alike, leaving no temporary file.
 */
import { breather } from '../breather.ts';
import { BLOCK_VALUES } from '../dataset/plan-tasks.ts';
import { prepareRun, type PreparedRun } from '../dataset/prepare.ts';
import { executeRun } from '../dataset/execute.ts';
import { datasetWriter } from '../dataset/write.ts';
import { namingFile } from '../formats/file-errors.ts';
import type { Block } from '../formats/dataset-shape.ts';
import { openDataset, type DatasetFile } from '../formats/dataset-read.ts';
import { Interrupted, InterruptGuard } from '../interrupt.ts';
import { specFromMeta } from '../dataset/meta-spec.ts';
import { modelRecipe } from '../model/model.ts';
import type { Sink } from '../output/sink.ts';
import { SpillFile } from '../output/spill-file.ts';
import { parseArgs, wholeNumber } from '../options/args.ts';
import { REPRODUCE } from '../options/commands.ts';
import { usageLine } from '../options/usage.ts';
import { admitFileCode } from '../model/trust-code.ts';
import { InputError, roundTripNumber } from '../../core/index.ts';

/** Every number of a file's blocks, in order, with where it is. */
async function* numbers(file: DatasetFile): AsyncGenerator<{ value: number; trajectory: number; row: number; column: number }> {
  const width = file.shape.columns.length;
  for await (const block of file.blocks(BLOCK_VALUES) as AsyncGenerator<Block>) {
    const data = block.data!;
    const rows = block.rowTo - block.rowFrom;
    for (let i = 0; i < data.length; i++) {
      const column = i % width;
      const r = Math.floor(i / width);
      yield { value: data[i], trajectory: block.first + Math.floor(r / rows), row: block.rowFrom + (r % rows), column };
    }
  }
}

export async function reproduceCommand(argv: readonly string[]): Promise<{ text: string; status: number }> {
  const args = parseArgs(argv, REPRODUCE);
  const [path] = args.operands;
  if (path === undefined) throw new InputError(`give the file to reproduce (usage: ${usageLine(REPRODUCE)})`);
  const workers = args.values.has('workers') ? wholeNumber(args.values.get('workers')!, '--workers') : undefined;
  const guard = new InterruptGuard();
  guard.hold();
  try {
    return await reproduceFile(path, { workers, cache: !args.flags.has('no-cache'), trustCode: args.flags.has('trust-code'), signal: guard.signal });
  } catch (error) {
    if (error instanceof Interrupted) throw new Interrupted(error.signal, `; ${path} was not reproduced`);
    throw namingFile(error, path, false);
  } finally {
    guard.release();
  }
}

interface ReproduceOptions {
  workers?: number;
  cache: boolean;
  trustCode: boolean;
  signal: AbortSignal;
}

async function reproduceFile(path: string, options: ReproduceOptions): Promise<{ text: string; status: number }> {
  const file = await openDataset(path);
  let run: PreparedRun | undefined;
  let rerun: SpillFile | undefined;
  let again: DatasetFile | undefined;
  let writer: ReturnType<typeof datasetWriter> | undefined;
  try {
    const spec = specFromMeta(file.meta, path);
    const recipe = await modelRecipe({ ...spec, cache: options.cache });
    admitFileCode(recipe, path, options.trustCode);
    run = await prepareRun(spec, recipe, { force: true, signal: options.signal });
    rerun = new SpillFile(undefined, `reproduce.${file.format}`);
    const spill = rerun;
    const sink: Sink = { write: (data) => spill.append(typeof data === 'string' ? Buffer.from(data) : data), commit: () => {}, abandon: () => {} };
    writer = datasetWriter(run, sink, undefined);
    await executeRun(run, writer.writer, { workers: options.workers, signal: options.signal, timeChunkRows: writer.timeChunkRows });
    again = await openDataset(rerun.path);
    const breathe = breather(options.signal);
    const expected = numbers(file);
    const got = numbers(again);
    let compared = 0;
    for (;;) {
      const [a, b] = await Promise.all([expected.next(), got.next()]);
      if (a.done || b.done) {
        if (a.done !== b.done) return { text: `${path}: the run gives ${a.done ? 'more' : 'fewer'} numbers than the file holds (after ${compared})\n`, status: 1 };
        break;
      }
      const x = a.value;
      const y = b.value;
      if (!Object.is(x.value, y.value) && !(Number.isNaN(x.value) && Number.isNaN(y.value))) {
        const name = file.shape.columns[x.column];
        const where = file.shape.total > 1 ? `trajectory ${x.trajectory}, ` : '';
        // Written as the files write numbers, so that -0 and 0 read as the two doubles they are.
        return { text: `${path}: differs at ${where}sample ${x.row}, ${name}: the file has ${roundTripNumber(x.value)}, the run gives ${roundTripNumber(y.value)}\n`, status: 1 };
      }
      // The comparison runs in microtasks alone: it returns to the event loop now and then to hear a signal.
      if (++compared % 4096 === 0) await breathe();
    }
    const { meta } = file;
    const version = meta.version === run.meta.version ? '' : ` (the file was written by phasebook ${meta.version}, this is ${run.meta.version})`;
    return { text: `${path}: reproduced, ${meta.count} trajectories × ${meta.samples} samples, all ${compared} numbers identical${version}\n`, status: 0 };
  } finally {
    writer?.writer.abandon();
    again?.close();
    file.close();
    rerun?.remove();
    await run?.model.close();
  }
}
