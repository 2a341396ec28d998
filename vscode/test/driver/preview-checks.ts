/**
 * What the driver checks in the preview webview's frame once the in-host suite has ended
 * (the extension host stops with it; the webview stays): the simulator's canvases hold a
 * drawing that moves, and the book's web workers were handed to the webview. Each check
 * returns null when it passes, else why it failed.
 */
import type { Frame, Page } from 'playwright-core';
import { readCanvases, type CanvasReading } from './canvas.ts';

const pause = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));

/** The frame of the preview whose chapter title is `title`, among the webviews' inner frames. */
export async function previewFrame(page: Page, title: string): Promise<Frame | undefined> {
  for (const frame of page.frames()) {
    try {
      if ((await frame.evaluate(() => document.querySelector('article[data-chapter] h1')?.textContent ?? null)) === title) return frame;
    } catch {
      // A frame that is navigating or not a preview.
    }
  }
  return undefined;
}

function describeCanvases(readings: readonly CanvasReading[]): string {
  return readings.map((r) => `${r.width}×${r.height}: ${r.drawn} drawn pixels`).join('; ');
}

export async function checkCanvas(frame: Frame): Promise<string | null> {
  // A simulator out of view pauses (the book's widgets spare the machine): show it first.
  await frame.evaluate(() => document.querySelector('[data-widget="simulator"]')?.scrollIntoView({ block: 'center' }));
  await pause(500);
  const first = await readCanvases(frame);
  await pause(1000);
  const second = await readCanvases(frame);
  console.log(`canvases: ${describeCanvases(second)}`);
  if (!second.some((r) => r.drawn > 200)) return `the simulator's canvases hold no drawing (${describeCanvases(second)})`;
  if (!second.some((r, i) => r.hash !== first[i]?.hash)) return 'the simulator drew once and then stood still for a second';
  return null;
}

export async function checkWorkers(frame: Frame): Promise<string | null> {
  const urls = await frame.evaluate(() =>
    ['compile-worker', 'stability-worker'].map((name) => {
      try {
        // Defined by the preview (src/preview/workers.ts), in the webview's page.
        return (globalThis as unknown as { phasebookWorkerUrl(name: string): string }).phasebookWorkerUrl(name);
      } catch (error) {
        return String(error);
      }
    }),
  );
  return urls.every((url) => url.startsWith('blob:')) ? null : `the workers were not handed to the webview: ${urls.join(', ')}`;
}
