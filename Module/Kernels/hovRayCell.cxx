#include "hovRayCell.h"

#include "hovGeometricPredicates.h" // Orient3d: exact planarity of quads
#include "hovPolynomial.h"          // FindRoots: the patch quadratic

#include <algorithm> // std::sort, std::swap, std::max, std::min
#include <cmath>     // fabs, isfinite

namespace hov
{
namespace
{
// Faces in cyclic order (VTK 9.1 face lists; the voxel's pixel faces are
// reordered cyclically).
const int TetFaces[4][4] = { { 0, 1, 3, -1 }, { 1, 2, 3, -1 }, { 2, 0, 3, -1 }, { 0, 2, 1, -1 } };
const int HexFaces[6][4] = { { 0, 4, 7, 3 }, { 1, 2, 6, 5 }, { 0, 1, 5, 4 }, { 3, 7, 6, 2 },
  { 0, 3, 2, 1 }, { 4, 5, 6, 7 } };
const int VoxelFaces[6][4] = { { 0, 4, 6, 2 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
  { 0, 2, 3, 1 }, { 4, 5, 7, 6 } };
const int WedgeFaces[5][4] = { { 0, 1, 2, -1 }, { 3, 5, 4, -1 }, { 0, 3, 4, 1 }, { 1, 4, 5, 2 },
  { 2, 5, 3, 0 } };
const int PyramidFaces[5][4] = { { 0, 3, 2, 1 }, { 0, 1, 4, -1 }, { 1, 2, 4, -1 },
  { 2, 3, 4, -1 }, { 3, 0, 4, -1 } };

void Sub(const double* a, const double* b, double* r)
{
  r[0] = a[0] - b[0], r[1] = a[1] - b[1], r[2] = a[2] - b[2];
}
void Cross(const double* a, const double* b, double* r)
{
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double Triple(const double* d, const double* a, const double* b)
{
  double c[3];
  Cross(a, b, c);
  return Dot(d, c);
}

/// +1 / -1: side of the plane with normal @p n on which the ray displaced by
/// e X + e^2 Y (e -> 0+) lies when the ray itself lies in the plane; 0 if the
/// perturbation is degenerate (n orthogonal to X and Y).
int PerturbedSide(const double n[3], const RayPerturbation& p)
{
  const double nx = Dot(n, p.X);
  if (nx != 0.0)
  {
    return nx > 0.0 ? 1 : -1;
  }
  const double ny = Dot(n, p.Y);
  return ny > 0.0 ? 1 : (ny < 0.0 ? -1 : 0);
}

/// Strict order of corners: id, then coordinates (ties only for repeated ids).
bool Less(const double* a, std::int64_t ia, const double* b, std::int64_t ib)
{
  if (ia != ib)
  {
    return ia < ib;
  }
  for (int k = 0; k < 3; ++k)
  {
    if (a[k] != b[k])
    {
      return a[k] < b[k];
    }
  }
  return false;
}

/// Puts the face's corners in the canonical order (see file doc).
void Canonical(int n, const double* const in[4], const std::int64_t ids[4], const double* out[4])
{
  if (n == 3)
  {
    int idx[3] = { 0, 1, 2 };
    std::sort(idx, idx + 3, [&](int a, int b) { return Less(in[a], ids[a], in[b], ids[b]); });
    for (int i = 0; i < 3; ++i)
    {
      out[i] = in[idx[i]];
    }
    return;
  }
  int m = 0;
  for (int i = 1; i < 4; ++i)
  {
    if (Less(in[i], ids[i], in[m], ids[m]))
    {
      m = i;
    }
  }
  const int next = (m + 1) % 4, prev = (m + 3) % 4;
  const int step = Less(in[next], ids[next], in[prev], ids[prev]) ? 1 : 3;
  for (int i = 0; i < 4; ++i)
  {
    out[i] = in[(m + step * i) % 4];
  }
}

/// Canonical plane of a planar face: normal and base point c0.
void FacePlane(int n, const double* const c[4], double normal[3])
{
  double a[3], b[3];
  if (n == 3)
  {
    Sub(c[1], c[0], a);
    Sub(c[2], c[0], b);
  }
  else
  {
    Sub(c[2], c[0], a);
    Sub(c[3], c[1], b);
  }
  Cross(a, b, normal);
}

int PatchCrossings(const double* const c[4], const double o[3], const double d[3], double t[2])
{
  double w[3], e10[3], e01[3], q[3], a[3], b[3];
  Sub(c[0], o, w);
  Sub(c[1], c[0], e10);
  Sub(c[3], c[0], e01);
  Sub(c[2], c[1], a);
  Sub(c[3], c[0], b);
  Sub(a, b, q);
  Polynomial p;
  p.Degree = 2;
  p.C[0] = Triple(d, w, e01);
  p.C[1] = Triple(d, w, q) + Triple(d, e10, e01);
  p.C[2] = Triple(d, e10, q);
  double u[Polynomial::MaxDegree];
  const int nu = FindRoots(p, 0.0, -PatchSlack, 1.0 + PatchSlack, u);
  int count = 0;
  const double dd = Dot(d, d);
  for (int i = 0; i < nu && count < 2; ++i)
  {
    double p0[3], e[3], pxd[3], exd[3];
    for (int k = 0; k < 3; ++k)
    {
      p0[k] = w[k] + u[i] * e10[k];
      e[k] = e01[k] + u[i] * q[k];
    }
    Cross(p0, d, pxd);
    Cross(e, d, exd);
    const double den = Dot(exd, exd);
    if (!(den > 0.0))
    {
      continue; // the ray runs along a ruling of the patch
    }
    const double v = -Dot(pxd, exd) / den;
    double hit[3] = { p0[0] + v * e[0], p0[1] + v * e[1], p0[2] + v * e[2] };
    const double ti = Dot(d, hit) / dd;
    if (std::isfinite(ti))
    {
      t[count++] = ti;
    }
  }
  if (count == 2 && t[1] < t[0])
  {
    std::swap(t[0], t[1]);
  }
  return count;
}

/**
 * Crossings of a face (FaceRayCrossingsKnown). A planar face whose plane the
 * ray runs in (n.d == 0 and n.c0 - n.o within rounding of 0) gives none; then
 * @p push (if given) is incremented by Push = 1e-7 h s n/|n| (h: the face's
 * extent, s: the side of the plane where the ray, or its symbolic
 * displacement if exactly in the plane, lies). Push depends only on the face
 * and the ray, so two cells sharing the face use the same vector.
 */
int FaceCrossingsImpl(int cornerCount, const double* const corners[4], const std::int64_t ids[4],
  const double o[3], const double d[3], double t[2], bool planar, const RayPerturbation* pert,
  double push[3])
{
  const double* c[4];
  Canonical(cornerCount, corners, ids, c);
  if (cornerCount == 4 && !planar)
  {
    return PatchCrossings(c, o, d, t);
  }
  double n[3];
  FacePlane(cornerCount, c, n);
  const double num = Dot(n, c[0]) - Dot(n, o), den = Dot(n, d);
  if (den != 0.0)
  {
    t[0] = num / den;
    return std::isfinite(t[0]) ? 1 : 0;
  }
  if (!push)
  {
    return 0;
  }
  double scale = 0.0, h = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    scale += std::fabs(n[k]) * (std::fabs(c[0][k]) + std::fabs(o[k]));
    for (int i = 1; i < cornerCount; ++i)
    {
      h = std::max(h, std::fabs(c[i][k] - c[0][k]));
    }
  }
  const double norm = std::sqrt(Dot(n, n));
  if (!(std::fabs(num) <= 64.0 * 2.220446049250313e-16 * scale) || !(norm > 0.0))
  {
    return 0; // parallel, off the plane
  }
  const int side = num != 0.0 ? (num > 0.0 ? -1 : 1) : (pert ? PerturbedSide(n, *pert) : 0);
  for (int k = 0; k < 3; ++k)
  {
    push[k] += 1e-7 * h * side * n[k] / norm;
  }
  return 0;
}

const int (*FaceTable(CellShape shape, int& count))[4]
{
  switch (GeometryShape(shape))
  {
    case CellShape::Tetra:
      count = 4;
      return TetFaces;
    case CellShape::Voxel:
      count = 6;
      return VoxelFaces;
    case CellShape::Hexahedron:
      count = 6;
      return HexFaces;
    case CellShape::Wedge:
      count = 5;
      return WedgeFaces;
    default:
      count = 5;
      return PyramidFaces;
  }
}

struct FaceData
{
  int N = 0;
  const double* C[4] = {};
  std::int64_t Ids[4] = {};
};

FaceData GetFace(CellShape shape, const double* points, const std::int64_t* ids, int f)
{
  FaceData face;
  int corners[4];
  face.N = CellFaceCorners(shape, f, corners);
  for (int i = 0; i < face.N; ++i)
  {
    face.C[i] = points + 3 * corners[i];
    face.Ids[i] = ids[corners[i]];
  }
  return face;
}

/// Half-space clipping for cells whose faces are all planes.
int ClipConvex(CellShape shape, const double* points, const std::int64_t* ids, const double o[3],
  const double d[3], double tMin, double tMax, RayCellInterval* out, const RayPerturbation& pert)
{
  const int nc = CellCornerCount(shape);
  double centroid[3] = { 0, 0, 0 };
  for (int i = 0; i < nc; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      centroid[k] += points[3 * i + k] / nc;
    }
  }
  double tIn = tMin, tOut = tMax;
  for (int f = 0, nf = CellFaceCount(shape); f < nf; ++f)
  {
    const FaceData face = GetFace(shape, points, ids, f);
    const double* c[4];
    Canonical(face.N, face.C, face.Ids, c);
    double n[3], toCentroid[3];
    FacePlane(face.N, c, n);
    Sub(centroid, c[0], toCentroid);
    const double inSide = Dot(n, toCentroid);
    if (inSide == 0.0)
    {
      continue; // degenerate face (zero normal) or flat cell: no constraint
    }
    const bool inward = inSide > 0.0; // the canonical normal points into the cell
    // The tetrahedron fast path's formula: offset n.c0, then n.o (bitwise the same t).
    const double num = Dot(n, c[0]) - Dot(n, o), den = Dot(n, d);
    if (den == 0.0)
    {
      // Parallel: outside iff o lies on the outer side (outward normal . (c0 - o) < 0).
      // Exactly in the plane: decided by the symbolic displacement of the ray;
      // the two cells sharing the face see opposite outward normals.
      const int side = num != 0.0 ? (num > 0.0 ? -1 : 1) : PerturbedSide(n, pert);
      if (side == 0 || (side > 0) != inward)
      {
        return 0;
      }
      continue;
    }
    const double t = num / den;
    if ((den > 0.0) == inward)
    {
      tIn = std::max(tIn, t);
    }
    else
    {
      tOut = std::min(tOut, t);
    }
  }
  if (!(tIn < tOut))
  {
    return 0;
  }
  out[0].T0 = tIn;
  out[0].T1 = tOut;
  return 1;
}

/// General cells: sorted crossings, gaps classified by their midpoint.
int SplitAndClassify(CellShape shape, const double* points, const std::int64_t* ids,
  const double o[3], const double d[3], double tMin, double tMax, RayCellInterval* out,
  unsigned planarFaces, const RayPerturbation& pert)
{
  double cand[2 * 6 + 2];
  double push[3] = { 0.0, 0.0, 0.0 }; // rays in a planar face's plane: see FaceCrossingsImpl
  int nCand = 0;
  cand[nCand++] = tMin;
  for (int f = 0, nf = CellFaceCount(shape); f < nf; ++f)
  {
    const FaceData face = GetFace(shape, points, ids, f);
    double t[2];
    const int nt = FaceCrossingsImpl(
      face.N, face.C, face.Ids, o, d, t, (planarFaces >> f) & 1u, &pert, push);
    for (int i = 0; i < nt; ++i)
    {
      if (t[i] > tMin && t[i] < tMax)
      {
        cand[nCand++] = t[i];
      }
    }
  }
  cand[nCand++] = tMax;
  std::sort(cand, cand + nCand);
  int count = 0;
  bool open = false;
  for (int i = 0; i + 1 < nCand; ++i)
  {
    const double a = cand[i], b = cand[i + 1];
    if (!(a < b))
    {
      continue; // zero-length gap: does not interrupt an interval
    }
    const double mid = 0.5 * (a + b);
    const double x[3] = { o[0] + mid * d[0] + push[0], o[1] + mid * d[1] + push[1],
      o[2] + mid * d[2] + push[2] };
    double pc[3];
    CellParametricCenter(shape, pc);
    const bool inside =
      InvertGeometry(shape, points, x, pc) && ParametricDistanceOutside(shape, pc) <= InsideSlack;
    if (!inside)
    {
      open = false;
    }
    else if (open)
    {
      out[count - 1].T1 = b;
    }
    else if (count < MaxRayCellIntervals)
    {
      out[count].T0 = a;
      out[count].T1 = b;
      ++count;
      open = true;
    }
  }
  return count;
}
}

int CellFaceCount(CellShape shape)
{
  int count = 0;
  FaceTable(shape, count);
  return count;
}

int CellFaceCorners(CellShape shape, int f, int corners[4])
{
  int count = 0;
  const int(*table)[4] = FaceTable(shape, count);
  for (int i = 0; i < 4; ++i)
  {
    corners[i] = table[f][i];
  }
  return table[f][3] < 0 ? 3 : 4;
}

bool IsQuadPlanar(const double* const corners[4])
{
  return Orient3d(corners[0], corners[1], corners[2], corners[3]) == 0;
}

int FaceRayCrossings(int cornerCount, const double* const corners[4], const std::int64_t ids[4],
  const double origin[3], const double direction[3], double t[2])
{
  return FaceRayCrossingsKnown(cornerCount, corners, ids, origin, direction, t,
    cornerCount == 3 || IsQuadPlanar(corners));
}

int FaceRayCrossingsKnown(int cornerCount, const double* const corners[4],
  const std::int64_t ids[4], const double origin[3], const double direction[3], double t[2],
  bool planar)
{
  return FaceCrossingsImpl(
    cornerCount, corners, ids, origin, direction, t, planar, nullptr, nullptr);
}

unsigned PlanarFaceMask(CellShape shape, const double* points)
{
  unsigned mask = 0;
  const std::int64_t ids[8] = { 0, 1, 2, 3, 4, 5, 6, 7 }; // planarity ignores ids
  for (int f = 0, nf = CellFaceCount(shape); f < nf; ++f)
  {
    const FaceData face = GetFace(shape, points, ids, f);
    if (face.N == 3 || IsQuadPlanar(face.C))
    {
      mask |= 1u << f;
    }
  }
  return mask;
}

RayPerturbation DefaultRayPerturbation(const double direction[3])
{
  RayPerturbation p;
  int k = 0; // the axis along which d is smallest: X is not parallel to d
  for (int i = 1; i < 3; ++i)
  {
    if (std::fabs(direction[i]) < std::fabs(direction[k]))
    {
      k = i;
    }
  }
  p.X[0] = p.X[1] = p.X[2] = 0.0;
  p.X[k] = 1.0;
  Cross(direction, p.X, p.Y);
  return p;
}

int RayCellIntervals(CellShape shape, const double* points, const std::int64_t* cornerIds,
  const double origin[3], const double direction[3], double tMin, double tMax,
  RayCellInterval* out)
{
  return RayCellIntervals(shape, points, cornerIds, origin, direction, tMin, tMax, out,
    PlanarFaceMask(shape, points));
}

int RayCellIntervals(CellShape shape, const double* points, const std::int64_t* cornerIds,
  const double origin[3], const double direction[3], double tMin, double tMax,
  RayCellInterval* out, unsigned planarFaces)
{
  return RayCellIntervals(shape, points, cornerIds, origin, direction, tMin, tMax, out,
    planarFaces, DefaultRayPerturbation(direction));
}

int RayCellIntervals(CellShape shape, const double* points, const std::int64_t* cornerIds,
  const double origin[3], const double direction[3], double tMin, double tMax,
  RayCellInterval* out, unsigned planarFaces, const RayPerturbation& perturbation)
{
  if (!(tMin <= tMax) || !std::isfinite(tMin) || !std::isfinite(tMax) ||
    !(Dot(direction, direction) > 0.0))
  {
    return 0;
  }
  const unsigned all = (1u << CellFaceCount(shape)) - 1u;
  return (planarFaces & all) == all
    ? ClipConvex(shape, points, cornerIds, origin, direction, tMin, tMax, out, perturbation)
    : SplitAndClassify(
        shape, points, cornerIds, origin, direction, tMin, tMax, out, planarFaces, perturbation);
}
}
