// The GPU backend's start-up as far as it goes without a GPU: where OptiX's disk cache is, when and how the compile
// of the GPU programs is reported, and the lines the command line prints of it.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/progress.h"
#include "backends/optix/compile_progress_reporter.h"
#include "backends/optix/program_cache_directory.h"
#include "support/scoped_variable.h"

namespace candela {
namespace {

using Stage = ProgramCompileProgress::Stage;

TEST(ProgramCache, FolderFromTheEnvironment) {
  ScopedVariable home("HOME", "/home/someone"), xdg("XDG_CACHE_HOME", nullptr), own("CANDELA_OPTIX_CACHE", nullptr);
  EXPECT_EQ(optix::defaultProgramCacheDirectory(), "/home/someone/.cache/candela/optix");
  {
    ScopedVariable relative("XDG_CACHE_HOME", "relative/ignored");
    EXPECT_EQ(optix::defaultProgramCacheDirectory(), "/home/someone/.cache/candela/optix");
  }
  ScopedVariable xdgSet("XDG_CACHE_HOME", "/var/cache/me");
  EXPECT_EQ(optix::defaultProgramCacheDirectory(), "/var/cache/me/candela/optix");
  ScopedVariable ownSet("CANDELA_OPTIX_CACHE", "/scratch/optix");
  EXPECT_EQ(optix::defaultProgramCacheDirectory(), "/scratch/optix");
}

TEST(ProgramCache, NoFolderWithoutAnyVariable) {
  ScopedVariable home("HOME", nullptr), xdg("XDG_CACHE_HOME", nullptr), own("CANDELA_OPTIX_CACHE", nullptr);
  EXPECT_EQ(optix::defaultProgramCacheDirectory(), "");
}

// What a listener heard, in order.
class Recorder {
 public:
  ProgramCompileListener listener() {
    return [this](const ProgramCompileProgress& p) {
      std::lock_guard<std::mutex> lock(mutex_);
      heard_.push_back(p);
    };
  }
  std::vector<ProgramCompileProgress> heard() {
    std::lock_guard<std::mutex> lock(mutex_);
    return heard_;
  }

