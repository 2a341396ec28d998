/**
 * The drawing surface shared by the plots. Drawing code takes a `Context`,
 * the minimal subset of CanvasRenderingContext2D it uses, so unit tests can
 * pass a recording fake (tests/unit/support/fake-canvas.ts) instead of a
 * browser canvas.
 */

export type Context = Pick<
  CanvasRenderingContext2D,
  | 'beginPath'
  | 'moveTo'
  | 'lineTo'
  | 'stroke'
  | 'fill'
  | 'arc'
  | 'rect'
  | 'fillRect'
  | 'clearRect'
  | 'fillText'
  | 'measureText'
  | 'drawImage'
  | 'save'
  | 'restore'
  | 'setTransform'
> & {
  strokeStyle: string | CanvasGradient | CanvasPattern;
  fillStyle: string | CanvasGradient | CanvasPattern;
  lineWidth: number;
  lineJoin: CanvasLineJoin;
  lineCap: CanvasLineCap;
  globalAlpha: number;
  font: string;
  textAlign: CanvasTextAlign;
  textBaseline: CanvasTextBaseline;
};

/** What a plot needs to make its offscreen buffers: a canvas of a given device-pixel size. */
export interface Surface {
  width: number;
  height: number;
  getContext(kind: '2d'): Context | null;
}

export type SurfaceFactory = (width: number, height: number) => Surface;

/** An offscreen canvas element, which drawImage and toBlob both accept. */
export const createSurface: SurfaceFactory = (width, height) => {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  return canvas as Surface;
};

/** The 2D context of a surface, or a one-line error when the browser gives none. */
export function context2d(surface: Surface): Context {
  const ctx = surface.getContext('2d');
  if (!ctx) throw new Error('this browser gave no 2D canvas context');
  return ctx;
}

/** The device pixel ratio, rounded to a quarter so tiny zoom steps do not resize buffers. */
export function pixelRatio(): number {
  const dpr = typeof window === 'undefined' ? 1 : window.devicePixelRatio || 1;
  return Math.max(1, Math.round(dpr * 4) / 4);
}

/**
 * Sizes a visible canvas to `cssWidth × cssHeight` CSS pixels backed by
 * device pixels, so lines stay crisp on HiDPI screens. Returns true when the
 * backing store changed (and so was cleared).
 */
export function sizeCanvas(canvas: HTMLCanvasElement, cssWidth: number, cssHeight: number, ratio: number): boolean {
  const width = Math.max(1, Math.round(cssWidth * ratio));
  const height = Math.max(1, Math.round(cssHeight * ratio));
  canvas.style.width = `${cssWidth}px`;
  canvas.style.height = `${cssHeight}px`;
  if (canvas.width === width && canvas.height === height) return false;
  canvas.width = width;
  canvas.height = height;
  return true;
}

/**
 * Sizes a visible canvas (sizeCanvas) and returns its 2D context set to draw
 * in CSS pixels, or null when the browser gives none.
 */
export function scaledContext(canvas: HTMLCanvasElement, cssWidth: number, cssHeight: number, ratio: number): CanvasRenderingContext2D | null {
  sizeCanvas(canvas, cssWidth, cssHeight, ratio);
  const g = canvas.getContext('2d');
  g?.setTransform(ratio, 0, 0, ratio, 0, 0);
  return g;
}
