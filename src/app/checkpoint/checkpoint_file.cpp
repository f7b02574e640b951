#include "app/checkpoint/checkpoint_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "io/atomic_file.h"
#include "io/file_bytes.h"
#include "io/images/exr_decoding.h"
#include "io/images/exr_memory_stream.h"
#include "io/load_diagnostics.h"
#include "kernel/film.h"

namespace candela {

namespace {

constexpr const char* kFormatAttribute = "candela.checkpoint";
constexpr const char* kFormatVersion = "1";
constexpr const char* kNextSampleAttribute = "candela.nextSample";
constexpr const char* kSamplesPerPixelAttribute = "candela.spp";

// The film's channels (kernel/film_channels.h) as EXR channels, for writing and for reading alike: the layer
// "sum.<name>", of a channel per component for a Vec3 ("sum.radiance.R"); counts as unsigned integers.
std::vector<ExrChannel> sumChannels(const FilmSums& film) {
  std::vector<ExrChannel> channels;
  forEachFilmChannel(film, [&](auto channel, const auto& values) {
    using Value = typename decltype(channel)::Type;
    if (!channel.inFilm(film.hasAovs())) return;
    const std::string layer = std::string("sum.") + channel.name;
    const char* base = reinterpret_cast<const char*>(values.data());
    if constexpr (std::is_same_v<Value, Vec3>) {
      for (int i = 0; i < 3; ++i)
        channels.push_back({layer + "." + channel.components[i], base + size_t(i) * sizeof(float), sizeof(Vec3)});
    } else {
      static_assert(std::is_same_v<Value, float> || std::is_same_v<Value, uint32_t>,
                    "a checkpoint stores channels of Vec3, float and uint32_t");
      channels.push_back({layer, base, sizeof(Value), std::is_same_v<Value, uint32_t>});
    }
  });
  return channels;
}

// A checkpoint that cannot be resumed from, told apart from OpenEXR's own exceptions.
class ResumeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void cannotResume(const std::string& path, const std::string& why) {
  throw ResumeError("cannot resume from '" + printableText(path) + "': " + why);
}

std::string attribute(const Imf::Header& header, const std::string& name) {
  const auto* a = header.findTypedAttribute<Imf::StringAttribute>(name);
  return a ? a->value() : std::string();
}

uint32_t parseCount(const std::string& path, const std::string& name, const std::string& text) {
  uint32_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty())
    cannotResume(path, "its attribute " + name + " is not a count");
  return value;
}

void checkIdentity(const std::string& path, const Imf::Header& header, const ExrAttributes& identity) {
  for (const auto& [name, value] : identity) {
    const std::string stored = attribute(header, name);
    if (stored != value)
      cannotResume(path, "it was rendered with " + name.substr(name.find('.') + 1) + " '" + printableText(stored) +
                             "', this render has '" + printableText(value) + "'");
  }
}

// Whether a value of a sum may be what a render adds up: finite (kernel/film_accumulation.h), and not negative
// unless the channel is signed (the normals). Counts are.
bool isPlausibleSum(Vec3 v, bool isSigned) { return isFinite(v) && (isSigned || (v.x >= 0 && v.y >= 0 && v.z >= 0)); }
bool isPlausibleSum(float v, bool isSigned) { return std::isfinite(v) && (isSigned || v >= 0); }
bool isPlausibleSum(uint32_t, bool) { return true; }
bool isZeroSum(Vec3 v) { return v.x == 0 && v.y == 0 && v.z == 0; }
bool isZeroSum(float v) { return v == 0; }
bool isZeroSum(uint32_t v) { return v == 0; }

// Refuses sums that no render writes: a file that holds them was made otherwise, and its values would reach the
// image (a negative radiance sum is a negative pixel).
void checkSums(const std::string& path, const Checkpoint& checkpoint) {
  const FilmSums& film = checkpoint.film;
  forEachFilmChannel(film, [&](auto channel, const auto& values) {
    const bool isSigned = std::string_view(channel.name) == "normal";
    for (size_t i = 0; i < values.size(); ++i) {
      if (!isPlausibleSum(values[i], isSigned))
        cannotResume(path, std::string(isSigned ? "a value that is not finite" : "a negative or infinite value") +
                               " in " + channel.description);
      if (film.samples[i] == 0 && !isZeroSum(values[i]))
        cannotResume(path, std::string("a value for a pixel without samples in ") + channel.description);
    }
  });
  for (size_t i = 0; i < film.samples.size(); ++i) {
    if (film.samples[i] > checkpoint.nextSample)
      cannotResume(path, "a pixel holds more samples than the " + std::to_string(checkpoint.nextSample) +
                             " sample indices it says were rendered");
    if (!film.oddSamples.empty() && film.oddSamples[i] > film.samples[i])
      cannotResume(path, "a pixel holds more odd samples than samples");
  }
}

}  // namespace

