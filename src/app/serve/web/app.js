// candela serve's page: shows the frames the server streams over a WebSocket and sends it the camera input and
// the panel's edits. Plain JavaScript modules, no build step; the server embeds these files.
import { drawStripedJpeg, unpackStripedJpeg } from './striped_jpeg.mjs';
import { VideoStream, canDecodeH264 } from './video_stream.mjs';

const $ = (id) => document.getElementById(id);
const canvas = $('image');
const context = canvas.getContext('2d');
const view = $('view');

// What tests and scripts read (window.candela): frames drawn, the last frame's header, the role, messages.
// `stream`: how frames come, 'jpeg' (stripes) or 'h264' (the video stream).
const state = { frames: 0, header: null, control: false, hello: null, message: null, closed: false, stream: 'jpeg' };
window.candela = state;

let socket = null;
const fps = { count: 0, since: performance.now(), value: 0 };

function send(message) {
  if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(message));
}

function connect() {
  const scheme = location.protocol === 'https:' ? 'wss' : 'ws';
  socket = new WebSocket(`${scheme}://${location.host}/ws${location.search}`);
  socket.binaryType = 'arraybuffer';
  socket.onopen = () => { $('connection').textContent = ''; sendSize(); };
  socket.onclose = () => {
    state.closed = true;
    $('connection').textContent = 'disconnected: reload the page to connect again';
  };
  socket.onmessage = (event) => {
    if (typeof event.data === 'string') onText(JSON.parse(event.data));
    else onBinary(event.data);
  };
}

// A frame smaller than the view (a preview) is drawn whole here first, then scaled, so that no seam shows where
// its stripes meet.
const frameCanvas = document.createElement('canvas');
const frameContext = frameCanvas.getContext('2d');

// Draws a frame's JPEG stripes (src/io/images/striped_jpeg.h) into the view.
async function drawFrame(frame) {
  if (frame.width === canvas.width && frame.height === canvas.height) {
    await drawStripedJpeg(context, frame);
    return;
  }
  if (frameCanvas.width !== frame.width || frameCanvas.height !== frame.height) {
    frameCanvas.width = frame.width;
    frameCanvas.height = frame.height;
  }
  await drawStripedJpeg(frameContext, frame);
  context.imageSmoothingEnabled = true;
  context.drawImage(frameCanvas, 0, 0, canvas.width, canvas.height);
}

// A binary message: the JSON header's length (4 bytes, little-endian), the header, then its payload: a PNG for a
// screenshot, JPEG stripes for a frame.
function onBinary(buffer) {
  const length = new DataView(buffer).getUint32(0, true);
  const header = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, length)));
  if (header.kind === 'screenshot') {
    download(new Blob([new Uint8Array(buffer, 4 + length)], { type: 'image/png' }), header.name);
    return;
  }
  if (header.kind !== 'frame') return;
  if (header.format === 'h264') {
    if (video) video.decode(header, new Uint8Array(buffer, 4 + length));
    else acknowledgeFrame(header);
    return;
  }
  // The server sends no other frame until this one is acknowledged, once drawn.
  const acknowledge = () => acknowledgeFrame(header);
  let frame;
  try {
    frame = unpackStripedJpeg(buffer, 4 + length);
  } catch (error) {
    showMessage(`a frame that cannot be shown: ${error.message}`, true);
    acknowledge();
    return;
  }
  drawFrame(frame).then(() => frameShown(header), acknowledge);
}

function acknowledgeFrame(header) { send({ type: 'frame_ack', frame: header.frame }); }

// After a frame is drawn: what tests read, the acknowledgement that lets the server send the next, the status.
function frameShown(header) {
  state.frames += 1;
  state.header = header;
  acknowledgeFrame(header);
  showStatus(header);
  window.dispatchEvent(new CustomEvent('candela-frame', { detail: header }));
}

