import { describe, expect, it } from 'vitest';
import { fontLoader, mathFaceCss, mathPreloads, textFaceCss } from '../../../site/lib/fonts.ts';

/** The @font-face rules of a stylesheet, as `family → font-display values`. */
function displays(css: string): Map<string, Set<string>> {
  const byFamily = new Map<string, Set<string>>();
  for (const rule of css.match(/@font-face\{[^}]*\}/g) ?? []) {
    const family = /font-family:'([^']+)'/.exec(rule)?.[1] ?? '?';
    const display = /font-display:(\w+)/.exec(rule)?.[1] ?? 'none';
    byFamily.set(family, (byFamily.get(family) ?? new Set()).add(display));
  }
  return byFamily;
}

describe('site/lib/fonts.ts: math waits for its faces, prose does not', () => {
  it("declares every KaTeX family (KaTeX 0.16's stylesheet lists 20 files in 12 families) with font-display: block", () => {
    const math = displays(mathFaceCss);
    expect([...math.keys()].sort()).toEqual([
      'KaTeX_AMS', 'KaTeX_Caligraphic', 'KaTeX_Fraktur', 'KaTeX_Main', 'KaTeX_Math', 'KaTeX_SansSerif', 'KaTeX_Script',
      'KaTeX_Size1', 'KaTeX_Size2', 'KaTeX_Size3', 'KaTeX_Size4', 'KaTeX_Typewriter',
    ]);
    for (const [family, values] of math) expect([family, [...values]]).toEqual([family, ['block']]);
    expect(mathFaceCss.match(/@font-face/g)).toHaveLength(20);
  });

  it('declares the text faces optional, and no KaTeX face among them', () => {
    const text = displays(textFaceCss);
    expect([...text.keys()].sort()).toEqual(['Inter Variable', 'JetBrains Mono', 'Source Serif 4 Variable']);
    for (const values of text.values()) expect([...values]).toEqual(['optional']);
  });

  it("leaves math out of the head script's slow-connection rule: the script declares only the text faces", () => {
    for (const chapter of [false, true]) {
      const script = fontLoader(chapter);
      expect(script).toContain(JSON.stringify(textFaceCss));
      expect(script).not.toContain('KaTeX');
    }
  });

  it('preloads the two math faces of a first view as files of the site', () => {
    expect(mathPreloads).toHaveLength(2);
    expect(mathPreloads[0]).toMatch(/KaTeX_Main-Regular\.[\w-]*\.?woff2$/);
    expect(mathPreloads[1]).toMatch(/KaTeX_Math-Italic\.[\w-]*\.?woff2$/);
  });
});
