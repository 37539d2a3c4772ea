#include "hovIsosurface.h"

#include "hovTransferFunction.h" // the table of the volume pieces
#include "hovTwoFieldSegment.h"  // volume pieces (one field: IntegratePolynomialScalar)

#include <algorithm> // std::sort, std::min, std::max, std::remove_if
#include <cmath>     // fabs, isfinite
#include <limits>    // epsilon

namespace hov
{
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();
// A root this close to an end whose value is on the isovalue is the end's
// crossing: at least 16 ulp of L (below that it is rounding of the root), at
// most 1e-6 L (a genuinely distinct crossing is never merged farther away).
constexpr double SnapMinUlps = 16.0;
constexpr double SnapMaxFraction = 1e-6;

/// sum |c_i| L^i: the scale of s and of its rounding errors on [0, L].
double Magnitude(const Polynomial& s, double length)
{
  double m = 0.0;
  for (int i = s.Degree; i >= 0; --i)
  {
    m = m * length + std::fabs(s.C[i]);
  }
  return m;
}

/// Sign of s(t) - iso beside the end at @p t toward @p inner (0 if on it).
int SideSign(const Polynomial& s, double iso, double t)
{
  const double v = Evaluate(s, t) - iso;
  return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}

/**
 * Applies the end rule to the crossings of isovalue @p index in
 * [first, last) of @p out: snaps them onto an end whose value is on the
 * isovalue, adds the end crossing if no root was reported there, merges
 * duplicates.
 */
void SnapEnds(const Polynomial& s, double length, double iso, int index, double magnitude,
  std::vector<IsovalueCrossing>& out)
{
  const double tol = EndSnapRelative * std::max(magnitude, std::fabs(iso));
  const Polynomial ds = Derivative(s);
  for (int end = 0; end < 2; ++end)
  {
    const double tEnd = end == 0 ? 0.0 : length;
    if (!(std::fabs(EvaluateCompensated(s, tEnd, iso)) <= tol))
    {
      continue;
    }
    const double slope = std::fabs(Evaluate(ds, tEnd));
    double snap = std::min(SnapMaxFraction * length, slope > 0.0 ? 2.0 * tol / slope : INFINITY);
    snap = std::max(snap, SnapMinUlps * Eps * length);
    bool found = false;
    for (IsovalueCrossing& c : out)
    {
      if (c.Index == index && std::fabs(c.T - tEnd) <= snap)
      {
        if (found)
        {
          c.Index = -1; // duplicate of the end crossing: removed below
        }
        c.T = tEnd;
        found = true;
      }
    }
    if (!found)
    {
      // The direction from the inner side, as IsovalueCrossings does at ends.
      const double inner = end == 0 ? std::min(snap * 2.0, length) : std::max(length - 2.0 * snap, 0.0);
      const int side = SideSign(s, iso, inner);
      out.push_back(IsovalueCrossing{ tEnd, index, end == 0 ? side : -side });
    }
  }
}
}

int SurfaceCrossings(const Polynomial& s, double length, const double* isovalues, int count,
  bool includeFront, std::vector<IsovalueCrossing>& out)
{
  out.clear();
  if (!(length >= 0.0) || !std::isfinite(length) || !isovalues || count <= 0)
  {
    return 0;
  }
  for (int i = 0; i <= std::min(s.Degree, Polynomial::MaxDegree); ++i)
  {
    if (!std::isfinite(s.C[i]))
    {
      return 0;
    }
  }
  if (EffectiveDegree(s) == 0)
  {
    return 0; // constant: no surface (also if equal to an isovalue)
  }
  IsovalueCrossings(s, length, isovalues, count, out);
  const double magnitude = Magnitude(s, length);
  for (int i = 0; i < count; ++i)
  {
    if (std::isfinite(isovalues[i]))
    {
      SnapEnds(s, length, isovalues[i], i, magnitude, out);
    }
  }
  out.erase(std::remove_if(out.begin(), out.end(),
              [includeFront](const IsovalueCrossing& c) {
                return c.Index < 0 || (c.T <= 0.0 && !includeFront);
              }),
    out.end());
  std::sort(out.begin(), out.end(), [](const IsovalueCrossing& a, const IsovalueCrossing& b) {
    return a.T < b.T || (a.T == b.T && a.Index < b.Index);
  });
  return static_cast<int>(out.size());
}

