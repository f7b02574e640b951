#include "io/load_budget.h"

#include <atomic>
#include <chrono>
#include <limits>
#include <mutex>

#include "io/available_memory.h"
#include "io/load_diagnostics.h"

namespace candela {

namespace {

std::atomic<uint64_t> budget{std::numeric_limits<uint64_t>::max()};
std::atomic<uint64_t> charged{0};

using Clock = std::chrono::steady_clock;
std::mutex progressMutex;  // guards the listener and the times below
std::function<void(const LoadProgress&)> progressListener;
double progressInterval = 2.0;
Clock::time_point loadStart = Clock::now(), lastProgress = Clock::now();

}  // namespace

void noteLoadProgress(const std::string& file, const std::string& element) {
  std::unique_lock lock(progressMutex, std::try_to_lock);
  if (!lock || !progressListener) return;
  const Clock::time_point now = Clock::now();
  if (std::chrono::duration<double>(now - lastProgress).count() < progressInterval) return;
  lastProgress = now;
  progressListener({std::chrono::duration<double>(now - loadStart).count(), charged.load(), file, element});
}

void beginLoadBudget() {
  charged = 0;
  budget = availableMemoryBytes() / 2;
  std::lock_guard lock(progressMutex);
  loadStart = lastProgress = Clock::now();
}

void setLoadProgressListener(std::function<void(const LoadProgress&)> listener, double interval) {
  std::lock_guard lock(progressMutex);
  progressListener = std::move(listener);
  progressInterval = interval;
}

void chargeLoadMemory(uint64_t bytes, const std::string& file, const std::string& element) {
  const uint64_t limit = budget.load();
  const uint64_t before = charged.fetch_add(bytes);
  if (bytes <= limit && before <= limit - bytes) {
    noteLoadProgress(file, element);
    return;
  }
  charged.fetch_sub(bytes);
  std::string why = before > 0 ? "; with the rest of the scene that is more than the " : ", more than the ";
  throw LoadBudgetError(printableText(file + ": " + element + " needs about " + memorySizeText(bytes) + why +
                                      memorySizeText(limit) + " this load may use (" +
                                      (processMemoryLimit() > 0 ? "--max-memory" : "the memory available") + ")"));
}

void releaseLoadMemory(uint64_t bytes) {
  uint64_t now = charged.load();
  while (!charged.compare_exchange_weak(now, now > bytes ? now - bytes : 0)) {
  }
}

uint64_t loadMemoryLeft() {
  const uint64_t limit = budget.load(), used = charged.load();
  return limit > used ? limit - used : 0;
}

}  // namespace candela
