/**
 * The book's web workers (the compile worker, the stability chart's) in the
 * preview webview. The book starts them as
 * `new Worker(new URL('./x-worker.ts', import.meta.url), …)`, which Vite
 * bundles; esbuild does not, and a webview could not start a worker from
 * its resource URLs anyway (they are another origin). So each worker is
 * bundled on its own into dist/workers/<name>.js, and the plugin below
 * rewrites the `new URL(…)` into `globalThis.phasebookWorkerUrl('<name>')`,
 * which the preview answers with a blob: URL of the fetched script
 * (src/preview/workers.ts). Without it, a worker fails to start and the
 * book's own fallback (compile on the page) or error applies.
 */
import { readdir, readFile } from 'node:fs/promises';
import path from 'node:path';
import type { Plugin } from 'esbuild';

const WORKER_URL = /new Worker\(\s*new URL\(\s*(['"])\.\/([\w-]+)\.ts\1\s*,\s*import\.meta\.url\s*\)/g;

export interface WorkerEntry {
  readonly name: string;
  readonly file: string;
}

async function filesUnder(folder: string): Promise<string[]> {
  const entries = await readdir(folder, { withFileTypes: true, recursive: true });
  return entries.filter((e) => e.isFile() && e.name.endsWith('.ts')).map((e) => path.join(e.parentPath, e.name));
}

/** Every worker the modules under `folder` start by URL. */
export async function findWorkers(folder: string): Promise<WorkerEntry[]> {
  const found = new Map<string, WorkerEntry>();
  for (const file of await filesUnder(folder)) {
    const text = await readFile(file, 'utf8');
    for (const match of text.matchAll(WORKER_URL)) found.set(match[2], { name: match[2], file: path.join(path.dirname(file), `${match[2]}.ts`) });
  }
  return [...found.values()];
}

export function webWorkers(): Plugin {
  return {
    name: 'phasebook-web-workers',
    setup(build) {
      build.onLoad({ filter: /[\\/]widgets[\\/].*\.ts$/ }, async (args) => {
        const text = await readFile(args.path, 'utf8');
        if (!text.match(WORKER_URL)) return undefined;
        const contents = text.replace(WORKER_URL, (_all, _quote, name: string) => `new Worker(globalThis.phasebookWorkerUrl(${JSON.stringify(name)})`);
        return { contents, loader: 'ts' };
      });
    },
  };
}
