/**
 * `phasebook merge --output FILE SHARD…`: joins the shards of one run
 * (`simulate … --shard i/n`) into the file the whole run would have written,
 * byte for byte. The shards must all be there, once each, and come from one
 * spec: their metas must agree in everything but the shard. A shard is data
 * from whoever made it: every row is checked as it is read
 * (formats/dataset-read.ts), every message names the file it is about, and
 * SIGINT or SIGTERM stops the merge and removes its partial output, as they
 * stop simulate.
 */
import { InputError } from '../../core/index.ts';
import { parseArgs } from '../options/args.ts';
import { MERGE } from '../options/commands.ts';
import { breather } from '../breather.ts';
import { BLOCK_VALUES } from '../dataset/plan-tasks.ts';
import { unshardedMeta, type DatasetMeta } from '../dataset/meta.ts';
import type { DatasetShape, DatasetWriter } from '../formats/dataset-shape.ts';
import { openDataset, type DatasetFile } from '../formats/dataset-read.ts';
import { NpzDatasetWriter } from '../formats/npz-dataset.ts';
import { ParquetDatasetWriter } from '../formats/parquet-dataset.ts';
import { TextDatasetWriter } from '../formats/text-dataset.ts';
import { Interrupted, InterruptGuard } from '../interrupt.ts';
import { fileSink, type Sink } from '../output/sink.ts';
import { shardRange } from '../dataset/spec.ts';
import { refuseSameFile } from '../output/same-file.ts';
import { usageLine } from '../options/usage.ts';

/** The first key in which two metas differ, for the message. */
function firstDifference(a: Record<string, unknown>, b: Record<string, unknown>): string {
  for (const key of new Set([...Object.keys(a), ...Object.keys(b)])) {
    if (JSON.stringify(a[key]) !== JSON.stringify(b[key])) return key;
  }
  return 'the order of its keys';
}

/** --output and the shards, each given. */
export function mergeArguments(argv: readonly string[]): { output: string; inputs: string[] } {
  const args = parseArgs(argv, MERGE);
  const output = args.values.get('output');
  if (output === undefined) throw new InputError(`--output is required (usage: ${usageLine(MERGE)})`);
  if (args.operands.length === 0) throw new InputError(`give the shard files to merge (usage: ${usageLine(MERGE)})`);
  return { output, inputs: args.operands };
}

/** The shards in order, checked to be all of one run's. */
function checkShards(files: DatasetFile[]): DatasetFile[] {
  const first = files[0];
  const of = first.meta.shard?.of;
  for (const file of files) {
    if (!file.meta.shard) throw new InputError(`${file.path} is not a shard (it was written without --shard)`);
    if (file.format !== first.format) throw new InputError(`${file.path} is ${file.format} but ${first.path} is ${first.format}: shards of one run share a format`);
    const whole = unshardedMeta(file.meta) as unknown as Record<string, unknown>;
    const reference = unshardedMeta(first.meta) as unknown as Record<string, unknown>;
    if (JSON.stringify(whole) !== JSON.stringify(reference)) {
      throw new InputError(`${file.path} and ${first.path} come from different runs: their meta differs in ${firstDifference(whole, reference)}`);
    }
  }
  const byIndex = new Map<number, DatasetFile>();
  for (const file of files) {
    const { index } = file.meta.shard!;
    const other = byIndex.get(index);
    if (other) throw new InputError(`${file.path} and ${other.path} are both shard ${index}/${of}`);
    byIndex.set(index, file);
  }
  const missing = Array.from({ length: of! }, (_, i) => i + 1).filter((i) => !byIndex.has(i));
  if (missing.length) throw new InputError(`shard${missing.length > 1 ? 's' : ''} ${missing.map((i) => `${i}/${of}`).join(', ')} of the run ${missing.length > 1 ? 'are' : 'is'} missing`);
  const ordered = Array.from({ length: of! }, (_, i) => byIndex.get(i + 1)!);
  for (const file of ordered) {
    const { first: expected } = shardRange(file.meta.trajectories, { index: file.meta.shard!.index, of: of! });
    if (file.meta.shard!.first !== expected) throw new InputError(`${file.path} says it starts at trajectory ${file.meta.shard!.first}, but shard ${file.meta.shard!.index}/${of} starts at ${expected}`);
  }
  return ordered;
}

function writerFor(file: DatasetFile, sink: Sink, shape: DatasetShape, meta: DatasetMeta, output: string): DatasetWriter {
  if (file.format === 'npz') return new NpzDatasetWriter(sink, shape, meta, file.times!, output);
  if (file.format === 'parquet') return new ParquetDatasetWriter(sink, shape, meta, meta.layout === 'wide' ? 'wide' : 'long');
  return new TextDatasetWriter(sink, 'json', shape, meta);
}

export async function mergeCommand(argv: readonly string[]): Promise<string> {
  const { output, inputs } = mergeArguments(argv);
  // Renamed onto a shard, the merged file would replace one of the parts it is made from.
  for (const input of inputs) refuseSameFile(output, input, '--output', 'shard');
  const files: DatasetFile[] = [];
  try {
    for (const input of inputs) files.push(await openDataset(input));
    const shards = checkShards(files);
    const meta = unshardedMeta(shards[0].meta);
    const shape: DatasetShape = { ...shards[0].shape, count: meta.trajectories, first: 0 };
    const guard = new InterruptGuard();
    const sink = fileSink(output, guard);
    // Reading shards resolves its promises at once, in microtasks: the merge returns to the event loop now and then to hear a signal.
    const breathe = breather(guard.signal);
    let writer: DatasetWriter | undefined;
    try {
      writer = writerFor(shards[0], sink, shape, meta, output);
      if (writer.order === 'time') {
        // Row group by row group, every shard's trajectories in turn.
        const streams = shards.filter((s) => s.shape.count > 0).map((s) => s.blocks(BLOCK_VALUES));
        for (;;) {
          const next = await Promise.all(streams.map((s) => s.next()));
          if (next.every((n) => n.done)) break;
          for (const n of next) if (!n.done) writer.write(n.value);
          await breathe();
        }
      } else {
        for (const shard of shards) {
          for await (const block of shard.blocks(BLOCK_VALUES)) {
            writer.write(block);
            await breathe();
          }
        }
      }
      guard.signal.throwIfAborted();
      writer.finish();
      sink.commit();
    } catch (error) {
      writer?.abandon();
      sink.abandon();
      if (error instanceof Interrupted) throw new Interrupted(error.signal, `; ${output} was not written`);
      throw error;
    } finally {
      guard.release();
    }
    return '';
  } finally {
    for (const file of files) file.close();
  }
}
