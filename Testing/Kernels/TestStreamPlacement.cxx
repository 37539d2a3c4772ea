// hov::PlaceInStream (hovStreamPlacement.h), the storage rule of the OpenGL
// projection's streaming buffers: the storage stays within 2.5x the largest
// group however many groups and frames are streamed. Regression: the storage
// doubled at every refill, so it grew to a whole frame's geometry; with a
// transfer function of thousands of nodes (ParaView's default colour map) that
// was gigabytes: GL_OUT_OF_MEMORY, then GL_INVALID_VALUE from the mapping and
// an empty image, or a crash in llvmpipe. (The OpenGL side is exercised by
// hov.Cxx.TestProjectionStream.)
#include "hovStreamPlacement.h"

#include <gtest/gtest.h>

#include <iostream>

TEST(StreamPlacement, StorageWithinTwoAndAHalfGroups)
{
  // One group: 2 chunks of 3000 vertices (11 floats) and 9000 indices each.
  const size_t vertexBytes = 2 * 3000 * 11 * sizeof(float);
  const size_t indexBytes = 2 * 9000 * sizeof(unsigned int);
  size_t vertexCapacity = 0, indexCapacity = 0;
  for (int frame = 0; frame < 12; ++frame)
  {
    size_t vertexUsed = 0, indexUsed = 0; // a frame starts at the beginning
    for (int g = 0; g < 10; ++g)
    {
      hov::PlaceInStream(vertexBytes, vertexUsed, vertexCapacity);
      hov::PlaceInStream(indexBytes, indexUsed, indexCapacity);
      ASSERT_LE(vertexUsed + vertexBytes, vertexCapacity);
      ASSERT_LE(indexUsed + indexBytes, indexCapacity);
      vertexUsed += vertexBytes;
      indexUsed += indexBytes;
    }
  }
  const double vertexRatio = static_cast<double>(vertexCapacity) / vertexBytes;
  const double indexRatio = static_cast<double>(indexCapacity) / indexBytes;
  std::cout << "[measured] after 12 frames of 10 groups: vertex storage " << vertexRatio
            << " groups, index storage " << indexRatio << " groups (bound 2.5)\n";
  EXPECT_GE(vertexRatio, 1.0);
  EXPECT_LE(vertexRatio, 2.5);
  EXPECT_GE(indexRatio, 1.0);
  EXPECT_LE(indexRatio, 2.5);
}

TEST(StreamPlacement, GrowsOnlyForALargerGroup)
{
  size_t used = 0, capacity = 0;
  EXPECT_TRUE(hov::PlaceInStream(100, used, capacity)); // first storage
  EXPECT_EQ(capacity, 125u);
  used += 100;
  EXPECT_TRUE(hov::PlaceInStream(100, used, capacity)); // refill: same storage size
  EXPECT_EQ(capacity, 125u);
  EXPECT_EQ(used, 0u);
  used += 100;
  EXPECT_TRUE(hov::PlaceInStream(400, used, capacity)); // larger group: grows
  EXPECT_EQ(capacity, 500u);
  used += 400;
  EXPECT_TRUE(hov::PlaceInStream(200, used, capacity));
  EXPECT_EQ(capacity, 500u);
  used += 200;
  EXPECT_FALSE(hov::PlaceInStream(200, used, capacity)); // fits after the first
  EXPECT_EQ(used, 200u);
}