// The H.264 stream, where the server offers it and this browser decodes it, unless the address asks for JPEG
// (?stream=jpeg). After repeated decoder failures the page goes back to JPEG stripes.
const kMaxVideoFailures = 3;
let video = null;

async function chooseStream(streams) {
  const wanted = new URLSearchParams(location.search).get('stream');
  if (wanted === 'jpeg' || !streams.includes('h264') || !(await canDecodeH264())) return;
  video = new VideoStream({
    shown: (header, frame) => {
      context.imageSmoothingEnabled = true;
      // The decoded picture may have one column or row more than the frame (even sizes): drawn without it.
      context.drawImage(frame, 0, 0, header.width, header.height, 0, 0, canvas.width, canvas.height);
      frame.close();
      frameShown(header);
    },
    lost: acknowledgeFrame,
    restart: () => {
      if (video.failures < kMaxVideoFailures) {
        send({ type: 'stream', codec: 'h264' });  // the server's next frame is a key frame
        return;
      }
      showMessage(`the video stream cannot be decoded here (${video.lastError?.message ?? 'unknown error'}): ` +
                  'JPEG frames from now on', true);
      video.close();
      video = null;
      state.stream = 'jpeg';
      send({ type: 'stream', codec: 'jpeg' });
    },
  });
  state.stream = 'h264';
  send({ type: 'stream', codec: 'h264' });
}

function onText(message) {
  if (message.type === 'hello') {
    state.hello = message;
    $('backend').textContent = message.backend;
    $('device').textContent = message.device;
    $('scene').textContent = message.scene;
    const s = message.stats;
    $('stats').textContent = `${s.triangles} triangles, ${s.vertices} vertices, ${s.meshes} meshes ` +
      `(${s.instances} instances), ${s.materials} materials, ${s.textures} textures`;
    buildDenoisers(message.denoisers);
    $('atrous_passes').max = message.max_atrous_passes;
    buildOverrides(message.override_parameters);
    buildAnimations(message.animations);
    showControls(message.controls);
    chooseStream(message.streams ?? ['jpeg']);
  } else if (message.type === 'role') {
    state.control = message.control;
    $('role').textContent = message.control ? `in control (${message.clients} watching)`
                                            : `watching (${message.clients} watching)`;
    $('take-control').hidden = message.control;
  } else if (message.type === 'message') {
    showMessage(message.text, message.error);
  } else if (message.type === 'view_file') {
    download(new Blob([message.text], { type: 'application/json' }), message.name);
    showMessage(message.note ? `saved ${message.name} (${message.note})` : `saved ${message.name}`, false);
  }
}

function showMessage(text, isError) {
  state.message = text;
  $('message').textContent = text;
  $('message').className = isError ? 'error' : 'ok';
}

function download(blob, name) {
  const link = document.createElement('a');
  link.href = URL.createObjectURL(blob);
  link.download = name;
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 10000);
}

const vector = (v) => v.map((x) => x.toFixed(3)).join(' ');

function showStatus(h) {
  fps.count += 1;
  const now = performance.now();
  if (now - fps.since > 500) {
    fps.value = (1000 * fps.count) / (now - fps.since);
    fps.count = 0;
    fps.since = now;
  }
  $('rate').textContent = `${fps.value.toFixed(1)} fps here, ${h.fps.toFixed(1)} sent`;
  $('timing').textContent = `render ${h.render_ms.toFixed(1)}, post ${h.post_ms.toFixed(1)}, ` +
    `encode ${h.encode_ms.toFixed(1)} ms`;
  $('samples').textContent = `${h.samples} per pixel`;
  $('image-size').textContent = `${h.width} x ${h.height}${h.preview ? ' (moving: preview)' : ''}`;
  const link = `${(h.bytes_per_second / 1e6).toFixed(1)} MB/s`;
  $('stream').textContent = h.format === 'h264'
    ? `H.264 up to ${(h.kilobits_per_second / 1000).toFixed(1)} Mbit/s, rate factor ${h.rate_factor.toFixed(0)}, ${link}`
    : `JPEG q${h.quality}, ${h.stripes} stripes, ${link}`;
  $('camera').textContent = `${vector(h.camera.position)} looking ${vector(h.camera.forward)}`;
  // The CPU renders while the GPU programs compile (a first start on the machine); then the GPU takes over.
  $('backend').textContent = h.backend;
  $('device').textContent = h.device;
  $('starting').textContent = h.starting ? h.starting.note : '';
  $('starting').hidden = !h.starting;
  showControls(h.controls);
}

