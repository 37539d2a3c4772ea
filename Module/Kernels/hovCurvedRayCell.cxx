// Inside intervals of a ray in a curved Lagrange cell: see hovCurvedRayCell.h.
#include "hovCurvedRayCell.h"

#include <algorithm> // std::sort
#include <cmath>     // std::sqrt

namespace hov
{
namespace
{
/// A candidate end of a gap: its t and, if known, its parametric point.
struct Stop
{
  double T;
  double PC[3];
  bool HasPC;
};

/// Classify the point o + t d: outside if it is outside the faces' bounding
/// box; else inside iff the inversion converges with DistanceOutside <=
/// slack (first from the guess alone, then from every start of
/// InvertLagrangeGeometry). @p pc: guess in, result out.
bool InsideAt(const LagrangeCellView& cell, const CurvedCellFaces& faces, const double o[3],
  const double d[3], double t, double pc[3], double slack, int& failures)
{
  const double x[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
  for (int k = 0; k < 3; ++k)
  {
    if (x[k] < faces.Bounds[2 * k] || x[k] > faces.Bounds[2 * k + 1])
    {
      return false;
    }
  }
  LagrangeInversionSettings quick;
  quick.UseStartGrid = false;
  quick.MaxIterations = 25;
  double guess[3] = { pc[0], pc[1], pc[2] };
  LagrangeInversionResult r = InvertLagrangeGeometry(cell, x, pc, quick);
  if (!r.Converged())
  {
    std::copy(guess, guess + 3, pc);
    r = InvertLagrangeGeometry(cell, x, pc);
  }
  if (!r.Converged())
  {
    ++failures;
    return false;
  }
  return cell.Basis->DistanceOutside(pc) <= slack;
}

/// Sorted, merged stops: tMin, the crossings inside (tMin, tMax), tMax.
void CollectStops(const std::vector<FaceCrossing>& crossings, double tMin, double tMax,
  double merge, std::vector<Stop>& stops, CurvedRayStatus& status)
{
  stops.clear();
  stops.push_back({ tMin, { 0, 0, 0 }, false });
  std::vector<const FaceCrossing*> inside;
  for (const FaceCrossing& c : crossings)
  {
    if (c.T > tMin && c.T < tMax)
    {
      inside.push_back(&c);
    }
  }
  std::sort(inside.begin(), inside.end(),
    [](const FaceCrossing* a, const FaceCrossing* b) { return a->T < b->T; });
  for (const FaceCrossing* c : inside)
  {
    if (c->T - stops.back().T <= merge)
    {
      continue;
    }
    Stop s{ c->T, { c->PC[0], c->PC[1], c->PC[2] }, true };
    stops.push_back(s);
    ++status.Crossings;
    status.Grazing += c->Grazing ? 1 : 0;
  }
  if (tMax - stops.back().T <= merge && stops.size() > 1)
  {
    stops.back().T = tMax; // a crossing at tMax: keep its coordinates
  }
  else
  {
    stops.push_back({ tMax, { 0, 0, 0 }, false });
  }
}
}

int RayCurvedCellIntervals(const LagrangeCellView& cell, const CurvedCellFaces& faces,
  const double origin[3], const double direction[3], double tMin, double tMax,
  CurvedRayInterval* out, int maxOut, const CurvedRaySettings& settings,
  CurvedRayStatus* status, std::vector<FaceCrossing>* scratch)
{
  CurvedRayStatus st;
  std::vector<FaceCrossing> local;
  std::vector<FaceCrossing>& crossings = scratch ? *scratch : local;
  crossings.clear();
  const double dLen =
    std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  if (!(tMin <= tMax) || !(dLen > 0.0) || faces.Faces.empty())
  {
    if (status)
    {
      *status = st;
    }
    return 0;
  }
  FaceSearchStatus search;
  for (int f = 0; f < static_cast<int>(faces.Faces.size()); ++f)
  {
    FaceRayCrossings(cell, faces, f, origin, direction, crossings, settings.Faces, &search);
  }
  st.Patches = search.Patches;
  st.Complete = search.Complete;
  std::vector<Stop> stops;
  CollectStops(crossings, tMin, tMax, settings.MergeRelative * faces.Extent / dLen, stops, st);
  int count = 0;
  bool open = false;
  double centre[3];
  cell.Basis->ParametricCenter(centre);
  for (size_t g = 0; g + 1 < stops.size(); ++g)
  {
    const Stop& a = stops[g];
    const Stop& b = stops[g + 1];
    if (!(b.T > a.T))
    {
      continue;
    }
    double pc[3];
    for (int k = 0; k < 3; ++k)
    {
      pc[k] = (a.HasPC && b.HasPC) ? 0.5 * (a.PC[k] + b.PC[k])
        : a.HasPC                  ? a.PC[k]
        : b.HasPC                  ? b.PC[k]
                                   : centre[k];
    }
    const bool inside = InsideAt(cell, faces, origin, direction, 0.5 * (a.T + b.T), pc,
      settings.InsideSlack, st.InversionFailures);
    if (inside)
    {
      if (!open)
      {
        if (count >= maxOut)
        {
          break;
        }
        out[count].T0 = a.T;
        std::copy(a.HasPC ? a.PC : pc, (a.HasPC ? a.PC : pc) + 3, out[count].PC0);
        ++count;
      }
      out[count - 1].T1 = b.T;
      // The end's coordinates: the crossing's, else (tMax) inverted from the midpoint's.
      double end[3] = { pc[0], pc[1], pc[2] };
      if (b.HasPC)
      {
        std::copy(b.PC, b.PC + 3, end);
      }
      else
      {
        InsideAt(cell, faces, origin, direction, b.T, end, 1.0, st.InversionFailures);
      }
      std::copy(end, end + 3, out[count - 1].PC1);
    }
    open = inside;
  }
  // tMin inside: its coordinates by inversion from the first interval's guess.
  if (count > 0 && out[0].T0 == tMin && !stops[0].HasPC)
  {
    InsideAt(cell, faces, origin, direction, tMin, out[0].PC0, 1.0, st.InversionFailures);
  }
  if (status)
  {
    *status = st;
  }
  return count;
}
}
