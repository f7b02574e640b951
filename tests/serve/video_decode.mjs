// node video_decode.mjs <folder> <width> <height> <frames> [report]: decodes the frames write_h264_frames wrote
// with the page's VideoStream (src/app/serve/web/video_stream.mjs) in a headless Chromium, draws each as the page
// does, and compares it with the pixels that went in: the colours must come back (the stream's matrix and range
// are the decoder's), each frame within kMinPsnr and each channel's mean within kMaxMeanError. With `report`, the
// frames' PSNR is a measurement, not a test: each frame's is printed, then their mean and least, and only the
// decoding must succeed.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchBrowser } from './serve_harness.mjs';

const [folder, width, height, count, mode] = process.argv.slice(2);
const reportOnly = mode === 'report';
const kMinPsnr = 36;
const kMaxMeanError = 1.0;
const web = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../src/app/serve/web');

// WebCodecs needs a secure context: the page from http://127.0.0.1. It fetches the access units and, to compare
// with, the pixels that went in.
const server = http.createServer((request, response) => {
  if (request.url === '/video_stream.mjs') {
    response.writeHead(200, { 'content-type': 'text/javascript' });
    response.end(fs.readFileSync(path.join(web, 'video_stream.mjs')));
    return;
  }
  const frame = request.url.match(/^\/(frame-\d+\.(h264|rgb))$/);
  if (frame) {
    response.writeHead(200, { 'content-type': 'application/octet-stream' });
    response.end(fs.readFileSync(path.join(folder, frame[1])));
    return;
  }
  response.writeHead(200, { 'content-type': 'text/html' });
  response.end(`<canvas id="c" width="${width}" height="${height}"></canvas>`);
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const browser = await launchBrowser();
let status = 0;
try {
  const page = await browser.newPage();
  await page.goto(`http://127.0.0.1:${server.address().port}/`);
  // Each frame's PSNR and mean error per channel, computed in the page: a 1080p frame's pixels are too many to
  // hand to Node.
  const decoded = await page.evaluate(async ({ width, height, count }) => {
    const { VideoStream, canDecodeH264 } = await import('/video_stream.mjs');
    if (!(await canDecodeH264())) return { skipped: 'this Chromium does not decode H.264' };
    const context = document.getElementById('c').getContext('2d');
    const drawn = [];
    let failure = null;
    await new Promise((resolve) => {
      const stream = new VideoStream({
        shown: (header, frame) => {
          context.drawImage(frame, 0, 0, header.width, header.height, 0, 0, width, height);
          frame.close();
          drawn.push(context.getImageData(0, 0, width, height).data);
          if (drawn.length === count) resolve();
        },
        lost: (header) => { failure = `frame ${header.frame} was lost`; resolve(); },
        restart: () => { failure = `the decoder failed: ${stream.lastError?.message}`; resolve(); },
      });
      (async () => {
        for (let i = 0; i < count; ++i) {
          const bytes = new Uint8Array(await (await fetch(`/frame-${i}.h264`)).arrayBuffer());
          // The codec string: the SPS's profile, constraints and level after the first start code (00 00 00 01 67).
          const codec = 'avc1.' + [bytes[5], bytes[6], bytes[7]].map((b) => b.toString(16).padStart(2, '0')).join('');
          stream.decode({ frame: i + 1, key: i === 0, codec, width, height }, bytes);
        }
      })();
    });
    const frames = [];
    for (let i = 0; i < drawn.length; ++i) {
      const source = new Uint8Array(await (await fetch(`/frame-${i}.rgb`)).arrayBuffer());
      const pixels = drawn[i];
      let squares = 0;
      const error = [0, 0, 0];
      for (let p = 0; p < source.length / 3; ++p)
        for (let c = 0; c < 3; ++c) {
          const d = pixels[4 * p + c] - source[3 * p + c];
          squares += d * d;
          error[c] += d;
        }
      frames.push({
        psnr: 10 * Math.log10((255 * 255 * source.length) / squares),
        means: error.map((e) => e / (source.length / 3)),
      });
    }
    return { frames, failure };
  }, { width: Number(width), height: Number(height), count: Number(count) });
  if (decoded.skipped) {
    console.log(`skipped: ${decoded.skipped}`);
    status = 77;
  } else {
    assert.equal(decoded.failure, null, decoded.failure);
    decoded.frames.forEach(({ psnr, means }, i) => {
      console.log(`frame ${i}: PSNR ${psnr.toFixed(2)} dB, mean error per channel ${means.map((m) => m.toFixed(2))}`);
      if (reportOnly) return;
      assert.ok(psnr >= kMinPsnr, `frame ${i}: PSNR ${psnr.toFixed(2)} dB, at least ${kMinPsnr} expected`);
      for (const m of means) assert.ok(Math.abs(m) <= kMaxMeanError, `frame ${i}: a channel off by ${m.toFixed(2)}`);
    });
    const psnrs = decoded.frames.map((f) => f.psnr);
    const mean = psnrs.reduce((sum, p) => sum + p, 0) / psnrs.length;
    console.log(`PSNR over ${psnrs.length} frames: mean ${mean.toFixed(2)} dB, least ${Math.min(...psnrs).toFixed(2)} dB`);
  }
} catch (error) {
  console.error(error);
  status = 1;
} finally {
  await browser.close();
  server.close();
}
process.exit(status);
