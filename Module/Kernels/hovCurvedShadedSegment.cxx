#include "hovCurvedShadedSegment.h"

#include "hovGradientOpacity.h" // GradientOpacityFunction
#include "hovShadedSegment.h"   // IntegrateShadedSegment
#include "hovTransferFunction.h"
#include "hovVolumeShading.h" // IntegrateLinearScalarShaded

#include <algorithm> // std::sort, std::min, std::max
#include <cmath>     // std::isfinite
#include <vector>    // pieces, breakpoints

namespace hov
{
namespace
{
/// Panels and bisection depth of one segment's quadrature (see the file doc).
constexpr int MaxShadedPanels = 128;
constexpr int MaxShadedDepth = 16;

/// Field and world gradient along the ray, by Newton inversion from the last sample.
/// The field is interpolated from the node scalars minus the first one (Field,
/// Offset added back): the same polynomial, but a constant field then has
/// the gradient (0, 0, 0) exactly instead of the rounding of sum_i dN_i s_i,
/// ~1e-16 in a random direction, whose normal is noise (and the adaptive
/// quadrature never converges on noise).
struct RaySampler
{
  const LagrangeCellView* Cell;
  LagrangeCellView Field; ///< Cell with the shifted scalars
  std::vector<double> Shifted;
  double Offset = 0.0;
  double Origin[3]; ///< the point at the segment's start
  double Direction[3];
  double PC[3];
  bool Failed = false;

  void SetCell(const LagrangeCellView& cell)
  {
    this->Cell = &cell;
    this->Field = cell;
    const int n = cell.Basis->GetNodeCount();
    if (cell.Scalars && n > 0)
    {
      this->Offset = cell.Scalars[0];
      this->Shifted.resize(n);
      for (int i = 0; i < n; ++i)
      {
        this->Shifted[i] = cell.Scalars[i] - this->Offset;
      }
      this->Field.Scalars = this->Shifted.data();
    }
  }

  void At(double t, double& value, double gradient[3])
  {
    const double x[3] = { this->Origin[0] + t * this->Direction[0],
      this->Origin[1] + t * this->Direction[1], this->Origin[2] + t * this->Direction[2] };
    double pc[3] = { this->PC[0], this->PC[1], this->PC[2] };
    const LagrangeInversionResult inv = InvertLagrangeGeometry(*this->Cell, x, pc);
    if (inv.Converged())
    {
      std::copy(pc, pc + 3, this->PC);
    }
    else
    {
      this->Failed = true;
    }
    double dfdpc[3], xx[3], jac[9];
    value = EvaluateLagrangeScalar(this->Field, pc, dfdpc) + this->Offset;
    EvaluateLagrangePosition(*this->Cell, pc, xx, jac);
    // J^T g = df/dpc (J[3 i + j] = dx_i / dpc_j).
    const double jt[9] = { jac[0], jac[3], jac[6], jac[1], jac[4], jac[7], jac[2], jac[5], jac[8] };
    if (!Solve3x3(jt, dfdpc, gradient, 1e-14))
    {
      gradient[0] = gradient[1] = gradient[2] = 0.0; // no normal: ambient only
    }
  }

