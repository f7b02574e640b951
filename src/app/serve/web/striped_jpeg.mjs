// The page's side of a striped JPEG frame (src/io/images/striped_jpeg.h): unpacking the message, and drawing its
// stripes. A module of its own so that the page can take it as it is; striped_jpeg_message_test.mjs (tests/display)
// checks the unpacking against messages the C++ side packed.

// The message at `offset` in `buffer` (an ArrayBuffer; a frame's payload follows its JSON header):
// { width, height, stripes: [{ firstRow, rows, bytes }] }, each stripe's bytes a Uint8Array view of one JPEG file.
// Throws an Error for bytes that are not such a message.
export function unpackStripedJpeg(buffer, offset = 0) {
  const view = new DataView(buffer, offset);
  if (view.byteLength < 12) throw new Error('striped JPEG: shorter than its header');
  const width = view.getUint32(0, true), height = view.getUint32(4, true), count = view.getUint32(8, true);
  if (count === 0 || count > height) throw new Error('striped JPEG: no stripes, or more than rows');
  let at = 12 + 8 * count;
  if (view.byteLength < at) throw new Error('striped JPEG: shorter than its stripe table');
  const stripes = [];
  for (let i = 0; i < count; ++i) {
    const firstRow = view.getUint32(12 + 8 * i, true), length = view.getUint32(16 + 8 * i, true);
    const next = i + 1 < count ? view.getUint32(20 + 8 * i, true) : height;
    if ((i === 0 && firstRow !== 0) || next <= firstRow || next > height)
      throw new Error('striped JPEG: stripes that do not tile the rows');
    if (at + length > view.byteLength) throw new Error('striped JPEG: stripes past its end');
    stripes.push({ firstRow, rows: next - firstRow, bytes: new Uint8Array(buffer, offset + at, length) });
    at += length;
  }
  if (at !== view.byteLength) throw new Error('striped JPEG: bytes after its last stripe');
  return { width, height, stripes };
}

// Decodes the stripes at once (the browser may decode them in parallel) and then draws them all, each at its first
// row, in the frame's pixels: a context of another size scales them with its transform, e.g.
// context.setTransform(canvas.width / frame.width, 0, 0, canvas.height / frame.height, 0, 0).
export async function drawStripedJpeg(context, frame) {
  const bitmaps = await Promise.all(
    frame.stripes.map((s) => createImageBitmap(new Blob([s.bytes], { type: 'image/jpeg' }))));
  bitmaps.forEach((bitmap, i) => {
    context.drawImage(bitmap, 0, frame.stripes[i].firstRow);
    bitmap.close();
  });
}
