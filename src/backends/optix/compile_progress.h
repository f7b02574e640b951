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

// When a GPU backend compiles the programs of its first frame, and when its constructor returns:
// - Wait: the constructor compiles those of a first frame of default settings and returns once they are compiled.
// - InBackground: the constructor begins compiling them and returns at once (the interactive front ends, which
//   render on the CPU meanwhile; Backend::startingCompile says how the compile goes).
// - AtFirstFrame: the constructor compiles nothing; the first frame (or Backend::preparePrograms before it), when
//   scene, settings and AOVs are final, compiles all the programs it needs at once and waits for them (render and
//   bench, which time the GPU and would otherwise compile programs of settings they never render).
enum class ProgramStart { Wait, InBackground, AtFirstFrame };

// Called on a thread of the backend's, one call at a time; it must not throw.
using ProgramCompileListener = std::function<void(const ProgramCompileProgress&)>;

}  // namespace candela
