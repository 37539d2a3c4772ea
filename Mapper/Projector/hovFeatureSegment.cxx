#include "hovFeatureSegment.h"

#include "hovGeneralCells.h" // the general cells
#include "hovCellSetup.h"   // the tetrahedra

#include "hovCellShapes.h"      // derivatives, geometry inversion
#include "hovIsosurface.h"      // crossings, surfaces in the segment integral
#include "hovTwoFieldSegment.h" // separate colour field

#include "vtkSMPTools.h" // per-tetrahedron fields in parallel

#include <algorithm> // std::sort, std::unique
#include <cmath>     // std::abs

namespace
{
using Ray = hov::ViewRays::Ray;

/// As hov::GeneralCellTile: terms below this times the cell's largest
/// |scalar| on a piece are rounding noise (keeps affine linear fields exact-linear).
constexpr double NegligibleRelative = 8.0 * 2.220446049250313e-16;

hov::Polynomial Linear(double value, double slope)
{
  hov::Polynomial p;
  p.C[0] = value;
  p.C[1] = slope;
  p.Degree = slope != 0.0 ? 1 : 0;
  return p;
}

/// 3x3 inverse (row-major), false if singular.
bool Invert3(const double* a, double* inv)
{
  const glm::dmat3 m(a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]); // columns
  const double det = glm::determinant(m);
  if (!(std::abs(det) > 0.0))
  {
    return false;
  }
  const glm::dmat3 r = glm::inverse(m);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      inv[3 * i + j] = r[j][i];
    }
  }
  return true;
}
}

void hov::FeatureSegment::TetraFields(
  const hov::CellSetup& setup, const std::vector<double>& values, std::vector<LinearField>& out)
{
  const auto& tets = setup.GetTetras();
  const auto& points = setup.GetPoints();
  out.resize(tets.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(tets.size()), [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType k = b; k < e; ++k)
    {
      const auto& tet = tets[k];
      const glm::dvec3 p0 = points[tet.Points[0]];
      const glm::dvec3 e1 = points[tet.Points[1]] - p0, e2 = points[tet.Points[2]] - p0,
                       e3 = points[tet.Points[3]] - p0;
      const double v0 = values[tet.Points[0]];
      const glm::dvec3 dv(values[tet.Points[1]] - v0, values[tet.Points[2]] - v0,
        values[tet.Points[3]] - v0);
      // Rows of M are the edges: M g = dv.
      const glm::dmat3 m = glm::transpose(glm::dmat3(e1, e2, e3));
      out[k].Gradient = glm::inverse(m) * dv;
      out[k].RefScalar = v0;
    }
  });
}

void hov::FeatureSegment::RestrictTetra(
  const FrameData& frame, vtkIdType tet, const Ray& ray, double t0, double t1)
{
  const auto& cell = frame.Setup->GetTetras()[tet];
  auto restrict = [&](const glm::dvec3& g, double ref) {
    // As the fast path: s at the ray origin, then along the ray.
    const double sAtOrigin = ref + glm::dot(g, ray.Origin - frame.Setup->RefPoint(cell));
    const double slope = glm::dot(g, ray.Direction);
    return Linear(sAtOrigin + t0 * slope, slope);
  };
  this->Pieces.resize(1);
  Piece& piece = this->Pieces[0];
  piece.T0 = t0;
  piece.T1 = t1;
  piece.S[0] = restrict(cell.Gradient, cell.RefScalar);
  piece.S[1] = frame.TetColor && !frame.TetColor->empty()
    ? restrict((*frame.TetColor)[tet].Gradient, (*frame.TetColor)[tet].RefScalar)
    : piece.S[0];
  piece.S[2] = frame.TetIso && !frame.TetIso->empty()
    ? restrict((*frame.TetIso)[tet].Gradient, (*frame.TetIso)[tet].RefScalar)
    : piece.S[0];
}

