#pragma once
#include <cstdint>
#include <string>

#include "backends/film_sums.h"
#include "io/images/image_io.h"

namespace candela {

// A resumable render's state: the film's sums with their per-pixel sample counts, the sample indices they hold,
// and the settings that made them (render_identity.h), all in one OpenEXR file. Its R, G and B channels are the
// image so far, so that any EXR viewer shows it; the sums are layers named "sum.*".
struct Checkpoint {
  ExrAttributes identity;
  uint32_t nextSample = 0;       // the film holds the sample indices [0, nextSample) of every pixel
  uint32_t samplesPerPixel = 0;  // what the render was asked for, for messages
  FilmSums film;
};

// Replaces `path` atomically (io/atomic_file.h); throws WriteError naming it, and std::invalid_argument for a
// film whose channels do not fit its size (FilmSums::channelsFit).
void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint);

// Reads a checkpoint written for a render whose identity is `identity`, whose film is width x height with AOV
// sums or without. Throws std::runtime_error with one line naming the file: not a readable checkpoint, or one of
// another render (naming the first setting that differs).
Checkpoint readCheckpoint(const std::string& path, const ExrAttributes& identity, uint32_t width, uint32_t height,
                          bool withAovs);

}  // namespace candela
