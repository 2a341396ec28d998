/**
 * Points drawn as pixels: a phase portrait's iterates, an ensemble's cloud,
 * written as words straight into an image's buffer, where as many fillRect
 * calls would take longer than a frame.
 */

/**
 * Where on an image a point of a plane falls: device pixels from the
 * image's top left, x = qScale·q + qOffset and y = pScale·p + pOffset. Plain
 * numbers rather than the plot's scale functions: a portrait or a cloud maps
 * hundreds of thousands of points a frame.
 */
export interface PixelMapping {
  readonly width: number;
  readonly height: number;
  readonly qScale: number;
  readonly qOffset: number;
  readonly pScale: number;
  readonly pOffset: number;
}

/** The affine mapping through two points of each axis: `x(q)` and `y(p)` as the plot's scales give them. */
export function pixelMapping(width: number, height: number, x: (q: number) => number, y: (p: number) => number): PixelMapping {
  const qScale = x(1) - x(0);
  const pScale = y(1) - y(0);
  return { width, height, qScale, qOffset: x(0), pScale, pOffset: y(0) };
}

/**
 * The image word of a computed colour, `rgb(r, g, b)` or `rgba(r, g, b, a)`
 * as getComputedStyle gives it (plots/theme.ts): bytes R, G, B, A in memory
 * order, which on the little-endian machines browsers run on is A·2²⁴ + B·2¹⁶ + G·2⁸ + R.
 */
export function pixelWord(colour: string): number {
  const m = /rgba?\(([^)]+)\)/.exec(colour);
  const [r = 0, g = 0, b = 0, a = 1] = m ? m[1].split(/[\s,/]+/).filter(Boolean).map(Number) : [];
  const alpha = Math.round(Math.min(1, Math.max(0, a)) * 255);
  return ((alpha << 24) | (b << 16) | (g << 8) | r) >>> 0;
}

/** Marks each point of `pairs` (x, y one after the other) in `pixels` with `colour`; returns the points that fell on the image. */
export function markPoints(pixels: Uint32Array, to: PixelMapping, pairs: ArrayLike<number>, colour: number): number {
  const { width, height, qScale, qOffset, pScale, pOffset } = to;
  let marked = 0;
  for (let i = 0; i + 1 < pairs.length; i += 2) {
    const x = Math.floor(qScale * pairs[i] + qOffset);
    const y = Math.floor(pScale * pairs[i + 1] + pOffset);
    if (x >= 0 && x < width && y >= 0 && y < height) {
      pixels[y * width + x] = colour;
      marked++;
    }
  }
  return marked;
}

/** Where a panel's plotting area falls on the canvas in device pixels, and the plane's mapping onto an image of that size. */
export interface PixelArea {
  readonly left: number;
  readonly top: number;
  readonly to: PixelMapping;
}

/** The plotting area `rect` (CSS px) of a drawing at pixel ratio `dpr`, with the plane mapped by `mx` and `my`. */
export function pixelArea(rect: { left: number; top: number; width: number; height: number }, dpr: number, mx: { scale: (x: number) => number }, my: { scale: (y: number) => number }): PixelArea {
  const left = Math.round(rect.left * dpr);
  const top = Math.round(rect.top * dpr);
  const width = Math.max(1, Math.round(rect.width * dpr));
  const height = Math.max(1, Math.round(rect.height * dpr));
  return { left, top, to: pixelMapping(width, height, (q) => mx.scale(q) * dpr - left, (p) => my.scale(p) * dpr - top) };
}

/**
 * Lays `image` over the plotting area through `layer`, a canvas kept for it:
 * the points are an image of their own, put over the background, with no
 * read back from the drawing's canvas.
 */
export function drawPixels(g: CanvasRenderingContext2D, layer: HTMLCanvasElement, area: PixelArea, image: ImageData, dpr: number): void {
  // Resized only when the image's size changes: setting a canvas's size, even to the same, reallocates it.
  if (layer.width !== image.width || layer.height !== image.height) [layer.width, layer.height] = [image.width, image.height];
  layer.getContext('2d')?.putImageData(image, 0, 0);
  // g draws in CSS pixels: the image's device pixels fall one to one on the canvas's.
  g.drawImage(layer, area.left / dpr, area.top / dpr, image.width / dpr, image.height / dpr);
}
