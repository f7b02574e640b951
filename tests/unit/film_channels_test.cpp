// The film's channels are declared once (kernel/film_channels.h) and every mirror of them follows the list: the
// film's pointers, FilmSums' vectors, their size and bytes, the CPU backend's film, the accumulation's pixel and
// the checkpoint file, which keeps the channels it had.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "app/checkpoint/checkpoint_file.h"
#include "backends/cpu/host_film.h"
#include "backends/film_sums.h"
#include "kernel/film_accumulation.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

// The list read directly, without forEachFilmChannel: what the mirrors must match.
struct ListedChannel {
  std::string name;
  size_t bytesPerPixel;
  bool aovsOnly;
};
const std::vector<ListedChannel>& listedChannels() {
#define CANDELA_LISTED_CHANNEL(Type, name, presence, ...) \
  {#name, sizeof(Type), FilmChannelPresence::presence == FilmChannelPresence::WithAovs},
  static const std::vector<ListedChannel> channels = {CANDELA_FILM_CHANNELS(CANDELA_LISTED_CHANNEL)};
#undef CANDELA_LISTED_CHANNEL
  return channels;
}

// Whether two vectors hold the same bytes (Vec3 has no ==).
template <class T>
bool sameValues(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// A film whose every value differs from every other: finite sums, counts within [0, 1000).
FilmSums distinctFilm(uint32_t width, uint32_t height, bool withAovs) {
  FilmSums film = FilmSums::zero(width, height, withAovs);
  int channelIndex = 0;
  forEachFilmChannel(film, [&](auto, auto& values) {
    ++channelIndex;
    for (size_t i = 0; i < values.size(); ++i) {
      using Value = std::remove_reference_t<decltype(values[i])>;
      const float v = float(channelIndex * 100 + int(i)) + 0.25f;
      if constexpr (std::is_same_v<Value, Vec3>)
        values[i] = {v, v + 0.5f, v + 0.75f};
      else if constexpr (std::is_same_v<Value, float>)
        values[i] = v;
      else  // counts a render could make: fewer odd samples than samples
        values[i] = uint32_t(1000 - channelIndex * 100 + int(i));
    }
  });
  return film;
}

TEST(FilmChannels, FilmSumsHaveAVectorPerChannelOfTheList) {
  for (bool withAovs : {false, true}) {
    const FilmSums film = FilmSums::zero(5, 3, withAovs);
    std::vector<std::string> visited;
    forEachFilmChannel(film, [&](auto channel, const auto& values) {
      const ListedChannel& listed = listedChannels().at(visited.size());
      visited.push_back(channel.name);
      EXPECT_EQ(channel.name, listed.name);
      EXPECT_EQ(sizeof(typename decltype(channel)::Type), listed.bytesPerPixel) << channel.name;
      EXPECT_EQ(channel.aovsOnly, listed.aovsOnly) << channel.name;
      EXPECT_EQ(values.size(), !listed.aovsOnly || withAovs ? 15u : 0u) << channel.name << " with AOVs " << withAovs;
    });
    EXPECT_EQ(visited.size(), listedChannels().size());
    EXPECT_EQ(film.hasAovs(), withAovs);
    EXPECT_TRUE(film.channelsFit());
  }
  // Nothing besides: the size and a vector per channel.
  EXPECT_EQ(sizeof(FilmSums), 2 * sizeof(uint32_t) + listedChannels().size() * sizeof(std::vector<Vec3>));
  EXPECT_EQ(sizeof(FilmView), listedChannels().size() * sizeof(void*));
}

TEST(FilmChannels, BytesAreTheSumOverTheList) {
  for (bool withAovs : {false, true}) {
    size_t expected = 0;
    for (const ListedChannel& c : listedChannels())
      if (!c.aovsOnly || withAovs) expected += 7 * 4 * c.bytesPerPixel;
    EXPECT_EQ(FilmSums::zero(7, 4, withAovs).bytes(), expected) << "with AOVs " << withAovs;
  }
}

TEST(FilmChannels, TheCpuFilmPointsEveryChannelAtItsSums) {
  for (bool withAovs : {false, true}) {
    HostFilm film;
    film.reset(4, 2, withAovs);
    const FilmView view = film.view();
    forEachFilmChannel(view, film.sums(), [&](auto channel, auto* pointer, const auto& values) {
      if (channel.inFilm(withAovs))
        EXPECT_EQ(pointer, values.data()) << channel.name;
      else
        EXPECT_EQ(pointer, nullptr) << channel.name << " without AOVs";
    });
  }
}

// The accumulation loads and stores every channel the film has, and only those.
TEST(FilmChannels, APixelsSumsLoadAndStoreEveryChannel) {
  for (bool withAovs : {false, true}) {
    HostFilm from, to;
    from.reset(3, 2, withAovs);
    from.load(distinctFilm(3, 2, withAovs));
    to.reset(3, 2, withAovs);
    for (size_t pixel = 0; pixel < 6; ++pixel) {
      if (withAovs)
        PixelSums<true>::load(from.view(), pixel).store(to.view(), pixel);
      else
        PixelSums<false>::load(from.view(), pixel).store(to.view(), pixel);
    }
    forEachFilmChannel(from.sums(), to.sums(), [&](auto channel, const auto& a, const auto& b) {
      EXPECT_TRUE(sameValues(a, b)) << channel.name << " with AOVs " << withAovs;
    });
  }
}

class FilmFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("candela-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(FilmFilesTest, AChannelOfAnotherSizeIsRefused) {
  for (size_t wrong = 0; wrong < listedChannels().size(); ++wrong) {
    for (int change : {-1, +1}) {
      FilmSums sums = FilmSums::zero(4, 3, true);
      size_t index = 0;
      forEachFilmChannel(sums, [&](auto, auto& values) {
        if (index++ == wrong) values.resize(values.size() + change);
      });
      const std::string what = listedChannels()[wrong].name + (change < 0 ? " short" : " long");
      EXPECT_FALSE(sums.channelsFit()) << what;
      HostFilm film;
      film.reset(4, 3, true);
      EXPECT_THROW(film.load(sums), std::invalid_argument) << what;
      EXPECT_THROW(writeCheckpoint(path("film.exr"), Checkpoint{{}, 1, 1, sums}), std::invalid_argument) << what;
    }
  }
  EXPECT_FALSE(fs::exists(path("film.exr")));
}

const ExrAttributes kIdentity = {{"candela.scene", "a test"}};

TEST_F(FilmFilesTest, ARoundTripKeepsEveryChannel) {
  for (bool withAovs : {false, true}) {
    const Checkpoint written{kIdentity, 1000, 1000, distinctFilm(6, 5, withAovs)};
    writeCheckpoint(path("film.exr"), written);
    const Checkpoint read = readCheckpoint(path("film.exr"), kIdentity, 6, 5, withAovs);
    EXPECT_EQ(read.nextSample, 1000u);
    ASSERT_TRUE(read.film.sameShape(written.film));
    forEachFilmChannel(written.film, read.film, [&](auto channel, const auto& a, const auto& b) {
      EXPECT_EQ(b.size(), channel.inFilm(withAovs) ? 30u : 0u) << channel.name;
      EXPECT_TRUE(sameValues(a, b)) << channel.name << " with AOVs " << withAovs;
    });
  }
}

// The file keeps the channels of the first checkpoints, by name and type, so that those still resume.
TEST_F(FilmFilesTest, TheFileKeepsItsChannels) {
  const std::vector<std::pair<std::string, Imf::PixelType>> formatOne = {{"R", Imf::FLOAT},
                                                                         {"G", Imf::FLOAT},
                                                                         {"B", Imf::FLOAT},
                                                                         {"sum.radiance.R", Imf::FLOAT},
                                                                         {"sum.radiance.G", Imf::FLOAT},
                                                                         {"sum.radiance.B", Imf::FLOAT},
                                                                         {"sum.samples", Imf::UINT},
                                                                         {"sum.emission.R", Imf::FLOAT},
                                                                         {"sum.emission.G", Imf::FLOAT},
                                                                         {"sum.emission.B", Imf::FLOAT},
                                                                         {"sum.albedo.R", Imf::FLOAT},
                                                                         {"sum.albedo.G", Imf::FLOAT},
                                                                         {"sum.albedo.B", Imf::FLOAT},
                                                                         {"sum.normal.X", Imf::FLOAT},
                                                                         {"sum.normal.Y", Imf::FLOAT},
                                                                         {"sum.normal.Z", Imf::FLOAT},
                                                                         {"sum.depth", Imf::FLOAT},
                                                                         {"sum.luminanceSquares", Imf::FLOAT},
                                                                         {"sum.oddLuminance", Imf::FLOAT},
                                                                         {"sum.oddSamples", Imf::UINT}};
  writeCheckpoint(path("film.exr"), Checkpoint{kIdentity, 8, 8, FilmSums::zero(2, 2, true)});
  Imf::InputFile file(path("film.exr").c_str());
  const Imf::ChannelList& channels = file.header().channels();
  for (const auto& [name, type] : formatOne) {
    const Imf::Channel* channel = channels.findChannel(name);
    ASSERT_NE(channel, nullptr) << name;
    EXPECT_EQ(channel->type, type) << name;
  }
}

// Sums no render writes are refused on resumption: they would reach the image (a negative radiance sum is a
// negative pixel) or break the filters that read the counts.
TEST_F(FilmFilesTest, ForgedSumsAreRefused) {
  const auto refusal = [&](const std::function<void(FilmSums&)>& forge) -> std::string {
    FilmSums film = distinctFilm(6, 5, true);
    forge(film);
    writeCheckpoint(path("forged.exr"), Checkpoint{kIdentity, 1000, 1000, film});
    try {
      readCheckpoint(path("forged.exr"), kIdentity, 6, 5, true);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(refusal([](FilmSums&) {}), "") << "an unforged film";
  EXPECT_NE(refusal([](FilmSums& f) { f.radiance[3].y = -1.0f; }).find("negative"), std::string::npos);
  EXPECT_NE(refusal([](FilmSums& f) { f.emission[0].x = -0.5f; }).find("negative"), std::string::npos);
  EXPECT_NE(refusal([](FilmSums& f) { f.luminanceSquares[7] = -2.0f; }).find("negative"), std::string::npos);
  EXPECT_NE(refusal([](FilmSums& f) { f.depth[1] = std::numeric_limits<float>::infinity(); }).find("infinite"),
            std::string::npos);
  EXPECT_EQ(refusal([](FilmSums& f) { f.normal[2] = {-1.0f, -2.0f, -3.0f}; }), "") << "normals are signed";
  EXPECT_NE(refusal([](FilmSums& f) { f.samples[4] = 0; }).find("a pixel without samples"), std::string::npos);
  EXPECT_NE(refusal([](FilmSums& f) { f.samples[4] = 1001; }).find("more samples than"), std::string::npos);
  EXPECT_NE(refusal([](FilmSums& f) { f.oddSamples[4] = f.samples[4] + 1; }).find("more odd samples"),
            std::string::npos);
}

// A resumption reads the header as every other EXR reader does, checked first: an attribute that claims 2 GB in
// a small file is refused before OpenEXR allocates it.
TEST_F(FilmFilesTest, AnAttributeThatClaimsMoreThanTheFileIsRefusedFirst) {
  std::string bytes = {0x76, 0x2f, 0x31, 0x01, 0x02, 0x00, 0x00, 0x00};
  bytes += std::string("candela.checkpoint") + '\0' + "mystery" + '\0';
  const int32_t claimed = 2000000000;
  bytes.append(reinterpret_cast<const char*>(&claimed), 4);
  bytes += std::string(32, 'x');
  std::ofstream(path("bomb.exr"), std::ios::binary) << bytes;
  try {
    readCheckpoint(path("bomb.exr"), kIdentity, 6, 5, true);
    ADD_FAILURE() << "a header whose attribute claims 2 GB was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("claims 2000000000 bytes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace candela
