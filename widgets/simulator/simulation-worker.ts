/**
 * Integrates a simulator's model off the main thread, so that a slow model
 * or a huge batch costs the page no frames (see chunk-protocol.ts for the
 * conversation, chunk-runner.ts for the work). The model is rebuilt here
 * from its compiled code (a few `new Function` calls, no mathjs), and the
 * core's own Simulation advances it: the numbers are those the page would
 * compute, bit for bit. It makes no request of any kind.
 *
 * Each slice is posted as soon as it is done; between slices the worker
 * yields to its message queue, so a restart or a new dt is taken within one
 * slice, and whatever the old generation had in hand is never sent.
 */
import { ChunkRunner } from './chunk-runner.ts';
import type { WorkerReply, WorkerRequest } from './chunk-protocol.ts';

const scope = self as unknown as {
  postMessage(message: WorkerReply, transfer?: Transferable[]): void;
  onmessage: ((event: MessageEvent<WorkerRequest>) => void) | null;
};

const runner = new ChunkRunner(() => performance.now());
let scheduled = false;
// A message to itself rather than setTimeout, whose nested calls are clamped to 4 ms.
const tick = new MessageChannel();
tick.port1.onmessage = () => {
  scheduled = false;
  const chunk = runner.slice();
  if (chunk) scope.postMessage(chunk, chunk.state ? [chunk.rows.buffer, chunk.state.buffer] : [chunk.rows.buffer]);
  schedule();
};

function schedule(): void {
  if (scheduled || !runner.busy) return;
  scheduled = true;
  tick.port2.postMessage(null);
}

scope.onmessage = (event) => {
  const request = event.data;
  if (request.type === 'start') {
    try {
      runner.start(request);
    } catch (error) {
      scope.postMessage({ type: 'failed', gen: request.gen, message: error instanceof Error ? error.message : String(error) });
    }
  } else runner.advance(request.gen, request.target);
  schedule();
};

scope.postMessage({ type: 'ready' });