void hov::FeatureSegment::RestrictField(const FrameData& frame, int g, const double* scalars,
  const Ray& ray, double t0, double t1, std::vector<hov::RestrictedPiece>& out)
{
  const hov::GeneralCells& cells = frame.Setup->GetGeneralCells();
  const hov::GeneralCells::Cell& cell = cells.GetCells()[g];
  double lo = scalars[0], hi = scalars[0];
  for (int i = 1; i < cell.NodeCount; ++i)
  {
    lo = std::min(lo, scalars[i]);
    hi = std::max(hi, scalars[i]);
  }
  if (lo == hi)
  {
    out.resize(1);
    out[0] = hov::RestrictedPiece();
    out[0].T0 = t0;
    out[0].T1 = t1;
    out[0].S.C[0] = lo;
    return;
  }
  const double origin[3] = { ray.Origin.x, ray.Origin.y, ray.Origin.z };
  const double direction[3] = { ray.Direction.x, ray.Direction.y, ray.Direction.z };
  if (cell.Affine && scalars == cells.GetScalars(cell))
  {
    // The cell's own scalar: its kept Field and inverse Jacobian, no set-up per ray.
    out.resize(1);
    hov::GeneralCells::RestrictAffine(cell, cells.GetNodes(cell), origin, direction, t0, t1, out[0]);
  }
  else
  {
    hov::RestrictCellScalar(cell.Shape, cells.GetNodes(cell), scalars, origin, direction, t0, t1,
      frame.Restriction, out);
  }
  const double tol = NegligibleRelative * std::max(std::abs(lo), std::abs(hi));
  for (hov::RestrictedPiece& piece : out)
  {
    hov::TrimNegligibleTerms(piece.S, piece.T1 - piece.T0, tol);
  }
}

void hov::FeatureSegment::RestrictGeneral(
  const FrameData& frame, int g, const Ray& ray, double t0, double t1)
{
  const hov::GeneralCells& cells = frame.Setup->GetGeneralCells();
  const hov::GeneralCells::Cell& cell = cells.GetCells()[g];
  const hov::Features& features = *frame.Features;
  const std::vector<double>* fields[3] = { nullptr, features.ColorField, features.IsoField };
  int source[3] = { 0, 0, 0 }; // which restriction each field uses
  this->RestrictField(frame, g, cells.GetScalars(cell), ray, t0, t1, this->Restricted[0]);
  for (int f = 1; f < 3; ++f)
  {
    if (!fields[f])
    {
      continue;
    }
    const vtkIdType* ids = cells.GetNodeIds(cell);
    this->NodeValues[f].resize(cell.NodeCount);
    for (int i = 0; i < cell.NodeCount; ++i)
    {
      this->NodeValues[f][i] = (*fields[f])[ids[i]];
    }
    this->RestrictField(frame, g, this->NodeValues[f].data(), ray, t0, t1, this->Restricted[f]);
    source[f] = f;
  }
  this->Pieces.clear();
  for (int f = 0; f < 3; ++f)
  {
    if (this->Restricted[source[f]].empty())
    {
      return; // the restriction failed (invalid input): nothing to integrate
    }
  }
  // Common breakpoints of the restrictions in use.
  this->Breaks.clear();
  for (int f = 0; f < 3; ++f)
  {
    if (source[f] == f)
    {
      for (const hov::RestrictedPiece& p : this->Restricted[f])
      {
        this->Breaks.push_back(p.T0);
        this->Breaks.push_back(p.T1);
      }
    }
  }
  std::sort(this->Breaks.begin(), this->Breaks.end());
  this->Breaks.erase(std::unique(this->Breaks.begin(), this->Breaks.end()), this->Breaks.end());
  for (size_t b = 0; b + 1 < this->Breaks.size(); ++b)
  {
    Piece piece;
    piece.T0 = this->Breaks[b];
    piece.T1 = this->Breaks[b + 1];
    const double mid = 0.5 * (piece.T0 + piece.T1);
    for (int f = 0; f < 3; ++f)
    {
      const std::vector<hov::RestrictedPiece>& list = this->Restricted[source[f]];
      size_t m = 0;
      while (m + 1 < list.size() && list[m].T1 <= mid)
      {
        ++m;
      }
      piece.S[f] = list[m].T0 == piece.T0 ? list[m].S
                                          : hov::ComposeAffine(list[m].S, piece.T0 - list[m].T0, 1.0);
    }
    this->Pieces.push_back(piece);
  }
}

