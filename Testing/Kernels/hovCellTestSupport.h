/**
 * @file hovCellTestSupport.h
 * @brief Random straight-edged test cells for the TestCell* kernel tests:
 * corners from a reference shape under a random affine map (optionally with
 * a random perturbation of every corner: non-affine geometry), higher-order
 * nodes placed by the corners' map (straight edges), random node scalars.
 */
#ifndef hovCellTestSupport_h
#define hovCellTestSupport_h

#include "hovCellShapes.h"
#include "hovRayCell.h" // RandomChord

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace hovtest
{
struct TestCell
{
  hov::CellShape Shape = hov::CellShape::Tetra;
  std::vector<double> Points;        ///< 3 per node
  std::vector<double> Scalars;       ///< 1 per node
  std::vector<std::int64_t> Ids;     ///< 1 per corner
};

inline const std::vector<hov::CellShape>& AllCellShapes()
{
  using S = hov::CellShape;
  static const std::vector<S> all = { S::Tetra, S::Voxel, S::Hexahedron, S::Wedge, S::Pyramid,
    S::QuadraticTetra, S::QuadraticHexahedron, S::QuadraticWedge, S::QuadraticPyramid,
    S::TriQuadraticHexahedron };
  return all;
}

inline std::string ShapeName(hov::CellShape s)
{
  return "type" + std::to_string(static_cast<int>(s));
}

/// Reference corner position of corner @p i (the pyramid's apex above the base centre).
inline void ReferenceCorner(hov::CellShape shape, int i, double x[3])
{
  hov::CellNodeParametricCoords(shape, i, x);
  if (hov::GeometryShape(shape) == hov::CellShape::Pyramid && i == 4)
  {
    x[0] = x[1] = 0.5;
  }
}

/**
 * A random cell: corners = M (reference corner) + b with M = I + 0.3 U
 * (U uniform in [-1,1]); voxels get a diagonal M; @p distortion > 0 adds
 * uniform noise of that size to every corner (never to voxels).
 */
inline TestCell MakeRandomCell(hov::CellShape shape, std::mt19937_64& rng, double distortion)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  TestCell cell;
  cell.Shape = shape;
  double m[9], b[3];
  for (int k = 0; k < 9; ++k)
  {
    m[k] = (k % 4 == 0 ? 1.0 : 0.0) + 0.3 * u(rng);
  }
  if (shape == hov::CellShape::Voxel)
  {
    m[1] = m[2] = m[3] = m[5] = m[6] = m[7] = 0.0;
    m[0] = std::fabs(m[0]), m[4] = std::fabs(m[4]), m[8] = std::fabs(m[8]);
    distortion = 0.0;
  }
  for (double& v : b)
  {
    v = u(rng);
  }
  const int nc = hov::CellCornerCount(shape), n = hov::CellNodeCount(shape);
  std::vector<double> corners(3 * nc);
  for (int i = 0; i < nc; ++i)
  {
    double r[3];
    ReferenceCorner(shape, i, r);
    for (int k = 0; k < 3; ++k)
    {
      corners[3 * i + k] =
        m[3 * k] * r[0] + m[3 * k + 1] * r[1] + m[3 * k + 2] * r[2] + b[k] + distortion * u(rng);
    }
    cell.Ids.push_back(100 + i);
  }
  cell.Points.resize(3 * n);
  for (int i = 0; i < n; ++i)
  {
    double pc[3];
    hov::CellNodeParametricCoords(shape, i, pc);
    hov::EvaluateGeometry(shape, corners.data(), pc, &cell.Points[3 * i], nullptr);
    if (i < nc)
    {
      for (int k = 0; k < 3; ++k)
      {
        cell.Points[3 * i + k] = corners[3 * i + k]; // corners exactly
      }
    }
    cell.Scalars.push_back(u(rng));
  }
  return cell;
}

/// A random parametric point inside the domain, at least @p margin from its boundary.
inline void RandomInteriorPC(hov::CellShape shape, std::mt19937_64& rng, double margin, double pc[3])
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  do
  {
    for (int k = 0; k < 3; ++k)
    {
      pc[k] = u(rng);
    }
  } while (hov::ParametricDistanceOutside(shape, pc) > -margin);
}

/// A ray through two random interior points; its inside interval.
inline bool RandomChord(const hovtest::TestCell& cell, std::mt19937_64& rng, double o[3], double d[3],
  hov::RayCellInterval& chord)
{
  double pa[3], pb[3], xb[3];
  hovtest::RandomInteriorPC(cell.Shape, rng, 0.05, pa);
  hovtest::RandomInteriorPC(cell.Shape, rng, 0.05, pb);
  hov::EvaluateGeometry(cell.Shape, cell.Points.data(), pa, o, nullptr);
  hov::EvaluateGeometry(cell.Shape, cell.Points.data(), pb, xb, nullptr);
  for (int k = 0; k < 3; ++k)
  {
    d[k] = xb[k] - o[k];
  }
  hov::RayCellInterval iv[hov::MaxRayCellIntervals];
  const int n =
    hov::RayCellIntervals(cell.Shape, cell.Points.data(), cell.Ids.data(), o, d, -10, 10, iv);
  if (n == 0)
  {
    return false;
  }
  chord = iv[0];
  for (int i = 1; i < n; ++i)
  {
    if (iv[i].T0 <= 0.0) // the interval containing t = 0
    {
      chord = iv[i];
    }
  }
  return true;
}
}

#endif
