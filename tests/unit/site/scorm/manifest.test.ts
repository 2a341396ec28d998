import { describe, expect, it } from 'vitest';
import { escapeXml, packageHref, scormManifest } from '../../../../site/scorm/manifest.ts';

/** The values of one attribute on every element of one name, read back as XML reads them. */
function attributes(xml: string, element: string, attribute: string): string[] {
  const unescape = (text: string) => text.replace(/&(lt|gt|quot|apos|amp);/g, (_all, name: string) => ({ lt: '<', gt: '>', quot: '"', apos: "'", amp: '&' })[name]!);
  return [...xml.matchAll(new RegExp(`<${element}\\s[^>]*?\\b${attribute}="([^"]*)"`, 'g'))].map((m) => unescape(m[1]));
}

describe('site/scorm/manifest.ts: a chapter’s imsmanifest.xml (SCORM 1.2)', () => {
  const files = ['introduction/index.html', '_astro/core.B1x.js', '_astro/KaTeX_Main-Regular.B22.woff2', 'phasebook-scorm.js'];
  const xml = scormManifest({ slug: 'introduction', title: 'Introduction — Phasebook', launch: 'introduction/index.html', files });

  it('names ADL SCORM 1.2 and the SCORM 1.2 namespaces', () => {
    expect(xml).toMatch(/^<\?xml version="1.0" encoding="UTF-8"\?>/);
    expect(xml).toContain('<schema>ADL SCORM</schema>');
    expect(xml).toContain('<schemaversion>1.2</schemaversion>');
    expect(xml).toContain('xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2"');
    expect(xml).toContain('xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2"');
  });

  it('has one organization with one item, launching one SCO resource at the chapter’s page', () => {
    const organizations = attributes(xml, 'organization', 'identifier');
    expect(organizations).toHaveLength(1);
    expect(attributes(xml, 'organizations', 'default')).toEqual(organizations);
    const items = attributes(xml, 'item', 'identifierref');
    expect(items).toHaveLength(1);
    expect(attributes(xml, 'resource', 'identifier')).toEqual(items);
    expect(attributes(xml, 'resource', 'adlcp:scormtype')).toEqual(['sco']);
    expect(attributes(xml, 'resource', 'href')).toEqual(['introduction/index.html']);
  });

  it('lists every file of the package once, and nothing else', () => {
    expect(attributes(xml, 'file', 'href').sort()).toEqual([...files].sort());
  });

  it('escapes names and titles for XML and for a URI', () => {
    const odd = ['a&b/index.html', '_astro/x"y<z>.js', "it's here.css"];
    const made = scormManifest({ slug: 'a&b', title: 'Lagrange & <Hamilton> "quoted"', launch: 'a&b/index.html', files: odd });
    expect(made).not.toMatch(/&(?!amp;|lt;|gt;|quot;|apos;)/);
    expect(made).toContain('<title>Lagrange &amp; &lt;Hamilton&gt; &quot;quoted&quot;</title>');
    expect(attributes(made, 'file', 'href').map(decodeURIComponent).sort()).toEqual([...odd].sort());
    expect(attributes(made, 'file', 'href')).toContain("it's%20here.css");
    for (const id of attributes(made, 'resource', 'identifier')) expect(id).toMatch(/^[A-Za-z_][A-Za-z0-9._-]*$/);
    expect(escapeXml(`<&>"'`)).toBe('&lt;&amp;&gt;&quot;&apos;');
    expect(packageHref('_astro/a b#c.js')).toBe('_astro/a%20b%23c.js');
  });

  it('refuses a launch page that is not in the package', () => {
    expect(() => scormManifest({ slug: 'x', title: 'X', launch: 'x/index.html', files: ['y/index.html'] })).toThrow(/not among/);
  });
});
