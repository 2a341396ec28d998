/**
 * Compiles models off the main thread: the symbolic derivatives and the
 * generated stepper of a reader's new H (core/model/compile-model.ts), with mathjs
 * loaded here rather than in the page. Builds are linear in the size of H,
 * but mathjs alone is 100 kB of script to parse, and a big H still takes
 * a moment: the page stays responsive and shows progress meanwhile.
 *
 * In: {id, spec} to build, {cancel: id} to stop a build an edit made
 * obsolete. Out: {id, progress}, then {id, model} or {id, error: {name, message}}.
 */
import { compileModel, type ModelKeySpec } from '../../../core/index.ts';

export type CompileRequest = { id: number; spec: ModelKeySpec } | { cancel: number };
export type CompileReply =
  | { id: number; progress: number }
  | { id: number; model: Awaited<ReturnType<typeof compileModel>> }
  | { id: number; error: { name: string; message: string } };

const running = new Map<number, AbortController>();
const reply = (message: CompileReply) => postMessage(message);

self.onmessage = async (event: MessageEvent<CompileRequest>) => {
  const request = event.data;
  if ('cancel' in request) {
    running.get(request.cancel)?.abort();
    return;
  }
  const controller = new AbortController();
  running.set(request.id, controller);
  try {
    const model = await compileModel(request.spec, {
      signal: controller.signal,
      progress: (done, total) => reply({ id: request.id, progress: done / total }),
    });
    reply({ id: request.id, model });
  } catch (error) {
    const e = error instanceof Error ? error : new Error(String(error));
    reply({ id: request.id, error: { name: e.name, message: e.message } });
  } finally {
    running.delete(request.id);
  }
};
