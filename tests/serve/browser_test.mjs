// Browser tests of candela serve: node browser_test.mjs <candela executable> <test name>. Each test starts its own
// server on a free port (CPU backend, a small image) and a headless Chromium, and exits non-zero on failure.
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { writeAnimatedScene } from './animated_scene.mjs';
import { launchBrowser, rawGet, startServer, stopServer } from './serve_harness.mjs';

const [candela, testName] = process.argv.slice(2);
const serverOptions = ['--backend', 'cpu', '--port', '0', '--max-depth', '3', '--no-cache'];
const serverArgs = ['cornell-box', ...serverOptions];
const viewport = { width: 560, height: 300 };  // the image gets what the 340-pixel panel leaves

async function until(what, predicate, timeoutMs = 20000) {
  const start = performance.now();  // monotonic: a wall clock set forward mid-test ends no wait early
  for (;;) {
    const value = await predicate();
    if (value) return value;
    if (performance.now() - start > timeoutMs) throw new Error(`timed out waiting for ${what}`);
    await new Promise((r) => setTimeout(r, 50));
  }
}

const frames = (page) => page.evaluate(() => window.candela.frames);
const header = (page) => page.evaluate(() => window.candela.header);
// Waits for a frame sent after the call, at rest (not a preview) when `atRest`.
async function nextFrame(page, atRest = false) {
  const after = (await header(page))?.frame ?? 0;
  return until('a new frame', async () => {
    const h = await header(page);
    return h && h.frame > after && (!atRest || !h.preview) ? h : null;
  });
}
// The canvas's pixels, summed per channel and as a list of 8x8 block means, to compare two frames.
const pixels = (page) => page.evaluate(() => {
  const c = document.getElementById('image');
  const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let sum = 0;
  const blocks = new Array(64).fill(0);
  for (let y = 0; y < c.height; ++y)
    for (let x = 0; x < c.width; ++x) {
      const i = 4 * (y * c.width + x);
      const v = data[i] + data[i + 1] + data[i + 2];
      sum += v;
      blocks[Math.floor((8 * y) / c.height) * 8 + Math.floor((8 * x) / c.width)] += v;
    }
  return { mean: sum / (3 * c.width * c.height), blocks: blocks.map((b) => b / ((3 * c.width * c.height) / 64)) };
});
const blockDifference = (a, b) => a.blocks.reduce((s, v, i) => s + Math.abs(v - b.blocks[i]), 0) / 64;

async function withPage(args, body, scene = 'cornell-box') {
  const server = await startServer(candela, [scene, ...serverOptions, ...args]);
  const browser = await launchBrowser();
  try {
    const page = await browser.newPage({ viewport });
    page.on('pageerror', (e) => { throw e; });
    await body(page, server);
  } finally {
    await browser.close();
    const status = await stopServer(server);
    assert.equal(status.code, 0, `candela serve should stop cleanly on SIGTERM; stderr:\n${server.stderr}`);
  }
  return server;
}

// The address with `name=value` added to its query (which may hold the token already).
function withQuery(url, name, value) {
  const u = new URL(url);
  u.searchParams.set(name, value);
  return u.toString();
}

// The canvas when the first frame at rest with `samples` samples per pixel is drawn, and the stream it came by.
// With `orMore`, the first with at least that many: the video stream at rest does not send every frame.
async function canvasAtSamples(args, stream, samples, orMore = false) {
  let captured = null;
  await withPage(args, async (page, server) => {
    await page.addInitScript(({ wanted, orMore }) => {
      window.captured = new Promise((resolve) => {
        window.addEventListener('candela-frame', (event) => {
          const h = event.detail;
          if (h.preview || (orMore ? h.samples < wanted : h.samples !== wanted)) return;
          const c = document.getElementById('image');
          const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
          const decodes = typeof VideoDecoder !== 'undefined';
          resolve({ header: h, stream: window.candela.stream, decodes, width: c.width, height: c.height,
                    data: Array.from(data) });
        });
      });
    }, { wanted: samples, orMore });
    await page.goto(withQuery(server.url, 'stream', stream));
    // Rendering the samples is the wait: a sanitizer build on a loaded machine takes more than 20 s for 48.
    captured = await until(`a frame of ${samples} samples`, () => page.evaluate(() =>
      Promise.race([window.captured, new Promise((r) => setTimeout(() => r(null), 200))])), 60000);
  });
  return captured;
}

