#include "io/available_memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

namespace candela {

namespace {

constexpr uint64_t kUnlimited = std::numeric_limits<uint64_t>::max();

std::atomic<uint64_t> processLimit{0};

uint64_t memAvailable() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  uint64_t kib = 0;
  std::string unit;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024;
  const long pages = sysconf(_SC_AVPHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
  return pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) : kUnlimited;
}

uint64_t cgroupRoom() {
  std::ifstream maxFile("/sys/fs/cgroup/memory.max"), currentFile("/sys/fs/cgroup/memory.current");
  std::string max;
  uint64_t current = 0;
  if (!(maxFile >> max) || max == "max" || !(currentFile >> current)) return kUnlimited;
  const uint64_t limit = std::stoull(max);
  return limit > current ? limit - current : 0;
}

// Room under an rlimit, given how much of it the process uses now.
uint64_t rlimitRoom(int resource, uint64_t used) {
  rlimit limit{};
  if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnlimited;
  return limit.rlim_cur > used ? limit.rlim_cur - used : 0;
}

// The process's virtual and resident sizes now.
std::pair<uint64_t, uint64_t> sizesNow() {
  std::ifstream in("/proc/self/statm");
  uint64_t pages = 0, resident = 0;
  in >> pages >> resident;
  const uint64_t pageSize = uint64_t(sysconf(_SC_PAGESIZE));
  return {pages * pageSize, resident * pageSize};
}

}  // namespace

uint64_t availableMemoryBytes() {
  const auto [virtualSize, residentSize] = sizesNow();
  uint64_t room = std::min(memAvailable(), cgroupRoom());
  room = std::min(room, rlimitRoom(RLIMIT_AS, virtualSize));
  room = std::min(room, rlimitRoom(RLIMIT_DATA, virtualSize));
  if (const uint64_t limit = processLimit.load(); limit > 0)
    room = std::min(room, limit > residentSize ? limit - residentSize : 0);
  return room;
}

void setProcessMemoryLimit(uint64_t bytes) { processLimit = bytes; }

uint64_t processMemoryLimit() { return processLimit.load(); }

std::optional<uint64_t> parseMemorySize(const std::string& text) {
  size_t end = 0;
  double value = 0;
  try {
    value = std::stod(text, &end);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  std::string unit = text.substr(end);
  for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
  if (unit.size() > 1 && unit.back() == 'B') unit.pop_back();
  if (unit.size() == 2 && unit[1] == 'I') unit.pop_back();  // GiB, MiB: the binary units, as G and M are here
  double scale = 1;
  if (unit == "K")
    scale = 0x1p10;
  else if (unit == "M")
    scale = 0x1p20;
  else if (unit == "G")
    scale = 0x1p30;
  else if (unit == "T")
    scale = 0x1p40;
  else if (!unit.empty() && unit != "B")
    return std::nullopt;
  const double bytes = value * scale;
  if (!std::isfinite(bytes) || bytes < 1 || bytes > 0x1p62) return std::nullopt;
  return uint64_t(bytes);
}

std::string memorySizeText(uint64_t bytes) {
  char buffer[32];
  if (bytes >= (uint64_t(1) << 30))
    std::snprintf(buffer, sizeof buffer, "%.1f GiB", double(bytes) / 0x1p30);
  else
    std::snprintf(buffer, sizeof buffer, "%.0f MiB", std::ceil(double(bytes) / 0x1p20));
  return buffer;
}

}  // namespace candela
