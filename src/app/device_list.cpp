#include "app/device_list.h"

#include <stdexcept>

namespace candela {

namespace {

// More contexts than this in one process is a typing error, not a machine.
constexpr size_t kMaxListedDevices = 64;
constexpr int kMaxDeviceIndex = 1023;

}  // namespace

DeviceRequest parseDeviceRequest(const std::string& text) {
  DeviceRequest request;
  request.given = true;
  if (text == "all") return request;
  request.all = false;
  const std::string usage = "'" + text + "' is not 'all' or a comma-separated list of GPU indices like 0,1";
  size_t start = 0;
  for (;;) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item.empty() || item.size() > 4 || item.find_first_not_of("0123456789") != std::string::npos)
      throw std::invalid_argument(usage);
    const int index = std::stoi(item);
    if (index > kMaxDeviceIndex) throw std::invalid_argument("GPU index " + item + " is out of range");
    request.indices.push_back(index);
    if (request.indices.size() > kMaxListedDevices)
      throw std::invalid_argument("more than " + std::to_string(kMaxListedDevices) + " devices listed");
    if (comma == std::string::npos) return request;
    start = comma + 1;
  }
}

std::vector<int> resolveDevices(const DeviceRequest& request, const std::vector<std::string>& gpuNames) {
  const int count = int(gpuNames.size());
  if (count == 0) throw std::invalid_argument("--devices: this machine has no GPU");
  if (request.all) {
    std::vector<int> same;
    for (int i = 0; i < count; ++i)
      if (gpuNames[size_t(i)] == gpuNames[0]) same.push_back(i);
    return same;
  }
  for (int index : request.indices)
    if (index >= count)
      throw std::invalid_argument("--devices: there is no GPU " + std::to_string(index) + ": this machine has " +
                                  (count == 1 ? std::string("one, GPU 0")
                                              : std::to_string(count) + ", GPUs 0 to " + std::to_string(count - 1)));
  return request.indices;
}

}  // namespace candela