RGBA IsosurfaceHitColor(const Isosurface& surface, const double point[3], const double gradient[3],
  const double toViewer[3], const ShadingLight* lights, int lightCount,
  const ShadingMaterial& material, double minCosine)
{
  double normal[3];
  SurfaceNormal(gradient, toViewer, normal);
  const double cosIncidence =
    normal[0] * toViewer[0] + normal[1] * toViewer[1] + normal[2] * toViewer[2];
  const double alpha = EdgeOnOpacity(surface.Opacity, cosIncidence, minCosine);
  double rgb[3];
  ShadePhong(surface.Color, point, normal, toViewer, lights, lightCount, material, rgb);
  return RGBA{ alpha * rgb[0], alpha * rgb[1], alpha * rgb[2], alpha };
}

namespace
{
/// The fields and tables of the volume between the surfaces.
struct Volume
{
  const TransferFunction& Extinction;
  const Polynomial& S1;
  const TransferFunction& Color;
  const Polynomial& S2;
  double Length;
};

/// Volume piece [t0, t1] of the segment, composited behind @p result.Color.
/// (One field and one table: IntegrateTwoFields is IntegratePolynomialScalar.)
void AddVolume(const Volume& v, double t0, double t1, const PolynomialSegmentSettings& settings,
  int& panelsLeft, IsosurfaceSegmentResult& result)
{
  if (!(t1 > t0))
  {
    return;
  }
  const double transmit = 1.0 - result.Color.A;
  PolynomialSegmentSettings piece = settings;
  piece.MaxPanels = std::max(panelsLeft, 1);
  PolynomialSegmentResult r;
  if (t0 == 0.0 && t1 == v.Length)
  {
    r = IntegrateTwoFields(v.Extinction, v.S1, v.Color, v.S2, v.Length, piece);
  }
  else
  {
    // Budget Tolerance (t1 - t0)/L, relaxed by the transmittance in front.
    piece.Tolerance = transmit > 0.0 ? settings.Tolerance * ((t1 - t0) / v.Length) / transmit
                                     : settings.Tolerance;
    r = IntegrateTwoFields(v.Extinction, ComposeAffine(v.S1, t0, 1.0), v.Color,
      ComposeAffine(v.S2, t0, 1.0), t1 - t0, piece);
  }
  panelsLeft -= r.Panels;
  result.ErrorEstimate += transmit * r.ErrorEstimate;
  result.Pieces += r.Pieces;
  result.Panels += r.Panels;
  result.Converged = result.Converged && r.Converged;
  CompositeBehind(result.Color, r.Color);
}

IsosurfaceSegmentResult Integrate(const Volume& v, const IsovalueCrossing* crossings,
  int crossingCount, SurfaceShadeFunction shade, void* user,
  const PolynomialSegmentSettings& settings)
{
  IsosurfaceSegmentResult result;
  if (!(v.Length > 0.0) || !std::isfinite(v.Length))
  {
    return result;
  }
  int panelsLeft = std::max(settings.MaxPanels, 1);
  double tPrev = 0.0;
  for (int i = 0; i < crossingCount && crossings && result.Color.A < 1.0; ++i)
  {
    const double t = std::min(std::max(crossings[i].T, tPrev), v.Length);
    AddVolume(v, tPrev, t, settings, panelsLeft, result);
    tPrev = t;
    if (result.Color.A >= 1.0 || !shade)
    {
      continue;
    }
    const RGBA surface = shade(user, crossings[i]);
    if (surface.A > 0.0 || surface.R != 0.0 || surface.G != 0.0 || surface.B != 0.0)
    {
      CompositeBehind(result.Color, surface);
      ++result.Surfaces;
    }
  }
  if (result.Color.A < 1.0)
  {
    AddVolume(v, tPrev, v.Length, settings, panelsLeft, result);
  }
  return result;
}
}

IsosurfaceSegmentResult IntegrateWithSurfaces(const TransferFunction& tf, const Polynomial& s,
  double length, const IsovalueCrossing* crossings, int crossingCount, SurfaceShadeFunction shade,
  void* user, const PolynomialSegmentSettings& settings)
{
  return Integrate(Volume{ tf, s, tf, s, length }, crossings, crossingCount, shade, user, settings);
}

IsosurfaceSegmentResult IntegrateWithSurfaces(const TransferFunction& extinction,
  const Polynomial& s1, const TransferFunction& color, const Polynomial& s2, double length,
  const IsovalueCrossing* crossings, int crossingCount, SurfaceShadeFunction shade, void* user,
  const PolynomialSegmentSettings& settings)
{
  return Integrate(
    Volume{ extinction, s1, color, s2, length }, crossings, crossingCount, shade, user, settings);
}
}
