#!/usr/bin/env node
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A tiny static file server for the playground: serves the repository root on 127.0.0.1 only,
// with the MIME types browsers insist on (`application/wasm` for streaming compilation,
// `text/javascript` for module scripts and workers). No dependencies, no directory listings.
//
//   node scripts/serve.mjs [--port 8080] [--root DIR]
//
// (or PORT=8080; --port 0 picks a free port). --root serves another folder, e.g. the published
// site (`--root dist/site`), at / instead of the repository at /web/.
//
// Like a well-configured static host it sends validators and answers conditional requests:
// every file gets an ETag and a Last-Modified date, `Cache-Control: no-cache` (the browser may
// keep a copy but asks each time, so a rebuilt dist/ is picked up on reload), and a request
// whose If-None-Match (or If-Modified-Since) still matches gets `304 Not Modified` with no body.
// Precompressed files are served when the client accepts them: for `x.js`, a `x.js.br` or
// `x.js.gz` beside it (as scripts/build-site.mjs writes) that is not older than `x.js` is sent
// with `Content-Encoding: br` or `gzip`, `Vary: Accept-Encoding` and the type of `x.js`.
//
// It prints the playground URL on stdout as its first line, so scripts and tests can read the
// port back when they asked for port 0.

import { createServer } from 'node:http';
import { createReadStream } from 'node:fs';
import { realpath, stat } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const HOST = '127.0.0.1';
const DEFAULT_PORT = 8080;
const REPO_ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

const MIME_TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.puz': 'text/plain; charset=utf-8',
  '.txt': 'text/plain; charset=utf-8',
  '.md': 'text/markdown; charset=utf-8',
  '.obj': 'text/plain; charset=utf-8',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.jpeg': 'image/jpeg',
  '.gif': 'image/gif',
  '.ico': 'image/x-icon',
  '.webp': 'image/webp',
};

/** MIME type for a file name; unknown files are served as opaque bytes. */
export function mimeTypeFor(fileName) {
  return MIME_TYPES[path.extname(fileName).toLowerCase()] ?? 'application/octet-stream';
}

/**
 * Maps a URL path to an absolute file path inside `root`, or returns null when the path is
 * malformed, names a hidden entry, or would escape the root (`..`, encoded separators, NUL bytes).
 */
export function resolveInsideRoot(root, urlPath) {
  let decoded;
  try {
    decoded = decodeURIComponent(urlPath);
  } catch {
    return null;
  }
  if (decoded.includes('\0') || decoded.includes('\\')) return null;
  // Hidden entries (.git, .env, ...) are never part of the playground.
  if (decoded.split('/').some((segment) => segment.startsWith('.') && segment !== '.' && segment !== '..')) {
    return null;
  }
  // No normalisation first: a `..` that climbs above the root must be refused, not clamped.
  const resolved = path.resolve(root, '.' + decoded);
  return isInside(root, resolved) ? resolved : null;
}

function isInside(root, candidate) {
  return candidate === root || candidate.startsWith(root + path.sep);
}

function sendText(response, status, text, extraHeaders = {}) {
  response.writeHead(status, {
    'Content-Type': 'text/plain; charset=utf-8',
    'Content-Length': Buffer.byteLength(text),
    ...extraHeaders,
  });
  response.end(text);
}

function redirect(response, location) {
  sendText(response, 302, `Found: ${location}\n`, { Location: location });
}

