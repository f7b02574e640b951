#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace candela {

// Bytes this process can still allocate: the least of the system's MemAvailable, the room left under the
// cgroup's memory.max, under the address-space and data limits (ulimit -v, -d) and under the process's own
// limit (setProcessMemoryLimit, from --max-memory).
uint64_t availableMemoryBytes();

// The most resident memory the process may use (0: no limit of its own), for the whole process.
void setProcessMemoryLimit(uint64_t bytes);
uint64_t processMemoryLimit();

// "512M", "4G", "1.5GiB", "2048" (bytes): a size as --max-memory takes it; nothing when it is not one.
std::optional<uint64_t> parseMemorySize(const std::string& text);

// "1.2 GiB", "340 MiB": bytes for a sentence.
std::string memorySizeText(uint64_t bytes);

}  // namespace candela
