#include "hovCellShapes.h"

#include "hovShapeArithmetic.h" // Dual, LinePoly

#include <algorithm> // std::copy

// The shape-function half of hovCellShapes.h (the geometry map, its inverse
// and the domain tests are in hovCellGeometry.cxx).
namespace hov
{
namespace
{
using detail::Dual;
using detail::LinePoly;

// VTK 9.1 InterpolationFunctions, one template for double, Dual and LinePoly.
template <class T>
void LinearShapes(CellShape shape, const T& r, const T& s, const T& t, T* w)
{
  const T rm = 1.0 - r, sm = 1.0 - s, tm = 1.0 - t;
  switch (shape)
  {
    case CellShape::Tetra:
      w[0] = 1.0 - r - s - t;
      w[1] = r;
      w[2] = s;
      w[3] = t;
      break;
    case CellShape::Voxel:
      w[0] = rm * sm * tm;
      w[1] = r * sm * tm;
      w[2] = rm * s * tm;
      w[3] = r * s * tm;
      w[4] = rm * sm * t;
      w[5] = r * sm * t;
      w[6] = rm * s * t;
      w[7] = r * s * t;
      break;
    case CellShape::Hexahedron:
      w[0] = rm * sm * tm;
      w[1] = r * sm * tm;
      w[2] = r * s * tm;
      w[3] = rm * s * tm;
      w[4] = rm * sm * t;
      w[5] = r * sm * t;
      w[6] = r * s * t;
      w[7] = rm * s * t;
      break;
    case CellShape::Wedge:
      w[0] = (1.0 - r - s) * tm;
      w[1] = r * tm;
      w[2] = s * tm;
      w[3] = (1.0 - r - s) * t;
      w[4] = r * t;
      w[5] = s * t;
      break;
    default: // Pyramid
      w[0] = rm * sm * tm;
      w[1] = r * sm * tm;
      w[2] = r * s * tm;
      w[3] = rm * s * tm;
      w[4] = t;
      break;
  }
}

template <class T>
void QuadraticTetraShapes(const T& r, const T& s, const T& t, T* w)
{
  const T u = 1.0 - r - s - t;
  w[0] = u * (2.0 * u - 1.0);
  w[1] = r * (2.0 * r - 1.0);
  w[2] = s * (2.0 * s - 1.0);
  w[3] = t * (2.0 * t - 1.0);
  w[4] = 4.0 * u * r;
  w[5] = 4.0 * r * s;
  w[6] = 4.0 * s * u;
  w[7] = 4.0 * u * t;
  w[8] = 4.0 * r * t;
  w[9] = 4.0 * s * t;
}

template <class T>
void QuadraticHexShapes(const T& pr, const T& ps, const T& pt, T* w)
{
  // VTK maps (0,1) to the isoparametric (-1,1).
  const T r = 2.0 * (pr - 0.5), s = 2.0 * (ps - 0.5), t = 2.0 * (pt - 0.5);
  const T rm = 1.0 - r, rp = 1.0 + r, sm = 1.0 - s, sp = 1.0 + s, tm = 1.0 - t, tp = 1.0 + t;
  const T r2 = 1.0 - r * r, s2 = 1.0 - s * s, t2 = 1.0 - t * t;
  w[0] = 0.125 * rm * sm * tm * (-r - s - t - 2.0);
  w[1] = 0.125 * rp * sm * tm * (r - s - t - 2.0);
  w[2] = 0.125 * rp * sp * tm * (r + s - t - 2.0);
  w[3] = 0.125 * rm * sp * tm * (-r + s - t - 2.0);
  w[4] = 0.125 * rm * sm * tp * (-r - s + t - 2.0);
  w[5] = 0.125 * rp * sm * tp * (r - s + t - 2.0);
  w[6] = 0.125 * rp * sp * tp * (r + s + t - 2.0);
  w[7] = 0.125 * rm * sp * tp * (-r + s + t - 2.0);
  w[8] = 0.25 * r2 * sm * tm;
  w[9] = 0.25 * s2 * rp * tm;
  w[10] = 0.25 * r2 * sp * tm;
  w[11] = 0.25 * s2 * rm * tm;
  w[12] = 0.25 * r2 * sm * tp;
  w[13] = 0.25 * s2 * rp * tp;
  w[14] = 0.25 * r2 * sp * tp;
  w[15] = 0.25 * s2 * rm * tp;
  w[16] = 0.25 * t2 * rm * sm;
  w[17] = 0.25 * t2 * rp * sm;
  w[18] = 0.25 * t2 * rp * sp;
  w[19] = 0.25 * t2 * rm * sp;
}

template <class T>
void QuadraticWedgeShapes(const T& r, const T& s, const T& t, T* w)
{
  const T u = 1.0 - r - s, tm = 1.0 - t;
  w[0] = 2.0 * u * tm * (0.5 - r - s - t);
  w[1] = 2.0 * r * tm * (r - t - 0.5);
  w[2] = 2.0 * s * tm * (s - t - 0.5);
  w[3] = 2.0 * u * t * (t - r - s - 0.5);
  w[4] = 2.0 * r * t * (r + t - 1.5);
  w[5] = 2.0 * s * t * (s + t - 1.5);
  w[6] = 4.0 * r * u * tm;
  w[7] = 4.0 * r * s * tm;
  w[8] = 4.0 * u * s * tm;
  w[9] = 4.0 * r * u * t;
  w[10] = 4.0 * r * s * t;
  w[11] = 4.0 * u * s * t;
  w[12] = 4.0 * t * u * tm;
  w[13] = 4.0 * t * r * tm;
  w[14] = 4.0 * t * s * tm;
}

template <class T>
void QuadraticPyramidShapes(const T& pr, const T& ps, const T& pt, T* w)
{
  const T r = 2.0 * (pr - 0.5), s = 2.0 * (ps - 0.5), t = 2.0 * (pt - 0.5);
  const T r2 = r * r, s2 = s * s, t2 = t * t;
  const T rs = r * s, rt = r * t, st = s * t, rst = r * s * t;
  w[0] = -(1.0 - r) * (1.0 - s) * (1.0 - t) *
    (4.0 + 3.0 * r + 3.0 * s + 2.0 * rs + 2.0 * t + rt + st + 2.0 * rst) / 16.0;
  w[1] = -(1.0 + r) * (1.0 - s) * (1.0 - t) *
    (4.0 - 3.0 * r + 3.0 * s - 2.0 * rs + 2.0 * t - rt + st - 2.0 * rst) / 16.0;
  w[2] = -(1.0 + r) * (1.0 + s) * (1.0 - t) *
    (4.0 - 3.0 * r - 3.0 * s + 2.0 * rs + 2.0 * t - rt - st + 2.0 * rst) / 16.0;
  w[3] = -(1.0 - r) * (1.0 + s) * (1.0 - t) *
    (4.0 + 3.0 * r - 3.0 * s - 2.0 * rs + 2.0 * t + rt - st - 2.0 * rst) / 16.0;
  w[4] = t * (1.0 + t) / 2.0;
  w[5] = (1.0 - r2) * (1.0 - s) * (1.0 - t) * (2.0 + s + st) / 8.0;
  w[6] = (1.0 + r) * (1.0 - s2) * (1.0 - t) * (2.0 - r - rt) / 8.0;
  w[7] = (1.0 - r2) * (1.0 + s) * (1.0 - t) * (2.0 - s - st) / 8.0;
  w[8] = (1.0 - r) * (1.0 - s2) * (1.0 - t) * (2.0 + r + rt) / 8.0;
  w[9] = (1.0 - r) * (1.0 - s) * (1.0 - t2) / 4.0;
  w[10] = (1.0 + r) * (1.0 - s) * (1.0 - t2) / 4.0;
  w[11] = (1.0 + r) * (1.0 + s) * (1.0 - t2) / 4.0;
  w[12] = (1.0 - r) * (1.0 + s) * (1.0 - t2) / 4.0;
}

template <class T>
void TriQuadraticHexShapes(const T& pr, const T& ps, const T& pt, T* w)
{
  const T r = 2.0 * (pr - 0.5), s = 2.0 * (ps - 0.5), t = 2.0 * (pt - 0.5);
  const T g1r = -0.5 * r * (1.0 - r), g1s = -0.5 * s * (1.0 - s), g1t = -0.5 * t * (1.0 - t);
  const T g2r = (1.0 + r) * (1.0 - r), g2s = (1.0 + s) * (1.0 - s), g2t = (1.0 + t) * (1.0 - t);
  const T g3r = 0.5 * r * (1.0 + r), g3s = 0.5 * s * (1.0 + s), g3t = 0.5 * t * (1.0 + t);
  const T* gr[3] = { &g1r, &g2r, &g3r };
  const T* gs[3] = { &g1s, &g2s, &g3s };
  const T* gt[3] = { &g1t, &g2t, &g3t };
  // Node -> (index of r, s, t factor): 0 = g1 (at 0), 1 = g2 (at 1/2), 2 = g3 (at 1).
  static const int factors[27][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 2, 0 }, { 0, 2, 0 },
    { 0, 0, 2 }, { 2, 0, 2 }, { 2, 2, 2 }, { 0, 2, 2 }, { 1, 0, 0 }, { 2, 1, 0 }, { 1, 2, 0 },
    { 0, 1, 0 }, { 1, 0, 2 }, { 2, 1, 2 }, { 1, 2, 2 }, { 0, 1, 2 }, { 0, 0, 1 }, { 2, 0, 1 },
    { 2, 2, 1 }, { 0, 2, 1 }, { 0, 1, 1 }, { 2, 1, 1 }, { 1, 0, 1 }, { 1, 2, 1 }, { 1, 1, 0 },
    { 1, 1, 2 }, { 1, 1, 1 } };
  for (int i = 0; i < 27; ++i)
  {
    w[i] = *gr[factors[i][0]] * *gs[factors[i][1]] * *gt[factors[i][2]];
  }
}

template <class T>
void Shapes(CellShape shape, const T& r, const T& s, const T& t, T* w)
{
  switch (shape)
  {
    case CellShape::QuadraticTetra:
      QuadraticTetraShapes(r, s, t, w);
      break;
    case CellShape::QuadraticHexahedron:
      QuadraticHexShapes(r, s, t, w);
      break;
    case CellShape::QuadraticWedge:
      QuadraticWedgeShapes(r, s, t, w);
      break;
    case CellShape::QuadraticPyramid:
      QuadraticPyramidShapes(r, s, t, w);
      break;
    case CellShape::TriQuadraticHexahedron:
      TriQuadraticHexShapes(r, s, t, w);
      break;
    default:
      LinearShapes(shape, r, s, t, w);
      break;
  }
}

// Parametric coordinates of the nodes, VTK 9.1 GetParametricCoords (the
// quadratic cells' first nodes are their corners, in the linear order).
const double HexPC[27][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
  { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 }, { .5, 0, 0 }, { 1, .5, 0 }, { .5, 1, 0 }, { 0, .5, 0 },
  { .5, 0, 1 }, { 1, .5, 1 }, { .5, 1, 1 }, { 0, .5, 1 }, { 0, 0, .5 }, { 1, 0, .5 }, { 1, 1, .5 },
  { 0, 1, .5 }, { 0, .5, .5 }, { 1, .5, .5 }, { .5, 0, .5 }, { .5, 1, .5 }, { .5, .5, 0 },
  { .5, .5, 1 }, { .5, .5, .5 } };
const double TetPC[10][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { .5, 0, 0 },
  { .5, .5, 0 }, { 0, .5, 0 }, { 0, 0, .5 }, { .5, 0, .5 }, { 0, .5, .5 } };
const double WedgePC[15][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 },
  { 0, 1, 1 }, { .5, 0, 0 }, { .5, .5, 0 }, { 0, .5, 0 }, { .5, 0, 1 }, { .5, .5, 1 },
  { 0, .5, 1 }, { 0, 0, .5 }, { 1, 0, .5 }, { 0, 1, .5 } };
