#pragma once
// The film's channels, declared once: the film's per-pixel arrays (FilmView, kernel/film.h) and every mirror of them
// (the accumulation's pixel, FilmSums, the CPU and OptiX films, checkpoint files, the multi-GPU and MPI sums) are
// made from this list. For host and device code alike.
#include <cstdint>

#include "core/math.h"

namespace candela {

// The film's channels, one X(Type, name, presence, components, description) each:
//   Type         a pixel's value: Vec3, float or uint32_t;
//   name         the member's name in FilmView, FilmSums and the backends' films; the checkpoint's layer is
//                "sum.<name>";
//   presence     Always, or WithAovs for a channel that exists only while the AOVs are on (--aov, --denoise);
//   components   the checkpoint's names of a Vec3's components ("RGB": sum.radiance.R, .G, .B); "" for a scalar;
//   description  what the channel holds, for messages ("the film's radiance sums").
// Every channel is a sum or a count over the pixel's samples: the films of several GPUs or processes combine by
// adding channel by channel. The order here is that of FilmView's members and of forEachFilmChannel's visits; a
// checkpoint file orders its channels by name, whatever the order here.
//
// To add a film channel: add a line here. Then add samples to it (PixelSums::add, kernel/film_accumulation.h) and
// read it where its mean or estimate is wanted (HostFilm::readAovs, DeviceFilm::readAovs, the filters). Its arrays
// and device buffers, its checkpoint layer and its share of the multi-GPU and MPI sums follow from the line; a
// checkpoint written before it lacks the layer, and is refused by the renders that would have it.
#define CANDELA_FILM_CHANNELS(X)                                                   \
  X(Vec3, radiance, Always, "RGB", "the film's radiance sums")                     \
  X(uint32_t, samples, Always, "", "the film's sample counts")                     \
  X(Vec3, emission, WithAovs, "RGB", "the film's emission sums")                   \
  X(Vec3, albedo, WithAovs, "RGB", "the albedo AOV")                               \
  X(Vec3, normal, WithAovs, "XYZ", "the normal AOV")                               \
  X(float, depth, WithAovs, "", "the depth AOV")                                   \
  X(float, luminanceSquares, WithAovs, "", "the film's squared luminance sums")    \
  X(float, oddLuminance, WithAovs, "", "the film's luminance sums of odd samples") \
  X(uint32_t, oddSamples, WithAovs, "", "the film's counts of odd samples")

enum class FilmChannelPresence { Always, WithAovs };

// One line of CANDELA_FILM_CHANNELS, as forEachFilmChannel hands it to its visitor.
template <class T, FilmChannelPresence kPresence>
struct FilmChannel {
  using Type = T;
  static constexpr bool aovsOnly = kPresence == FilmChannelPresence::WithAovs;
  const char* name;
  const char* components;
  const char* description;

  // Whether a film with AOVs (withAovs) or without has the channel.
  CANDELA_HD static constexpr bool inFilm(bool withAovs) { return withAovs || !aovsOnly; }
};

// Calls visit(channel, film.<name>) for every channel of the list, in its order: `channel` is the line as a
// FilmChannel, `film` any struct with a member per channel (FilmView, FilmSums, a backend's buffers).
template <class Film, class Visit>
CANDELA_FN void forEachFilmChannel(Film& film, Visit&& visit) {
#define CANDELA_VISIT_FILM_CHANNEL(Type, name, presence, components, description) \
  visit(FilmChannel<Type, FilmChannelPresence::presence>{#name, components, description}, film.name);
  CANDELA_FILM_CHANNELS(CANDELA_VISIT_FILM_CHANNEL)
#undef CANDELA_VISIT_FILM_CHANNEL
}

// The same over two films at once: visit(channel, a.<name>, b.<name>).
template <class FilmA, class FilmB, class Visit>
CANDELA_FN void forEachFilmChannel(FilmA& a, FilmB& b, Visit&& visit) {
#define CANDELA_VISIT_FILM_CHANNEL(Type, name, presence, components, description) \
  visit(FilmChannel<Type, FilmChannelPresence::presence>{#name, components, description}, a.name, b.name);
  CANDELA_FILM_CHANNELS(CANDELA_VISIT_FILM_CHANNEL)
#undef CANDELA_VISIT_FILM_CHANNEL
}

}  // namespace candela
