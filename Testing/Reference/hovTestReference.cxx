// The reference ray integral of hovTestReference.h (IntegrateRay,
// IntegrateRayBruteForce) and the naming / description helpers.
#include "hovTestReference.h"
#include "hovTestReferenceVector.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

namespace hovTestRef
{
namespace
{
/// Optical depth of a piece of length x on which the opacity goes linearly
/// from aFront to a (exact for every semantics, see the header).
Real PieceDepth(Real x, Real aFront, Real a, int semantics, Real unit)
{
  if (!(x > 0))
  {
    return 0;
  }
  if (semantics != 0)
  {
    return x * (Extinction(aFront, semantics, unit) + Extinction(a, semantics, unit)) / 2;
  }
  const Real p0 = 1 - aFront;
  const Real p = 1 - a;
  const Real r = (p - p0) / p0;
  const Real l = r == 0 ? Real(1) : std::log1p(r) / r;
  return x / unit * (1 - std::log(p0) - (1 + r) * l);
}
}

const char* SemanticsName(int semantics)
{
  switch (semantics)
  {
    case 0:
      return "GPU_COMPATIBLE";
    case 1:
      return "VTK_UNSTRUCTURED";
    default:
      return "RAW_EXTINCTION";
  }
}

const char* EmissionName(int emission)
{
  return emission == 0 ? "WILLIAMS_MAX" : "WILHELMS_VAN_GELDER";
}

Real Extinction(Real a, int semantics, Real unit)
{
  switch (semantics)
  {
    case 0:
      return -std::log1p(-a) / unit;
    case 1:
      return a / unit;
    default:
      return a;
  }
}

RGBA IntegrateRay(vtkVolumeProperty* property, const Model& model, double s0, double s1, Real length)
{
  RGBA out;
  if (!(length > 0))
  {
    return out;
  }
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = property->GetScalarOpacity(0);
  const Real unit = property->GetScalarOpacityUnitDistance(0);

  // Pieces: (t, s) at every crossing of a colour or opacity node.
  std::vector<std::pair<Real, double>> cuts{ { Real(0), s0 }, { length, s1 } };
  if (s0 != s1)
  {
    std::vector<double> nodes;
    for (int i = 0; i < ctf->GetSize(); ++i)
    {
      double v[6];
      ctf->GetNodeValue(i, v);
      nodes.push_back(v[0]);
    }
    for (int i = 0; i < otf->GetSize(); ++i)
    {
      double v[4];
      otf->GetNodeValue(i, v);
      nodes.push_back(v[0]);
    }
    const double lo = std::min(s0, s1), hi = std::max(s0, s1);
    for (double x : nodes)
    {
      if (x > lo && x < hi)
      {
        cuts.emplace_back(length * ((Real(x) - s0) / (Real(s1) - s0)), x);
      }
    }
    std::sort(cuts.begin(), cuts.end());
  }

  const Real sSlope = (Real(s1) - s0) / length;
  auto scalarAt = [&](Real t) { return static_cast<double>(s0 + sSlope * t); };
  const bool wm = model.Emission == 0;
  const Real emissionFactor = Real(model.EmissionScale) / unit;
  Real depth = 0; // optical depth from the ray's front to the current piece
  QVec color(0);
  for (size_t k = 0; k + 1 < cuts.size(); ++k)
  {
    const Real tA = cuts[k].first, tB = cuts[k + 1].first;
    if (!(tB > tA))
    {
      continue;
    }
    const Real aA = otf->GetValue(cuts[k].second);
    const Real aB = otf->GetValue(cuts[k + 1].second);
    auto integrand = [&](Real t) -> QVec {
      const double s = scalarAt(t);
      const Real a = otf->GetValue(s);
      double c[3];
      ctf->GetColor(s, c);
      const Real transmittance = std::exp(-(depth + PieceDepth(t - tA, aA, a, model.Semantics, unit)));
      const Real weight =
        transmittance * (wm ? Extinction(a, model.Semantics, unit) : emissionFactor);
      return QVec(weight * c[0], weight * c[1], weight * c[2]);
    };
    color += boost::math::quadrature::gauss_kronrod<Real, 31>::integrate(
      integrand, tA, tB, 10, Real(1e-12));
    depth += PieceDepth(tB - tA, aA, aB, model.Semantics, unit);
  }
  out.R = color.V[0];
  out.G = color.V[1];
  out.B = color.V[2];
  out.A = -std::expm1(-depth);
  return out;
}

RGBA IntegrateRayBruteForce(
  vtkVolumeProperty* property, const Model& model, double s0, double s1, Real length, long steps)
{
  RGBA out;
  if (!(length > 0) || steps < 1)
  {
    return out;
  }
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = property->GetScalarOpacity(0);
  const Real unit = property->GetScalarOpacityUnitDistance(0);
  const Real dt = length / steps;
  const Real emissionFactor = Real(model.EmissionScale) / unit;
  Real transmittance = 1;
  for (long k = 0; k < steps; ++k)
  {
    const Real w = (k + Real(0.5)) / steps;
    const double s = static_cast<double>(s0 + (Real(s1) - s0) * w);
    const Real tau = Extinction(otf->GetValue(s), model.Semantics, unit);
    double c[3];
    ctf->GetColor(s, c);
    const Real absorbed = -std::expm1(-tau * dt);
    const Real weight = transmittance *
      (model.Emission == 0 ? absorbed : emissionFactor * (tau > 0 ? absorbed / tau : dt));
    out.R += weight * c[0];
    out.G += weight * c[1];
    out.B += weight * c[2];
    transmittance *= std::exp(-tau * dt);
  }
  out.A = 1 - transmittance;
  return out;
}

std::string DescribeProperty(vtkVolumeProperty* property)
{
  std::ostringstream os;
  os << std::setprecision(17);
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = property->GetScalarOpacity(0);
  os << "colour nodes:";
  for (int i = 0; i < ctf->GetSize(); ++i)
  {
    double v[6];
    ctf->GetNodeValue(i, v);
    os << " (" << v[0] << ": " << v[1] << ", " << v[2] << ", " << v[3] << ")";
  }
  os << "; opacity nodes:";
  for (int i = 0; i < otf->GetSize(); ++i)
  {
    double v[4];
    otf->GetNodeValue(i, v);
    os << " (" << v[0] << ": " << v[1] << ")";
  }
  os << "; unit distance " << property->GetScalarOpacityUnitDistance(0);
  return os.str();
}
}