const double PyramidPC[13][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
  { 0, 0, 1 }, { .5, 0, 0 }, { 1, .5, 0 }, { .5, 1, 0 }, { 0, .5, 0 }, { 0, 0, .5 },
  { 1, 0, .5 }, { 1, 1, .5 }, { 0, 1, .5 } };
const double VoxelPC[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 0, 0, 1 },
  { 1, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 } };

}

bool IsSupportedCellType(int t)
{
  return (t >= 10 && t <= 14) || (t >= 24 && t <= 27) || t == 29;
}

int CellNodeCount(CellShape shape)
{
  switch (shape)
  {
    case CellShape::Tetra:
      return 4;
    case CellShape::Voxel:
    case CellShape::Hexahedron:
      return 8;
    case CellShape::Wedge:
      return 6;
    case CellShape::Pyramid:
      return 5;
    case CellShape::QuadraticTetra:
      return 10;
    case CellShape::QuadraticHexahedron:
      return 20;
    case CellShape::QuadraticWedge:
      return 15;
    case CellShape::QuadraticPyramid:
      return 13;
    default:
      return 27;
  }
}

CellShape GeometryShape(CellShape shape)
{
  switch (shape)
  {
    case CellShape::QuadraticTetra:
      return CellShape::Tetra;
    case CellShape::QuadraticHexahedron:
    case CellShape::TriQuadraticHexahedron:
      return CellShape::Hexahedron;
    case CellShape::QuadraticWedge:
      return CellShape::Wedge;
    case CellShape::QuadraticPyramid:
      return CellShape::Pyramid;
    default:
      return shape;
  }
}