// ---- the panel -------------------------------------------------------------------------------------------------

const sliders = ['max_depth', 'samples_per_frame', 'env_intensity', 'env_rotation', 'exposure', 'atrous_passes',
                 'animation_time'];
const integerSliders = new Set(['max_depth', 'samples_per_frame', 'atrous_passes']);
const checkboxes = ['accumulate', 'bilateral'];
const selects = ['shading', 'tonemap', 'denoiser', 'animation'];
const numberSelects = new Set(['animation']);

// The value beside a slider: the server's where it lies beyond the slider's range (--max-depth 1024).
function showOutput(input, value = input.value) {
  const output = input.parentElement.querySelector('output');
  if (output) output.textContent = value;
}

// The clips of the scene's animation (the hello's "animations"): each one's name and time range.
let clips = [];
let playing = false;

// Shows the server's controls, except in the field being edited.
function showControls(controls) {
  if (!controls) return;
  const clip = clips[controls.animation];
  if (clip) {
    $('animation_time').min = clip.start;
    $('animation_time').max = clip.end;
  }
  playing = controls.playing;
  $('play').textContent = playing ? 'Pause' : 'Play';
  for (const id of [...sliders, ...selects]) {
    const input = $(id);
    if (document.activeElement === input || controls[id] === undefined) continue;
    const value = controls[id];
    input.value = value;
    showOutput(input, typeof value === 'number' ? Number(value.toFixed(2)) : value);
  }
  for (const id of checkboxes) if (document.activeElement !== $(id)) $(id).checked = controls[id];
  for (const row of document.querySelectorAll('.override')) {
    const [box, , slider] = row.querySelectorAll('input, span');
    const value = controls.overrides[row.dataset.name];
    if (document.activeElement === box || document.activeElement === slider) continue;
    box.checked = value !== undefined;
    if (value !== undefined) { slider.value = value; showOutput(slider); }
  }
}

function buildDenoisers(names) {
  const labels = { none: 'None', atrous: 'A-trous', optix: 'OptiX AI' };
  $('denoiser').replaceChildren(...names.map((n) => new Option(labels[n] || n, n)));
}

// The Animation section, for a scene with an animation: play or pause, the time (moving it pauses) and, where the
// scene has several, the animation that plays.
function buildAnimations(animations) {
  clips = animations;
  $('animation-panel').hidden = clips.length === 0;
  $('animation-choice').hidden = clips.length < 2;
  $('animation').replaceChildren(...clips.map((c, i) => new Option(c.name || `animation ${i}`, i)));
}

function buildOverrides(parameters) {
  const rows = parameters.map((p) => {
    const row = document.createElement('label');
    row.className = 'override';
    row.dataset.name = p.name;
    const box = Object.assign(document.createElement('input'), { type: 'checkbox' });
    const name = Object.assign(document.createElement('span'), { textContent: p.name });
    const slider = Object.assign(document.createElement('input'), {
      type: 'range', min: p.min, max: p.max, step: (p.max - p.min) / 200, value: (p.min + p.max) / 2,
    });
    const output = document.createElement('output');
    output.textContent = slider.value;
    const apply = () => send({ type: 'settings', overrides: { [p.name]: box.checked ? Number(slider.value) : null } });
    box.addEventListener('change', apply);
    slider.addEventListener('input', () => { showOutput(slider); if (box.checked) apply(); });
    row.append(box, name, slider, output);
    return row;
  });
  $('overrides').replaceChildren(...rows);
}

