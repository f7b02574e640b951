// Starts `candela serve` and a headless Chromium for the browser tests and the measuring client.
import { spawn } from 'node:child_process';
import http from 'node:http';

// Runs candela serve with `args` and resolves once it prints the address to open.
export function startServer(candela, args) {
  return new Promise((resolve, reject) => {
    const child = spawn(candela, ['serve', ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
    let stdout = '';
    const server = { child, stderr: '', url: null, exited: null };
    child.on('error', (e) => reject(new Error(`cannot run ${candela}: ${e.message}`)));
    child.stderr.on('data', (d) => { server.stderr += d; });
    child.on('exit', (code, signal) => {
      server.exited = { code, signal };
      if (!server.url) reject(new Error(`candela serve exited (${code ?? signal}) before printing an address:\n${server.stderr}`));
    });
    child.stdout.on('data', (d) => {
      stdout += d;
      const match = stdout.match(/open (http:\/\/\S+)/);
      if (match && !server.url) {
        server.url = match[1];
        resolve(server);
      }
    });
  });
}

// Stops the server with SIGTERM and resolves with its exit status.
export function stopServer(server) {
  if (server.exited) return Promise.resolve(server.exited);
  return new Promise((resolve) => {
    server.child.on('exit', (code, signal) => resolve({ code, signal }));
    server.child.kill('SIGTERM');
  });
}

export async function launchBrowser() {
  const { chromium } = await import('playwright-core');
  return chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu'],
  });
}

// One raw HTTP request with the path exactly as given (no normalisation); resolves with status and body.
export function rawGet(url, path, headers = {}) {
  const { hostname, port } = new URL(url);
  return new Promise((resolve, reject) => {
    const request = http.request({ host: hostname, port, path, method: 'GET', headers }, (response) => {
      let body = '';
      response.on('data', (d) => { body += d; });
      response.on('end', () => resolve({ status: response.statusCode, body, headers: response.headers }));
    });
    request.on('error', reject);
    request.end();
  });
}
