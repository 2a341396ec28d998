/**
 * A file that holds bytes aside while a run writes its output, to be copied
 * into the output at the end: an NPZ's H and dx/dt arrays come after its x
 * in the archive, but are computed alongside it. It is a partial file
 * (partial-file.ts) beside the output, made exclusively under an
 * unpredictable name, so a run killed outright leaves nothing the next run
 * will not clean up.
 */
import { closeSync, readSync, unlinkSync, writeSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { outputError } from './output-error.ts';
import { createPartial } from './partial-file.ts';

const CHUNK = 1 << 20;

export class SpillFile {
  readonly path: string;
  private readonly fd: number;
  private size = 0;
  private closed = false;

  /** beside `target`, or in the temporary folder when the output is not a file */
  constructor(target: string | undefined, label: string) {
    const where = target ?? join(tmpdir(), `phasebook-${label}`);
    try {
      ({ path: this.path, fd: this.fd } = createPartial(`${where}.${label}`, 'wx+'));
    } catch (error) {
      throw outputError(error, where);
    }
  }

  append(bytes: Uint8Array): void {
    let done = 0;
    try {
      while (done < bytes.length) done += writeSync(this.fd, bytes, done, bytes.length - done, this.size + done);
    } catch (error) {
      throw outputError(error, this.path);
    }
    this.size += bytes.length;
  }

  get length(): number {
    return this.size;
  }

  /** Hands the bytes back in order, a megabyte at a time. */
  replay(each: (bytes: Uint8Array) => void): void {
    const buffer = Buffer.alloc(Math.min(CHUNK, Math.max(1, this.size)));
    for (let at = 0; at < this.size; ) {
      const n = readSync(this.fd, buffer, 0, Math.min(buffer.length, this.size - at), at);
      if (n === 0) throw new Error(`SpillFile: ${this.path} ended at ${at} of ${this.size} bytes`);
      each(buffer.subarray(0, n));
      at += n;
    }
  }

  /** Closes and removes the file; never throws. */
  remove(): void {
    if (this.closed) return;
    this.closed = true;
    try {
      closeSync(this.fd);
    } catch {
      // Already unusable: removing it is what matters.
    }
    try {
      unlinkSync(this.path);
    } catch {
      // Gone already.
    }
  }
}