  static void Sample(void* user, double t, double& value, double gradient[3])
  {
    static_cast<RaySampler*>(user)->At(t, value, gradient);
  }
};
}

CurvedSegmentResult IntegrateCurvedShadedSegment(const LagrangeCellView& cell,
  const CellDerivativeBounds& bounds, const TransferFunction& tf, const double origin[3],
  const double direction[3], double t0, double t1, const double* pcGuess,
  const CurvedSegmentSettings& settings)
{
  CurvedSegmentResult out;
  const double length = t1 - t0;
  if (!(length > 0.0))
  {
    return out;
  }
  static const VolumeShadingSettings unshaded;
  const VolumeShadingSettings& vs = settings.Shading ? *settings.Shading : unshaded;
  const GradientOpacityFunction* go = settings.GradientOpacity;
  RaySampler sampler;
  sampler.SetCell(cell);
  for (int k = 0; k < 3; ++k)
  {
    sampler.Origin[k] = origin[k] + t0 * direction[k];
    sampler.Direction[k] = direction[k];
  }
  if (pcGuess)
  {
    std::copy(pcGuess, pcGuess + 3, sampler.PC);
  }
  else
  {
    cell.Basis->ParametricCenter(sampler.PC);
  }
  SegmentRay ray;
  std::copy(sampler.Origin, sampler.Origin + 3, ray.Origin);
  std::copy(direction, direction + 3, ray.Direction);

  if (cell.Basis->GetLineDegree() == 1 && IsLagrangeGeometryAffine(cell) &&
    LightsAreDirectional(vs))
  {
    // Linear field, constant gradient: the closed form.
    double s0 = 0.0, s1 = 0.0, g0[3], g1[3];
    sampler.At(0.0, s0, g0);
    sampler.At(length, s1, g1);
    const double toViewer[3] = { -direction[0], -direction[1], -direction[2] };
    const ShadingTransform shade = ComputeShadingTransform(vs, g0, ray.Origin, toViewer);
    const double gamma = go ? go->EvaluateGradient(g0) : 1.0;
    IntegrationSettings integration;
    integration.Emission = settings.Quadrature.Emission;
    int pieces = 0;
    out.Color = IntegrateLinearScalarShaded(tf, s0, s1, length, shade, gamma, integration, &pieces);
    out.Pieces = pieces;
    out.ExactField = true;
    out.Converged = !sampler.Failed;
    return out;
  }

  // Breakpoints: the table-node crossings on the field representation.
  std::vector<FieldPiece> pieces;
  std::vector<double> breaks;
  if (RepresentFieldOnSegment(cell, bounds, origin, direction, t0, t1, pcGuess, settings, pieces))
  {
    const std::vector<double>& nodes = tf.GetNodes();
    for (const FieldPiece& piece : pieces)
    {
      double lo = piece.G.B[0], hi = piece.G.B[0];
      for (int i = 1; i <= piece.G.Degree; ++i)
      {
        lo = std::min(lo, piece.G.B[i]);
        hi = std::max(hi, piece.G.B[i]);
      }
      lo -= piece.Error;
      hi += piece.Error;
      for (double level : nodes)
      {
        if (level >= lo && level <= hi)
        {
          LocateBreakpoints(cell, origin, direction, piece, level, breaks);
        }
      }
      if (piece.T1 < t1)
      {
        breaks.push_back(piece.T1);
      }
    }
  }
  else
  {
    out.Converged = false;
  }
  // Segment-local, sorted, strictly inside (0, length).
  size_t kept = 0;
  for (double b : breaks)
  {
    const double local = b - t0;
    if (local > 0.0 && local < length)
    {
      breaks[kept++] = local;
    }
  }
  breaks.resize(kept);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  ShadedSegmentSettings quadrature;
  quadrature.Emission = settings.Quadrature.Emission;
  quadrature.Tolerance = settings.Quadrature.Tolerance;
  // A bounded cost per segment (every sample is a Newton inversion): beyond
  // it the result is kept with its estimate and Converged false (the caller
  // reports it), instead of minutes on a pathological field.
  quadrature.MaxPanels = MaxShadedPanels;
  quadrature.MaxDepth = MaxShadedDepth;
  const ShadedSegmentResult r = IntegrateShadedSegment(tf, &RaySampler::Sample, &sampler, length,
    breaks.data(), static_cast<int>(breaks.size()), vs, go, ray, quadrature);
  out.Color = r.Color;
  out.ErrorEstimate = r.ErrorEstimate;
  out.Breakpoints = static_cast<int>(breaks.size());
  out.Pieces = r.Panels;
  out.Samples = r.Samples;
  out.Converged = out.Converged && r.Converged && !sampler.Failed;
  return out;
}
}
