/**
 * An output that would replace one of the run's own inputs. The output is
 * renamed onto its path when complete (output.ts), so `--output` naming the
 * `--initial-file`, or a shard being merged, would silently swap the input
 * for the result. Names are not compared but files: the device and inode,
 * which a second path, a `..` or a symbolic link to the same file share.
 */
import { statSync } from 'node:fs';
import { InputError } from '../../core/index.ts';

/** Whether `a` and `b` are one existing file, whatever the paths that name it. */
export function sameFile(a: string, b: string): boolean {
  const first = statSync(a, { bigint: true, throwIfNoEntry: false });
  const second = statSync(b, { bigint: true, throwIfNoEntry: false });
  return first !== undefined && second !== undefined && first.dev === second.dev && first.ino === second.ino;
}

/** Refuses, in one line, an output that is the input `input` (named `inputOption` in the message). */
export function refuseSameFile(output: string, input: string, outputOption: string, inputOption: string): void {
  let same: boolean;
  try {
    same = sameFile(output, input);
  } catch {
    // A path that cannot even be looked at is reported where it is opened, in its own words.
    return;
  }
  if (same) {
    const also = output === input ? '' : ` (${output} and ${input} are one file)`;
    throw new InputError(`${outputOption} ${output} is the ${inputOption}${also}: the output would replace it; write to another file`);
  }
}
