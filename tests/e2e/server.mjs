/**
 * A tiny static file server over the built site (dist/), for the e2e tests:
 * 127.0.0.1 on a free port, real MIME types, `/<slug>/` → `<slug>/index.html`,
 * and a redirect from `/<slug>` to `/<slug>/` as static hosts do; at the
 * root of the host, or under a base path as a GitHub project site is.
 * Nothing is cached, so every test sees exactly the requests a page makes.
 * Text is sent gzip-compressed when the browser accepts it, as GitHub Pages
 * and other static hosts send it, so that load times measured through it
 * (bench/cold-load.mjs) are what a reader of the published book meets.
 */
import { createServer } from 'node:http';
import { createReadStream } from 'node:fs';
import { createGzip } from 'node:zlib';
import { stat } from 'node:fs/promises';
import { extname, join, normalize, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

export const DIST = process.env.PHASEBOOK_OUT_DIR ?? fileURLToPath(new URL('../../dist/', import.meta.url));

const MIME_TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.webp': 'image/webp',
  '.ico': 'image/x-icon',
  '.woff2': 'font/woff2',
  '.woff': 'font/woff',
  '.ttf': 'font/ttf',
  '.txt': 'text/plain; charset=utf-8',
  '.xml': 'application/xml; charset=utf-8',
};

/** The types static hosts compress. */
const COMPRESSIBLE = /^(text\/|application\/(json|xml)|image\/svg)/;

async function fileAt(path) {
  try {
    return await stat(path);
  } catch {
    return null;
  }
}

/**
 * @param {string} root directory to serve (default: dist/)
 * @param {{ base?: string }} [options] `base`: serve the site under this path (`/phasebook/`), as a
 *   project site is served, and nothing outside it
 * @returns {Promise<{ origin: string, close: () => Promise<void> }>}
 */
export async function startServer(root = DIST, { base: mount = '/' } = {}) {
  const base = resolve(root);
  if (!(await fileAt(join(base, 'index.html')))) {
    throw new Error(`No built site in ${base}: run \`npm run build\` first.`);
  }
  const server = createServer(async (request, response) => {
    const url = new URL(request.url ?? '/', 'http://127.0.0.1');
    // The path inside the site: under a base path, what lies outside it is not the site's.
    const inside = url.pathname.startsWith(mount) ? `/${url.pathname.slice(mount.length)}` : url.pathname === mount.slice(0, -1) ? '/' : null;
    if (inside === null) {
      response.writeHead(404, { 'Content-Type': MIME_TYPES['.txt'], 'Cache-Control': 'no-store' }).end('Not found');
      return;
    }
    let path;
    try {
      path = normalize(join(base, decodeURIComponent(inside)));
    } catch {
      response.writeHead(400).end('Bad request');
      return;
    }
    if (path !== base && !path.startsWith(base + sep)) {
      response.writeHead(403).end('Forbidden');
      return;
    }
    let info = await fileAt(path);
    if (info?.isDirectory()) {
      if (!url.pathname.endsWith('/')) {
        response.writeHead(301, { Location: `${url.pathname}/${url.search}` }).end();
        return;
      }
      path = join(path, 'index.html');
      info = await fileAt(path);
    }
    if (!info?.isFile()) {
      const notFound = join(base, '404.html');
      const page = await fileAt(notFound);
      response.writeHead(404, { 'Content-Type': MIME_TYPES['.html'], 'Cache-Control': 'no-store' });
      if (page) createReadStream(notFound).pipe(response);
      else response.end('Not found');
      return;
    }
    const type = MIME_TYPES[extname(path)] ?? 'application/octet-stream';
    const gzip = COMPRESSIBLE.test(type) && /\bgzip\b/.test(String(request.headers['accept-encoding'] ?? ''));
    response.writeHead(200, {
      'Content-Type': type,
      'Cache-Control': 'no-store',
      Vary: 'Accept-Encoding',
      ...(gzip ? { 'Content-Encoding': 'gzip' } : { 'Content-Length': info.size }),
    });
    if (request.method === 'HEAD') response.end();
    else if (gzip) createReadStream(path).pipe(createGzip({ level: 9 })).pipe(response);
    else createReadStream(path).pipe(response);
  });
  await new Promise((ready) => server.listen(0, '127.0.0.1', ready));
  const address = server.address();
  const port = typeof address === 'object' && address ? address.port : 0;
  return {
    origin: `http://127.0.0.1:${port}`,
    close: () => new Promise((done) => server.close(() => done())),
  };
}