// The peak signal-to-noise ratio of two RGBA canvases' colour channels, in dB.
function psnr(a, b) {
  let squares = 0, count = 0;
  for (let i = 0; i < a.length; ++i) {
    if (i % 4 === 3) continue;
    squares += (a[i] - b[i]) ** 2;
    count += 1;
  }
  return squares === 0 ? Infinity : 10 * Math.log10((255 * 255 * count) / squares);
}

// How close the video stream's pictures must come to the JPEG stripes' (each at its rest quality, JPEG q92 and
// H.264 rate factor 12, against each other; 37.3 dB measured at 48 samples, 199 x 300): a frame drawn one pixel
// off costs 12 dB, a wrong colour matrix or range as much. The colours against the source: video_decode.mjs.
const kVideoMinPsnr = 33;

const tests = {
  // Chromium decodes H.264, so the page takes the video stream; at rest its picture matches the JPEG stripes'
  // picture of the same frame (the same samples, the same seed).
  async video() {
    const samples = 48;
    const video = await canvasAtSamples(['--seed', '7'], 'auto', samples, true);
    if (!video.decodes) {
      console.log('skipped: this Chromium has no WebCodecs VideoDecoder');
      process.exit(77);
    }
    const jpeg = await canvasAtSamples(['--seed', '7'], 'jpeg', video.header.samples);
    assert.equal(video.stream, 'h264', 'the page takes the video stream');
    assert.equal(video.header.format, 'h264');
    assert.match(video.header.codec, /^avc1\.[0-9A-F]{6}$/);
    assert.equal(jpeg.stream, 'jpeg', '?stream=jpeg keeps the page on JPEG stripes');
    assert.equal(jpeg.header.format, 'jpeg-stripes');
    assert.deepEqual([video.width, video.height], [jpeg.width, jpeg.height]);
    const ratio = psnr(video.data, jpeg.data);
    console.log(`video against JPEG at ${samples} samples, ${video.width} x ${video.height}: PSNR ${ratio.toFixed(2)} dB`);
    assert.ok(ratio >= kVideoMinPsnr, `PSNR ${ratio.toFixed(2)} dB, at least ${kVideoMinPsnr} expected`);
  },

  // The page connects, frames arrive and are drawn, and the panel shows the backend and the scene.
  async frames() {
    await withPage([], async (page, server) => {
      const response = await page.goto(server.url);
      assert.equal(response.status(), 200);
      await until('three frames', async () => (await frames(page)) >= 3);
      const h = await nextFrame(page, true);
      assert.ok(h.width > 100 && h.height > 100, `the image follows the page's view: ${h.width} x ${h.height}`);
      assert.ok((await pixels(page)).mean > 10, 'the canvas shows the Cornell box, not black');
      assert.equal(await page.textContent('#backend'), 'cpu');
      // Each frame names what rendered it; only a GPU backend whose programs still compile has `starting`.
      assert.equal(h.backend, 'cpu');
      assert.ok(h.device.length > 0, 'the frame names its device');
      assert.equal(h.starting, null);
      assert.ok(await page.isHidden('#starting'), 'no compile note without a compile');
      assert.equal(await page.textContent('#scene'), 'cornell-box');
      assert.match(await page.textContent('#role'), /in control/);
      assert.match(await page.textContent('#samples'), /\d+ per pixel/);
    });
  },

  // A left drag over the image orbits the camera: the camera the frames report and the picture both change.
  async drag() {
    await withPage([], async (page, server) => {
      await page.goto(server.url);
      await until('frames', async () => (await frames(page)) >= 3);
      const before = await nextFrame(page, true);
      const imageBefore = await pixels(page);
      const box = await page.locator('#image').boundingBox();
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      await page.mouse.down();
      for (let i = 1; i <= 10; ++i) await page.mouse.move(box.x + box.width / 2 + 15 * i, box.y + box.height / 2);
      await page.mouse.up();
      const after = await until('the camera to move', async () => {
        const h = await header(page);
        return h.camera.position[0] !== before.camera.position[0] ? h : null;
      });
      assert.notDeepEqual(after.camera.forward, before.camera.forward, 'an orbit turns the camera');
      await nextFrame(page, true);
      const imageAfter = await pixels(page);
      assert.ok(blockDifference(imageBefore, imageAfter) > 2, 'the picture changes with the camera');
    });
  },

  // The panel's edits reach the render: the depth the backend renders with, and the exposure of the picture.
  async panel() {
    await withPage([], async (page, server) => {
      await page.goto(server.url);
      await until('frames', async () => (await frames(page)) >= 2);
      assert.equal((await nextFrame(page)).applied.max_depth, 3);
      await page.locator('#max_depth').fill('2');
      await until('max depth 2 to be rendered', async () => (await header(page)).applied.max_depth === 2);
      // Material edits reach the backend: the Disney model with metallic 1 makes the painted walls metal, which look
      // nothing like them.
      await nextFrame(page);
      const painted = await pixels(page);
      await page.click('summary:text-is("Materials")');
      await page.locator('#shading').selectOption('disney');
      const metallic = page.locator('.override[data-name="metallic"]');
      await metallic.locator('input[type=range]').fill('1');
      await metallic.locator('input[type=checkbox]').check();
      await until('the metallic override', async () => (await header(page)).controls.overrides.metallic === 1);
      await nextFrame(page);
      const metal = await pixels(page);
      assert.ok(blockDifference(painted, metal) > 2, `metal walls change the picture: ${painted.mean} then ${metal.mean}`);
      assert.equal((await header(page)).controls.shading, 'disney');
      const bright = await pixels(page);
      await page.locator('#exposure').fill('-4');
      await until('exposure -4 to be applied', async () => (await header(page)).controls.exposure === -4);
      await nextFrame(page);
      const dark = await pixels(page);
      assert.ok(dark.mean < 0.5 * bright.mean, `four stops darker: ${bright.mean} then ${dark.mean}`);
      await page.locator('#tonemap').selectOption('reinhard');
      await until('the Reinhard tone mapper', async () => (await header(page)).controls.tonemap === 'reinhard');
      await page.locator('#denoiser').selectOption('atrous');
      await until('the a-trous denoiser', async () => (await header(page)).controls.denoiser === 'atrous');
      await nextFrame(page);
      // The view file comes back as a download of a scene file with the camera.
      const download = page.waitForEvent('download');
      await page.click('#save-view');
      const file = await download;
      assert.equal(file.suggestedFilename(), 'candela-view.json');
      const screenshot = page.waitForEvent('download');
      await page.click('#screenshot');
      assert.equal((await screenshot).suggestedFilename(), 'candela-view.png');
    });
  },

  // A scene's animation plays in the page as in the viewer's window: the Animation section pauses and plays it,
  // its time slider moves it (and pauses it), its choice plays another clip from its start; --camera and
  // --animation choose where the view and the animation start.
  async animation() {
    const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'candela-serve-animation-'));
    try {
      const scene = writeAnimatedScene(folder);
      await withPage(['--camera', 'side', '--animation', 'Rise'], async (page, server) => {
        await page.goto(server.url);
        const h = await nextFrame(page);
        assert.ok(Math.abs(h.camera.position[0] - 6) < 1e-3, `--camera side: ${h.camera.position}`);
        assert.equal(h.controls.animation, 1, '--animation Rise plays the second clip');
        assert.deepEqual((await page.evaluate(() => window.candela.hello.animations)).map((a) => a.name),
                         ['Slide', 'Rise']);
        assert.ok(await page.isVisible('#animation-choice'), 'two clips: the page offers the choice');
      }, scene);

      await withPage([], async (page, server) => {
        await page.goto(server.url);
        const first = await nextFrame(page);
        assert.ok(first.controls.playing, 'the animation plays from the start');
        await until('the animation to move on', async () => (await header(page)).controls.animation_time !==
                                                           first.controls.animation_time);
        await page.click('#play');
        await until('the pause', async () => (await header(page)).controls.playing === false);
        assert.equal(await page.textContent('#play'), 'Play');
        const paused = (await nextFrame(page)).controls.animation_time;
        await nextFrame(page);
        assert.equal((await nextFrame(page)).controls.animation_time, paused, 'paused, the time stands');

        // The quad slides from x = -1 to 1: at 0.25 s it is left of the middle, at 1.75 s right of it.
        const at = async (seconds) => {
          await page.locator('#animation_time').fill(String(seconds));
          await until(`time ${seconds}`, async () => (await header(page)).controls.animation_time === seconds);
          await nextFrame(page, true);
          return pixels(page);
        };
        const left = await at(0.25);
        const right = await at(1.75);
        assert.ok(blockDifference(left, right) > 2, 'the pose changes the picture');
        assert.equal((await header(page)).controls.playing, false, 'moving the time pauses');

        await page.locator('#animation').selectOption('1');
        await until('the second clip from its start', async () => {
          const c = (await header(page)).controls;
          return c.animation === 1 && c.animation_time === 0;
        });
        await page.click('#play');
        await until('playing again', async () => (await header(page)).controls.playing === true);
      }, scene);
    } finally {
      fs.rmSync(folder, { recursive: true, force: true });
    }
  },

  // A token is required by default, on loopback too: requests without it (or with a wrong one) get 403 and no
  // frames; with it, frames come.
  async token() {
    const server = await startServer(candela, serverArgs);
    try {
      const token = new URL(server.url).searchParams.get('token');
      assert.match(token ?? '', /^[0-9a-f]{32}$/, 'a random token by default');
      assert.equal((await rawGet(server.url, '/')).status, 403);
      assert.equal((await rawGet(server.url, '/app.js')).status, 403);
      assert.equal((await rawGet(server.url, '/?token=wrong')).status, 403);
      assert.equal((await rawGet(server.url, `/?token=${token.slice(0, 31)}`)).status, 403);
      const upgrade = { Connection: 'Upgrade', Upgrade: 'websocket', 'Sec-WebSocket-Version': '13',
                        'Sec-WebSocket-Key': 'dGhlIHNhbXBsZSBub25jZQ==' };
      assert.equal((await rawGet(server.url, '/ws', upgrade)).status, 403, 'no WebSocket without the token');
      assert.equal((await rawGet(server.url, '/ws?token=wrong', upgrade)).status, 403);
      assert.equal((await rawGet(server.url, '/ws', { ...upgrade, Cookie: 'candela_token=wrong' })).status, 403);
    } finally {
      await stopServer(server);
    }
    await withPage(['--token', 'letmein'], async (page, s) => {
      assert.ok(s.url.endsWith('?token=letmein'));
      const refused = await page.goto(s.url.replace('letmein', 'letmeout'));
      assert.equal(refused.status(), 403);
      assert.equal(await page.evaluate(() => window.candela), undefined, 'a refused page gets no script');
      const response = await page.goto(s.url);
      assert.equal(response.status(), 200);
      await until('frames with the token', async () => (await frames(page)) >= 2);
    });
  },

  // Malformed, oversized, unknown and flooding WebSocket messages leave the server serving the page.
  async malformed() {
    const server = await withPage([], async (page, s) => {
      await page.goto(s.url);
      await until('frames', async () => (await frames(page)) >= 2);
      const results = await page.evaluate(async () => {
        const open = () => new Promise((resolve) => {
          const ws = new WebSocket(`ws://${location.host}/ws`);
          ws.onopen = () => resolve(ws);
        });
        const ws = await open();
        ws.send(JSON.stringify({ type: 'action', name: 'take_control' }));
        const garbage = [
          'not json', '{}', '[]', '42', 'null', '{"type":7}', '{"type":"teleport"}',
          '{"type":"pointer"}', '{"type":"pointer","action":"down","x":"a","y":1}',
          '{"type":"pointer","action":"down","x":1e308,"y":1}', '{"type":"pointer","action":"explode","x":1,"y":1}',
          '{"type":"wheel","steps":1e300}', '{"type":"resize","width":0,"height":-5}',
          '{"type":"resize","width":100000,"height":100}', '{"type":"resize","width":1.5,"height":100}',
          '{"type":"settings","max_depth":1000000}', '{"type":"settings","max_depth":-1}',
          '{"type":"settings","overrides":{"roughness":99}}', '{"type":"settings","overrides":{"nonsense":0.5}}',
          '{"type":"settings","overrides":[1,2]}', '{"type":"settings","denoiser":"magic"}',
          '{"type":"settings","exposure":"bright"}', '{"type":"keys","forward":"yes"}',
          '{"type":"frame_ack","frame":-1}', '{"type":"action","name":"rm -rf"}', '\u0000\u0001\u0002',
          '['.repeat(15000), '{"a":'.repeat(3000),
        ];
        for (const g of garbage) ws.send(g);
        ws.send(new Uint8Array([1, 2, 3, 4]));
        for (let i = 0; i < 3000; ++i) ws.send('{"type":"wheel","steps":0}');
        // Over the size limit: the server closes this socket.
        const closed = new Promise((resolve) => { ws.onclose = (e) => resolve(e.code); });
        ws.send('x'.repeat(100000));
        const code = await Promise.race([closed, new Promise((r) => setTimeout(() => r('open'), 5000))]);
        return { code };
      });
      assert.notEqual(results.code, 'open', 'an oversized message closes its socket');
      const count = await frames(page);
      await until('frames after the garbage', async () => (await frames(page)) >= count + 3);
      assert.match(await page.textContent('#role'), /in control/, 'control comes back when the other leaves');
      // The page still steers the render.
      await page.locator('#max_depth').fill('5');
      await until('max depth 5', async () => (await header(page)).applied.max_depth === 5);
    });
    const dropped = server.stderr.match(/dropped a message/g) ?? [];
    assert.ok(dropped.length >= 3, `dropped messages are logged:\n${server.stderr}`);
    assert.ok(dropped.length < 40, `each kind of problem is logged once, not per message (${dropped.length})`);
  },

  // Two browsers watch the same render; the first steers, the second's drags are ignored until it takes control.
  async control() {
    await withPage([], async (first, s) => {
      await first.goto(s.url);
      await until('frames', async () => (await frames(first)) >= 2);
      const second = await first.context().browser().newPage({ viewport });
      try {
        await second.goto(s.url);
        await until('frames in the second page', async () => (await frames(second)) >= 2);
        assert.match(await second.textContent('#role'), /watching \(2 watching\)/);
        assert.match(await first.textContent('#role'), /in control \(2 watching\)/);
        const drag = async (page) => {
          const box = await page.locator('#image').boundingBox();
          await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
          await page.mouse.down();
          for (let i = 1; i <= 8; ++i) await page.mouse.move(box.x + box.width / 2 + 20 * i, box.y + box.height / 2);
          await page.mouse.up();
        };
        const before = (await nextFrame(second)).camera.position;
        await drag(second);
        await nextFrame(second);
        await nextFrame(second);
        assert.deepEqual((await header(second)).camera.position, before, "a watcher's drag leaves the camera");
        await second.click('#take-control');
        await until('the second page to take control', async () => /in control/.test(await second.textContent('#role')));
        assert.match(await first.textContent('#role'), /watching/);
        await drag(second);
        await until('the camera to move', async () => {
          const h = await header(first);
          return h.camera.position[0] !== before[0];
        });
      } finally {
        await second.close();
      }
    });
  },

  // A browser that does not acknowledge its frames gets no more of them (none queue up for it) and holds up no
  // one: the page beside it keeps getting frames.
  async slow() {
    await withPage([], async (page, s) => {
      await page.goto(s.url);
      await until('frames', async () => (await frames(page)) >= 2);
      const before = await frames(page);
      const received = await page.evaluate(() => new Promise((resolve) => {
        const ws = new WebSocket(`ws://${location.host}/ws`);
        ws.binaryType = 'arraybuffer';
        let count = 0;
        ws.onmessage = (e) => { if (typeof e.data !== 'string') count += 1; };
        setTimeout(() => { ws.close(); resolve(count); }, 3000);
      }));
      assert.equal(received, 1, 'one frame, then none until it is acknowledged');
      assert.ok((await frames(page)) >= before + 3, 'the page kept drawing frames meanwhile');
    });
  },

  // Only the page's own files can be requested: nothing of the file system, however the path is spelt.
  async traversal() {
    const server = await startServer(candela, [...serverArgs, '--no-token']);
    try {
      for (const path of ['/../../../../etc/passwd', '/%2e%2e/%2e%2e/%2e%2e/etc/passwd', '/..%2f..%2f..%2fetc%2fpasswd',
                          '//etc/passwd', '/index.html/../../etc/passwd', '/app.js/..', '/web/app.js',
                          '/src/app/serve/web/app.js', '/CMakeLists.txt', '/.', '/..', '/%00', '/index.html%00.js']) {
        const r = await rawGet(server.url, path);
        assert.equal(r.status, 404, `${path} gives ${r.status}`);
        assert.ok(!r.body.includes('root:'), path);
      }
      // Without a token, only requests addressed to a loopback name are answered (no DNS rebinding).
      assert.equal((await rawGet(server.url, '/', { Host: 'evil.example:8080' })).status, 403);
      for (const path of ['/', '/index.html', '/app.js', '/style.css', '/app.js?x=1']) {
        const r = await rawGet(server.url, path);
        assert.equal(r.status, 200, path);
        assert.equal(r.headers['x-content-type-options'], 'nosniff');
      }
    } finally {
      await stopServer(server);
    }
  },

  // The measuring client (measure_client.py) connects, steers and prints its JSON.
  async measure() {
    const server = await startServer(candela, [...serverArgs, '--token', 'measure']);
    try {
      const script = fileURLToPath(new URL('./measure_client.py', import.meta.url));
      const stdout = await new Promise((resolve, reject) => {
        execFile('python3', [script, server.url, '--seconds', '3', '--width', '160', '--height', '120', '--inputs', '4'],
                 { timeout: 60000 }, (error, out, err) => (error ? reject(new Error(`${error}\n${err}`)) : resolve(out)));
      });
      const result = JSON.parse(stdout);
      assert.equal(result.backend, 'cpu');
      assert.ok(result.frames > 3 && result.fps_delivered > 1, stdout);
      assert.ok(result.inputs_timed >= 1 && result.input_to_frame_ms.median > 0, stdout);
    } finally {
      await stopServer(server);
    }
  },
};

if (!tests[testName]) {
  console.error(`unknown test '${testName}'; the tests: ${Object.keys(tests).join(', ')}`);
  process.exit(2);
}
try {
  await tests[testName]();
  console.log(`serve browser test '${testName}': passed`);
} catch (e) {
  console.error(`serve browser test '${testName}': FAILED\n${e.stack ?? e}`);
  process.exit(1);
}
