// Cell fields and convex-cell geometry of
// hovTestReferenceGeneral.h (the subdivision is in hovTestReferenceSubdivide.cxx).
#include "hovTestReferenceGeneral.h"
#include "hovTestReferenceVector.h"

#include "vtkHexahedron.h"     // trilinear shape functions
#include "vtkQuadraticTetra.h" // quadratic tetrahedron shape functions

#include <algorithm>
#include <cmath>
#include <limits>

namespace hovTestRef
{
namespace
{
/// Inverse of the 3x3 matrix with columns @p c (long double, by cofactors).
void Invert3(const Vec3 c[3], Real inv[3][3])
{
  const Vec3 r0 = Cross(c[1], c[2]), r1 = Cross(c[2], c[0]), r2 = Cross(c[0], c[1]);
  const Real det = Dot(c[0], r0);
  for (int k = 0; k < 3; ++k)
  {
    inv[0][k] = r0[k] / det;
    inv[1][k] = r1[k] / det;
    inv[2][k] = r2[k] / det;
  }
}

/// Outward plane normal of a face (Newell's method) through its corners.
Vec3 FaceNormal(const ConvexCell& cell, const std::vector<int>& face)
{
  Vec3 n{ 0, 0, 0 };
  for (size_t k = 0; k < face.size(); ++k)
  {
    const Vec3& a = cell.Corners[face[k]];
    const Vec3& b = cell.Corners[face[(k + 1) % face.size()]];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  Vec3 centroid{ 0, 0, 0 };
  for (const Vec3& c : cell.Corners)
  {
    centroid = Add(centroid, Scale(c, Real(1) / cell.Corners.size()));
  }
  return Dot(n, Sub(centroid, cell.Corners[face[0]])) > 0 ? Scale(n, -1) : n;
}
}

//------------------------------------------------------------------------------
QuadraticTetraField::QuadraticTetraField(const double corners[4][3], const double nodeScalars[10])
{
  this->Origin = FromDouble(corners[0]);
  const Vec3 edges[3] = { Sub(FromDouble(corners[1]), this->Origin),
    Sub(FromDouble(corners[2]), this->Origin), Sub(FromDouble(corners[3]), this->Origin) };
  Invert3(edges, this->Inverse);
  std::copy(nodeScalars, nodeScalars + 10, this->S);
}

Real QuadraticTetraField::operator()(const Vec3& x) const
{
  const Vec3 d = Sub(x, this->Origin);
  double pc[3];
  for (int k = 0; k < 3; ++k)
  {
    pc[k] = static_cast<double>(
      this->Inverse[k][0] * d[0] + this->Inverse[k][1] * d[1] + this->Inverse[k][2] * d[2]);
  }
  double w[10];
  vtkQuadraticTetra::InterpolationFunctions(pc, w);
  Real v = 0;
  for (int i = 0; i < 10; ++i)
  {
    v += Real(w[i]) * this->S[i];
  }
  return v;
}

//------------------------------------------------------------------------------
HexahedronField::HexahedronField(const double corners[8][3], const double nodeScalars[8])
{
  for (int i = 0; i < 8; ++i)
  {
    std::copy(corners[i], corners[i] + 3, this->X[i]);
    this->S[i] = nodeScalars[i];
  }
}

bool HexahedronField::Invert(const Vec3& x, double pc[3]) const
{
  for (int attempt = 0; attempt < 2; ++attempt)
  {
    for (int k = 0; k < 3; ++k)
    {
      pc[k] = attempt == 0 ? this->Guess[k] : 0.5;
    }
    for (int it = 0; it < 60; ++it)
    {
      double w[8], dw[24];
      vtkHexahedron::InterpolationFunctions(pc, w);
      vtkHexahedron::InterpolationDerivs(pc, dw);
      Vec3 r = x, cols[3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
      for (int i = 0; i < 8; ++i)
      {
        const Vec3 xi = FromDouble(this->X[i]);
        r = Sub(r, Scale(xi, w[i]));
        for (int j = 0; j < 3; ++j)
        {
          cols[j] = Add(cols[j], Scale(xi, dw[8 * j + i]));
        }
      }
      Real inv[3][3];
      Invert3(cols, inv);
      Real step = 0;
      for (int k = 0; k < 3; ++k)
      {
        const Real dk = inv[k][0] * r[0] + inv[k][1] * r[1] + inv[k][2] * r[2];
        pc[k] += static_cast<double>(dk);
        step = std::max(step, std::fabs(dk));
      }
      if (step < 1e-15)
      {
        std::copy(pc, pc + 3, this->Guess);
        return true;
      }
    }
  }
  return false;
}

Real HexahedronField::operator()(const Vec3& x) const
{
  double pc[3], w[8];
  this->Invert(x, pc);
  vtkHexahedron::InterpolationFunctions(pc, w);
  Real v = 0;
  for (int i = 0; i < 8; ++i)
  {
    v += Real(w[i]) * this->S[i];
  }
  return v;
}

//------------------------------------------------------------------------------
ConvexCell ConvexCell::Hexahedron(const double x[8][3])
{
  ConvexCell c;
  for (int i = 0; i < 8; ++i)
  {
    c.Corners.push_back(FromDouble(x[i]));
  }
  c.Faces = { { 0, 4, 7, 3 }, { 1, 2, 6, 5 }, { 0, 1, 5, 4 }, { 3, 7, 6, 2 }, { 0, 3, 2, 1 },
    { 4, 5, 6, 7 } };
  return c;
}

Real ConvexCell::MaxFaceNonPlanarity() const
{
  Real worst = 0;
  for (const auto& face : this->Faces)
  {
    const Vec3 n = Unit(FaceNormal(*this, face));
    for (int k : face)
    {
      worst = std::max(worst, std::fabs(Dot(n, Sub(this->Corners[k], this->Corners[face[0]]))));
    }
  }
  return worst;
}

bool IntersectConvex(const Ray& ray, const ConvexCell& cell, Real& tIn, Real& tOut)
{
  tIn = 0;
  tOut = ray.TFar;
  for (const auto& face : cell.Faces)
  {
    const Vec3 n = FaceNormal(cell, face);
    const Real denom = Dot(n, ray.Direction);
    const Real num = Dot(n, Sub(cell.Corners[face[0]], ray.Origin));
    if (denom > 0)
    {
      tOut = std::min(tOut, num / denom);
    }
    else if (denom < 0)
    {
      tIn = std::max(tIn, num / denom);
    }
    else if (num < 0)
    {
      return false;
    }
  }
  return tOut > tIn;
}

Real DistanceToCellEdges(const Ray& ray, const ConvexCell& cell)
{
  Real best = std::numeric_limits<Real>::infinity();
  const Vec3 end = ray.At(ray.TFar);
  for (const auto& face : cell.Faces)
  {
    for (size_t k = 0; k < face.size(); ++k)
    {
      best = std::min(best, SegmentDistance(ray.Origin, end, cell.Corners[face[k]],
                              cell.Corners[face[(k + 1) % face.size()]]));
    }
  }
  return best;
}
}
