/**
 * The book's web workers in the webview (see vscode/build/web-workers.ts):
 * each worker's script is fetched from the extension's resources once, at
 * start, and handed out as a blob: URL, the only kind of URL a webview may
 * start a worker from. A worker that could not be fetched makes
 * `phasebookWorkerUrl` throw, which the book's code treats as a worker
 * that cannot start.
 */

/** The workers' names, set by the build. */
declare const PHASEBOOK_WORKERS: readonly string[];

declare global {
  // A global's declaration must use `var`.
  var phasebookWorkerUrl: (name: string) => string;
}

export async function prepareWorkers(base: string): Promise<void> {
  const urls = new Map<string, string>();
  await Promise.all(
    PHASEBOOK_WORKERS.map(async (name) => {
      try {
        const response = await fetch(new URL(`${name}.js`, base));
        if (response.ok) urls.set(name, URL.createObjectURL(new Blob([await response.text()], { type: 'text/javascript' })));
      } catch {
        // Left out: the worker's caller falls back or reports.
      }
    }),
  );
  globalThis.phasebookWorkerUrl = (name) => {
    const url = urls.get(name);
    if (!url) throw new Error(`the ${name} could not be loaded in the preview`);
    return url;
  };
}
