// Face adjacency of vtkSteinVisibilitySort (see hovSteinTopology.h).
#include "hovSteinTopology.h"

#include "hovGeometricPredicates.h" // exact Orient3d

#include "vtkSMPTools.h"

#include <algorithm>
#include <array>

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

void Topology::Build(const Geometry& g)
{
  const vtkIdType n = g.NumberOfCells;
  const vtkIdType numPoints = static_cast<vtkIdType>(g.Points.size() / 3);
  // Bucket faces by their smallest corner id (counting sort).
  std::vector<vtkIdType> start(numPoints + 1, 0);
  for (vtkIdType c = 0; c < n; ++c)
  {
    if (g.Kinds[c] == KindBad)
    {
      continue;
    }
    const Shape& s = GetShape(g.Kinds[c]);
    for (int f = 0; f < s.NumFaces; ++f)
    {
      ++start[FaceKey(g, c, f)[0] + 1];
    }
  }
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    start[p + 1] += start[p];
  }
  std::vector<vtkIdType> entries(start[numPoints]);
  {
    std::vector<vtkIdType> cursor(start.begin(), start.end() - 1);
    for (vtkIdType c = 0; c < n; ++c)
    {
      if (g.Kinds[c] == KindBad)
      {
        continue;
      }
      const Shape& s = GetShape(g.Kinds[c]);
      for (int f = 0; f < s.NumFaces; ++f)
      {
        entries[cursor[FaceKey(g, c, f)[0]]++] = c * 8 + f;
      }
    }
  }
  std::vector<std::uint8_t> flags(entries.size());
  vtkSMPTools::For(0, numPoints, 1024, [&](vtkIdType begin, vtkIdType end) {
    std::vector<std::pair<std::array<vtkIdType, 4>, vtkIdType>> keyed;
    for (vtkIdType p = begin; p < end; ++p)
    {
      MatchBucket(g, entries.data() + start[p], start[p + 1] - start[p], flags.data() + start[p],
        keyed);
    }
  });
  // Collect in bucket order (deterministic).
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
  this->PlaneA.reset(new FilteredPlane[numInterior]); // default-initialised: not written here
  vtkSMPTools::For(0, numInterior, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      this->ModeA[i] = g.FaceCode(this->A[i], this->FaceA[i]) & 3;
      if (this->ModeA[i] == FaceExact)
      {
        vtkIdType t[3];
        g.ExactTriple(this->A[i], this->FaceA[i], t);
        this->PlaneA[i].Set(g.Point(t[0]), g.Point(t[1]), g.Point(t[2]));
      }
    }
  });
  this->NumberOfBoundaryCells = 0;
  for (vtkIdType c = 0; c < n; ++c)
  {
    this->NumberOfBoundaryCells += this->BoundaryFaces[c] != 0;
  }
  this->BuildCellFaces(n);
  this->BuildBoundary(g);
}

void Topology::BuildCellFaces(vtkIdType numCells)
{
  const vtkIdType m = this->NumberOfInteriorFaces();
  this->CellFaceOffsets.assign(numCells + 1, 0);
  for (vtkIdType i = 0; i < m; ++i)
  {
    ++this->CellFaceOffsets[this->A[i] + 1];
    ++this->CellFaceOffsets[this->B[i] + 1];
  }
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    this->CellFaceOffsets[c + 1] += this->CellFaceOffsets[c];
  }
  this->CellFaces.resize(2 * m);
  this->CellNeighbours.resize(2 * m);
  std::vector<vtkIdType> cursor(this->CellFaceOffsets.begin(), this->CellFaceOffsets.end() - 1);
  for (vtkIdType i = 0; i < m; ++i)
  {
    const vtkIdType a = cursor[this->A[i]]++, b = cursor[this->B[i]]++;
    this->CellFaces[a] = 2 * i;
    this->CellNeighbours[a] = this->B[i];
    this->CellFaces[b] = 2 * i + 1;
    this->CellNeighbours[b] = this->A[i];
  }
}

void Topology::BuildBoundary(const Geometry& g)
{
  const vtkIdType n = g.NumberOfCells;
  std::vector<vtkIdType> start(n + 1, 0);
  for (vtkIdType c = 0; c < n; ++c)
  {
    std::uint8_t mask = this->BoundaryFaces[c];
    vtkIdType count = 0;
    for (; mask; mask &= mask - 1)
    {
      ++count;
    }
    start[c + 1] = start[c] + count;
  }
  this->NumberOfBoundaryFaces = start[n];
  this->Boundary.reset(new BoundaryFace[start[n]]);
  vtkSMPTools::For(0, n, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType c = begin; c < end; ++c)
    {
      BoundaryFace* out = this->Boundary.get() + start[c];
      for (int f = 0; f < MaxFaces; ++f)
      {
        if (this->BoundaryFaces[c] & (1 << f))
        {
          out->Cell = c;
          out->Face = static_cast<std::uint8_t>(f);
          out->Mode = g.FaceCode(c, f) & 3;
          if (out->Mode == FaceExact)
          {
            vtkIdType t[3];
            g.ExactTriple(c, f, t);
            out->Plane.Set(g.Point(t[0]), g.Point(t[1]), g.Point(t[2]));
          }
          ++out;
        }
      }
    }
  });
}
}
