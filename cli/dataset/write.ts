/** The writer of a run's format, onto its sink. */
import type { PreparedRun } from './prepare.ts';
import type { DatasetWriter } from '../formats/dataset-shape.ts';
import { NpzDatasetWriter } from '../formats/npz-dataset.ts';
import { ParquetDatasetWriter } from '../formats/parquet-dataset.ts';
import { TextDatasetWriter } from '../formats/text-dataset.ts';
import type { Sink } from '../output/sink.ts';
import { sampleTimes } from './run-task.ts';

export interface ChosenWriter {
  writer: DatasetWriter;
  /** files kept beside the output while it is written */
  keepsFiles: boolean;
  /** rows per chunk in time order */
  timeChunkRows?: number;
}

export function datasetWriter(run: PreparedRun, sink: Sink, target: string | undefined): ChosenWriter {
  const { spec, shape, meta } = run;
  switch (spec.format) {
    case 'csv':
    case 'json':
      return { writer: new TextDatasetWriter(sink, spec.format, shape, meta), keepsFiles: false };
    case 'npz': {
      const plan = sampleTimes(run.times);
      const times = Float64Array.from({ length: plan.count }, (_, i) => plan.time(i));
      const writer = new NpzDatasetWriter(sink, shape, meta, times, target);
      return { writer, keepsFiles: true };
    }
    case 'parquet': {
      const writer = new ParquetDatasetWriter(sink, shape, meta, spec.layout);
      return { writer, keepsFiles: false, timeChunkRows: writer.groupRows };
    }
  }
}