void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint) {
  const FilmSums& film = checkpoint.film;
  if (!film.channelsFit()) throw std::invalid_argument("writeCheckpoint: a channel of the film has another size");
  std::vector<Vec3> means(film.pixelCount());
  for (size_t i = 0; i < means.size(); ++i) means[i] = filmMean(film.radiance[i], film.samples[i]);
  const char* base = reinterpret_cast<const char*>(means.data());
  std::vector<ExrChannel> channels = {{"R", base, sizeof(Vec3)},
                                      {"G", base + sizeof(float), sizeof(Vec3)},
                                      {"B", base + 2 * sizeof(float), sizeof(Vec3)}};
  for (ExrChannel& c : sumChannels(film)) channels.push_back(c);
  ExrAttributes attributes = {{kFormatAttribute, kFormatVersion},
                              {kNextSampleAttribute, std::to_string(checkpoint.nextSample)},
                              {kSamplesPerPixelAttribute, std::to_string(checkpoint.samplesPerPixel)}};
  attributes.insert(attributes.end(), checkpoint.identity.begin(), checkpoint.identity.end());
  AtomicFile file(path);
  writeExrChannelsTo(file, film.width, film.height, channels, attributes);
  file.commit();
}

Checkpoint readCheckpoint(const std::string& path, const ExrAttributes& identity, uint32_t width, uint32_t height,
                          bool withAovs) {
  std::vector<uint8_t> bytes;
  try {
    bytes = readFileBytes(path);
  } catch (const LoadError& e) {
    throw std::runtime_error(std::string("cannot resume: ") + e.what());
  }
  Checkpoint checkpoint;
  try {
    checkExrHeaders(path, bytes.data(), bytes.size(), UINT64_MAX, /*checkDataWindows=*/false);
  } catch (const LoadError& e) {
    cannotResume(path, std::string("not a readable OpenEXR file (") + e.what() + ")");
  }
  try {
    ExrMemoryStream stream(path, bytes.data(), bytes.size());
    Imf::InputFile exr(stream);
    const Imf::Header& header = exr.header();
    if (attribute(header, kFormatAttribute) != kFormatVersion)
      cannotResume(path, "it is not a candela checkpoint (written with --checkpoint)");
    checkIdentity(path, header, identity);
    checkpoint.identity = identity;
    checkpoint.nextSample = parseCount(path, kNextSampleAttribute, attribute(header, kNextSampleAttribute));
    checkpoint.samplesPerPixel =
        parseCount(path, kSamplesPerPixelAttribute, attribute(header, kSamplesPerPixelAttribute));
    const Imath::Box2i window = header.dataWindow();
    if (window.min.x != 0 || window.min.y != 0 || int64_t(window.max.x) + 1 != width ||
        int64_t(window.max.y) + 1 != height)
      cannotResume(path, "its pixels are not the " + std::to_string(width) + "x" + std::to_string(height) +
                             " its attributes say");
    if (withAovs != (header.channels().findChannel("sum.albedo.R") != nullptr))
      cannotResume(path, withAovs ? "its film has no AOV sums, which this render's --aov or --denoise needs"
                                  : "its film has AOV sums: resume with the --aov or --denoise it was rendered with");
    checkpoint.film = FilmSums::zero(width, height, withAovs);
    Imf::FrameBuffer frame;
    for (const ExrChannel& c : sumChannels(checkpoint.film)) {
      const Imf::Channel* stored = header.channels().findChannel(c.name);
      const Imf::PixelType type = c.isUint ? Imf::UINT : Imf::FLOAT;
      if (!stored || stored->type != type || stored->xSampling != 1 || stored->ySampling != 1)
        cannotResume(path, "its channel " + c.name + " is missing or not a full-resolution " +
                               (c.isUint ? "unsigned integer" : "float") + " channel");
      frame.insert(c.name, Imf::Slice(type, const_cast<char*>(c.base), c.xStride, c.xStride * width));
    }
    exr.setFrameBuffer(frame);
    exr.readPixels(window.min.y, window.max.y);
  } catch (const ResumeError&) {
    throw;
  } catch (const std::exception& e) {
    cannotResume(path, std::string("not a readable OpenEXR file (") + e.what() + ")");
  }
  checkSums(path, checkpoint);
  return checkpoint;
}

}  // namespace candela
