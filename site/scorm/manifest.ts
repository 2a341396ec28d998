/**
 * A chapter's `imsmanifest.xml`, as SCORM 1.2 asks for it (ADL SCORM 1.2
 * Content Aggregation Model, section 2.3): the IMS Content Packaging 1.1.2
 * manifest with ADL's extension namespace, metadata naming ADL SCORM 1.2,
 * one organization holding one item, and one SCO resource that the item
 * launches, listing every file of the package.
 */

export interface ManifestInput {
  /** The chapter's slug: the identifiers are made from it. */
  readonly slug: string;
  /** The chapter's title, as the LMS shows it. */
  readonly title: string;
  /** The launch page, a path inside the package (`introduction/index.html`). */
  readonly launch: string;
  /** Every file of the package but the manifest itself, as paths inside it. */
  readonly files: readonly string[];
}

/** Text for XML content or a quoted attribute: the five characters XML reserves, escaped. */
export function escapeXml(text: string): string {
  return text.replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&apos;' })[c]!);
}

/** A path inside the package as a relative URI: each segment percent-encoded where a URI needs it. */
export function packageHref(path: string): string {
  return path.split('/').map(encodeURIComponent).join('/');
}

/** An identifier (XML's NCName, as the schema types it) from a slug: letters, digits, '-', '_' and '.', never starting with a digit. */
function identifier(prefix: string, slug: string): string {
  return `${prefix}-${slug.replace(/[^A-Za-z0-9._-]/g, '_')}`;
}

export function scormManifest({ slug, title, launch, files }: ManifestInput): string {
  if (!files.includes(launch)) throw new Error(`the launch page ${launch} is not among the package's files`);
  const resource = identifier('sco', slug);
  const item = identifier('item', slug);
  const organization = identifier('phasebook', slug);
  const fileLines = [...files].sort().map((file) => `      <file href="${escapeXml(packageHref(file))}"/>`);
  return [
    '<?xml version="1.0" encoding="UTF-8"?>',
    `<manifest identifier="${identifier('manifest', slug)}" version="1.0"`,
    '    xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2"',
    '    xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2"',
    '    xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"',
    '    xsi:schemaLocation="http://www.imsproject.org/xsd/imscp_rootv1p1p2 imscp_rootv1p1p2.xsd http://www.imsglobal.org/xsd/imsmd_rootv1p2p1 imsmd_rootv1p2p1.xsd http://www.adlnet.org/xsd/adlcp_rootv1p2 adlcp_rootv1p2.xsd">',
    '  <metadata>',
    '    <schema>ADL SCORM</schema>',
    '    <schemaversion>1.2</schemaversion>',
    '  </metadata>',
    `  <organizations default="${organization}">`,
    `    <organization identifier="${organization}">`,
    `      <title>${escapeXml(title)}</title>`,
    `      <item identifier="${item}" identifierref="${resource}" isvisible="true">`,
    `        <title>${escapeXml(title)}</title>`,
    '      </item>',
    '    </organization>',
    '  </organizations>',
    '  <resources>',
    `    <resource identifier="${resource}" type="webcontent" adlcp:scormtype="sco" href="${escapeXml(packageHref(launch))}">`,
    ...fileLines,
    '    </resource>',
    '  </resources>',
    '</manifest>',
    '',
  ].join('\n');
}
