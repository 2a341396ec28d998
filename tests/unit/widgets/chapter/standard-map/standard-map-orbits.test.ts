/**
 * The portrait's pixels (widgets/chapter/standard-map/standard-map-orbits.ts):
 * the lattice of starts, the torus's p, the colour words an image holds, and
 * the marking of orbits, checked against the standard map written out here
 * (p' = p + K sin q, q' = q + p' mod 2π; Chirikov 1979) and, at K = 0, its
 * closed form: every orbit stays on its line p = p0.
 */
import { expect, test } from 'vitest';
import { standardMap } from '../../../../../core/index.ts';
import { markOrbits, P_DOMAIN, startGrid, torusP } from '../../../../../widgets/chapter/standard-map/standard-map-orbits.ts';
import { pixelMapping, pixelWord } from '../../../../../widgets/plots/pixel-image.ts';

const TWO_PI = 2 * Math.PI;

test('the lattice has the square number of starts nearest the count asked, all on the torus, none on q = 0 or π', () => {
  const grid = startGrid(1000);
  expect(grid.length).toBe(2 * 32 * 32);
  const starts = Array.from({ length: grid.length / 2 }, (_, k) => [grid[2 * k], grid[2 * k + 1]]);
  for (const [q, p] of starts) {
    expect(q).toBeGreaterThan(0);
    expect(q).toBeLessThan(TWO_PI);
    expect(p).toBeGreaterThanOrEqual(P_DOMAIN[0]);
    expect(p).toBeLessThan(P_DOMAIN[1]);
    expect(Math.abs(q - Math.PI)).toBeGreaterThan(1e-3);
  }
  expect(new Set(starts.map(([q, p]) => `${q},${p}`)).size).toBe(starts.length);
});

test('torusP reduces p into [−π, π) by whole turns', () => {
  for (const p of [-20, -Math.PI, -1, 0, 1, Math.PI, 7, 100]) {
    const r = torusP(p);
    expect(r).toBeGreaterThanOrEqual(-Math.PI);
    expect(r).toBeLessThan(Math.PI);
    const turns = (p - r) / TWO_PI;
    expect(Math.abs(turns - Math.round(turns))).toBeLessThan(1e-12);
  }
});

test('pixelWord packs a computed colour as the bytes R, G, B, A of an image', () => {
  const word = pixelWord('rgb(47, 125, 225)');
  const bytes = new Uint8ClampedArray(new Uint32Array([word]).buffer);
  expect([...bytes]).toEqual([47, 125, 225, 255]);
  expect([...new Uint8ClampedArray(new Uint32Array([pixelWord('rgba(1, 2, 3, 0.5)')]).buffer)]).toEqual([1, 2, 3, 128]);
});

/** A 64 × 64 image of the torus, q across and p up. */
const x = (q: number) => (q / TWO_PI) * 64;
const y = (p: number) => ((Math.PI - p) / TWO_PI) * 64;
const image = pixelMapping(64, 64, x, y);

test('at K = 0 each orbit marks only its own row: p is kept, the closed form of the free rotor', () => {
  const pixels = new Uint32Array(64 * 64);
  const p0 = 0.5;
  const marked = markOrbits(pixels, image, standardMap(0), Float64Array.of(0.1, p0), 500, new Uint32Array([7]));
  expect(marked).toBe(500);
  const row = Math.floor(y(p0));
  for (let i = 0; i < 64; i++) for (let j = 0; j < 64; j++) if (pixels[i * 64 + j]) expect(i).toBe(row);
});

test('at K = 1.2 the pixels marked are those of the map written out here, each orbit in its colour, whether drawn at once or in parts', () => {
  const K = 1.2;
  const starts: Array<[number, number]> = [[1, 0.3], [4, -2]];
  const pixels = new Uint32Array(64 * 64);
  markOrbits(pixels, image, standardMap(K), Float64Array.from(starts.flat()), 25, new Uint32Array([1, 2]));
  const expected = new Uint32Array(64 * 64);
  starts.forEach(([q, p], k) => {
    for (let n = 0; n < 25; n++) {
      p += K * Math.sin(q);
      q = (((q + p) % TWO_PI) + TWO_PI) % TWO_PI;
      const wrapped = p - TWO_PI * Math.floor((p + Math.PI) / TWO_PI);
      expected[Math.floor(y(wrapped)) * 64 + Math.floor(x(q))] = k + 1;
    }
  });
  // Over 25 iterates the two ways of keeping q and p on the torus differ by a few roundings, grown by at most
  // e^{25λ} with λ < 0.5 here: far below a pixel, so the images are the same (a longer chaotic orbit would not be).
  expect([...pixels]).toEqual([...expected]);
  expect(pixels.filter((w) => w === 1).length).toBeGreaterThan(10);
  expect(pixels.filter((w) => w === 2).length).toBeGreaterThan(10);
  // the same 25 iterates in parts of 10, 10 and 5, the states carried on between them
  const inParts = new Uint32Array(64 * 64);
  const states = Float64Array.from(starts.flat());
  const marked = [10, 10, 5].reduce((sum, part) => sum + markOrbits(inParts, image, standardMap(K), states, part, new Uint32Array([1, 2])), 0);
  expect(marked).toBe(50);
  expect([...inParts]).toEqual([...pixels]);
});

test('pixelMapping is the affine map through the scales it is given', () => {
  const m = pixelMapping(10, 10, (q) => 3 * q + 1, (p) => -2 * p + 5);
  expect([m.qScale, m.qOffset, m.pScale, m.pOffset]).toEqual([3, 1, -2, 5]);
});
