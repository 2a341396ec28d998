/**
 * The links of a PDF, read from its objects: poppler's pdftotext and pdfinfo
 * do not show them. Enough of PDF for a file Chromium (Skia) writes: plain
 * (uncompressed) objects for the catalog, the page tree, the annotations and
 * the named destinations; streams are skipped.
 */

/** A PDF name's characters, #xx escapes decoded. */
const nameOf = (raw) => raw.replace(/#([0-9a-fA-F]{2})/g, (_, hex) => String.fromCharCode(parseInt(hex, 16)));

/** Every `N 0 obj … endobj` of the file, its dictionary text (a stream's data left out), by number. */
function objectsOf(text) {
  const objects = new Map();
  for (const m of text.matchAll(/(\d+) 0 obj\b([\s\S]*?)\bendobj/g)) {
    const body = m[2];
    const stream = body.indexOf('stream');
    objects.set(Number(m[1]), stream >= 0 ? body.slice(0, stream) : body);
  }
  return objects;
}

const refOf = (dict, key) => {
  const m = dict.match(new RegExp(`/${key}\\s+(\\d+) 0 R`));
  return m ? Number(m[1]) : null;
};

/**
 * @param {Buffer} bytes the PDF
 * @returns {{ pages: number, destinations: Map<string, number>, links: { page: number, destination: string | null, uri: string | null }[] }}
 *   pages counted from 1; `destinations` maps each named destination to its page; each link annotation with
 *   the page it is on and its named destination (an internal link) or address (an external one)
 */
export function readLinks(bytes) {
  const text = bytes.toString('latin1');
  const objects = objectsOf(text);
  const trailerRoot = [...text.matchAll(/\/Root\s+(\d+) 0 R/g)].pop();
  if (!trailerRoot) throw new Error('no /Root in the PDF');
  const catalog = objects.get(Number(trailerRoot[1])) ?? '';
  // The pages in order: the page tree's leaves, depth first.
  const pageOrder = [];
  const walk = (number) => {
    const node = objects.get(number) ?? '';
    if (/\/Type\s*\/Pages\b/.test(node)) {
      const kids = node.match(/\/Kids\s*\[([^\]]*)\]/);
      for (const kid of kids?.[1].matchAll(/(\d+) 0 R/g) ?? []) walk(Number(kid[1]));
    } else pageOrder.push(number);
  };
  walk(refOf(catalog, 'Pages'));
  const pageIndex = new Map(pageOrder.map((number, i) => [number, i + 1]));

  const destinations = new Map();
  const dests = objects.get(refOf(catalog, 'Dests')) ?? '';
  for (const m of dests.matchAll(/\/([^\s/[\]<>()]+)\s*\[\s*(\d+) 0 R/g)) destinations.set(nameOf(m[1]), pageIndex.get(Number(m[2])) ?? null);

  const links = [];
  pageOrder.forEach((number, i) => {
    const page = objects.get(number) ?? '';
    const annots = page.match(/\/Annots\s*\[([^\]]*)\]/);
    for (const ref of annots?.[1].matchAll(/(\d+) 0 R/g) ?? []) {
      const annot = objects.get(Number(ref[1])) ?? '';
      if (!/\/Subtype\s*\/Link\b/.test(annot)) continue;
      const destination = annot.match(/\/Dest\s*\/([^\s/[\]<>()]+)/) ?? annot.match(/\/S\s*\/GoTo\s*\/D\s*\/([^\s/[\]<>()]+)/);
      const uri = annot.match(/\/URI\s*\(((?:\\.|[^\\)])*)\)/);
      links.push({ page: i + 1, destination: destination ? nameOf(destination[1]) : null, uri: uri ? uri[1].replace(/\\(.)/g, '$1') : null });
    }
  });
  return { pages: pageOrder.length, destinations, links };
}
