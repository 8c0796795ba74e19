// The memory estimate and guard (core/memory.hpp): quads, hexes and bytes from a wall's area, and whether the
// machine holds them.
#include <gtest/gtest.h>

#include "core/memory.hpp"

using namespace hexlayer;

// A 100 x 50 wall at size 0.5: 20 000 quads; 3 layers: 60 000 hexes of 2000 bytes (x 2 with 20-node hexes).
TEST(Memory, EstimateFromTheWallAreaSizeLayersAndOrder) {
  const MemoryEstimate linear = estimateMemory(100 * 50, 0.5, 3, 1, 1e9);
  EXPECT_DOUBLE_EQ(linear.quads, 20000);
  EXPECT_DOUBLE_EQ(linear.hexes, 60000);
  EXPECT_DOUBLE_EQ(linear.bytes, 1.2e8);
  EXPECT_TRUE(linear.fits());
  const MemoryEstimate quadratic = estimateMemory(100 * 50, 0.5, 3, 2, 1e9);
  EXPECT_DOUBLE_EQ(quadratic.bytes, 2.4e8);
  EXPECT_FALSE(estimateMemory(100 * 50, 0.5, 3, 2, 2e8).fits()) << "2.4e8 bytes on a machine of 2e8";
}

// From the quads made (adaptive sizing): 20 000 quads, 3 layers, the same as from the area they cover at 0.5.
TEST(Memory, EstimateFromTheQuadsMade) {
  const MemoryEstimate made = estimateMemoryOfQuads(20000, 3, 1, 1e9);
  EXPECT_DOUBLE_EQ(made.hexes, 60000);
  EXPECT_DOUBLE_EQ(made.bytes, estimateMemory(100 * 50, 0.5, 3, 1, 1e9).bytes);
  EXPECT_FALSE(estimateMemoryOfQuads(20000, 3, 2, 2e8).fits());
}

// The process has used some memory, and the machine has more than that.
TEST(Memory, PeakAndMachineAreMeasured) {
  const double peak = peakMemoryMiB();
  EXPECT_GT(peak, 1.0);
  EXPECT_GT(machineBytes(), peak * 1024 * 1024);
}
