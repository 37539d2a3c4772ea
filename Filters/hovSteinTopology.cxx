// Face adjacency of vtkSteinVisibilitySort (see hovSteinTopology.h).
#include "hovSteinTopology.h"

#include "hovGeometricPredicates.h" // exact Orient3d

#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <atomic> // the build generations

namespace hovStein
{
namespace
{
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
 * face f of cell c, one strictly (Newell faces: all corners off the face
 * strictly outside the deviation slab). Cell c lies on the inner side by
 * construction, so the plane separates the two cells.
 */
bool OtherOutside(const Geometry& g, vtkIdType c, int f, vtkIdType other)
{
  const std::uint8_t mode = g.FaceCode(c, f) & 3;
  const int n = g.NumberOfCorners(other);
  const vtkIdType* ids = g.CellCorners(other);
  const std::array<vtkIdType, 4> key = FaceKey(g, c, f);
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

/// Match the faces of one bucket (entries c*8+f with the same smallest id) in place.
void MatchBucket(const Geometry& g, vtkIdType* e, vtkIdType m, std::uint8_t* flag,
  std::vector<std::pair<std::array<vtkIdType, 4>, vtkIdType>>& keyed)
{
  keyed.resize(m);
  for (vtkIdType i = 0; i < m; ++i)
  {
    keyed[i] = { FaceKey(g, e[i] >> 3, static_cast<int>(e[i] & 7)), e[i] };
  }
  std::sort(keyed.begin(), keyed.end());
  for (vtkIdType i = 0; i < m; ++i)
  {
    e[i] = keyed[i].second;
    flag[i] = 0;
  }
  for (vtkIdType i = 0; i < m;)
  {
    vtkIdType j = i + 1;
    while (j < m && keyed[j].first == keyed[i].first)
    {
      ++j;
    }
    if (j == i + 2)
    {
      const vtkIdType a = e[i] >> 3, b = e[i + 1] >> 3;
      const int fa = static_cast<int>(e[i] & 7), fb = static_cast<int>(e[i + 1] & 7);
      if (a != b && (g.FaceCode(a, fa) & 3) != FaceSkip && (g.FaceCode(b, fb) & 3) != FaceSkip &&
        OtherOutside(g, a, fa, b))
      {
        flag[i] = 1; // interior face: entry i + 1 is its partner
        flag[i + 1] = 2;
      }
    }
    i = j;
  }
}
}

namespace
{
/**
 * The faces of the supported cells (entries c * 8 + f) bucketed by their
 * smallest corner id (counting sort): bucket p is entries[start[p],
 * start[p + 1]).
 */
void BucketFaces(const Geometry& g, std::vector<vtkIdType>& start, std::vector<vtkIdType>& entries)
{
  const vtkIdType n = g.NumberOfCells;
  const vtkIdType numPoints = static_cast<vtkIdType>(g.Points.size() / 3);
  start.assign(numPoints + 1, 0);
  for (vtkIdType c = 0; c < n; ++c)
  {
    const int numFaces = g.Kinds[c] == KindBad ? 0 : GetShape(g.Kinds[c]).NumFaces;
    for (int f = 0; f < numFaces; ++f)
    {
      ++start[FaceKey(g, c, f)[0] + 1];
    }
  }
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    start[p + 1] += start[p];
  }
  entries.resize(start[numPoints]);
  std::vector<vtkIdType> cursor(start.begin(), start.end() - 1);
  for (vtkIdType c = 0; c < n; ++c)
  {
    const int numFaces = g.Kinds[c] == KindBad ? 0 : GetShape(g.Kinds[c]).NumFaces;
    for (int f = 0; f < numFaces; ++f)
    {
      entries[cursor[FaceKey(g, c, f)[0]]++] = c * 8 + f;
    }
  }
}

/// MatchBucket on every bucket, in parallel over chunks of about equal numbers
/// of faces (low point ids hold more faces: a face goes to its smallest id).
void MatchFaces(const Geometry& g, const std::vector<vtkIdType>& start,
  std::vector<vtkIdType>& entries, std::vector<std::uint8_t>& flags)
{
  const vtkIdType numPoints = static_cast<vtkIdType>(start.size()) - 1;
  flags.resize(entries.size());
  const vtkIdType numChunks = std::max<vtkIdType>(1, std::min<vtkIdType>(256, numPoints));
  std::vector<vtkIdType> chunk(numChunks + 1);
  for (vtkIdType k = 0; k <= numChunks; ++k)
  {
    chunk[k] = std::lower_bound(start.begin(), start.end(), k * start[numPoints] / numChunks) -
      start.begin();
  }
  chunk[numChunks] = numPoints;
  vtkSMPTools::For(0, numChunks, 1, [&](vtkIdType k0, vtkIdType k1) {
    std::vector<std::pair<std::array<vtkIdType, 4>, vtkIdType>> keyed;
    for (vtkIdType p = chunk[k0]; p < chunk[k1]; ++p)
    {
      MatchBucket(g, entries.data() + start[p], start[p + 1] - start[p], flags.data() + start[p],
        keyed);
    }
  });
}
}

void Topology::Build(const Geometry& g)
{
  std::vector<vtkIdType> start, entries;
  BucketFaces(g, start, entries);
  std::vector<std::uint8_t> flags;
  MatchFaces(g, start, entries, flags);
  this->Collect(g, entries, flags);
  this->BuildCellFaces(g);
  this->BuildBoundary(g);
  static std::atomic<unsigned long> generations(0);
  this->Generation = ++generations;
}

void Topology::Collect(
  const Geometry& g, const std::vector<vtkIdType>& entries, const std::vector<std::uint8_t>& flags)
{
  // In bucket order (deterministic).
  const vtkIdType n = g.NumberOfCells;
  this->A.clear();
  this->B.clear();
  this->FaceA.clear();
  this->BoundaryFaces.assign(n, 0);
  const size_t numEntries = entries.size();
  this->A.reserve(numEntries / 2);
  this->B.reserve(numEntries / 2);
  this->FaceA.reserve(numEntries / 2);
  for (size_t i = 0; i < numEntries; ++i)
  {
    const vtkIdType c = entries[i] >> 3;
    const int f = static_cast<int>(entries[i] & 7);
    if (flags[i] == 1)
    {
      this->A.push_back(c);
      this->B.push_back(entries[i + 1] >> 3);
      this->FaceA.push_back(static_cast<std::uint8_t>(f));
    }
    else if (flags[i] == 0)
    {
      this->BoundaryFaces[c] |= static_cast<std::uint8_t>(1 << f);
    }
  }
  const vtkIdType numInterior = this->NumberOfInteriorFaces();
  this->ModeA.resize(numInterior);
  vtkSMPTools::For(0, numInterior, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      this->ModeA[i] = g.FaceCode(this->A[i], this->FaceA[i]) & 3;
    }
  });
  this->NumberOfBoundaryCells = 0;
  for (vtkIdType c = 0; c < n; ++c)
  {
    this->NumberOfBoundaryCells += this->BoundaryFaces[c] != 0;
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
  for (vtkIdType c = 0; c < n; ++c)
  {
    std::uint8_t mask = this->BoundaryFaces[c];
    vtkIdType count = g.Kinds[c] == KindBad ? 0 : GetShape(g.Kinds[c]).NumFaces;
    for (; mask; mask &= mask - 1)
    {
      --count;
    }
    this->CellFaceOffsets[c + 1] = this->CellFaceOffsets[c] + count;
  }
  // In parallel over bands of cells: each band scans all faces and fills its
  // own cells' lists, in increasing face order whatever the number of bands.
  this->CellFaces.resize(2 * m);
  this->CellNeighbours.resize(2 * m);
  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  const vtkIdType numBands = std::min<vtkIdType>(threads > 1 ? 2 * threads : 1, std::max<vtkIdType>(n, 1));
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
          this->CellFaces[e] = 2 * i;
          this->CellNeighbours[e] = b;
        }
        if (b >= first && b < last)
        {
          const vtkIdType e = cursor[b - first]++;
          this->CellFaces[e] = 2 * i + 1;
          this->CellNeighbours[e] = a;
        }
      }
    }
  });
}

void Topology::BuildBoundary(const Geometry& g)
{
  this->Boundary.clear();
  for (vtkIdType c = 0; c < g.NumberOfCells; ++c)
  {
    for (int f = 0; this->BoundaryFaces[c] && f < MaxFaces; ++f)
    {
      if (this->BoundaryFaces[c] & (1 << f))
      {
        this->Boundary.push_back(
          { c, static_cast<std::uint8_t>(f), static_cast<std::uint8_t>(g.FaceCode(c, f) & 3) });
      }
    }
  }
}
}
