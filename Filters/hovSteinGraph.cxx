// Visibility DAG of vtkSteinVisibilitySort's ADJACENCY_GRAPH algorithm (see hovSteinGraph.h).
#include "hovSteinGraph.h"

#include "hovGeometricPredicates.h" // exact Orient3d, Orient3dDirection
#include "hovSteinBoundaryPairs.h"  // BoundaryEdges
#include "hovSteinMerge.h"          // RadixSortDescending

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace hovStein
{
namespace
{
enum Side : std::int8_t
{
  EyeOutside = -1, ///< the eye strictly on the outer side of the face plane
  EyeOn = 0,
  EyeInside = 1,
  EyeUndecided = 2 ///< non-planar face with the eye near it, or degenerate face
};

inline double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/**
 * Side of the eye for a Newell face. The corners lie within the slab of
 * half-width dev around the plane; a warped face's local normals may tilt by
 * about dev/h (h its shortest edge). Decide only when the eye is off the slab
 * by more than that tilt over the eye's distance, with a factor of 2 to spare.
 */
int NewellSide(const Geometry& g, const ViewFrame& f, vtkIdType c, int face)
{
  const Plane& p = g.FacePlane(c, face);
  const Shape& s = GetShape(g.Kinds[c]);
  const vtkIdType* ids = g.CellCorners(c);
  double h = VTK_DOUBLE_MAX, centre[3] = { 0, 0, 0 };
  for (int i = 0; i < s.FaceSize[face]; ++i)
  {
    const double* a = g.Point(ids[s.Faces[face][i]]);
    const double* b = g.Point(ids[s.Faces[face][(i + 1) % s.FaceSize[face]]]);
    const double e[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    h = std::min(h, std::sqrt(Dot(e, e)));
    for (int k = 0; k < 3; ++k)
    {
      centre[k] += a[k] / s.FaceSize[face];
    }
  }
  if (!(h > 0))
  {
    return EyeUndecided;
  }
  const double tilt = 4 * p.Deviation / h;
  double value, margin;
  if (f.Parallel)
  {
    value = -Dot(p.N, f.Dop);
    margin = tilt;
  }
  else
  {
    const double r[3] = { centre[0] - f.Eye[0], centre[1] - f.Eye[1], centre[2] - f.Eye[2] };
    value = Dot(p.N, f.Eye) + p.D;
    margin = 2 * p.Deviation + tilt * std::sqrt(Dot(r, r));
  }
  return value > margin ? EyeOutside : (value < -margin ? EyeInside : EyeUndecided);
}

/// Side of the eye with respect to face @p face of cell @p c (see Side).
int EyeSide(const Geometry& g, const ViewFrame& f, vtkIdType c, int face)
{
  const int mode = g.FaceCode(c, face) & 3;
  if (mode == FaceExact)
  {
    vtkIdType t[3];
    g.ExactTriple(c, face, t);
    const double back[3] = { -f.Dop[0], -f.Dop[1], -f.Dop[2] };
    const double *a = g.Point(t[0]), *b = g.Point(t[1]), *cc = g.Point(t[2]);
    return f.Parallel ? hov::Orient3dDirection(a, b, cc, back) : hov::Orient3d(a, b, cc, f.Eye);
  }
  return mode == FaceNewell ? NewellSide(g, f, c, face) : EyeUndecided;
}

inline bool Ordered(const View& v, vtkIdType c)
{
  return v.Status[c] == StatusVisible || v.Status[c] == StatusStraddle;
}

/// Per interior face: +1 edge A -> B, -1 edge B -> A, 0 none, 2 undecided.
void FaceDirections(const Geometry& g, const Topology& t, const View& v, std::vector<std::int8_t>& dir)
{
  const vtkIdType m = t.NumberOfInteriorFaces();
  dir.resize(m);
  vtkSMPTools::For(0, m, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      if (!Ordered(v, t.A[i]) || !Ordered(v, t.B[i]))
      {
        dir[i] = 0;
        continue;
      }
      // EyeSide(g, v.Frame, t.A[i], t.FaceA[i]), exact faces from the topology's record.
      int side;
      if (t.ModeA[i] == FaceExact)
      {
        const vtkIdType* ids = t.TripleA.data() + 3 * i;
        const double *a = g.Point(ids[0]), *b = g.Point(ids[1]), *c = g.Point(ids[2]);
        const ViewFrame& f = v.Frame;
        const double back[3] = { -f.Dop[0], -f.Dop[1], -f.Dop[2] };
        side = f.Parallel ? hov::Orient3dDirection(a, b, c, back) : hov::Orient3d(a, b, c, f.Eye);
      }
      else
      {
        side = EyeSide(g, v.Frame, t.A[i], t.FaceA[i]);
      }
      // Eye on B's side (outside A's face): B is nearer, A comes first.
      dir[i] = static_cast<std::int8_t>(side == EyeOutside ? 1 : side == EyeInside ? -1 : side == EyeOn ? 0 : 2);
    }
  });
}

/// Face @p of cell @p c whose corners are those of face @p fa of cell @p a, or -1.
int MatchingFace(const Geometry& g, vtkIdType a, int fa, vtkIdType c)
{
  vtkIdType ia[4], ic[4];
  const int na = g.OrientedFace(a, fa, ia);
  std::sort(ia, ia + na);
  const Shape& s = GetShape(g.Kinds[c]);
  for (int f = 0; f < s.NumFaces; ++f)
  {
    if (s.FaceSize[f] == na)
    {
      g.OrientedFace(c, f, ic);
      std::sort(ic, ic + na);
      if (std::equal(ia, ia + na, ic))
      {
        return f;
      }
    }
  }
  return -1;
}

/**
 * The faces of step 3 (see hovSteinBoundaryPairs.h): boundary faces of
 * ordered cells with the eye strictly inside (EXIT), strictly outside (ENTRY)
 * or undecided (both), and both sides of undecided interior faces.
 */
void ViewFaces(const Geometry& g, const Topology& t, const View& v, const std::vector<std::int8_t>& dir,
  std::vector<ViewFace>& faces, GraphStats& stats)
{
  const vtkIdType n = g.NumberOfCells;
  std::vector<std::uint8_t> roles(MaxFaces * n, 0);
  vtkSMPTools::For(0, n, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType c = begin; c < end; ++c)
    {
      const std::uint8_t mask = t.BoundaryFaces[c];
      if (!mask || !Ordered(v, c))
      {
        continue;
      }
      for (int f = 0; f < MaxFaces; ++f)
      {
        if (mask & (1 << f))
        {
          const int side = EyeSide(g, v.Frame, c, f);
          roles[MaxFaces * c + f] = side == EyeInside ? 1 : side == EyeOutside ? 2 : side == EyeOn ? 0 : 3;
        }
      }
    }
  });
  for (size_t i = 0; i < dir.size(); ++i)
  {
    if (dir[i] == 2)
    {
      roles[MaxFaces * t.A[i] + t.FaceA[i]] = 3;
      const int fb = MatchingFace(g, t.A[i], t.FaceA[i], t.B[i]);
      if (fb >= 0)
      {
        roles[MaxFaces * t.B[i] + fb] = 3;
      }
    }
  }
  for (vtkIdType c = 0; c < n; ++c)
  {
    std::uint8_t cellRoles = 0;
    for (int f = 0; f < MaxFaces; ++f)
    {
      const std::uint8_t r = roles[MaxFaces * c + f];
      if (r)
      {
        faces.push_back({ c, static_cast<std::uint8_t>(f), r });
        cellRoles |= r;
      }
    }
    stats.ExitCells += cellRoles & 1;
    stats.EntryCells += (cellRoles >> 1) & 1;
  }
}
}