void hov::FeatureSegment::IsoGradient(
  const FrameData& frame, vtkIdType cellIndex, const double x[3], double grad[3])
{
  const hov::CellSetup& setup = *frame.Setup;
  const vtkIdType numTets = static_cast<vtkIdType>(setup.GetTetras().size());
  if (cellIndex < numTets)
  {
    const glm::dvec3 g = frame.TetIso && !frame.TetIso->empty()
      ? (*frame.TetIso)[cellIndex].Gradient
      : setup.GetTetras()[cellIndex].Gradient;
    grad[0] = g.x;
    grad[1] = g.y;
    grad[2] = g.z;
    return;
  }
  const hov::GeneralCells& cells = setup.GetGeneralCells();
  const hov::GeneralCells::Cell& cell = cells.GetCells()[cellIndex - numTets];
  const double* nodes = cells.GetNodes(cell);
  const double* values =
    frame.Features->IsoField ? this->NodeValues[2].data() : cells.GetScalars(cell);
  double pc[3], inv[9];
  if (cell.Affine)
  {
    std::copy(cell.InverseJacobian, cell.InverseJacobian + 9, inv);
    hov::CellNodeParametricCoords(cell.Shape, 0, pc);
    const double rel[3] = { x[0] - nodes[0], x[1] - nodes[1], x[2] - nodes[2] };
    for (int i = 0; i < 3; ++i)
    {
      pc[i] += inv[3 * i] * rel[0] + inv[3 * i + 1] * rel[1] + inv[3 * i + 2] * rel[2];
    }
  }
  else
  {
    hov::CellParametricCenter(cell.Shape, pc);
    hov::InvertGeometry(cell.Shape, nodes, x, pc);
    double xx[3], jac[9];
    hov::EvaluateGeometry(cell.Shape, nodes, pc, xx, jac);
    if (!Invert3(jac, inv))
    {
      grad[0] = grad[1] = grad[2] = 0.0; // the shading falls back to facing the viewer
      return;
    }
  }
  double derivs[3 * hov::MaxCellNodes];
  hov::CellShapeDerivatives(cell.Shape, pc, derivs);
  double dpc[3] = { 0.0, 0.0, 0.0 };
  const int n = cell.NodeCount;
  for (int i = 0; i < n; ++i)
  {
    dpc[0] += derivs[i] * values[i];
    dpc[1] += derivs[n + i] * values[i];
    dpc[2] += derivs[2 * n + i] * values[i];
  }
  // ds/dx_j = sum_i ds/dpc_i dpc_i/dx_j (inv = dpc/dx, row-major).
  for (int j = 0; j < 3; ++j)
  {
    grad[j] = dpc[0] * inv[j] + dpc[1] * inv[3 + j] + dpc[2] * inv[6 + j];
  }
}