int CellCornerCount(CellShape shape)
{
  return CellNodeCount(GeometryShape(shape));
}

void CellNodeParametricCoords(CellShape shape, int node, double pc[3])
{
  const double* p = nullptr;
  switch (GeometryShape(shape))
  {
    case CellShape::Tetra:
      p = TetPC[node];
      break;
    case CellShape::Voxel:
      p = VoxelPC[node];
      break;
    case CellShape::Hexahedron:
      p = HexPC[node];
      break;
    case CellShape::Wedge:
      p = WedgePC[node];
      break;
    default:
      p = PyramidPC[node];
      break;
  }
  pc[0] = p[0];
  pc[1] = p[1];
  pc[2] = p[2];
}

void CellParametricCenter(CellShape shape, double pc[3])
{
  const int n = CellCornerCount(shape);
  pc[0] = pc[1] = pc[2] = 0.0;
  for (int i = 0; i < n; ++i)
  {
    double q[3];
    CellNodeParametricCoords(shape, i, q);
    for (int k = 0; k < 3; ++k)
    {
      pc[k] += q[k] / n;
    }
  }
  if (GeometryShape(shape) == CellShape::Pyramid)
  {
    pc[0] = pc[1] = 0.5; // the collapsed cube: the apex has no (r, s)
  }
}

