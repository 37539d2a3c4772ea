// Inside intervals of a ray in a curved Lagrange cell: see hovCurvedRayCell.h.
#include "hovCurvedRayCell.h"

#include <algorithm> // std::sort
#include <cmath>     // std::sqrt

namespace hov
{
namespace
{
/// A candidate end of a gap: its t and, if known, its parametric point and
/// its FaceCrossing::Side (the ends tMin, tMax: 0).
struct Stop
{
  double T;
  double PC[3];
  bool HasPC;
  int Side;
};

/// True if o + t d is certainly outside the cell: outside the box of the face
/// nets (Bounds shrunk by half their NetMargin widening; the cell lies in the
/// nets' box). The ends of a clip to Bounds lie on its surface: outside.
bool OutsideNetBox(const CurvedCellFaces& faces, const double o[3], const double d[3], double t)
{
  const double half = 0.5 * FaceSearchSettings().NetMargin * faces.Extent;
  for (int k = 0; k < 3; ++k)
  {
    const double x = o[k] + t * d[k];
    if (x < faces.Bounds[2 * k] + half || x > faces.Bounds[2 * k + 1] - half)
    {
      return true;
    }
  }
  return false;
}

/**
 * Inside/outside of every gap from the crossings' sides alone (no inversion):
 * the sides must alternate and agree with the ends known to be outside; a gap
 * is inside iff the crossing at its start enters (the first gap: iff the first
 * crossing leaves). False if that cannot be decided (an undecided side, a
 * repeated side, no crossing with an end not known outside).
 */
bool GapsFromSides(const std::vector<Stop>& stops, bool startOutside, bool endOutside,
  std::vector<char>& inside)
{
  const size_t gaps = stops.size() - 1;
  inside.assign(gaps, 0);
  if (stops.size() == 2)
  {
    return startOutside || endOutside; // no crossing: all outside, if an end is
  }
  for (size_t i = 1; i + 1 < stops.size(); ++i)
  {
    if (stops[i].Side == 0 || (i > 1 && stops[i].Side != -stops[i - 1].Side))
    {
      return false;
    }
  }
  if ((startOutside && stops[1].Side != -1) || (endOutside && stops[gaps - 1].Side != 1))
  {
    return false;
  }
  inside[0] = stops[1].Side == 1;
  for (size_t g = 1; g < gaps; ++g)
  {
    inside[g] = stops[g].Side == -1;
  }
  return true;
}

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
  stops.push_back({ tMin, { 0, 0, 0 }, false, 0 });
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
      // One crossing seen from two patches (an edge): its side if they agree.
      if (stops.size() > 1 && stops.back().Side != c->Side)
      {
        stops.back().Side = 0;
      }
      continue;
    }
    Stop s{ c->T, { c->PC[0], c->PC[1], c->PC[2] }, true, c->Side };
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
    stops.push_back({ tMax, { 0, 0, 0 }, false, 0 });
  }
}
}

int RayCurvedCellIntervals(const LagrangeCellView& cell, const CurvedCellFaces& faces,
  const double origin[3], const double direction[3], double tMin, double tMax,
  CurvedRayInterval* out, int maxOut, const CurvedRaySettings& settings,
  CurvedRayStatus* status, std::vector<FaceCrossing>* scratch, const SharedFaceContext* shared)
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
  const int numFaces = static_cast<int>(faces.FaceFirstPatch.size()) - 1;
  if (shared && shared->Links && shared->Cache &&
    static_cast<int>(shared->Links->FaceIds.size()) == numFaces)
  {
    // Face by face: a face the neighbour has searched for this ray is taken
    // from the cache; a shared face searched here is stored for it.
    for (int k = 0; k < numFaces; ++k)
    {
      const int id = shared->Links->FaceIds[k];
      const double* frame = &shared->Links->Frames[9 * static_cast<size_t>(k)];
      bool complete = true;
      if (id >= 0 && shared->Cache->Take(id, shared->Cell, frame, crossings, complete))
      {
        search.Complete = search.Complete && complete;
        continue;
      }
      const size_t first = crossings.size();
      FaceSearchStatus one;
      for (int f = faces.FaceFirstPatch[k]; f < faces.FaceFirstPatch[k + 1]; ++f)
      {
        FaceRayCrossings(cell, faces, f, origin, direction, crossings, settings.Faces, &one);
      }
      search.Patches += one.Patches;
      search.Complete = search.Complete && one.Complete;
      if (id >= 0)
      {
        shared->Cache->Store(id, shared->Cell, frame, crossings, first, one.Complete);
      }
    }
  }
  else
  {
    for (int f = 0; f < static_cast<int>(faces.Faces.size()); ++f)
    {
      FaceRayCrossings(cell, faces, f, origin, direction, crossings, settings.Faces, &search);
    }
  }
  st.Patches = search.Patches;
  st.Complete = search.Complete;
  std::vector<Stop> stops;
  CollectStops(crossings, tMin, tMax, settings.MergeRelative * faces.Extent / dLen, stops, st);
  const size_t gaps = stops.size() - 1;
  // Inside/outside of each gap: from the crossings' sides if they decide it,
  // else by inverting the gap's midpoint (midPC then holds its coordinates).
  std::vector<char> inside;
  std::vector<double> midPC(3 * gaps, 0.0);
  double centre[3];
  cell.Basis->ParametricCenter(centre);
  const bool fromSides = GapsFromSides(stops, OutsideNetBox(faces, origin, direction, tMin),
    OutsideNetBox(faces, origin, direction, tMax), inside);
  for (size_t g = 0; g < gaps; ++g)
  {
    const Stop& a = stops[g];
    const Stop& b = stops[g + 1];
    double* pc = &midPC[3 * g];
    for (int k = 0; k < 3; ++k)
    {
      pc[k] = (a.HasPC && b.HasPC) ? 0.5 * (a.PC[k] + b.PC[k])
        : a.HasPC                  ? a.PC[k]
        : b.HasPC                  ? b.PC[k]
                                   : centre[k];
    }
    if (!fromSides)
    {
      inside[g] = b.T > a.T &&
        InsideAt(cell, faces, origin, direction, 0.5 * (a.T + b.T), pc, settings.InsideSlack,
          st.InversionFailures);
    }
  }
  int count = 0;
  bool open = false;
  for (size_t g = 0; g < gaps; ++g)
  {
    const Stop& a = stops[g];
    const Stop& b = stops[g + 1];
    if (!(b.T > a.T))
    {
      continue;
    }
    const double* pc = &midPC[3 * g];
    if (inside[g])
    {
      if (!open)
      {
        if (count >= maxOut)
        {
          break;
        }
        out[count].T0 = a.T;
        std::copy(a.HasPC ? a.PC : pc, (a.HasPC ? a.PC : pc) + 3, out[count].PC0);
        if (!a.HasPC)
        {
          // tMin inside: its coordinates by inversion, warm-started.
          InsideAt(cell, faces, origin, direction, a.T, out[count].PC0, 1.0, st.InversionFailures);
        }
        ++count;
      }
      out[count - 1].T1 = b.T;
      // The end's coordinates: the crossing's, else (tMax) inverted from the gap's guess.
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
    open = inside[g] != 0;
  }
  if (status)
  {
    *status = st;
  }
  return count;
}
}
