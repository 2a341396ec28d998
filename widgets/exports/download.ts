/**
 * Saving files from the page: a Blob behind an object URL, clicked through a
 * temporary <a download>, and revoked once the browser has taken it.
 */

/** Offers `parts` as a file named `filename`. */
export function downloadBlob(blob: Blob, filename: string): void {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = filename;
  a.rel = 'noopener';
  a.style.display = 'none';
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** Offers text parts (e.g. CSV blocks) as a file of the given MIME type. */
export function downloadText(parts: readonly string[], type: string, filename: string): void {
  downloadBlob(new Blob(parts as string[], { type }), filename);
}

/** The canvas as a PNG Blob. */
export function pngBlob(canvas: HTMLCanvasElement): Promise<Blob> {
  return new Promise((resolve, reject) => {
    canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('the browser could not encode the plot as PNG'))), 'image/png');
  });
}

/** A copy of the canvas on an opaque background, so a transparent plot reads in any image viewer. */
export function onBackground(canvas: HTMLCanvasElement, background: string): HTMLCanvasElement {
  const out = document.createElement('canvas');
  out.width = canvas.width;
  out.height = canvas.height;
  const ctx = out.getContext('2d');
  if (!ctx) return canvas;
  ctx.fillStyle = background;
  ctx.fillRect(0, 0, out.width, out.height);
  ctx.drawImage(canvas, 0, 0);
  return out;
}
