// Outputs are replaced whole or not at all: every failure leaves the previous file and no temporary behind.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "io/atomic_file.h"
#include "io/images/aov_io.h"
#include "io/images/image_io.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("candela-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    fs::permissions(dir_, fs::perms::owner_all);
    fs::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  void put(const std::string& name, const std::string& content) const { std::ofstream(path(name)) << content; }
  std::string get(const std::string& name) const {
    std::ifstream in(path(name), std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  // The names in the folder, to see that no temporary is left.
  std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const auto& entry : fs::directory_iterator(dir_)) result.push_back(entry.path().filename().string());
    std::sort(result.begin(), result.end());
    return result;
  }

  fs::path dir_;
};

Image grey(uint32_t width, uint32_t height) {
  Image image(width, height);
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = Vec3{1, 1, 1} * float(i % 97) / 97.0f;
  return image;
}

// Lowers the limit on file sizes, as a full disk would stop writes: beyond it, writes fail with EFBIG.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    previous_ = ::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    ::signal(SIGXFSZ, previous_);
  }

 private:
  rlimit saved_{};
  sighandler_t previous_;
};

TEST_F(AtomicFileTest, CommitReplacesTheFileAndKeepsItsPermissions) {
  put("out.txt", "old content");
  ::chmod(path("out.txt").c_str(), 0640);
  writeFileAtomically(path("out.txt"), "new", 3);
  EXPECT_EQ(get("out.txt"), "new");
  struct stat st {};
  ASSERT_EQ(::stat(path("out.txt").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
  EXPECT_EQ(names(), std::vector<std::string>{"out.txt"});
}

TEST_F(AtomicFileTest, UncommittedFileLeavesTheTargetAlone) {
  put("out.txt", "old");
  {
    AtomicFile file(path("out.txt"));
    file.write("new", 3);
    EXPECT_EQ(names().size(), 2u);  // the target and the temporary
  }
  EXPECT_EQ(get("out.txt"), "old");
  EXPECT_EQ(names(), std::vector<std::string>{"out.txt"});
}

TEST_F(AtomicFileTest, FailedWritesOfEveryFormatKeepThePreviousImage) {
  for (const char* name : {"out.png", "out.exr", "out.pfm"}) {
    put(name, "previous image");
    FileSizeLimit limit(4096);  // the image needs far more
    try {
      writeImage(path(name), grey(256, 256), {});
      ADD_FAILURE() << name << " written past the file size limit";
    } catch (const WriteError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("cannot write '" + path(name) + "': ", 0), 0u) << e.what();
    }
    EXPECT_EQ(get(name), "previous image") << name;
  }
  EXPECT_EQ(names(), (std::vector<std::string>{"out.exr", "out.pfm", "out.png"}));
}

TEST_F(AtomicFileTest, DevicesAreRefusedAlsoThroughSymbolicLinks) {
  fs::create_symlink("/dev/full", path("full.png"));
  try {
    writeImage(path("full.png"), grey(8, 8), {});
    ADD_FAILURE() << "wrote through a link to /dev/full";
  } catch (const WriteError& e) {
    EXPECT_NE(std::string(e.what()).find("leads to '/dev/full', not a regular file"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_symlink(path("full.png")));
  EXPECT_THROW(writeFileAtomically("/dev/full", "x", 1), WriteError);
}

TEST_F(AtomicFileTest, SymbolicLinkIsFollowedAndKept) {
  fs::create_directories(dir_ / "real");
  put("real/out.pfm", "old");
  fs::create_symlink("real/out.pfm", path("link.pfm"));
  writeImage(path("link.pfm"), grey(4, 4), {});
  EXPECT_TRUE(fs::is_symlink(path("link.pfm")));
  EXPECT_EQ(get("real/out.pfm").substr(0, 3), "PF\n");
}

TEST_F(AtomicFileTest, ReadOnlyFolderIsAnErrorAndTheFileSurvives) {
  put("out.png", "old");
  const fs::perms readWrite = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                              fs::perms::group_write | fs::perms::others_read | fs::perms::others_write;
  fs::permissions(path("out.png"), readWrite);
  fs::permissions(dir_,
                  fs::perms::owner_read | fs::perms::owner_exec | fs::perms::others_read | fs::perms::others_exec);
  // Permissions do not bind the superuser: then the write is tried as nobody, in a child process.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(2);
    try {
      writeImage(path("out.png"), grey(8, 8), {});
    } catch (const WriteError& e) {
      // The file itself is writable, so an in-place write would have replaced it.
      ::_exit(std::string(e.what()).find("is not writable") != std::string::npos ? 0 : 3);
    }
    ::_exit(1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  fs::permissions(dir_, fs::perms::owner_all);
  EXPECT_EQ(get("out.png"), "old");
  EXPECT_EQ(names(), std::vector<std::string>{"out.png"});
}

// Every signal whose default action ends the process removes the temporary first, then ends it as before.
TEST_F(AtomicFileTest, EndingSignalsWhileWritingRemoveTheTemporary) {
  for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT}) {
    put("out.pfm", "old");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      const rlimit noCore{0, 0};
      ::setrlimit(RLIMIT_CORE, &noCore);  // SIGQUIT's default action dumps core
      AtomicFile file(path("out.pfm"));
      file.write("partial", 7);
      ::raise(signal);
      ::_exit(0);  // not reached
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << strsignal(signal) << ": " << status;
    EXPECT_EQ(get("out.pfm"), "old") << strsignal(signal);
    EXPECT_EQ(names(), std::vector<std::string>{"out.pfm"}) << strsignal(signal);
  }
}

TEST_F(AtomicFileTest, FailingAovKeepsThePreviousImage) {
  put("out.png", "previous image");
  put("out.normal.png", "previous normals");
  fs::create_directories(dir_ / "out.albedo.png");  // the albedo cannot be written
  const Image image = grey(8, 8);
  AovImages aovs(8, 8);
  EXPECT_THROW(writeImageWithAovs(path("out.png"), image, {}, aovs, {Aov::Normal, Aov::Albedo}), WriteError);
  EXPECT_EQ(get("out.png"), "previous image");
  EXPECT_EQ(get("out.normal.png"), "previous normals");
  EXPECT_EQ(names(), (std::vector<std::string>{"out.albedo.png", "out.normal.png", "out.png"}));
  // Once it can, all three are written.
  fs::remove(dir_ / "out.albedo.png");
  EXPECT_EQ(writeImageWithAovs(path("out.png"), image, {}, aovs, {Aov::Normal, Aov::Albedo}).size(), 3u);
  EXPECT_EQ(get("out.png").substr(1, 3), "PNG");
}

}  // namespace
}  // namespace candela
