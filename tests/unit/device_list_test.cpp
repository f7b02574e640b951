// The --devices option (app/device_list.h).
#include "app/device_list.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace candela {
namespace {

std::string parseError(const std::string& text) {
  try {
    parseDeviceRequest(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string resolveError(const std::string& text, const std::vector<std::string>& gpus) {
  try {
    resolveDevices(parseDeviceRequest(text), gpus);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(DeviceList, ParsesAllAndLists) {
  EXPECT_TRUE(parseDeviceRequest("all").all);
  EXPECT_TRUE(parseDeviceRequest("all").given);
  EXPECT_FALSE(DeviceRequest{}.given);
  const DeviceRequest list = parseDeviceRequest("1,0,1");
  EXPECT_FALSE(list.all);
  EXPECT_EQ(list.indices, (std::vector<int>{1, 0, 1}));
  EXPECT_EQ(parseDeviceRequest("0,0").indices, (std::vector<int>{0, 0}));
}

TEST(DeviceList, RefusesMalformedListsInOneSentence) {
  const std::string usage = "is not 'all' or a comma-separated list of GPU indices like 0,1";
  for (const char* text : {"", ",", "0,", ",1", "0,,1", "-1", "1.5", " 0", "0 ,1", "ALL", "x", "0x1", "99999"})
    EXPECT_NE(parseError(text).find(usage), std::string::npos) << "'" << text << "': " << parseError(text);
  EXPECT_EQ(parseError("1024"), "GPU index 1024 is out of range");
  std::string many = "0";
  for (int i = 0; i < 64; ++i) many += ",0";
  EXPECT_EQ(parseError(many), "more than 64 devices listed");
}

TEST(DeviceList, AllTakesTheGpusOfTheFirstOnesKind) {
  EXPECT_EQ(resolveDevices({}, {"NVIDIA H200"}), (std::vector<int>{0}));
  EXPECT_EQ(resolveDevices({}, {"NVIDIA H200", "NVIDIA T400", "NVIDIA H200"}), (std::vector<int>{0, 2}));
}

TEST(DeviceList, AListNamesPresentGpusOnly) {
  EXPECT_EQ(resolveDevices(parseDeviceRequest("1,0"), {"A", "B"}), (std::vector<int>{1, 0}));
  EXPECT_EQ(resolveDevices(parseDeviceRequest("0,0"), {"A"}), (std::vector<int>{0, 0}));
  EXPECT_EQ(resolveError("0,1", {"A"}), "--devices: there is no GPU 1: this machine has one, GPU 0");
  EXPECT_EQ(resolveError("4", {"A", "A", "A"}), "--devices: there is no GPU 4: this machine has 3, GPUs 0 to 2");
  EXPECT_EQ(resolveError("0", {}), "--devices: this machine has no GPU");
}

}  // namespace
}  // namespace candela