hov::RGBA hov::FeatureSegment::Shade(
  const FrameData& frame, vtkIdType cell, const Ray& ray, double t, int surface)
{
  const hov::Features& features = *frame.Features;
  const glm::dvec3 x = ray.Origin + t * ray.Direction;
  const double xd[3] = { x.x, x.y, x.z };
  double g[3];
  this->IsoGradient(frame, cell, xd, g);
  const glm::dvec3 gw = features.NormalToWorld * glm::dvec3(g[0], g[1], g[2]);
  const glm::dvec4 xw = features.DataToWorld * glm::dvec4(x, 1.0);
  const glm::dvec3 dw = glm::normalize(glm::dmat3(features.DataToWorld) * ray.Direction);
  const double point[3] = { xw.x, xw.y, xw.z };
  const double gradient[3] = { gw.x, gw.y, gw.z };
  const double toViewer[3] = { -dw.x, -dw.y, -dw.z };
  return hov::IsosurfaceHitColor(features.Surfaces[surface], point, gradient, toViewer,
    features.Lights.data(), static_cast<int>(features.Lights.size()), features.Material,
    features.EdgeOnMinCosine);
}

hov::RGBA hov::FeatureSegment::Integrate(const FrameData& frame, vtkIdType cell,
  const Ray& ray, double t0, double t1, bool includeFront, vtkIdType& pieces)
{
  const vtkIdType numTets = static_cast<vtkIdType>(frame.Setup->GetTetras().size());
  if (cell < numTets)
  {
    this->RestrictTetra(frame, cell, ray, t0, t1);
  }
  else
  {
    this->RestrictGeneral(frame, static_cast<int>(cell - numTets), ray, t0, t1);
  }
  const hov::Features& features = *frame.Features;
  const hov::TransferFunction& tf = *frame.TF;
  const bool twoFields = features.ColorField != nullptr;
  const int numSurfaces = static_cast<int>(features.IsoValues.size());
  hov::RGBA sum;
  bool front = includeFront;
  if (features.VolumeActive() && numSurfaces == 0 && !twoFields)
  {
    hov::ShadedCellSegment::FrameData shaded;
    shaded.Setup = frame.Setup;
    shaded.Features = frame.Features;
    shaded.TF = frame.TF;
    shaded.Emission = frame.Segment.Emission;
    shaded.Tolerance = frame.Segment.Tolerance;
    for (const Piece& piece : this->Pieces)
    {
      hov::CompositeBehind(
        sum, this->Shaded.Integrate(shaded, cell, ray, piece.T0, piece.T1, piece.S[0], pieces));
      if (sum.A >= 1.0)
      {
        break;
      }
    }
    return sum;
  }
  for (const Piece& piece : this->Pieces)
  {
    const double length = piece.T1 - piece.T0;
    int crossings = 0;
    if (numSurfaces > 0)
    {
      crossings = hov::SurfaceCrossings(
        piece.S[2], length, features.IsoValues.data(), numSurfaces, front, this->Crossings);
    }
    front = false; // inner piece boundaries belong to the piece in front
    hov::PolynomialSegmentResult r;
    if (crossings > 0)
    {
      auto shade = [&](const hov::IsovalueCrossing& c) {
        return this->Shade(frame, cell, ray, piece.T0 + c.T, c.Index);
      };
      using Fn = decltype(shade);
      const hov::SurfaceShadeFunction call = [](void* user, const hov::IsovalueCrossing& c) {
        return (*static_cast<Fn*>(user))(c);
      };
      const hov::IsosurfaceSegmentResult s = twoFields || features.IsoField
        ? hov::IntegrateWithSurfaces(tf, piece.S[0], tf, piece.S[1], length,
            this->Crossings.data(), crossings, call, &shade, frame.Segment)
        : hov::IntegrateWithSurfaces(tf, piece.S[0], length, this->Crossings.data(), crossings,
            call, &shade, frame.Segment);
      r.Color = s.Color;
      r.Pieces = s.Pieces;
    }
    else if (twoFields)
    {
      r = hov::IntegrateTwoFields(tf, piece.S[0], tf, piece.S[1], length, frame.Segment);
    }
    else
    {
      r = hov::IntegratePolynomialScalar(tf, piece.S[0], length, frame.Segment);
    }
    pieces += r.Pieces;
    hov::CompositeBehind(sum, r.Color);
    if (sum.A >= 1.0)
    {
      break;
    }
  }
  return sum;
}
