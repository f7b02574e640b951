#pragma once
#include <cstdint>
#include <functional>
#include <string>

#include "io/load_diagnostics.h"

namespace candela {

// The memory one scene load may take, and what its loaders have claimed of it so far. A loader estimates what
// an element will cost before it decodes or builds it (from a header's sizes, a count of triangles or texels,
// a decompressed size) and charges that estimate: once the charges exceed the budget, the load stops with one
// LoadError that names the file, the element and the estimate, instead of decoding for minutes into swap.
//
// The budget is half of what the process may still allocate when the load begins (availableMemoryBytes: the
// machine's available memory, the cgroup's and ulimit's room, --max-memory); the other half is left for what the
// renderer makes of the scene (its flat arrays, mip levels and acceleration structures). It is one for the
// process, so that loaders on several threads charge the same budget.

// The error of a load over its budget. Code that survives a LoadError of one part (a texture left out with a
// warning) lets this one through: the load as a whole must stop.
class LoadBudgetError : public LoadError {
 public:
  using LoadError::LoadError;
};

// Starts a load's budget: nothing charged, the room measured now.
void beginLoadBudget();

// Charges `bytes` that `element` of `file` is about to take. Throws LoadBudgetError when the load's charges would then
// exceed its budget: "<file>: <element> needs about 1.2 GiB; with the rest of the scene that is more than the
// 4.0 GiB this load may use (--max-memory, or the memory available)".
void chargeLoadMemory(uint64_t bytes, const std::string& file, const std::string& element);

// Returns a charge once its memory is free again (a temporary buffer).
void releaseLoadMemory(uint64_t bytes);

// Bytes the load may still charge.
uint64_t loadMemoryLeft();

// Where a load is, for a progress line: how long it has run, what it has charged, and the element it charged last.
struct LoadProgress {
  double seconds = 0;
  uint64_t charged = 0;
  std::string file, element;
};

// Tells the progress listener (below) where the load is, when it is time for a line. Cheap: call it per shape,
// per few hundred rows of an image. chargeLoadMemory calls it too.
void noteLoadProgress(const std::string& file, const std::string& element);

// Called with the load's progress at most every `interval` seconds once it has run that long, from whichever
// thread charged last (never two calls at once); an empty function stops the calls.
void setLoadProgressListener(std::function<void(const LoadProgress&)> listener, double interval = 2.0);

}  // namespace candela
