#include "hovShadedCellSegment.h"

#include "hovCellSetup.h"    // the tetrahedra
#include "hovFeatures.h"     // the shading settings, frames
#include "hovGeneralCells.h" // the general cells

#include "hovFieldGradient.h"   // AffineGradientAlongLine, CellFieldAndGradient
#include "hovGradientRestriction.h" // RestrictCellGradient
#include "hovShadedSegment.h"   // IntegrateShadedPolynomial, IntegrateShadedSegment
#include "hovVolumeShading.h"   // IntegrateLinearScalarShaded

#include <algorithm> // std::max
#include <cmath>     // std::isfinite
#include <cstring>   // memcmp, memcpy

namespace
{
using Ray = hov::ViewRays::Ray;

/// The gradient's fit on non-affine cells (hov::RestrictCellGradient): the
/// scalar restriction's relative tolerance, and few pieces (a gradient that
/// needs more takes the pointwise route).
constexpr double GradientRelativeTolerance = 1e-10;
constexpr int MaxGradientPieces = 8;

/// A bounded cost per segment (pathological fields: the robustness test's
/// 1e9 scalars); beyond it the result is kept with its error estimate.
constexpr int MaxPanels = 256;
constexpr int MaxDepth = 20;

/// @p g (dataset coordinates) as a world gradient.
glm::dvec3 ToWorld(const hov::Features& f, const glm::dvec3& g)
{
  return f.NormalToWorld * g;
}

/// The polynomial gradient @p g (dataset coordinates) as world polynomials.
void ToWorld(const hov::Features& f, const hov::Polynomial g[3], hov::Polynomial out[3])
{
  const glm::dmat3& n = f.NormalToWorld; // n[column][row]
  for (int i = 0; i < 3; ++i)
  {
    out[i] = hov::Polynomial();
    out[i].Degree = std::max(g[0].Degree, std::max(g[1].Degree, g[2].Degree));
    for (int k = 0; k <= out[i].Degree; ++k)
    {
      out[i].C[k] = n[0][i] * g[0].C[k] + n[1][i] * g[1].C[k] + n[2][i] * g[2].C[k];
    }
  }
}

/**
 * grad s along the ray from @p t0 in an affine cell, from the coefficients
 * @p coefficients of its scalars and the kept inverse Jacobian
 * (hov::GeneralCells), as the scalar's restriction is; false (the pointwise
 * route then) for non-finite results.
 */
bool AffineGradient(const hov::GeneralCells::Cell& c, const double* nodes,
  const double (*coefficients)[hov::AffineFieldTerms], const double o[3], const double d[3],
  double t0, hov::Polynomial g[3])
{
  double start[3], step[3];
  hov::GeneralCells::AffineLine(c, nodes, o, d, t0, start, step);
  hov::AffineGradientAlongLine(coefficients, c.InverseJacobian, start, step, g);
  for (int k = 0; k < 3; ++k)
  {
    for (int i = 0; i <= g[k].Degree; ++i)
    {
      if (!std::isfinite(g[k].C[i]))
      {
        return false;
      }
    }
  }
  return true;
}

/// The segment's position in the lighting (world) frame, from ray parameter @p t0.
hov::SegmentRay WorldRay(const hov::Features& f, const Ray& ray, double t0)
{
  hov::SegmentRay out;
  const glm::dvec4 x = f.DataToWorld * glm::dvec4(ray.Origin + t0 * ray.Direction, 1.0);
  const glm::dvec3 d = glm::normalize(glm::dmat3(f.DataToWorld) * ray.Direction);
  for (int k = 0; k < 3; ++k)
  {
    out.Origin[k] = x[k];
    out.Direction[k] = d[k];
  }
  return out;
}

/// Pointwise field and world gradient of a general cell along a ray piece.
struct CellSampler
{
  const hov::Features* F;
  hov::CellShape Shape;
  const double* Nodes;
  const double* Scalars;
  glm::dvec3 Origin, Direction; ///< dataset coordinates, at the piece's start
  double PC[3];

