#!/usr/bin/env node
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A tiny static file server for the playground: serves the repository root on 127.0.0.1 only,
// with the MIME types browsers insist on (`application/wasm` for streaming compilation,
// `text/javascript` for module scripts and workers). No dependencies, no directory listings.
//
//   node scripts/serve.mjs [--port 8080]      (or PORT=8080; --port 0 picks a free port)
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
async function handleRequest(root, request, response) {
  if (request.method !== 'GET' && request.method !== 'HEAD') {
    sendText(response, 405, 'Method not allowed\n', { Allow: 'GET, HEAD' });
    return;
  }
  // The raw path, not `new URL(...).pathname`: the URL parser would silently clamp `/../`.
  const rawPath = (request.url ?? '/').split(/[?#]/, 1)[0];
  const search = (request.url ?? '').slice(rawPath.length).split('#', 1)[0];
  if (rawPath === '/') {
    redirect(response, '/web/');
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
  response.writeHead(200, {
    'Content-Type': mimeTypeFor(target),
    'Content-Length': info.size,
    // A development server: always revalidate so a rebuilt dist/ is picked up on reload.
    'Cache-Control': 'no-cache',
    'X-Content-Type-Options': 'nosniff',
  });
  if (request.method === 'HEAD') {
    response.end();
    return;
  }
  const stream = createReadStream(target);
  stream.on('error', () => response.destroy());
  stream.pipe(response);
}

/**
 * Starts the server. Resolves to `{ server, port, url, close }` once it listens;
 * `url` is the playground page.
 */
export async function startServer({ port = DEFAULT_PORT, root = REPO_ROOT } = {}) {
  const realRoot = await realpath(root);
  const server = createServer((request, response) => {
    handleRequest(realRoot, request, response).catch(() => {
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
    url: `http://${HOST}:${actualPort}/web/`,
    close: () => new Promise((resolve) => server.close(() => resolve())),
  };
}

/** Port from `--port N` / `--port=N`, else $PORT, else the default. */
function portFromCommandLine(argv, env) {
  let value = env.PORT;
  for (let i = 0; i < argv.length; i += 1) {
    if (argv[i] === '--port') value = argv[i + 1];
    else if (argv[i].startsWith('--port=')) value = argv[i].slice('--port='.length);
  }
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
  let running;
  try {
    running = await startServer({ port });
  } catch (error) {
    console.error(`serve: cannot listen on ${HOST}:${port}: ${error.message}`);
    process.exit(1);
  }
  console.log(running.url);
  console.error(`serving ${REPO_ROOT} (Ctrl+C to stop)`);
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
