// RayCellIntervals with the faces' planarity precomputed (PlanarFaceMask,
// what the CPU projector does once per cell) gives bit for bit the result of
// the plain call, for planar and distorted cells of every shape, and
// FaceRayCrossingsKnown equals FaceRayCrossings. The mask itself: all faces of
// a planar-faced cell, none of the quads of a distorted hexahedron.
#include "hovCellTestSupport.h"

#include "hovRayCell.h"

#include <gtest/gtest.h>

#include <random>

using hov::CellShape;

TEST(CellRayPlanarMask, SameIntervalsAsThePlainCall)
{
  std::mt19937_64 rng(71);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (CellShape shape : hovtest::AllCellShapes())
  {
    for (double distortion : { 0.0, 0.25 })
    {
      for (int c = 0; c < 6; ++c)
      {
        const hovtest::TestCell cell = hovtest::MakeRandomCell(shape, rng, distortion);
        const unsigned mask = hov::PlanarFaceMask(shape, cell.Points.data());
        for (int r = 0; r < 40; ++r)
        {
          const double o[3] = { 3 * u(rng), 3 * u(rng), 3 * u(rng) };
          const double target[3] = { 0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng) };
          const double d[3] = { target[0] - o[0], target[1] - o[1], target[2] - o[2] };
          hov::RayCellInterval a[hov::MaxRayCellIntervals], b[hov::MaxRayCellIntervals];
          const int na = hov::RayCellIntervals(
            shape, cell.Points.data(), cell.Ids.data(), o, d, 0.0, 10.0, a);
          const int nb = hov::RayCellIntervals(
            shape, cell.Points.data(), cell.Ids.data(), o, d, 0.0, 10.0, b, mask);
          ASSERT_EQ(na, nb) << hovtest::ShapeName(shape);
          for (int i = 0; i < na; ++i)
          {
            EXPECT_EQ(a[i].T0, b[i].T0);
            EXPECT_EQ(a[i].T1, b[i].T1);
          }
          hits += na > 0;
        }
      }
    }
  }
  EXPECT_GT(hits, 200);
}

TEST(CellRayPlanarMask, MaskOfPlanarAndDistortedCells)
{
  std::mt19937_64 rng(72);
  // A right prism with exactly representable corners: every face exactly planar.
  const std::vector<double> wedge = { 0, 0, 0, 0, 2, 0, 3, 0, 0, 0, 0, 1, 0, 2, 1, 3, 0, 1 };
  EXPECT_EQ(hov::PlanarFaceMask(CellShape::Wedge, wedge.data()), 0x1Fu);
  const hovtest::TestCell tet = hovtest::MakeRandomCell(CellShape::Tetra, rng, 0.3);
  EXPECT_EQ(hov::PlanarFaceMask(CellShape::Tetra, tet.Points.data()), 0xFu);
  // A unit cube with corner 6 moved off all three of its faces: those are bilinear.
  std::vector<double> hex = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1.1, 1.15, 1.2, 0, 1, 1 };
  const unsigned mask = hov::PlanarFaceMask(CellShape::Hexahedron, hex.data());
  int planar = 0;
  for (int f = 0; f < 6; ++f)
  {
    planar += (mask >> f) & 1u;
  }
  EXPECT_EQ(planar, 3); // the faces away from corner 6
  for (int f = 0; f < 6; ++f)
  {
    int corners[4];
    hov::CellFaceCorners(CellShape::Hexahedron, f, corners);
    const double* c[4] = { &hex[3 * corners[0]], &hex[3 * corners[1]], &hex[3 * corners[2]],
      &hex[3 * corners[3]] };
    const std::int64_t ids[4] = { corners[0], corners[1], corners[2], corners[3] };
    const double o[3] = { 0.3, 0.4, -2.0 }, d[3] = { 0.1, 0.05, 1.0 };
    double ta[2], tb[2];
    const int na = hov::FaceRayCrossings(4, c, ids, o, d, ta);
    const int nb = hov::FaceRayCrossingsKnown(4, c, ids, o, d, tb, (mask >> f) & 1u);
    ASSERT_EQ(na, nb);
    for (int i = 0; i < na; ++i)
    {
      EXPECT_EQ(ta[i], tb[i]);
    }
  }
}