  static void Sample(void* user, double t, double& value, double gradient[3])
  {
    auto* self = static_cast<CellSampler*>(user);
    const glm::dvec3 x = self->Origin + t * self->Direction;
    const double xd[3] = { x.x, x.y, x.z };
    double g[3] = { 0.0, 0.0, 0.0 };
    hov::CellFieldAndGradient(self->Shape, self->Nodes, self->Scalars, xd, self->PC, value, g);
    const glm::dvec3 gw = ToWorld(*self->F, glm::dvec3(g[0], g[1], g[2]));
    gradient[0] = gw.x;
    gradient[1] = gw.y;
    gradient[2] = gw.z;
  }
};
}

hov::RGBA hov::ShadedCellSegment::Integrate(const FrameData& frame, vtkIdType cell,
  const Ray& ray, double t0, double t1, const hov::Polynomial& s, vtkIdType& pieces)
{
  const hov::Features& f = *frame.Features;
  const hov::TransferFunction& tf = *frame.TF;
  const double length = t1 - t0;
  const hov::GradientOpacityFunction* go = f.UseGradientOpacity ? &f.GradientOpacity : nullptr;
  const hov::SegmentRay wray = WorldRay(f, ray, t0);
  hov::ShadedSegmentSettings settings;
  settings.Emission = frame.Emission;
  settings.Tolerance = frame.Tolerance;
  settings.MaxPanels = MaxPanels;
  settings.MaxDepth = MaxDepth;
  const vtkIdType numTets = static_cast<vtkIdType>(frame.Setup->GetTetras().size());
  hov::ShadedSegmentResult r;
  if (cell < numTets)
  {
    const glm::dvec3 gw = ToWorld(f, frame.Setup->GetTetras()[cell].Gradient);
    const double g[3] = { gw.x, gw.y, gw.z };
    if (hov::LightsAreDirectional(f.VolumeShading))
    {
      // Constant gradient, constant light and view: the closed form.
      const double toViewer[3] = { -wray.Direction[0], -wray.Direction[1], -wray.Direction[2] };
      const hov::ShadingTransform shade =
        hov::ComputeShadingTransform(f.VolumeShading, g, wray.Origin, toViewer);
      const double gamma = go ? go->EvaluateGradient(g) : 1.0;
      hov::IntegrationSettings integration;
      integration.Emission = frame.Emission;
      int n = 0;
      const double sBack = s.C[0] + (s.Degree > 0 ? s.C[1] * length : 0.0);
      const hov::RGBA c = hov::IntegrateLinearScalarShaded(
        tf, s.C[0], sBack, length, shade, gamma, integration, &n);
      pieces += n;
      return c;
    }
    hov::Polynomial gp[3];
    for (int k = 0; k < 3; ++k)
    {
      gp[k].C[0] = g[k];
    }
    r = hov::IntegrateShadedPolynomial(tf, s, gp, length, f.VolumeShading, go, wray, settings);
  }
  else
  {
    const hov::GeneralCells& cells = frame.Setup->GetGeneralCells();
    const hov::GeneralCells::Cell& c = cells.GetCells()[cell - numTets];
    const double* nodes = cells.GetNodes(c);
    const double* scalars = cells.GetScalars(c);
    const double o[3] = { ray.Origin.x, ray.Origin.y, ray.Origin.z };
    const double d[3] = { ray.Direction.x, ray.Direction.y, ray.Direction.z };
    hov::Polynomial g[3], gw[3];
    const double(*coefficients)[hov::AffineFieldTerms] =
      c.Affine ? this->Coefficients.Get(c.Shape, scalars) : nullptr;
    if (coefficients && AffineGradient(c, nodes, coefficients, o, d, t0, g))
    {
      ToWorld(f, g, gw);
      r = hov::IntegrateShadedPolynomial(tf, s, gw, length, f.VolumeShading, go, wray, settings);
    }
    else if (!this->IntegrateFitted(frame, c, ray, t0, t1, s, settings, r))
    {
      // The pointwise route. Breakpoints: the table-node crossings of the
      // restricted scalar (the ones the integral would step over left out).
      hov::ShadedBreakpoints(
        tf, s, g, nullptr, length, this->Breaks, &this->Smooth, MaxPanels / 2);
      CellSampler sampler{ &f, c.Shape, nodes, scalars, ray.Origin + t0 * ray.Direction,
        ray.Direction, { 0.0, 0.0, 0.0 } };
      hov::CellParametricCenter(c.Shape, sampler.PC);
      r = hov::IntegrateShadedSegment(tf, &CellSampler::Sample, &sampler, length,
        this->Breaks.data(), static_cast<int>(this->Breaks.size()), f.VolumeShading, go, wray,
        settings, this->Smooth.data());
    }
  }
  pieces += std::max(r.Panels, 1);
  if (std::isfinite(r.ErrorEstimate))
  {
    this->WorstError = std::max(this->WorstError, r.ErrorEstimate);
  }
  return r.Color;
}