void CellShapeFunctions(CellShape shape, const double pc[3], double* w)
{
  Shapes<double>(shape, pc[0], pc[1], pc[2], w);
}

namespace
{
/// Per node, which factor of each coordinate x the trilinear shape function
/// takes: 1 for x, 0 for 1 - x (VTK's node orders).
constexpr int VoxelCorners[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 },
  { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 } };
constexpr int HexCorners[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
  { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } }; // the pyramid's base: the first 4

/**
 * Derivatives of the first @p count nodes' products a b c of one-variable
 * linear factors (a of r, b of s, c of t, slopes da, db, dc = +-1) in the
 * order the dual numbers evaluate (a b) c: d/dr = (da b) c, d/ds = (a db) c,
 * d/dt = (a b) dc; @p n nodes in all (VTK's layout).
 */
void TrilinearDerivatives(
  const int (*corners)[3], int count, const double pc[3], double* derivs, int n)
{
  for (int i = 0; i < count; ++i)
  {
    double f[3], df[3];
    for (int k = 0; k < 3; ++k)
    {
      f[k] = corners[i][k] ? pc[k] : 1.0 - pc[k];
      df[k] = corners[i][k] ? 1.0 : -1.0;
    }
    derivs[i] = (df[0] * f[1]) * f[2];
    derivs[n + i] = (f[0] * df[1]) * f[2];
    derivs[2 * n + i] = (f[0] * f[1]) * df[2];
  }
}

