#pragma once
// What the GPU backend tells while it compiles its programs for the GPU. OptiX keeps the compiled programs in its
// disk cache (optix_context.h), so a start takes a fraction of a second, except the first on a machine (or after
// a driver update), which compiles them: many seconds. No OptiX types here: the application's layer includes it.
#include <cstdint>
#include <functional>
#include <string>

namespace candela {

// OptiX splits a module's compile into tasks as it goes, each of which may find more: `known` grows.
struct CompileTaskCounts {
  uint32_t done = 0, known = 0;
};

struct ProgramCompileProgress {
  // Started: the compile has gone on for a moment (kProgramCompileQuietSeconds), so it is not a cached start.
  // Running: again every tenth of a second. Finished or Failed: the last of one compile's reports (a failure then
  // throws, with OptiX's log). Nothing at all is reported for a compile that ends within the quiet moment.
  enum class Stage { Started, Running, Finished, Failed };
  Stage stage = Stage::Started;
  std::string gpuName;         // "NVIDIA H200"
  std::string cacheDirectory;  // where OptiX keeps the compiled programs; empty when they are not kept
  CompileTaskCounts tasks;
  double seconds = 0.0;  // since the compile began
};

constexpr double kProgramCompileQuietSeconds = 0.5;

// When a GPU backend's constructor returns: once the programs of a first frame are compiled (Wait: render and
// bench, which time the GPU), or at once, compiling them in the background (InBackground: the interactive front
// ends, which render on the CPU meanwhile; Backend::startingCompile says how the compile goes).
enum class ProgramStart { Wait, InBackground };

// Called on a thread of the backend's, one call at a time; it must not throw.
using ProgramCompileListener = std::function<void(const ProgramCompileProgress&)>;

}  // namespace candela
