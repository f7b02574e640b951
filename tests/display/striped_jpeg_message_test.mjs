// node striped_jpeg_message_test.mjs <message file> <width> <height> <stripes>: unpacks a message that
// write_striped_jpeg packed with the page's module (src/app/serve/web/striped_jpeg.mjs) and checks that its stripes tile
// the frame and that each is a whole JPEG file of the frame's width and the stripe's rows.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { unpackStripedJpeg } from '../../src/app/serve/web/striped_jpeg.mjs';

const [file, width, height, stripeCount] = process.argv.slice(2);
const bytes = readFileSync(file);
// As the page gets it: the frame's JSON header first, the message after it.
const prefix = 5;
const buffer = new ArrayBuffer(prefix + bytes.length);
new Uint8Array(buffer, prefix).set(bytes);
const frame = unpackStripedJpeg(buffer, prefix);
assert.equal(frame.width, Number(width));
assert.equal(frame.height, Number(height));
assert.equal(frame.stripes.length, Number(stripeCount));

// The frame size in a JPEG's start-of-frame segment (FFC0 to FFC2), found by walking the segments.
function jpegSize(jpeg) {
  assert.equal(jpeg[0], 0xff);
  assert.equal(jpeg[1], 0xd8);
  for (let at = 2; at + 9 < jpeg.length;) {
    assert.equal(jpeg[at], 0xff);
    const marker = jpeg[at + 1], length = (jpeg[at + 2] << 8) | jpeg[at + 3];
    if (marker >= 0xc0 && marker <= 0xc2)
      return { height: (jpeg[at + 5] << 8) | jpeg[at + 6], width: (jpeg[at + 7] << 8) | jpeg[at + 8] };
    at += 2 + length;
  }
  throw new Error('no start-of-frame segment');
}

let row = 0;
for (const stripe of frame.stripes) {
  assert.equal(stripe.firstRow, row);
  assert.deepEqual(jpegSize(stripe.bytes), { width: frame.width, height: stripe.rows });
  assert.equal(stripe.bytes[stripe.bytes.length - 2], 0xff);
  assert.equal(stripe.bytes[stripe.bytes.length - 1], 0xd9);
  row += stripe.rows;
}
assert.equal(row, frame.height);
assert.throws(() => unpackStripedJpeg(buffer.slice(0, buffer.byteLength - 1), prefix));
console.log(`unpacked ${frame.stripes.length} stripes of ${frame.width}x${frame.height}`);