 private:
  std::mutex mutex_;
  std::vector<ProgramCompileProgress> heard_;
};

ProgramCompileProgress about() {
  ProgramCompileProgress p;
  p.gpuName = "NVIDIA H200";
  p.cacheDirectory = "/home/someone/.cache/candela/optix";
  return p;
}

void sleepSeconds(double seconds) { std::this_thread::sleep_for(std::chrono::duration<double>(seconds)); }

TEST(CompileProgressReporter, QuietWhenTheCompileIsQuick) {
  Recorder recorder;
  {
    optix::CompileProgressReporter reporter(recorder.listener(), about(), [] { return CompileTaskCounts{3, 3}; });
    reporter.finish();
  }
  {
    optix::CompileProgressReporter failing(recorder.listener(), about(), [] { return CompileTaskCounts{1, 3}; });
  }
  EXPECT_TRUE(recorder.heard().empty());
}

TEST(CompileProgressReporter, StartsRunsAndFinishes) {
  Recorder recorder;
  {
    optix::CompileProgressReporter reporter(recorder.listener(), about(), [] { return CompileTaskCounts{2, 5}; });
    sleepSeconds(kProgramCompileQuietSeconds + 0.35);
    reporter.finish();
  }
  const std::vector<ProgramCompileProgress> heard = recorder.heard();
  ASSERT_GE(heard.size(), 3u);
  EXPECT_EQ(heard.front().stage, Stage::Started);
  EXPECT_GE(heard.front().seconds, kProgramCompileQuietSeconds);
  for (size_t i = 1; i + 1 < heard.size(); ++i) EXPECT_EQ(heard[i].stage, Stage::Running);
  EXPECT_EQ(heard.back().stage, Stage::Finished);
  for (size_t i = 1; i < heard.size(); ++i) EXPECT_GE(heard[i].seconds, heard[i - 1].seconds);
  EXPECT_EQ(heard.back().gpuName, "NVIDIA H200");
  EXPECT_EQ(heard.back().tasks.done, 2u);
  EXPECT_EQ(heard.back().tasks.known, 5u);
}

TEST(CompileProgressReporter, FailsWhereTheCompileEndsWithoutFinishing) {
  Recorder recorder;
  {
    optix::CompileProgressReporter reporter(recorder.listener(), about(), [] { return CompileTaskCounts{1, 4}; });
    sleepSeconds(kProgramCompileQuietSeconds + 0.25);
  }
  const std::vector<ProgramCompileProgress> heard = recorder.heard();
  ASSERT_GE(heard.size(), 2u);
  EXPECT_EQ(heard.front().stage, Stage::Started);
  EXPECT_EQ(heard.back().stage, Stage::Failed);
}

TEST(CompileProgressReporter, NoListenerNoThread) {
  optix::CompileProgressReporter reporter({}, about(), [] { return CompileTaskCounts{}; });
  sleepSeconds(kProgramCompileQuietSeconds + 0.15);
  reporter.finish();
}

ProgramCompileProgress at(Stage stage, uint32_t done, uint32_t known, double seconds) {
  ProgramCompileProgress p = about();
  p.stage = stage;
  p.tasks = {done, known};
  p.seconds = seconds;
  return p;
}

TEST(CompileProgressLines, SayWhatCompilesWhereItIsKeptAndHowLongItTook) {
  EXPECT_EQ(compileStartLine(at(Stage::Started, 0, 3, 0.5)),
            "optix: compiling the GPU programs for NVIDIA H200 (first start on this machine; cached in "
            "/home/someone/.cache/candela/optix)...");
  ProgramCompileProgress uncached = at(Stage::Started, 0, 3, 0.5);
  uncached.cacheDirectory.clear();
  EXPECT_EQ(compileStartLine(uncached),
            "optix: compiling the GPU programs for NVIDIA H200 (not cached: every start compiles them)...");
  EXPECT_EQ(compileStatusLine(at(Stage::Running, 12, 40, 8.14)), "optix: compiling, 12/40 tasks done, 8.1s");
  EXPECT_EQ(compileEndLine(at(Stage::Finished, 40, 40, 65.0)), "optix: compiled the GPU programs in 1m05s (40 tasks)");
  EXPECT_EQ(compileEndLine(at(Stage::Failed, 7, 40, 3.0)), "optix: compiling the GPU programs failed after 3.0s");
}

// What a printer wrote for `reports`.
std::string printed(bool terminal, const std::vector<ProgramCompileProgress>& reports) {
  std::FILE* file = std::tmpfile();
  CompileProgressPrinter printer(file, terminal);
  for (const ProgramCompileProgress& p : reports) printer(p);
  std::rewind(file);
  std::string text;
  for (int c; (c = std::fgetc(file)) != EOF;) text += char(c);
  std::fclose(file);
  return text;
}

TEST(CompileProgressPrinter, RedrawsOneLineOnATerminal) {
  const std::string text = printed(true, {at(Stage::Started, 0, 3, 0.5), at(Stage::Running, 1, 9, 0.6),
                                          at(Stage::Running, 2, 9, 0.7), at(Stage::Finished, 9, 9, 9.8)});
  const std::string status1 = "optix: compiling, 1/9 tasks done, 0.6s";
  const std::string status2 = "optix: compiling, 2/9 tasks done, 0.7s";
  const std::string end = "optix: compiled the GPU programs in 9.8s (9 tasks)";
  EXPECT_EQ(text,
            compileStartLine(at(Stage::Started, 0, 3, 0.5)) + "\n\r" + status1 + "\r" + status2 + "\r" + end + "\n");
}

TEST(CompileProgressPrinter, CoversALongerLineWithSpaces) {
  const std::string longer = compileStatusLine(at(Stage::Running, 1000, 9000, 100.0));
  const std::string shorter = compileStatusLine(at(Stage::Running, 1, 9, 0.7));
  const std::string text = printed(true, {at(Stage::Running, 1000, 9000, 100.0), at(Stage::Running, 1, 9, 0.7)});
  EXPECT_EQ(text, "\r" + longer + "\r" + shorter + std::string(longer.size() - shorter.size(), ' '));
}

TEST(CompileProgressPrinter, WritesPlainLinesEveryFewSecondsOtherwise) {
  const std::string text =
      printed(false, {at(Stage::Started, 0, 3, 0.5), at(Stage::Running, 1, 9, 0.6), at(Stage::Running, 2, 9, 5.4),
                      at(Stage::Running, 3, 9, 5.6), at(Stage::Running, 4, 9, 10.7), at(Stage::Finished, 9, 9, 12.0)});
  EXPECT_EQ(text, compileStartLine(at(Stage::Started, 0, 3, 0.5)) + "\n" +
                      compileStatusLine(at(Stage::Running, 3, 9, 5.6)) + "\n" +
                      compileStatusLine(at(Stage::Running, 4, 9, 10.7)) + "\n" +
                      compileEndLine(at(Stage::Finished, 9, 9, 12.0)) + "\n");
}

}  // namespace
}  // namespace candela
