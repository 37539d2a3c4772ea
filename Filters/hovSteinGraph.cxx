// Visibility DAG of vtkSteinVisibilitySort's ADJACENCY_GRAPH algorithm (see hovSteinGraph.h).
#include "hovSteinGraph.h"

#include "hovSteinBoundaryPairs.h"  // BoundaryPairs
#include "hovSteinBuckets.h"        // ParallelSelect
#include "hovSteinBuffers.h"        // FillBuffer
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
    return f.TriangleSide(g.Point(t[0]), g.Point(t[1]), g.Point(t[2]));
  }
  return mode == FaceNewell ? NewellSide(g, f, c, face) : EyeUndecided;
}

/**
 * EyeSide of the exact face @p face of cell @p c with the exact predicate;
 * also sets @p plane (if not null) to the face's filtered plane.
 */
int ExactSide(const Geometry& g, const ViewFrame& f, vtkIdType c, int face, FilteredPlane* plane)
{
  vtkIdType ids[3];
  g.ExactTriple(c, face, ids);
  const double *a = g.Point(ids[0]), *b = g.Point(ids[1]), *cc = g.Point(ids[2]);
  if (plane)
  {
    plane->Set(a, b, cc);
  }
  return f.TriangleSide(a, b, cc);
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
  ParallelSelect(n, [&v](vtkIdType c) { return !Ordered(v, c); }, first);
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
  FillBuffer<std::int8_t>& dir = this->Directions;
  const ViewFrame& f = v.Frame;
  const vtkIdType m = t.NumberOfInteriorFaces();
  dir.resize(m);
  const bool allOrdered = v.AllOrdered; // skips two random reads per face
  const std::uint32_t* triples = t.TripleA.empty() ? nullptr : t.TripleA.data();
  vtkSMPTools::For(0, m, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      if (!allOrdered && (!Ordered(v, t.A[i]) || !Ordered(v, t.B[i])))
      {
        dir[i] = 0;
        continue;
      }
      // EyeSide(g, f, t.A[i], t.FaceA[i]); exact faces from the topology's triple.
      const std::uint32_t* triple = triples ? triples + 3 * i : nullptr;
      int side;
      if (triple && triple[0] != Topology::NoTriple)
      {
        side = f.TriangleSide(g.Point(triple[0]), g.Point(triple[1]), g.Point(triple[2]));
      }
      else
      {
        side = EyeSide(g, f, t.A[i], t.FaceA[i]);
      }
      // Eye on B's side (outside A's face, EyeOutside = -1): B is nearer, A
      // comes first (1); EyeInside (1): -1; EyeOn: 0 (no branch on the side).
      dir[i] = static_cast<std::int8_t>(side == EyeUndecided ? 2 : -side);
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
namespace
{
/// Role in step 2 of a face with the eye on @p side: EXIT 1, ENTRY 2, both 3, none 0.
inline std::uint8_t Role(int side)
{
  return side == EyeInside ? 1 : side == EyeOutside ? 2 : side == EyeOn ? 0 : 3;
}

constexpr vtkIdType BoundaryBlock = 4096; ///< boundary faces per block
constexpr vtkIdType CellBlock = 2048;     ///< cells per block
}

/**
 * The role of every boundary face (0 for cells not ordered), exact faces from
 * their filtered planes, in parallel over fixed blocks; per block the number
 * of faces with a role (RoleStart, then made a prefix sum).
 */
void GraphSort::BoundaryRoles(const Geometry& g, const Topology& t, const View& v, bool buildPlanes)
{
  const vtkIdType nb = static_cast<vtkIdType>(t.Boundary.size());
  if (buildPlanes)
  {
    // A fresh block (default-initialised; huge-page advice as FillBuffer's).
    FillBuffer<FilteredPlane>(nb).swap(this->BoundaryPlanes);
  }
  const vtkIdType numBlocks = (nb + BoundaryBlock - 1) / BoundaryBlock;
  this->Roles.resize(nb);
  this->RoleStart.assign(numBlocks + 1, 0);
  const ViewFrame& f = v.Frame;
  const double back[3] = { -f.Dop[0], -f.Dop[1], -f.Dop[2] };
  const double* x = f.Parallel ? back : f.Eye; // the eye, or the direction towards it
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      vtkIdType count = 0;
      for (vtkIdType k = blk * BoundaryBlock; k < std::min(nb, (blk + 1) * BoundaryBlock); ++k)
      {
        const Topology::BoundaryFace& bf = t.Boundary[k];
        std::uint8_t role = 0;
        if (bf.Mode == FaceExact && buildPlanes)
        {
          // Every exact face's plane, also of cells not ordered in this view.
          const int side = ExactSide(g, f, bf.Cell, bf.Face, &this->BoundaryPlanes[k]);
          role = Ordered(v, bf.Cell) ? Role(side) : 0;
        }
        else if (Ordered(v, bf.Cell))
        {
          int side = bf.Mode == FaceExact ? this->BoundaryPlanes[k].Side(x, f.Parallel) : 0;
          if (side == 0) // not decided by the filter, or not an exact face
          {
            side = EyeSide(g, f, bf.Cell, bf.Face);
          }
          role = Role(side);
        }
        this->Roles[k] = role;
        count += role != 0;
      }
      this->RoleStart[blk + 1] = count;
    }
  });
  for (vtkIdType blk = 0; blk < numBlocks; ++blk)
  {
    this->RoleStart[blk + 1] += this->RoleStart[blk];
  }
}

