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

/// Cells not ordered by the DAG (bad, hidden), back to front by rearmost depth,
/// appended to @p order; returns the number of the others.
vtkIdType AppendUnordered(const Geometry& g, const View& v, std::vector<vtkIdType>& order)
{
  const vtkIdType n = g.NumberOfCells;
  std::vector<vtkIdType> first;
  for (vtkIdType c = 0; c < n; ++c)
  {
    if (!Ordered(v, c))
    {
      first.push_back(c);
    }
  }
  std::vector<float> keys(first.size());
  for (size_t i = 0; i < first.size(); ++i)
  {
    keys[i] = static_cast<float>(v.RearDepth(g, first[i]));
  }
  RadixSortDescending(first, keys);
  order.insert(order.end(), first.begin(), first.end());
  return n - static_cast<vtkIdType>(first.size());
}
}

/// Per interior face: +1 edge A -> B, -1 edge B -> A, 0 none, 2 undecided.
void GraphSort::FaceDirections(const Geometry& g, const Topology& t, const View& v)
{
  std::vector<std::int8_t>& dir = this->Directions;
  const ViewFrame& f = v.Frame;
  const double back[3] = { -f.Dop[0], -f.Dop[1], -f.Dop[2] };
  const double* x = f.Parallel ? back : f.Eye; // the eye, or the direction towards it
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
        side = t.PlaneA[i].Side(x, f.Parallel);
        if (side == 0) // not decided by the filter: the exact predicate
        {
          const vtkIdType* ids = t.TripleA.data() + 3 * i;
          const double *a = g.Point(ids[0]), *b = g.Point(ids[1]), *c = g.Point(ids[2]);
          side = f.Parallel ? hov::Orient3dDirection(a, b, c, x) : hov::Orient3d(a, b, c, x);
        }
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


/**
 * One cell's part of the DAG and of step 3: its outgoing face edges and
 * incoming face edge count (from @p dir), the roles of its faces in step 3
 * (boundary faces with the eye strictly inside: EXIT (1), strictly outside:
 * ENTRY (2), undecided: both (3); both sides of undecided interior faces: 3)
 * in @p roles (MaxFaces per cell).
 */
void GraphSort::CellPart(const Geometry& g, const Topology& t, const View& v, vtkIdType c,
  BlockCounts& counts)
{
  Digraph& d = this->Graph;
  const std::int8_t* dir = this->Directions.data();
  std::uint8_t* r = this->Roles.data() + MaxFaces * c;
  std::fill(r, r + MaxFaces, 0);
  d.FaceCount[c] = 0;
  d.InDegree[c] = 0;
  if (!Ordered(v, c))
  {
    return;
  }
  const std::uint8_t mask = t.BoundaryFaces[c];
  for (int f = 0; mask && f < MaxFaces; ++f)
  {
    if (mask & (1 << f))
    {
      const int side = EyeSide(g, v.Frame, c, f);
      r[f] = side == EyeInside ? 1 : side == EyeOutside ? 2 : side == EyeOn ? 0 : 3;
    }
  }
  const vtkIdType first = t.CellFaceOffsets[c], last = t.CellFaceOffsets[c + 1];
  const vtkIdType* faces = t.CellFaces.data();
  const vtkIdType* neighbours = t.CellNeighbours.data();
  vtkIdType* out = d.FaceTargets.data() + first;
  int numOut = 0, numIn = 0;
  for (vtkIdType e = first; e < last; ++e)
  {
    const vtkIdType i = faces[e] >> 1;
    const bool isB = (faces[e] & 1) != 0;
    const std::int8_t s = dir[i];
    // s == 1: A -> B, s == -1: B -> A (branch-free: the side is a coin flip).
    const int edge = s == 1 || s == -1;
    const int outgoing = edge & static_cast<int>((s == 1) != isB);
    out[numOut] = neighbours[e]; // kept only if outgoing (the slot exists: e < last)
    numOut += outgoing;
    numIn += edge - outgoing;
    if (s == 2)
    {
      const int f = isB ? MatchingFace(g, t.A[i], t.FaceA[i], c) : t.FaceA[i];
      if (f >= 0)
      {
        r[f] = 3;
      }
      counts.Undecided += !isB;
    }
  }
  d.FaceCount[c] = static_cast<std::uint8_t>(numOut);
  d.InDegree[c] = numIn;
  std::uint8_t cellRoles = 0;
  for (int f = 0; f < MaxFaces; ++f)
  {
    cellRoles |= r[f];
    counts.Faces += r[f] != 0;
  }
  counts.FaceEdges += numOut;
  counts.ExitCells += cellRoles & 1;
  counts.EntryCells += (cellRoles >> 1) & 1;
}

/**
 * Per cell, in parallel over fixed blocks of cells: the face edges of the DAG
 * (CellPart) and the faces of step 3 (see hovSteinBoundaryPairs.h), in cell
 * order whatever the number of threads.
 */
void GraphSort::CellPass(const Geometry& g, const Topology& t, const View& v, GraphStats& stats)
{
  const vtkIdType n = g.NumberOfCells;
  Digraph& d = this->Graph;
  d.FaceOffsets = t.CellFaceOffsets.data();
  d.FaceTargets.resize(t.CellFaces.size());
  d.FaceCount.resize(n);
  d.InDegree.resize(n);
  this->Roles.resize(MaxFaces * n); // every entry is written
  constexpr vtkIdType blockSize = 2048;
  const vtkIdType numBlocks = (n + blockSize - 1) / blockSize;
  std::vector<BlockCounts>& counts = this->Counts;
  counts.resize(numBlocks);
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      BlockCounts local; // not counts[blk]: neighbouring blocks share cache lines
      for (vtkIdType c = blk * blockSize; c < std::min(n, (blk + 1) * blockSize); ++c)
      {
        this->CellPart(g, t, v, c, local);
      }
      counts[blk] = local;
    }
  });
  std::vector<vtkIdType> first(numBlocks + 1, 0);
  for (vtkIdType blk = 0; blk < numBlocks; ++blk)
  {
    first[blk + 1] = first[blk] + counts[blk].Faces;
    stats.ExitCells += counts[blk].ExitCells;
    stats.EntryCells += counts[blk].EntryCells;
    stats.FaceEdges += counts[blk].FaceEdges;
    stats.Undecided += counts[blk].Undecided;
  }
  std::vector<ViewFace>& faces = this->Faces;
  faces.resize(first[numBlocks]);
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      ViewFace* out = faces.data() + first[blk];
      for (vtkIdType c = blk * blockSize; c < std::min(n, (blk + 1) * blockSize); ++c)
      {
        for (int f = 0; f < MaxFaces; ++f)
        {
          const std::uint8_t r = this->Roles[MaxFaces * c + f];
          if (r)
          {
            *out++ = { c, static_cast<std::uint8_t>(f), r };
          }
        }
      }
    }
  });
}

void GraphSort::Sort(const Geometry& g, const Topology& t, const View& v,
  std::vector<vtkIdType>& order, GraphStats& stats)
{
  const vtkIdType n = g.NumberOfCells;
  stats = GraphStats();
  order.clear();
  order.reserve(n + 1); // + 1: see TopologicalOrder
  const vtkIdType numOrdered = AppendUnordered(g, v, order);
  if (numOrdered == 0)
  {
    return;
  }
  this->FaceDirections(g, t, v);
  this->CellPass(g, t, v, stats);
  this->Extra.clear();
  PairStats pairStats;
  this->Boundary.Edges(g, v, this->Faces, this->Extra, pairStats);
  stats.Tests = pairStats.Tests;
  stats.FacePairs = pairStats.FacePairs;
  stats.ObstructEdges = static_cast<vtkIdType>(this->Extra.size());
  this->Graph.AddExtraEdges(this->Extra, n);
  TopologicalOrder(this->Graph, g, v, numOrdered, order, stats);
}
}
