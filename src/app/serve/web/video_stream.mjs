// The page's side of candela serve's H.264 stream (src/io/video/h264_encoder.h): a WebCodecs VideoDecoder fed the
// frames' access units, one per frame, with no reordering (the stream has no B-frames), so that each decoded frame
// comes out before the next goes in.

// Whether this browser's WebCodecs decode the stream: H.264 at 1080p (any profile of the stream's features).
export async function canDecodeH264() {
  if (typeof VideoDecoder === 'undefined') return false;
  try {
    const config = { codec: 'avc1.42C028', codedWidth: 1920, codedHeight: 1080, optimizeForLatency: true };
    return (await VideoDecoder.isConfigSupported(config)).supported === true;
  } catch {
    return false;
  }
}

// Decodes the frames' access units and calls `shown(header, videoFrame)` for each decoded one (which must close
// the frame), `lost(header)` for each that will not be shown (it came before a key frame, or the decoder failed),
// and `restart()` when the stream must start again at a key frame (the server then sends one).
export class VideoStream {
  constructor({ shown, lost, restart }) {
    this.shown = shown;
    this.lost = lost;
    this.restart = restart;
    this.decoder = null;
    this.config = null;
    this.pending = new Map();  // frame number -> header, until its output
    this.failures = 0;
  }

  // One frame's message: its header ({frame, key, codec, width, height}) and its access unit (a Uint8Array).
  decode(header, bytes) {
    if (header.key) this.configure(header);
    if (!this.decoder || this.decoder.state !== 'configured') {
      // A delta frame without the key frame before it: nothing to decode it against.
      this.lost(header);
      this.restart();
      return;
    }
    this.pending.set(header.frame, header);
    this.decoder.decode(new EncodedVideoChunk({
      type: header.key ? 'key' : 'delta', timestamp: header.frame, data: bytes }));
  }

  configure(header) {
    // The coded size comes with the stream (its SPS): the config needs none.
    const config = { codec: header.codec, optimizeForLatency: true };
    const same = this.config && this.config.codec === config.codec && this.size === `${header.width}x${header.height}`;
    if (same && this.decoder && this.decoder.state === 'configured') return;
    this.close();
    this.decoder = new VideoDecoder({
      output: (frame) => this.output(frame),
      error: (error) => this.failed(error),
    });
    this.decoder.configure(config);
    this.config = config;
    this.size = `${header.width}x${header.height}`;
  }

  output(frame) {
    const header = this.pending.get(frame.timestamp);
    this.pending.delete(frame.timestamp);
    this.failures = 0;
    if (header) this.shown(header, frame);
    else frame.close();
  }

  failed(error) {
    this.failures += 1;
    this.lastError = error;
    for (const header of this.pending.values()) this.lost(header);
    this.pending.clear();
    this.decoder = null;
    this.config = null;
    this.restart();
  }

  close() {
    if (this.decoder && this.decoder.state !== 'closed') this.decoder.close();
    for (const header of this.pending.values()) this.lost(header);
    this.pending.clear();
    this.decoder = null;
  }
}