/**
 * One cell's part of the DAG: its outgoing face edges and incoming face edge
 * count (from Directions); both sides of its undecided interior faces go to
 * @p undecided (role 3).
 */
void GraphSort::CellPart(const Geometry& g, const Topology& t, const View& v, vtkIdType c,
  BlockCounts& counts, std::vector<ViewFace>& undecided)
{
  Digraph& d = this->Graph;
  const std::int8_t* dir = this->Directions.data();
  d.FaceCount[c] = 0;
  d.InDegree[c] = 0;
  if (!Ordered(v, c))
  {
    return;
  }
  const vtkIdType first = t.CellFaceOffsets[c], last = t.CellFaceOffsets[c + 1];
  const std::uint32_t* faces = t.CellFaces.data();
  const CellIndex* neighbours = t.CellNeighbours.data();
  CellIndex* out = d.FaceTargets.data() + first;
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
        undecided.push_back({ c, static_cast<std::uint8_t>(f), 3, -1 });
      }
      counts.Undecided += !isB;
    }
  }
  d.FaceCount[c] = static_cast<std::uint8_t>(numOut);
  d.InDegree[c] = numIn;
  counts.FaceEdges += numOut;
}

/**
 * In parallel over fixed blocks of cells: the roles of the boundary faces,
 * the face edges of the DAG (CellPart), then the faces of step 3 (see
 * hovSteinBoundaryPairs.h) in cell order whatever the number of threads.
 */
void GraphSort::CellPass(const Geometry& g, const Topology& t, const View& v, GraphStats& stats)
{
  this->BoundaryRoles(g, t, v, this->PlanesGeneration != t.Generation);
  const vtkIdType n = g.NumberOfCells;
  Digraph& d = this->Graph;
  d.FaceOffsets = t.CellFaceOffsets.data();
  d.FaceTargets.resize(t.CellFaces.size());
  d.FaceCount.resize(n);
  d.InDegree.resize(n);
  const vtkIdType numBlocks = (n + CellBlock - 1) / CellBlock;
  this->Counts.resize(numBlocks);
  this->Undecided.resize(numBlocks);
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      // Locals, not Counts[blk] / Undecided[blk]: neighbouring blocks share cache lines.
      BlockCounts local;
      std::vector<ViewFace> undecided;
      undecided.swap(this->Undecided[blk]); // its capacity
      undecided.clear();
      for (vtkIdType c = blk * CellBlock; c < std::min(n, (blk + 1) * CellBlock); ++c)
      {
        this->CellPart(g, t, v, c, local, undecided);
      }
      this->Counts[blk] = local;
      this->Undecided[blk].swap(undecided);
    }
  });
  for (const BlockCounts& counts : this->Counts)
  {
    stats.FaceEdges += counts.FaceEdges;
    stats.Undecided += counts.Undecided;
  }
  this->CollectFaces(t, stats);
}