/// The linear cells' derivatives in closed form (the Newton inversions' inner
/// loop); false for the quadratic cells.
bool LinearDerivatives(CellShape shape, const double pc[3], double* d)
{
  const double r = pc[0], s = pc[1], t = pc[2];
  switch (shape)
  {
    case CellShape::Tetra:
    {
      const double v[12] = { -1.0, 1.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 1.0 };
      std::copy(v, v + 12, d);
      return true;
    }
    case CellShape::Voxel:
      TrilinearDerivatives(VoxelCorners, 8, pc, d, 8);
      return true;
    case CellShape::Hexahedron:
      TrilinearDerivatives(HexCorners, 8, pc, d, 8);
      return true;
    case CellShape::Wedge:
    {
      // (1 - r - s) t-factor products; u = 1 - r - s has slopes (-1, -1, 0).
      const double u = 1.0 - r - s, tm = 1.0 - t;
      const double v[18] = { -tm, tm, 0.0, -t, t, 0.0, // d/dr
        -tm, 0.0, tm, -t, 0.0, t,                         // d/ds
        -u, -r, -s, u, r, s };                            // d/dt
      std::copy(v, v + 18, d);
      return true;
    }
    case CellShape::Pyramid:
      TrilinearDerivatives(HexCorners, 4, pc, d, 5);
      d[4] = 0.0; // the apex: w = t
      d[9] = 0.0;
      d[14] = 1.0;
      return true;
    default:
      return false;
  }
}
}

void CellShapeDerivatives(CellShape shape, const double pc[3], double* derivs)
{
  if (LinearDerivatives(shape, pc, derivs))
  {
    return;
  }
  detail::CellShapeDerivativesDual(shape, pc, derivs);
}

namespace detail
{
void CellShapeDerivativesDual(CellShape shape, const double pc[3], double* derivs)
{
  Dual r(pc[0]), s(pc[1]), t(pc[2]);
  r.G[0] = s.G[1] = t.G[2] = 1.0;
  Dual w[MaxCellNodes];
  Shapes<Dual>(shape, r, s, t, w);
  const int n = CellNodeCount(shape);
  for (int i = 0; i < n; ++i)
  {
    derivs[i] = w[i].G[0];
    derivs[n + i] = w[i].G[1];
    derivs[2 * n + i] = w[i].G[2];
  }
}
}

void CellShapeFunctionsAlongLine(
  CellShape shape, const double pcStart[3], const double pcStep[3], Polynomial* w)
{
  LinePoly r, s, t;
  r.C[0] = pcStart[0];
  r.C[1] = pcStep[0];
  s.C[0] = pcStart[1];
  s.C[1] = pcStep[1];
  t.C[0] = pcStart[2];
  t.C[1] = pcStep[2];
  LinePoly lw[MaxCellNodes];
  Shapes<LinePoly>(shape, r, s, t, lw);
  const int n = CellNodeCount(shape);
  for (int i = 0; i < n; ++i)
  {
    w[i] = Polynomial();
    w[i].Degree = Polynomial::MaxDegree;
    for (int k = 0; k < LinePoly::N; ++k)
    {
      w[i].C[k] = lw[i].C[k];
    }
    w[i].Degree = EffectiveDegree(w[i]);
  }
}

double InterpolateCellScalar(CellShape shape, const double* values, const double pc[3])
{
  double w[MaxCellNodes];
  CellShapeFunctions(shape, pc, w);
  double sum = 0.0;
  for (int i = 0, n = CellNodeCount(shape); i < n; ++i)
  {
    sum += w[i] * values[i];
  }
  return sum;
}

}