for (const id of sliders) {
  $(id).addEventListener('input', (e) => {
    showOutput(e.target);
    const value = Number(e.target.value);
    send({ type: 'settings', [id]: integerSliders.has(id) ? Math.round(value) : value });
  });
}
for (const id of checkboxes) $(id).addEventListener('change', (e) => send({ type: 'settings', [id]: e.target.checked }));
for (const id of selects) {
  $(id).addEventListener('change', (e) => {
    send({ type: 'settings', [id]: numberSelects.has(id) ? Number(e.target.value) : e.target.value });
  });
}
$('play').addEventListener('click', () => send({ type: 'settings', playing: !playing }));

const action = (name) => () => send({ type: 'action', name });
$('screenshot').addEventListener('click', action('screenshot'));
$('save-view').addEventListener('click', action('save_view'));
$('frame-scene').addEventListener('click', action('frame'));
$('reset-camera').addEventListener('click', action('reset'));
$('take-control').addEventListener('click', action('take_control'));

// ---- camera input ----------------------------------------------------------------------------------------------

// The canvas has the view's size in device pixels; the server renders for that size and takes pointer positions
// in the same pixels.
function sendSize() {
  const ratio = window.devicePixelRatio || 1;
  const clamp = (v) => Math.max(16, Math.min(4096, Math.round(v * ratio)));
  canvas.width = clamp(view.clientWidth);
  canvas.height = clamp(view.clientHeight);
  send({ type: 'resize', width: canvas.width, height: canvas.height });
}
new ResizeObserver(sendSize).observe(view);

const buttonNames = ['left', 'middle', 'right'];
function pointer(action, event) {
  const ratio = window.devicePixelRatio || 1;
  send({ type: 'pointer', action, button: buttonNames[event.button] || 'left',
         x: event.offsetX * ratio, y: event.offsetY * ratio });
}
canvas.addEventListener('pointerdown', (e) => {
  if (e.button > 2) return;
  view.focus();
  canvas.setPointerCapture(e.pointerId);
  pointer('down', e);
  e.preventDefault();
});
// Moves matter only while a button is held (a drag); hovering sends nothing.
canvas.addEventListener('pointermove', (e) => { if (e.buttons) pointer('move', e); });
canvas.addEventListener('pointerup', (e) => { if (e.button <= 2) pointer('up', e); });
canvas.addEventListener('contextmenu', (e) => e.preventDefault());
canvas.addEventListener('wheel', (e) => {
  e.preventDefault();
  const pixels = e.deltaMode === 1 ? e.deltaY * 33 : e.deltaMode === 2 ? e.deltaY * 400 : e.deltaY;
  send({ type: 'wheel', steps: Math.max(-100, Math.min(100, -pixels / 100)) });
}, { passive: false });

const flyKeys = { KeyW: 'forward', KeyS: 'back', KeyA: 'left', KeyD: 'right', KeyQ: 'down', KeyE: 'up' };
const held = {};
const typing = (e) => ['INPUT', 'SELECT', 'TEXTAREA'].includes(e.target.tagName) && e.target.type !== 'range' &&
  e.target.type !== 'checkbox';
function sendKeys() { send({ type: 'keys', ...held }); }
document.addEventListener('keydown', (e) => {
  if (typing(e) || e.repeat || e.ctrlKey || e.metaKey || e.altKey) return;
  if (flyKeys[e.code]) { held[flyKeys[e.code]] = true; sendKeys(); }
  if (e.code === 'KeyF') send({ type: 'action', name: 'frame' });
  if (e.code === 'KeyR') send({ type: 'action', name: 'reset' });
});
document.addEventListener('keyup', (e) => {
  if (flyKeys[e.code] && held[flyKeys[e.code]]) { held[flyKeys[e.code]] = false; sendKeys(); }
});
window.addEventListener('blur', () => {
  for (const k of Object.keys(held)) held[k] = false;
  sendKeys();
});

connect();
