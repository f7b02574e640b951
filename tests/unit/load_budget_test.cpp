#include <gtest/gtest.h>

#include <string>

#include "io/available_memory.h"
#include "io/load_budget.h"

namespace candela {
namespace {

TEST(MemorySize, ReadsUnitsAsBinaryMultiples) {
  EXPECT_EQ(parseMemorySize("2048"), 2048u);
  EXPECT_EQ(parseMemorySize("512M"), uint64_t(512) << 20);
  EXPECT_EQ(parseMemorySize("4G"), uint64_t(4) << 30);
  EXPECT_EQ(parseMemorySize("1.5GiB"), uint64_t(3) << 29);
  EXPECT_EQ(parseMemorySize("64kb"), uint64_t(64) << 10);
  EXPECT_FALSE(parseMemorySize("lots"));
  EXPECT_FALSE(parseMemorySize("4X"));
  EXPECT_FALSE(parseMemorySize("0"));
  EXPECT_FALSE(parseMemorySize("-1G"));
  EXPECT_FALSE(parseMemorySize("nanG"));
}

TEST(LoadBudget, RefusesTheChargeThatExceedsItNamingFileAndElement) {
  setProcessMemoryLimit(uint64_t(1) << 62);  // a limit of its own, so that the message names --max-memory
  beginLoadBudget();
  const uint64_t left = loadMemoryLeft();
  ASSERT_GT(left, uint64_t(1) << 20);
  chargeLoadMemory(left / 2, "a.ply", "its faces");
  EXPECT_EQ(loadMemoryLeft(), left - left / 2);
  try {
    chargeLoadMemory(left, "b.png", "an image");
    FAIL() << "the charge past the budget was accepted";
  } catch (const LoadBudgetError& e) {
    EXPECT_NE(std::string(e.what()).find("b.png: an image needs about"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--max-memory"), std::string::npos) << e.what();
  }
  EXPECT_EQ(loadMemoryLeft(), left - left / 2);  // the refused charge is not kept
  releaseLoadMemory(left / 2);
  EXPECT_EQ(loadMemoryLeft(), left);
  setProcessMemoryLimit(0);
  beginLoadBudget();
}

}  // namespace
}  // namespace candela
