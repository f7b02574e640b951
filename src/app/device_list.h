#pragma once
// The --devices option of render, bench, view and serve: which GPUs one process renders on.
#include <string>
#include <vector>

namespace candela {

struct DeviceRequest {
  bool given = false;        // whether the command line named the devices; if not, "all"
  bool all = true;           // every GPU of the kind of GPU 0
  std::vector<int> indices;  // otherwise these CUDA device indices, in order; a repeat is one more context there
};

// "all", or CUDA device indices separated by commas ("0,1", "0,0"). Throws std::invalid_argument with one
// sentence about the text otherwise.
DeviceRequest parseDeviceRequest(const std::string& text);

// The GPUs `request` names on a machine whose GPUs, by CUDA device index, have the names `gpuNames`: for "all",
// those named like GPU 0 (a slower or smaller GPU beside them would hold the others back); for a list, its
// indices, which must be present. Throws std::invalid_argument with one sentence ("--devices: ...") otherwise.
std::vector<int> resolveDevices(const DeviceRequest& request, const std::vector<std::string>& gpuNames);

}  // namespace candela
