// The general-scalar ray integral of hovTestReferenceGeneral.h
// (BreakTimes, IntegrateRayGeneral, IntegrateRayGeneralBruteForce).
#include "hovTestReferenceGeneral.h"
#include "hovTestReferenceVector.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <boost/math/quadrature/gauss_kronrod.hpp> // the adaptive quadratures
#include <boost/math/tools/minima.hpp>             // brent_find_minima (extrema of s)
#include <boost/math/tools/toms748_solve.hpp>      // node crossings

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace hovTestRef
{
namespace
{
/// An interior extremum of s in (a, b) (Brent on s or -s), if s there is
/// strictly beyond both ends by more than round-off; else nothing is added.
void AddExtremum(const ScalarFunction& s, Real a, Real b, bool maximum, std::vector<Real>& out)
{
  const Real sign = maximum ? -1 : 1;
  auto f = [&](Real t) { return sign * s(t); };
  std::uintmax_t iterations = 200;
  const auto r = boost::math::tools::brent_find_minima(
    f, a, b, std::numeric_limits<Real>::digits / 2, iterations);
  const Real fa = f(a), fb = f(b);
  const Real scale = std::max({ std::fabs(fa), std::fabs(fb), Real(1e-300) });
  const Real slack = 64 * std::numeric_limits<Real>::epsilon() * scale;
  if (r.first > a && r.first < b && r.second < fa - slack && r.second < fb - slack)
  {
    out.push_back(r.first);
  }
}

/// Sign of x with 0 for exact zeros.
int Sign(Real x)
{
  return (x > 0) - (x < 0);
}
}

std::vector<double> TransferFunctionNodes(vtkVolumeProperty* property)
{
  std::vector<double> nodes;
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = property->GetScalarOpacity(0);
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
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::vector<Real> BreakTimes(const ScalarFunction& s, Real length, const std::vector<double>& nodes,
  int samples, GeneralStats* stats)
{
  samples = std::max(samples, 4);
  std::vector<Real> t(samples + 1), v(samples + 1);
  for (int k = 0; k <= samples; ++k)
  {
    t[k] = length * k / samples;
    v[k] = s(t[k]);
  }
  // 1. Extrema: where the differences change sign (zeros carry the previous
  // sign), plus a search in the first and last two intervals, where an
  // extremum close to an end leaves no sign change among the samples.
  std::vector<Real> extrema;
  int previous = 0;
  for (int k = 0; k < samples; ++k)
  {
    const int d = Sign(v[k + 1] - v[k]);
    if (d != 0 && previous != 0 && d != previous)
    {
      AddExtremum(s, t[k - 1], t[k + 1], previous > 0, extrema);
    }
    previous = d != 0 ? d : previous;
  }
  for (bool maximum : { false, true })
  {
    AddExtremum(s, t[0], t[2], maximum, extrema);
    AddExtremum(s, t[samples - 2], t[samples], maximum, extrema);
  }
  // The same extremum may be found twice (by a sign change and by the end
  // search) at locations that differ by Brent's tolerance (~1e-10 L): keep one.
  std::sort(extrema.begin(), extrema.end());
  const Real merge = length * Real(1e-7);
  extrema.erase(std::unique(extrema.begin(), extrema.end(),
                  [merge](Real a, Real b) { return b - a < merge; }),
    extrema.end());

  std::vector<Real> monotone{ Real(0) };
  monotone.insert(monotone.end(), extrema.begin(), extrema.end());
  monotone.push_back(length);

  // 2. Node crossings on each monotone piece.
  std::vector<Real> cuts = monotone;
  int crossings = 0;
  for (size_t p = 0; p + 1 < monotone.size(); ++p)
  {
    const Real a = monotone[p], b = monotone[p + 1];
    const Real sa = s(a), sb = s(b);
    for (double node : nodes)
    {
      const Real g = node;
      if ((sa - g) * (sb - g) < 0)
      {
        std::uintmax_t iterations = 200;
        auto f = [&](Real x) { return s(x) - g; };
        const auto r = boost::math::tools::toms748_solve(f, a, b, sa - g, sb - g,
          boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 2),
          iterations);
        cuts.push_back((r.first + r.second) / 2);
        ++crossings;
      }
    }
  }
  std::sort(cuts.begin(), cuts.end());
  if (stats)
  {
    stats->Extrema += static_cast<int>(extrema.size());
    stats->Crossings += crossings;
  }
  return cuts;
}

RGBA IntegrateRayGeneral(vtkVolumeProperty* property, const Model& model, const ScalarFunction& s,
  Real length, const GeneralOptions& options, GeneralStats* stats)
{
  RGBA out;
  if (!(length > 0))
  {
    return out;
  }
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = property->GetScalarOpacity(0);
  const Real unit = property->GetScalarOpacityUnitDistance(0);
  const std::vector<Real> cuts =
    BreakTimes(s, length, TransferFunctionNodes(property), options.Samples, stats);

  auto tau = [&](Real t) {
    return Extinction(otf->GetValue(static_cast<double>(s(t))), model.Semantics, unit);
  };
  const bool wm = model.Emission == 0;
  const Real emissionFactor = Real(model.EmissionScale) / unit;
  using Outer = boost::math::quadrature::gauss_kronrod<Real, 31>;
  using Inner = boost::math::quadrature::gauss_kronrod<Real, 15>;
  Real depth = 0; // optical depth from the front to the current piece
  QVec color(0);
  for (size_t k = 0; k + 1 < cuts.size(); ++k)
  {
    const Real tA = cuts[k], tB = cuts[k + 1];
    if (!(tB > tA))
    {
      continue;
    }
    if (stats)
    {
      ++stats->Pieces;
    }
    // Pieces shorter than 1e-6 L (a node crossing next to an extremum) get
    // one non-adaptive rule each: exact far below 1e-12 there, whereas the
    // relative error test can keep bisecting on round-off (measured: 3e7
    // evaluations for a 2e-10 piece).
    const bool tiny = tB - tA < length * Real(1e-6);
    const int innerDepth = tiny ? 0 : options.InnerDepth;
    const int outerDepth = tiny ? 0 : options.OuterDepth;
    auto depthTo = [&](Real t) {
      return t > tA ? Inner::integrate(tau, tA, t, innerDepth, options.InnerTolerance) : Real(0);
    };
    auto integrand = [&](Real t) -> QVec {
      const double sv = static_cast<double>(s(t));
      const Real a = otf->GetValue(sv);
      double c[3];
      ctf->GetColor(sv, c);
      const Real weight = std::exp(-(depth + depthTo(t))) *
        (wm ? Extinction(a, model.Semantics, unit) : emissionFactor);
      return QVec(weight * c[0], weight * c[1], weight * c[2]);
    };
    color += Outer::integrate(integrand, tA, tB, outerDepth, options.Tolerance);
    depth += depthTo(tB);
  }
  out.R = color.V[0];
  out.G = color.V[1];
  out.B = color.V[2];
  out.A = -std::expm1(-depth);
  return out;
}

RGBA IntegrateRayGeneralBruteForce(vtkVolumeProperty* property, const Model& model,
  const ScalarFunction& s, Real length, long steps)
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
    const double sv = static_cast<double>(s((k + Real(0.5)) * dt));
    const Real tau = Extinction(otf->GetValue(sv), model.Semantics, unit);
    double c[3];
    ctf->GetColor(sv, c);
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
}