namespace
{
/// Compressed adjacency of the face edges and the Obstructs() edges.
void BuildDigraph(const Topology& t, const std::vector<std::int8_t>& dir,
  const std::vector<std::pair<vtkIdType, vtkIdType>>& extra, vtkIdType n, Digraph& d)
{
  d.Offsets.assign(n + 1, 0);
  const vtkIdType m = t.NumberOfInteriorFaces();
  for (vtkIdType i = 0; i < m; ++i)
  {
    if (dir[i] == 1 || dir[i] == -1)
    {
      ++d.Offsets[(dir[i] == 1 ? t.A[i] : t.B[i]) + 1];
    }
  }
  for (const auto& e : extra)
  {
    ++d.Offsets[e.first + 1];
  }
  for (vtkIdType c = 0; c < n; ++c)
  {
    d.Offsets[c + 1] += d.Offsets[c];
  }
  d.Targets.resize(d.Offsets[n]);
  std::vector<vtkIdType> cursor(d.Offsets.begin(), d.Offsets.end() - 1);
  for (vtkIdType i = 0; i < m; ++i)
  {
    if (dir[i] == 1)
    {
      d.Targets[cursor[t.A[i]]++] = t.B[i];
    }
    else if (dir[i] == -1)
    {
      d.Targets[cursor[t.B[i]]++] = t.A[i];
    }
  }
  for (const auto& e : extra)
  {
    d.Targets[cursor[e.first]++] = e.second;
  }
}

/// Cells split into ordered ones (by id) and the others (back to front by rearmost depth).
void SplitCells(const View& v, vtkIdType n, std::vector<vtkIdType>& first, std::vector<vtkIdType>& rough)
{
  for (vtkIdType c = 0; c < n; ++c)
  {
    (Ordered(v, c) ? rough : first).push_back(c);
  }
  std::vector<float> keys(first.size());
  for (size_t i = 0; i < first.size(); ++i)
  {
    keys[i] = static_cast<float>(v.Rear[first[i]]);
  }
  RadixSortDescending(first, keys);
}
}

void SortByGraph(const Geometry& g, const Topology& t, const View& v,
  std::vector<vtkIdType>& order, GraphStats& stats)
{
  const vtkIdType n = g.NumberOfCells;
  stats = GraphStats();
  order.clear();
  order.reserve(n);
  std::vector<vtkIdType> first, rough;
  SplitCells(v, n, first, rough);
  order.insert(order.end(), first.begin(), first.end());
  if (rough.empty())
  {
    return;
  }
  std::vector<std::int8_t> dir;
  FaceDirections(g, t, v, dir);
  std::vector<ViewFace> faces;
  ViewFaces(g, t, v, dir, faces, stats);
  std::vector<std::pair<vtkIdType, vtkIdType>> extra;
  PairStats pairStats;
  BoundaryEdges(g, v, faces, extra, pairStats);
  stats.Tests = pairStats.Tests;
  stats.FacePairs = pairStats.FacePairs;
  for (std::int8_t s : dir)
  {
    stats.FaceEdges += s == 1 || s == -1;
    stats.Undecided += s == 2;
  }
  stats.ObstructEdges = static_cast<vtkIdType>(extra.size());
  Digraph d;
  BuildDigraph(t, dir, extra, n, d);
  TopologicalOrder(d, rough, v.Rear, order, stats);
}
}