/**
 * The faces of step 3: the boundary faces with a role, compacted in parallel,
 * and (rarely) the undecided interior faces merged in by (cell, face); the
 * counts of cells with EXIT and ENTRY faces.
 */
void GraphSort::CollectFaces(const Topology& t, GraphStats& stats)
{
  std::vector<ViewFace>& faces = this->Faces;
  const vtkIdType nb = static_cast<vtkIdType>(t.Boundary.size());
  const vtkIdType numBlocks = static_cast<vtkIdType>(this->RoleStart.size()) - 1;
  faces.resize(this->RoleStart[numBlocks]);
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      ViewFace* out = faces.data() + this->RoleStart[blk];
      for (vtkIdType k = blk * BoundaryBlock; k < std::min(nb, (blk + 1) * BoundaryBlock); ++k)
      {
        if (this->Roles[k])
        {
          *out++ = { t.Boundary[k].Cell, t.Boundary[k].Face, this->Roles[k],
            k < INT32_MAX ? static_cast<std::int32_t>(k) : -1 };
        }
      }
    }
  });
  if (stats.Undecided > 0)
  {
    for (const std::vector<ViewFace>& marks : this->Undecided)
    {
      faces.insert(faces.end(), marks.begin(), marks.end());
    }
    std::sort(faces.begin(), faces.end(), [](const ViewFace& a, const ViewFace& b) {
      return a.Cell < b.Cell || (a.Cell == b.Cell && a.Face < b.Face);
    });
  }
  std::uint8_t cellRoles = 0;
  for (size_t k = 0; k < faces.size(); ++k)
  {
    cellRoles |= faces[k].Roles;
    if (k + 1 == faces.size() || faces[k + 1].Cell != faces[k].Cell)
    {
      stats.ExitCells += cellRoles & 1;
      stats.EntryCells += (cellRoles >> 1) & 1;
      cellRoles = 0;
    }
  }
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
    if (this->Boundary.DroppedLog)
    {
      this->Boundary.DroppedLog->clear(); // this view's: none
    }
    this->Graph.ExtraOffsets.clear(); // nor edges (GetObstructEdges)
    this->Graph.ExtraTargets.clear();
    return;
  }
  this->FaceDirections(g, t, v);
  this->CellPass(g, t, v, stats);
  this->PlanesGeneration = t.Generation; // the boundary faces' planes are made
  PairStats pairStats;
  Digraph& d = this->Graph;
  this->Boundary.Edges(g, t, v, this->Faces, d.ExtraOffsets, d.ExtraTargets, pairStats);
  stats.Tests = pairStats.Tests;
  stats.FacePairs = pairStats.FacePairs;
  stats.DroppedFacePairs = pairStats.DroppedFacePairs;
  stats.KeptFacePairs = pairStats.KeptFacePairs;
  stats.ObstructEdges = static_cast<vtkIdType>(d.ExtraTargets.size());
  for (const vtkIdType target : d.ExtraTargets)
  {
    ++d.InDegree[target];
  }
  TopologicalOrder(d, g, v, numOrdered, order, stats);
}

std::vector<std::pair<vtkIdType, vtkIdType>> GraphSort::GetObstructEdges() const
{
  std::vector<std::pair<vtkIdType, vtkIdType>> edges;
  const Digraph& d = this->Graph;
  for (size_t c = 0; c + 1 < d.ExtraOffsets.size(); ++c)
  {
    for (vtkIdType e = d.ExtraOffsets[c]; e < d.ExtraOffsets[c + 1]; ++e)
    {
      edges.emplace_back(static_cast<vtkIdType>(c), d.ExtraTargets[e]);
    }
  }
  return edges;
}

void GraphSort::ReleaseBuffers()
{
  // Swapped with empty vectors: clear() would keep the capacity.
  FillBuffer<std::int8_t>().swap(this->Directions);
  std::vector<std::uint8_t>().swap(this->Roles);
  std::vector<vtkIdType>().swap(this->RoleStart);
  std::vector<BlockCounts>().swap(this->Counts);
  std::vector<std::vector<ViewFace>>().swap(this->Undecided);
  std::vector<ViewFace>().swap(this->Faces);
  this->Graph = Digraph();
  this->Boundary.ReleaseBuffers();
}
}