/** Serves one request; everything that is not a readable file inside the root is an error. */
async function handleRequest({ root, home, onResponse }, request, response) {
  if (request.method !== 'GET' && request.method !== 'HEAD') {
    sendText(response, 405, 'Method not allowed\n', { Allow: 'GET, HEAD' });
    return;
  }
  // The raw path, not `new URL(...).pathname`: the URL parser would silently clamp `/../`.
  const rawPath = (request.url ?? '/').split(/[?#]/, 1)[0];
  const search = (request.url ?? '').slice(rawPath.length).split('#', 1)[0];
  if (rawPath === '/' && home !== '/') {
    redirect(response, home);
    return;
  }
  const filePath = rawPath.startsWith('/') ? resolveInsideRoot(root, rawPath) : null;
  if (filePath === null) {
    sendText(response, 403, 'Forbidden\n');
    return;
  }
  let target = filePath;
  let info;
  try {
    // Follow symlinks only as long as they stay inside the root.
    target = await realpath(filePath);
    if (!isInside(root, target)) {
      sendText(response, 403, 'Forbidden\n');
      return;
    }
    info = await stat(target);
    if (info.isDirectory()) {
      // Directories need a trailing slash so relative URLs in their index.html resolve.
      if (!rawPath.endsWith('/')) {
        redirect(response, rawPath + '/' + search);
        return;
      }
      target = path.join(target, 'index.html');
      info = await stat(target);
    }
    if (!info.isFile()) throw Object.assign(new Error('not a file'), { code: 'ENOENT' });
  } catch (error) {
    const missing = error.code === 'ENOENT' || error.code === 'ENOTDIR';
    sendText(response, missing ? 404 : 500, missing ? 'Not found\n' : 'Internal error\n');
    return;
  }
  const variant = await pickEncoding(target, info, request.headers['accept-encoding']);
  const validators = {
    ETag: `"${info.size.toString(16)}-${Math.floor(info.mtimeMs).toString(16)}${variant ? `-${variant.suffix}` : ''}"`,
    'Last-Modified': new Date(Math.floor(info.mtimeMs / 1000) * 1000).toUTCString(),
  };
  const common = {
    ...validators,
    // A development server: always revalidate so a rebuilt dist/ is picked up on reload (a
    // 304 costs a round trip, not the file).
    'Cache-Control': 'no-cache',
    'X-Content-Type-Options': 'nosniff',
    ...(variant !== undefined ? { Vary: 'Accept-Encoding' } : {}),
  };
  if (notModified(request.headers, validators.ETag, info.mtimeMs)) {
    response.writeHead(304, common);
    response.end();
    onResponse?.({ method: request.method, path: rawPath, status: 304, bytes: 0, headerBytes: headerLength(response), encoding: null });
    return;
  }
  const sent = variant ?? { file: target, size: info.size, encoding: null };
  response.writeHead(200, {
    'Content-Type': mimeTypeFor(target),
    'Content-Length': sent.size,
    ...(sent.encoding ? { 'Content-Encoding': sent.encoding } : {}),
    ...common,
  });
  onResponse?.({
    method: request.method, path: rawPath, status: 200, bytes: request.method === 'HEAD' ? 0 : sent.size,
    headerBytes: headerLength(response), encoding: sent.encoding,
  });
  if (request.method === 'HEAD') {
    response.end();
    return;
  }
  const stream = createReadStream(sent.file);
  stream.on('error', () => response.destroy());
  stream.pipe(response);
}

/** The length of a response's status line and headers as sent (HTTP/1.1), for byte counts. */
function headerLength(response) {
  let length = `HTTP/1.1 ${response.statusCode} ${response.statusMessage ?? ''}\r\n\r\n`.length;
  for (const [name, value] of Object.entries(response.getHeaders())) length += `${name}: ${value}\r\n`.length;
  // Node adds Date, Connection and Keep-Alive itself.
  return length + 80;
}

/** Encodings served from precompressed files beside the original, best first. */
const PRECOMPRESSED = [
  { encoding: 'br', suffix: 'br', extension: '.br' },
  { encoding: 'gzip', suffix: 'gz', extension: '.gz' },
];

/** The encodings an Accept-Encoding header allows (q=0 refuses one). */
export function acceptedEncodings(header) {
  const accepted = new Set();
  for (const part of String(header ?? '').split(',')) {
    const [name, ...parameters] = part.trim().toLowerCase().split(';');
    if (!name) continue;
    const q = parameters.map((p) => p.trim()).find((p) => p.startsWith('q='));
    if (q !== undefined && !(Number(q.slice(2)) > 0)) continue;
    accepted.add(name);
  }
  return accepted;
}

/**
 * The precompressed variant of `target` to send, or null when none applies; undefined when the
 * file has no variant at all (then the answer does not vary with Accept-Encoding).
 */
async function pickEncoding(target, info, acceptEncoding) {
  const accepted = acceptedEncodings(acceptEncoding);
  let any;
  for (const { encoding, suffix, extension } of PRECOMPRESSED) {
    let variant;
    try {
      variant = await stat(target + extension);
    } catch {
      continue;
    }
    // A stale variant (the file was rebuilt after it) is ignored.
    if (!variant.isFile() || variant.mtimeMs < info.mtimeMs) continue;
    any = null;
    if (accepted.has(encoding) || accepted.has('*')) return { file: target + extension, size: variant.size, encoding, suffix };
  }
  return any;
}

/** Whether a conditional GET can be answered with 304 (If-None-Match wins over the date). */
function notModified(headers, etag, mtimeMs) {
  const ifNoneMatch = headers['if-none-match'];
  if (ifNoneMatch !== undefined) {
    return ifNoneMatch.trim() === '*' || ifNoneMatch.split(',').map((tag) => tag.trim().replace(/^W\//, '')).includes(etag);
  }
  const since = Date.parse(headers['if-modified-since'] ?? '');
  return Number.isFinite(since) && Math.floor(mtimeMs / 1000) * 1000 <= since;
}

/**
 * Starts the server. Resolves to `{ server, port, url, close }` once it listens;
 * `url` is the playground page: /web/ of the repository, or / of another root. `onResponse`,
 * if given, is called for every file answered with { method, path, status (200 or 304), bytes
 * (the body's length as sent, compressed or not), encoding }.
 */
export async function startServer({ port = DEFAULT_PORT, root = REPO_ROOT, onResponse = null } = {}) {
  const realRoot = await realpath(root);
  const home = realRoot === await realpath(REPO_ROOT) ? '/web/' : '/';
  const server = createServer((request, response) => {
    handleRequest({ root: realRoot, home, onResponse }, request, response).catch(() => {
      if (!response.headersSent) sendText(response, 500, 'Internal error\n');
      else response.destroy();
    });
  });
  await new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, HOST, () => {
      server.off('error', reject);
      resolve();
    });
  });
  const actualPort = server.address().port;
  return {
    server,
    port: actualPort,
    url: `http://${HOST}:${actualPort}${home}`,
    close: () => new Promise((resolve) => server.close(() => resolve())),
  };
}

/** The value of `--NAME V` / `--NAME=V` on the command line, or undefined. */
function option(argv, name) {
  let value;
  for (let i = 0; i < argv.length; i += 1) {
    if (argv[i] === `--${name}`) value = argv[i + 1];
    else if (argv[i].startsWith(`--${name}=`)) value = argv[i].slice(name.length + 3);
  }
  return value;
}

/** Port from `--port N` / `--port=N`, else $PORT, else the default. */
function portFromCommandLine(argv, env) {
  const value = option(argv, 'port') ?? env.PORT;
  if (value === undefined || value === '') return DEFAULT_PORT;
  const port = Number(value);
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    throw new Error(`invalid port: ${value}`);
  }
  return port;
}

async function main() {
  let port;
  try {
    port = portFromCommandLine(process.argv.slice(2), process.env);
  } catch (error) {
    console.error(`serve: ${error.message}`);
    process.exit(2);
  }
  const root = path.resolve(option(process.argv.slice(2), 'root') ?? REPO_ROOT);
  let running;
  try {
    running = await startServer({ port, root });
  } catch (error) {
    console.error(`serve: cannot listen on ${HOST}:${port}: ${error.message}`);
    process.exit(1);
  }
  console.log(running.url);
  console.error(`serving ${root} (Ctrl+C to stop)`);
  const stop = () => {
    running.close().then(() => process.exit(0));
    // Open keep-alive connections would delay close(); do not wait for them forever.
    setTimeout(() => process.exit(0), 500).unref();
  };
  process.on('SIGINT', stop);
  process.on('SIGTERM', stop);
}

if (process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href) {
  main();
}