const double (*hov::ShadedCellSegment::CoefficientCache::Get(
  hov::CellShape shape, const double* scalars))[hov::AffineFieldTerms]
{
  const int n = hov::CellNodeCount(shape);
  if (!(this->Valid && shape == this->Shape &&
        std::memcmp(scalars, this->Scalars, n * sizeof(double)) == 0))
  {
    // A new cell (or the same one with other scalars: compared by value).
    this->Valid = false;
    this->Shape = shape;
    std::memcpy(this->Scalars, scalars, n * sizeof(double));
    this->Usable = hov::AffineGradientCoefficients(shape, scalars, this->C);
    this->Valid = true;
  }
  return this->Usable ? this->C : nullptr;
}

bool hov::ShadedCellSegment::IntegrateFitted(const FrameData& frame,
  const hov::GeneralCells::Cell& c, const Ray& ray, double t0, double t1,
  const hov::Polynomial& s, const hov::ShadedSegmentSettings& settings,
  hov::ShadedSegmentResult& out)
{
  const hov::Features& f = *frame.Features;
  const hov::GeneralCells& cells = frame.Setup->GetGeneralCells();
  const double o[3] = { ray.Origin.x, ray.Origin.y, ray.Origin.z };
  const double d[3] = { ray.Direction.x, ray.Direction.y, ray.Direction.z };
  hov::CellRestrictionSettings fit;
  fit.RelativeTolerance = GradientRelativeTolerance;
  fit.MaxPieces = MaxGradientPieces;
  hov::CellRestrictionStatus status;
  if (hov::RestrictCellGradient(c.Shape, cells.GetNodes(c), cells.GetScalars(c), o, d, t0, t1,
        fit, this->GradientPieces, &status) == 0 ||
    !status.Converged || status.NewtonFailures > 0)
  {
    return false;
  }
  const hov::GradientOpacityFunction* go = f.UseGradientOpacity ? &f.GradientOpacity : nullptr;
  hov::ShadedSegmentResult sum;
  const double length = t1 - t0;
  for (const hov::GradientPiece& piece : this->GradientPieces)
  {
    // The segment's tolerance and panel budget shared among the sub-pieces
    // as the quadrature shares them among its panels: in proportion to the
    // length, and what the pieces in front left.
    hov::ShadedSegmentSettings share = settings;
    share.Tolerance = settings.Tolerance * ((piece.T1 - piece.T0) / length);
    share.MaxPanels = std::max(settings.MaxPanels - sum.Panels, 1);
    // s in the piece's own variable, tau' = t - piece.T0.
    const hov::Polynomial sp =
      piece.T0 == t0 ? s : hov::ComposeAffine(s, piece.T0 - t0, 1.0);
    hov::Polynomial gw[3];
    ToWorld(f, piece.G, gw);
    const hov::ShadedSegmentResult r = hov::IntegrateShadedPolynomial(*frame.TF, sp, gw,
      piece.T1 - piece.T0, f.VolumeShading, go, WorldRay(f, ray, piece.T0), share);
    sum.ErrorEstimate += (1.0 - sum.Color.A) * r.ErrorEstimate;
    hov::CompositeBehind(sum.Color, r.Color);
    sum.Panels += r.Panels;
    sum.Samples += r.Samples;
    sum.SkippedBreakpoints += r.SkippedBreakpoints;
    sum.Converged = sum.Converged && r.Converged;
    if (sum.Color.A >= 1.0)
    {
      break; // nothing behind is visible
    }
  }
  out = sum;
  return true;
}
