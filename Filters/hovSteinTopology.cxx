// Face adjacency of vtkSteinVisibilitySort (see hovSteinTopology.h).
#include "hovSteinTopology.h"

#include "hovGeometricPredicates.h" // exact Orient3d
#include "hovSteinBuckets.h"         // ParallelAppend, ParallelBuckets, FillBuffer

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <atomic> // the build generations

namespace hovStein
{
/// What MatchFaces finds in a chunk of buckets (bucket order): its interior
/// faces are written to the topology's arrays from First on (a bound: half the
/// chunk's entries), its boundary entries (c * 8 + f) are listed.
struct ChunkMatches
{
  vtkIdType First = 0, Count = 0;
  std::vector<vtkIdType> Boundary;
};

namespace
{
/// The number of bits set in @p mask (a cell's boundary faces).
inline int BitCount(std::uint8_t mask)
{
  int count = 0;
  for (; mask; mask &= mask - 1)
  {
    ++count;
  }
  return count;
}

/// Sorted corner ids of face f of cell c (triangles padded with -1 at the end).
std::array<vtkIdType, 4> FaceKey(const Geometry& g, vtkIdType c, int f)
{
  const Shape& s = GetShape(g.Kinds[c]);
  const vtkIdType* corners = g.CellCorners(c);
  std::array<vtkIdType, 4> k = { -1, -1, -1, -1 };
  const int m = s.FaceSize[f];
  for (int i = 0; i < m; ++i)
  {
    k[i] = corners[s.Faces[f][i]];
  }
  auto order = [&](int i, int j) {
    if (k[j] < k[i])
    {
      std::swap(k[i], k[j]);
    }
  };
  if (m == 3)
  {
    order(0, 1);
    order(1, 2);
    order(0, 1);
  }
  else
  {
    order(0, 1);
    order(2, 3);
    order(0, 2);
    order(1, 3);
    order(1, 2);
  }
  return k;
}

/**
 * True when every corner of cell @p other lies on the closed outer side of
 * face f of cell c (sorted corner ids @p key: FaceKey), one strictly (Newell
 * faces: all corners off the face strictly outside the deviation slab). Cell
 * c lies on the inner side by construction, so the plane separates the two
 * cells.
 */
bool OtherOutside(
  const Geometry& g, vtkIdType c, int f, vtkIdType other, const std::array<vtkIdType, 4>& key)
{
  const std::uint8_t mode = g.FaceCode(c, f) & 3;
  const int n = g.NumberOfCorners(other);
  const vtkIdType* ids = g.CellCorners(other);
  bool strict = false;
  if (mode == FaceExact)
  {
    vtkIdType t[3];
    g.ExactTriple(c, f, t);
    for (int i = 0; i < n; ++i)
    {
      if (std::find(key.begin(), key.end(), ids[i]) != key.end())
      {
        continue; // on the face (exactly coplanar): no test needed
      }
      const int s = hov::Orient3d(g.Point(t[0]), g.Point(t[1]), g.Point(t[2]), g.Point(ids[i]));
      if (s > 0)
      {
        return false; // inside A's face: not a proper neighbour
      }
      strict = strict || s < 0;
    }
    return strict;
  }
  if (mode != FaceNewell)
  {
    return false;
  }
  const Plane& p = g.FacePlane(c, f);
  for (int i = 0; i < n; ++i)
  {
    if (std::find(key.begin(), key.end(), ids[i]) != key.end())
    {
      continue;
    }
    const double* x = g.Point(ids[i]);
    if (!(p.N[0] * x[0] + p.N[1] * x[1] + p.N[2] * x[2] + p.D > p.Deviation))
    {
      return false;
    }
  }
  return true;
}

/**
 * A face in its bucket (whose point id is the face's smallest corner id): its
 * other corner ids plus one, sorted (a triangle's third is 0: FaceKey's -1,
 * first in either width), and its entry c * 8 + f, so that matching reads the
 * bucket alone, not the cells' tables at random. Id: 32 bits where the point
 * ids and entries fit (16 bytes a face), else vtkIdType (32 bytes a face:
 * beyond 4G points or 512M cells only).
 */
template <typename Id>
struct FaceEntry
{
  Id K[3]; ///< FaceKey()[1..3] + 1
  Id Entry;
  bool operator<(const FaceEntry& o) const
  {
    return this->K[0] != o.K[0] ? this->K[0] < o.K[0]
      : this->K[1] != o.K[1]    ? this->K[1] < o.K[1]
      : this->K[2] != o.K[2]    ? this->K[2] < o.K[2]
                                : this->Entry < o.Entry;
  }
  bool SameFace(const FaceEntry& o) const
  {
    return this->K[0] == o.K[0] && this->K[1] == o.K[1] && this->K[2] == o.K[2];
  }
  vtkIdType Cell() const { return static_cast<vtkIdType>(this->Entry >> 3); }
  int Face() const { return static_cast<int>(this->Entry & 7); }
};

/// Whether FaceEntry<std::uint32_t> holds every point id + 1 and entry.
bool NarrowEntries(const Geometry& g)
{
  const vtkIdType numPoints = static_cast<vtkIdType>(g.Points.size() / 3);
  return numPoints < 0xffffffffLL && g.NumberOfCells <= 0x1fffffffLL;
}

/**
 * Matches the faces of bucket @p p (entries @p e, @p m of them; sorted here):
 * writes the interior faces to @p t's arrays at out.First + out.Count on, and
 * lists the boundary entries.
 */
template <typename Id>
void MatchBucket(const Geometry& g, vtkIdType p, FaceEntry<Id>* e, vtkIdType m, Topology& t,
  ChunkMatches& out)
{
  std::sort(e, e + m);
  for (vtkIdType i = 0; i < m;)
  {
    vtkIdType j = i + 1;
    while (j < m && e[j].SameFace(e[i]))
    {
      ++j;
    }
    bool interior = false;
    if (j == i + 2)
    {
      const vtkIdType a = e[i].Cell(), b = e[i + 1].Cell();
      const int fa = e[i].Face(), fb = e[i + 1].Face();
      const std::uint8_t mode = g.FaceCode(a, fa) & 3;
      std::array<vtkIdType, 4> key = { p, -1, -1, -1 };
      for (int k = 0; k < 3; ++k)
      {
        key[k + 1] = static_cast<vtkIdType>(e[i].K[k]) - 1;
      }
      interior = a != b && mode != FaceSkip && (g.FaceCode(b, fb) & 3) != FaceSkip &&
        OtherOutside(g, a, fa, b, key);
      if (interior)
      {
        const vtkIdType k = out.First + out.Count++;
        t.A[k] = static_cast<CellIndex>(a);
        t.B[k] = static_cast<CellIndex>(b);
        t.FaceA[k] = static_cast<std::uint8_t>(fa);
        if (!t.TripleA.empty())
        {
          std::uint32_t* triple = t.TripleA.data() + 3 * k;
          triple[0] = Topology::NoTriple;
          triple[1] = triple[2] = 0;
          if (mode == FaceExact)
          {
            vtkIdType ids[3];
            g.ExactTriple(a, fa, ids);
            for (int q = 0; q < 3; ++q)
            {
              triple[q] = static_cast<std::uint32_t>(ids[q]);
            }
          }
        }
      }
    }
    for (vtkIdType k = i; !interior && k < j; ++k)
    {
      out.Boundary.push_back(static_cast<vtkIdType>(e[k].Entry));
    }
    i = j;
  }
}

/// The smallest corner id of face f of cell c (FaceKey(g, c, f)[0]).
vtkIdType SmallestCorner(const Geometry& g, vtkIdType c, int f)
{
  const Shape& s = GetShape(g.Kinds[c]);
  const vtkIdType* corners = g.CellCorners(c);
  vtkIdType k = corners[s.Faces[f][0]];
  for (int i = 1; i < s.FaceSize[f]; ++i)
  {
    k = std::min(k, corners[s.Faces[f][i]]);
  }
  return k;
}

/**
 * The faces of the supported cells (FaceEntry: entries c * 8 + f and their
 * keys) bucketed by their smallest corner id (ParallelBuckets): bucket p is
 * entries[start[p], start[p + 1]), in increasing entry order.
 */
template <typename Id>
void BucketFaces(
  const Geometry& g, std::vector<vtkIdType>& start, FillBuffer<FaceEntry<Id>>& entries)
{
  const vtkIdType numPoints = static_cast<vtkIdType>(g.Points.size() / 3);
  auto items = [&g](vtkIdType begin, vtkIdType end, auto&& emit) {
    for (vtkIdType c = begin; c < end; ++c)
    {
      const int numFaces = g.Kinds[c] == KindBad ? 0 : GetShape(g.Kinds[c]).NumFaces;
      for (int f = 0; f < numFaces; ++f)
      {
        emit(SmallestCorner(g, c, f), [&g, c, f]() {
          const std::array<vtkIdType, 4> k = FaceKey(g, c, f); // k[0] is the bucket
          return FaceEntry<Id>{ { static_cast<Id>(k[1] + 1), static_cast<Id>(k[2] + 1),
                                  static_cast<Id>(k[3] + 1) },
            static_cast<Id>(c * 8 + f) };
        });
      }
    }
  };
  ParallelBuckets(g.NumberOfCells, numPoints, items, start, entries);
}

/**
 * MatchBucket on every bucket, in parallel over chunks of about equal numbers
 * of faces (low point ids hold more faces: a face goes to its smallest id);
 * sizes @p t's interior face arrays for the bound.
 */
template <typename Id>
void MatchFaces(const Geometry& g, const std::vector<vtkIdType>& start,
  FillBuffer<FaceEntry<Id>>& entries, Topology& t, std::vector<ChunkMatches>& chunks)
{
  const vtkIdType numPoints = static_cast<vtkIdType>(start.size()) - 1;
  const vtkIdType numChunks = std::max<vtkIdType>(1, std::min<vtkIdType>(256, numPoints));
  std::vector<vtkIdType> chunk(numChunks + 1);
  for (vtkIdType k = 0; k <= numChunks; ++k)
  {
    chunk[k] = std::lower_bound(start.begin(), start.end(), k * start[numPoints] / numChunks) -
      start.begin();
  }
  chunk[numChunks] = numPoints;
  chunks.assign(numChunks, ChunkMatches());
  vtkIdType bound = 0;
  for (vtkIdType k = 0; k < numChunks; ++k)
  {
    chunks[k].First = bound;
    bound += (start[chunk[k + 1]] - start[chunk[k]]) / 2;
  }
  t.A.resize(bound);
  t.B.resize(bound);
  t.FaceA.resize(bound);
  // Point ids as uint32 (NoTriple reserved), else no triples (EyeSide instead).
  t.TripleA.resize(numPoints < static_cast<vtkIdType>(Topology::NoTriple) ? 3 * bound : 0);
  vtkSMPTools::For(0, numChunks, 1, [&](vtkIdType k0, vtkIdType k1) {
    for (vtkIdType k = k0; k < k1; ++k)
    {
      ChunkMatches found = chunks[k]; // local: chunks[k] shares cache lines with its neighbours
      for (vtkIdType p = chunk[k]; p < chunk[k + 1]; ++p)
      {
        MatchBucket(g, p, entries.data() + start[p], start[p + 1] - start[p], t, found);
      }
      chunks[k] = std::move(found);
    }
  });
}
}

void Topology::Build(const Geometry& g, bool wideEntries)
{
  std::vector<ChunkMatches> chunks;
  auto match = [&](auto id) {
    using Id = decltype(id);
    std::vector<vtkIdType> start;
    FillBuffer<FaceEntry<Id>> entries;
    BucketFaces(g, start, entries);
    MatchFaces(g, start, entries, *this, chunks);
  };
  if (!wideEntries && NarrowEntries(g))
  {
    match(std::uint32_t());
  }
  else
  {
    match(vtkIdType());
  }
  this->Collect(g, chunks);
  this->BuildCellFaces(g);
  this->BuildBoundary(g);
  static std::atomic<unsigned long> generations(0);
  this->Generation = ++generations;
}

void Topology::Collect(const Geometry& g, const std::vector<ChunkMatches>& chunks)
{
  // Close the gaps between the chunks' interior faces (in chunk order: a
  // chunk moves down, never over a chunk not yet moved), one array per task.
  auto close = [&chunks](auto& values, vtkIdType width) {
    vtkIdType m = 0;
    for (const ChunkMatches& chunk : chunks)
    {
      if (chunk.First != m)
      {
        const auto from = values.begin() + width * chunk.First;
        std::copy(from, from + width * chunk.Count, values.begin() + width * m);
      }
      m += chunk.Count;
    }
    values.resize(values.empty() ? 0 : width * m);
  };
  vtkSMPTools::For(0, 4, 1, [&](vtkIdType t0, vtkIdType t1) {
    for (vtkIdType task = t0; task < t1; ++task)
    {
      switch (task)
      {
        case 0:
          close(this->A, 1);
          break;
        case 1:
          close(this->B, 1);
          break;
        case 2:
          close(this->FaceA, 1);
          break;
        default:
          close(this->TripleA, 3);
      }
    }
  });
  const vtkIdType n = g.NumberOfCells;
  this->BoundaryFaces.assign(n, 0);
  for (const ChunkMatches& chunk : chunks)
  {
    for (vtkIdType e : chunk.Boundary)
    {
      this->BoundaryFaces[e >> 3] |= static_cast<std::uint8_t>(1 << (e & 7));
    }
  }
}

void Topology::BuildCellFaces(const Geometry& g)
{
  // A supported cell's faces are all interior or boundary faces: its count
  // needs no pass over the faces.
  const vtkIdType n = g.NumberOfCells;
  const vtkIdType m = this->NumberOfInteriorFaces();
  this->CellFaceOffsets.resize(n + 1);
  this->CellFaceOffsets[0] = 0;
  vtkSMPTools::For(0, n, 16384, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType c = begin; c < end; ++c)
    {
      const int faces = g.Kinds[c] == KindBad ? 0 : GetShape(g.Kinds[c]).NumFaces;
      this->CellFaceOffsets[c + 1] = faces - BitCount(this->BoundaryFaces[c]);
    }
  });
  ParallelRunningSum(this->CellFaceOffsets.data(), n);
  // In parallel over bands of cells: each band scans all faces and fills its
  // own cells' lists, in increasing face order whatever the number of bands.
  this->CellFaces.resize(2 * m);
  this->CellNeighbours.resize(2 * m);
  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  const vtkIdType numBands = std::min<vtkIdType>(std::max(threads, 1), std::max<vtkIdType>(n, 1));
  vtkSMPTools::For(0, numBands, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType band = b0; band < b1; ++band)
    {
      const vtkIdType first = band * n / numBands, last = (band + 1) * n / numBands;
      std::vector<vtkIdType> cursor(
        this->CellFaceOffsets.begin() + first, this->CellFaceOffsets.begin() + last);
      for (vtkIdType i = 0; i < m; ++i)
      {
        const vtkIdType a = this->A[i], b = this->B[i];
        if (a >= first && a < last)
        {
          const vtkIdType e = cursor[a - first]++;
          this->CellFaces[e] = static_cast<std::uint32_t>(2 * i);
          this->CellNeighbours[e] = static_cast<CellIndex>(b);
        }
        if (b >= first && b < last)
        {
          const vtkIdType e = cursor[b - first]++;
          this->CellFaces[e] = static_cast<std::uint32_t>(2 * i + 1);
          this->CellNeighbours[e] = static_cast<CellIndex>(a);
        }
      }
    }
  });
}

void Topology::BuildBoundary(const Geometry& g)
{
  // Each cell's boundary faces, counted then written per block, in parallel.
  this->Boundary.clear();
  ParallelAppend(
    g.NumberOfCells, [this](vtkIdType c) { return BitCount(this->BoundaryFaces[c]); },
    [this, &g](vtkIdType c, BoundaryFace* out) {
      const std::uint8_t mask = this->BoundaryFaces[c];
      for (int f = 0; mask >> f; ++f)
      {
        if (mask & (1 << f))
        {
          *out++ = { c, static_cast<std::uint8_t>(f),
            static_cast<std::uint8_t>(g.FaceCode(c, f) & 3) };
        }
      }
      return out;
    },
    this->Boundary);
  vtkSMPThreadLocal<vtkIdType> cells(0);
  vtkSMPTools::For(0, g.NumberOfCells, 16384, [&](vtkIdType begin, vtkIdType end) {
    vtkIdType& local = cells.Local();
    for (vtkIdType c = begin; c < end; ++c)
    {
      local += this->BoundaryFaces[c] != 0;
    }
  });
  this->NumberOfBoundaryCells = 0;
  for (vtkIdType count : cells)
  {
    this->NumberOfBoundaryCells += count;
  }
}
}
