/**
 * Reads the pixels of the preview's simulator canvases from inside the webview's frame:
 * how many differ from the canvas's most common colour (its background), and a hash of
 * them all, to tell a drawing that moves from one that stands still.
 */
import type { Frame } from 'playwright-core';

export interface CanvasReading {
  readonly width: number;
  readonly height: number;
  /** Pixels not of the background colour. */
  readonly drawn: number;
  readonly hash: number;
}

export function readCanvases(frame: Frame): Promise<CanvasReading[]> {
  return frame.evaluate(() =>
    [...document.querySelectorAll<HTMLCanvasElement>('[data-widget="simulator"][data-ready] canvas')].map((canvas) => {
      const context = canvas.getContext('2d');
      if (!context || !canvas.width || !canvas.height) return { width: canvas.width, height: canvas.height, drawn: 0, hash: 0 };
      const pixels = new Uint32Array(context.getImageData(0, 0, canvas.width, canvas.height).data.buffer);
      const counts = new Map<number, number>();
      let hash = 0;
      for (let i = 0; i < pixels.length; i++) {
        counts.set(pixels[i], (counts.get(pixels[i]) ?? 0) + 1);
        hash = (Math.imul(hash, 31) + pixels[i]) | 0;
      }
      const background = Math.max(...counts.values());
      return { width: canvas.width, height: canvas.height, drawn: pixels.length - background, hash };
    }),
  );
}
