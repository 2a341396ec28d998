/**
 * Where an ensemble moves: in a worker when its model's stepper is
 * generated code that can travel there (simulator/portable-model.ts), on
 * the page otherwise (an H given as an opaque JS function), with the same
 * core code and the same frames either way. One request is in flight at a
 * time: the page asks for the next frame's steps once the last has come.
 */
import { Ensemble, type EnsembleSetup, type Model } from '../../../core/index.ts';
import { portableModel } from '../../simulator/portable-model.ts';
import { ensembleFrame } from './ensemble-frame.ts';
import type { EnsembleFrame, EnsembleReply, EnsembleRequest } from './ensemble-protocol.ts';

export interface EnsembleRunner {
  /** (Re)starts the ensemble from its disc; resolves with the first frame. */
  start(setup: EnsembleSetup): Promise<EnsembleFrame>;
  /** Carries it `steps` further. */
  advance(steps: number): Promise<EnsembleFrame>;
  /** Ends the worker, if any. */
  stop(): void;
}

export function ensembleRunner(model: Model): EnsembleRunner {
  const source = portableModel(model);
  return source && typeof Worker !== 'undefined' ? new WorkerRunner(model, source) : new PageRunner(model);
}

class PageRunner implements EnsembleRunner {
  #ensemble: Ensemble | null = null;
  constructor(private readonly model: Model) {}

  async start(setup: EnsembleSetup): Promise<EnsembleFrame> {
    this.#ensemble = new Ensemble(this.model.stepper, this.model.params, setup);
    return ensembleFrame(this.#ensemble);
  }

  async advance(steps: number): Promise<EnsembleFrame> {
    if (!this.#ensemble) throw new Error('the ensemble was asked to move before it was started');
    this.#ensemble.advance(steps);
    return ensembleFrame(this.#ensemble);
  }

  stop(): void {
    this.#ensemble = null;
  }
}

class WorkerRunner implements EnsembleRunner {
  #worker: Worker | null = null;
  #id = 0;
  readonly #waiting = new Map<number, { resolve: (frame: EnsembleFrame) => void; reject: (error: Error) => void }>();

  constructor(
    private readonly model: Model,
    private readonly source: NonNullable<ReturnType<typeof portableModel>>,
  ) {}

  start(setup: EnsembleSetup): Promise<EnsembleFrame> {
    // The parameters as they are now: a cell that changes one rebuilds the widget.
    return this.#ask({ kind: 'start', id: 0, model: this.source, params: Float64Array.from(this.model.params), setup });
  }

  advance(steps: number): Promise<EnsembleFrame> {
    return this.#ask({ kind: 'advance', id: 0, steps });
  }

  stop(): void {
    this.#worker?.terminate();
    this.#worker = null;
    for (const waiter of this.#waiting.values()) waiter.reject(new Error('the ensemble was stopped'));
    this.#waiting.clear();
  }

  #ask(request: EnsembleRequest): Promise<EnsembleFrame> {
    const worker = (this.#worker ??= this.#open());
    const id = ++this.#id;
    return new Promise((resolve, reject) => {
      this.#waiting.set(id, { resolve, reject });
      worker.postMessage({ ...request, id });
    });
  }

  #open(): Worker {
    const worker = new Worker(new URL('./ensemble-worker.ts', import.meta.url), { type: 'module', name: 'phasebook-ensemble' });
    worker.onmessage = (event: MessageEvent<EnsembleReply>) => {
      const reply = event.data;
      const waiter = this.#waiting.get(reply.id);
      if (!waiter) return;
      this.#waiting.delete(reply.id);
      if ('error' in reply) waiter.reject(new Error(reply.error));
      else waiter.resolve(reply.frame);
    };
    worker.onerror = (event) => {
      event.preventDefault();
      const error = new Error(event.message || 'the ensemble’s worker failed');
      for (const waiter of this.#waiting.values()) waiter.reject(error);
      this.#waiting.clear();
    };
    return worker;
  }
}
