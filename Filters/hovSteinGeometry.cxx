// View-independent data of vtkSteinVisibilitySort (see hovSteinGeometry.h).
#include "hovSteinGeometry.h"

#include "hovGeometricPredicates.h" // exact Orient3d
#include "hovSteinBuckets.h"         // ParallelRunningSum

#include "vtkAOSDataArrayTemplate.h"
#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace hovStein
{
namespace
{
// Faces in any orientation (oriented per cell from the centroid).
const Shape TetShape = { 4, 4, 6, { 3, 3, 3, 3 }, { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 } },
  { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } } };
const Shape HexShape = { 8, 6, 12, { 4, 4, 4, 4, 4, 4 },
  { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 3, 0, 4, 7 } },
  { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 }, { 7, 4 }, { 0, 4 },
    { 1, 5 }, { 2, 6 }, { 3, 7 } } };
const Shape WedgeShape = { 6, 5, 9, { 3, 3, 4, 4, 4 },
  { { 0, 1, 2 }, { 3, 5, 4 }, { 0, 3, 4, 1 }, { 1, 4, 5, 2 }, { 2, 5, 3, 0 } },
  { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 3, 4 }, { 4, 5 }, { 5, 3 }, { 0, 3 }, { 1, 4 }, { 2, 5 } } };
const Shape PyramidShape = { 5, 5, 8, { 4, 3, 3, 3, 3 },
  { { 0, 3, 2, 1 }, { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 0, 4 } },
  { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 0, 4 }, { 1, 4 }, { 2, 4 }, { 3, 4 } } };
const Shape NoShape = { 0, 0, 0, {}, {}, {} };

/// Kind and number of corners of a VTK cell type with @p npts points (KindBad if unsupported).
Kind KindOf(int type, vtkIdType npts, int& corners)
{
  struct Entry
  {
    int Type, Points;
    Kind K;
  };
  static const Entry table[] = { { VTK_TETRA, 4, KindTet }, { VTK_QUADRATIC_TETRA, 10, KindTet },
    { VTK_HEXAHEDRON, 8, KindHex }, { VTK_VOXEL, 8, KindHex },
    { VTK_QUADRATIC_HEXAHEDRON, 20, KindHex }, { VTK_TRIQUADRATIC_HEXAHEDRON, 27, KindHex },
    { VTK_WEDGE, 6, KindWedge }, { VTK_QUADRATIC_WEDGE, 15, KindWedge },
    { VTK_PYRAMID, 5, KindPyramid }, { VTK_QUADRATIC_PYRAMID, 13, KindPyramid } };
  for (const Entry& e : table)
  {
    if (e.Type == type)
    {
      if (npts != e.Points)
      {
        break;
      }
      corners = GetShape(e.K).NumCorners;
      return e.K;
    }
  }
  corners = static_cast<int>(npts);
  return KindBad;
}

/// Point ids of cells, thread-safe: unstructured grids in parallel, others pre-extracted.
struct CellSource
{
  vtkDataSet* Input;
  vtkUnstructuredGrid* Grid;
  vtkSMPThreadLocalObject<vtkIdList> Lists;
  explicit CellSource(vtkDataSet* input)
    : Input(input)
    , Grid(vtkUnstructuredGrid::SafeDownCast(input))
  {
  }
  int Type(vtkIdType c) { return this->Grid ? this->Grid->GetCellTypesArray()->GetValue(c) : this->Input->GetCellType(c); }
  vtkIdList* Ids(vtkIdType c)
  {
    vtkIdList* ids = this->Lists.Local();
    if (this->Grid)
    {
      this->Grid->GetCells()->GetCellAtId(c, ids);
    }
    else
    {
      this->Input->GetCellPoints(c, ids);
    }
    return ids;
  }
};

inline void Sub(const double* a, const double* b, double* r)
{
  r[0] = a[0] - b[0];
  r[1] = a[1] - b[1];
  r[2] = a[2] - b[2];
}

/// Code of a triangle face (a, b, c): exact, reversed if the centroid is outside.
std::uint8_t TriangleCode(const double* a, const double* b, const double* c, const double* centre)
{
  const int s = hov::Orient3d(a, b, c, centre);
  if (s == 0)
  {
    return FaceSkip;
  }
  return static_cast<std::uint8_t>(FaceExact | (s < 0 ? 4 : 0));
}

/// Code of a quadrilateral face: exact if its corners are coplanar, else Newell.
std::uint8_t QuadCode(const double* p[4], const double* centre, Plane& plane)
{
  for (int omit = 3; omit >= 0; --omit)
  {
    const double* t[3] = { p[(omit + 1) % 4], p[(omit + 2) % 4], p[(omit + 3) % 4] };
    const int s = hov::Orient3d(t[0], t[1], t[2], centre);
    if (s != 0 && hov::Orient3d(t[0], t[1], t[2], p[omit]) == 0)
    {
      return static_cast<std::uint8_t>(FaceExact | (s < 0 ? 4 : 0) | (omit << 3));
    }
  }
  double n[3] = { 0, 0, 0 }, m[3] = { 0, 0, 0 };
  for (int i = 0; i < 4; ++i)
  {
    const double* u = p[i];
    const double* v = p[(i + 1) % 4];
    n[0] += (u[1] - v[1]) * (u[2] + v[2]);
    n[1] += (u[2] - v[2]) * (u[0] + v[0]);
    n[2] += (u[0] - v[0]) * (u[1] + v[1]);
    for (int k = 0; k < 3; ++k)
    {
      m[k] += 0.25 * u[k];
    }
  }
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 0) || !std::isfinite(len))
  {
    return FaceSkip;
  }
  for (double& v : n)
  {
    v /= len;
  }
  double d = -(n[0] * m[0] + n[1] * m[1] + n[2] * m[2]);
  double dev = 0;
  for (int i = 0; i < 4; ++i)
  {
    dev = std::max(dev, std::fabs(n[0] * p[i][0] + n[1] * p[i][1] + n[2] * p[i][2] + d));
  }
  const double side = n[0] * centre[0] + n[1] * centre[1] + n[2] * centre[2] + d;
  if (std::fabs(side) <= dev)
  {
    return FaceSkip; // centroid within the face's slab: flat cell
  }
  const double sign = side > 0 ? -1.0 : 1.0; // outward: the centroid on the negative side
  plane = { { sign * n[0], sign * n[1], sign * n[2] }, sign * d, dev };
  return FaceNewell;
}

/// Bounds of the finite coordinates: lo[k] > hi[k] if there are none.
struct Bounds
{
  double Lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double Hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  void Add(const double* x)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (std::isfinite(x[k]))
      {
        this->Lo[k] = std::min(this->Lo[k], x[k]);
        this->Hi[k] = std::max(this->Hi[k], x[k]);
      }
    }
  }
};

/**
 * The points of @p input in world coordinates (@p model applied, unless null
 * or the identity) into @p out, 3 per point, and the bounds of their finite
 * coordinates. In parallel where the points are a float or double array
 * (thread-safe reads), else one GetPoint() call at a time.
 */
void ReadPoints(vtkDataSet* input, vtkMatrix4x4* model, FillBuffer<double>& out, double lo[3],
  double hi[3])
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  out.resize(3 * numPoints); // every coordinate is written below
  double m[16];
  const bool identity = !model || model->IsIdentity();
  if (!identity)
  {
    vtkMatrix4x4::DeepCopy(m, model);
  }
  vtkPointSet* set = vtkPointSet::SafeDownCast(input);
  vtkDataArray* data = set && set->GetPoints() ? set->GetPoints()->GetData() : nullptr;
  vtkDoubleArray* doubles = vtkDoubleArray::FastDownCast(data);
  vtkFloatArray* floats = vtkFloatArray::FastDownCast(data);
  vtkSMPThreadLocal<Bounds> bounds;
  auto read = [&](vtkIdType begin, vtkIdType end) {
    Bounds& b = bounds.Local();
    for (vtkIdType i = begin; i < end; ++i)
    {
      double* x = out.data() + 3 * i;
      if (doubles)
      {
        std::copy_n(doubles->GetPointer(3 * i), 3, x);
      }
      else if (floats)
      {
        std::copy_n(floats->GetPointer(3 * i), 3, x);
      }
      else
      {
        input->GetPoint(i, x);
      }
      if (!identity)
      {
        double y[3], w = m[12] * x[0] + m[13] * x[1] + m[14] * x[2] + m[15];
        for (int k = 0; k < 3; ++k)
        {
          y[k] = (m[4 * k] * x[0] + m[4 * k + 1] * x[1] + m[4 * k + 2] * x[2] + m[4 * k + 3]) / w;
        }
        std::copy(y, y + 3, x);
      }
      b.Add(x);
    }
  };
  if ((doubles || floats) && data->GetNumberOfComponents() == 3 &&
    data->GetNumberOfTuples() >= numPoints)
  {
    vtkSMPTools::For(0, numPoints, 16384, read);
  }
  else
  {
    doubles = nullptr;
    floats = nullptr;
    read(0, numPoints);
  }
  Bounds all;
  for (const Bounds& b : bounds)
  {
    for (int k = 0; k < 3; ++k)
    {
      all.Lo[k] = std::min(all.Lo[k], b.Lo[k]);
      all.Hi[k] = std::max(all.Hi[k], b.Hi[k]);
    }
  }
  std::copy_n(all.Lo, 3, lo);
  std::copy_n(all.Hi, 3, hi);
}

/// The offsets and connectivity of a grid's cell array when they are plain
/// vtkIdType arrays (read in place), else null.
struct SharedIds
{
  vtkAOSDataArrayTemplate<vtkIdType>* Offsets = nullptr;
  vtkAOSDataArrayTemplate<vtkIdType>* Connectivity = nullptr;
  static SharedIds Of(vtkUnstructuredGrid* grid)
  {
    vtkCellArray* cells = grid ? grid->GetCells() : nullptr;
    SharedIds ids;
    if (cells && cells->IsStorageShareable())
    {
      ids.Offsets = vtkAOSDataArrayTemplate<vtkIdType>::FastDownCast(cells->GetOffsetsArray());
      ids.Connectivity =
        vtkAOSDataArrayTemplate<vtkIdType>::FastDownCast(cells->GetConnectivityArray());
    }
    if (!ids.Offsets || !ids.Connectivity)
    {
      ids = SharedIds();
    }
    return ids;
  }
};
}

const Shape* const ShapeTable[5] = { &NoShape, &TetShape, &HexShape, &WedgeShape, &PyramidShape };

int Geometry::OrientedFace(vtkIdType c, int f, vtkIdType ids[4]) const
{
  const Shape& s = GetShape(this->Kinds[c]);
  const vtkIdType* corners = this->CellCorners(c);
  const int n = s.FaceSize[f];
  const bool reversed = (this->FaceCode(c, f) & 4) != 0;
  for (int i = 0; i < n; ++i)
  {
    ids[i] = corners[s.Faces[f][reversed ? (n - i) % n : i]];
  }
  return n;
}

}

namespace hovStein
{
namespace
{
/// Sets the axis-plane bits (see FaceMode) of the exact faces of cell @p c.
void MarkAxisPlanes(Geometry& g, vtkIdType c)
{
  const Shape& s = GetShape(g.Kinds[c]);
  std::uint8_t* codes = g.FaceCodes.data() + MaxFaces * c;
  for (int f = 0; f < s.NumFaces; ++f)
  {
    if ((codes[f] & 3) != FaceExact)
    {
      continue;
    }
    vtkIdType t[3];
    g.ExactTriple(c, f, t);
    int axis, sigma;
    if (hov::AxisAlignedPlane(g.Point(t[0]), g.Point(t[1]), g.Point(t[2]), axis, sigma) &&
      sigma != 0)
    {
      codes[f] =
        static_cast<std::uint8_t>((codes[f] & 31) | ((axis + 1) << 5) | (sigma < 0 ? 128 : 0));
    }
  }
}

/// Corners and faces of one supported cell; false if it is invalid.
bool FillCell(Geometry& g, vtkIdType c, Kind kind, int type, const vtkIdType* ids,
  vtkIdType numIds, vtkIdType numPoints)
{
  const Shape& s = GetShape(kind);
  // Shared cells: the corners are the ids themselves (nothing to write; never
  // voxels, whose corners are reordered).
  assert(!g.SharedCells || type != VTK_VOXEL);
  vtkIdType* own = g.SharedCells ? nullptr : g.Corners.data() + g.CornerOffsets[c];
  const vtkIdType* corners = own ? own : ids;
  static const int voxelToHex[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };
  double centre[3] = { 0, 0, 0 };
  for (int i = 0; i < s.NumCorners; ++i)
  {
    const int at = type == VTK_VOXEL ? voxelToHex[i] : i;
    const vtkIdType id = at < numIds ? ids[at] : -1;
    if (id < 0 || id >= numPoints)
    {
      return false;
    }
    if (own)
    {
      own[i] = id;
    }
    const double* x = g.Point(id);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      centre[k] += x[k] / s.NumCorners;
    }
  }
  std::uint8_t* codes = g.FaceCodes.data() + MaxFaces * c;
  if (kind == KindTet)
  {
    // One exact test orients all four faces (centroid-free, exact for every tet).
    const int o = hov::Orient3d(g.Point(corners[0]), g.Point(corners[2]), g.Point(corners[1]),
      g.Point(corners[3]));
    for (int f = 0; f < 4; ++f)
    {
      codes[f] = o == 0 ? FaceSkip : static_cast<std::uint8_t>(FaceExact | (o < 0 ? 4 : 0));
    }
    return true;
  }
  for (int f = 0; f < s.NumFaces; ++f)
  {
    const double* p[4];
    for (int i = 0; i < s.FaceSize[f]; ++i)
    {
      p[i] = g.Point(corners[s.Faces[f][i]]);
    }
    codes[f] = s.FaceSize[f] == 3 ? TriangleCode(p[0], p[1], p[2], centre)
                                  : QuadCode(p, centre, g.Planes[g.PlaneOffsets[c] + f]);
  }
  return true;
}
}

void Geometry::Build(vtkDataSet* input, vtkMatrix4x4* model)
{
  if (!this->Build(input, model, true))
  {
    this->Build(input, model, false); // a bad cell among shared ones: own corners
  }
}

bool Geometry::SharedCellsMoved(vtkDataSet* input) const
{
  if (!this->SharedCells)
  {
    return false;
  }
  // The arrays are held: a new array cannot take an old one's address.
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(input);
  const SharedIds now = SharedIds::Of(grid);
  return !now.Offsets || grid->GetCells() != this->SharedCells.Get() ||
    now.Offsets != this->SharedOffsets.Get() ||
    now.Connectivity != this->SharedConnectivity.Get() ||
    now.Offsets->GetNumberOfValues() != this->NumberOfCells + 1 ||
    now.Offsets->GetPointer(0) != this->CornerStart ||
    now.Connectivity->GetPointer(0) != this->CornerIds ||
    now.Connectivity->GetNumberOfValues() != this->CornerStart[this->NumberOfCells];
}

bool Geometry::Build(vtkDataSet* input, vtkMatrix4x4* model, bool shareCells)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  const vtkIdType n = input->GetNumberOfCells();
  this->NumberOfCells = n;
  double lo[3], hi[3];
  ReadPoints(input, model, this->Points, lo, hi);
  this->Diagonal = lo[0] <= hi[0] ? std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) +
                                      (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]))
                                  : 0.0;
  this->MaxAbsCoordinate = 0;
  for (int k = 0; k < 3 && lo[0] <= hi[0]; ++k)
  {
    this->MaxAbsCoordinate = std::max({ this->MaxAbsCoordinate, std::abs(lo[k]), std::abs(hi[k]) });
  }

  // Pass 1: kinds and corner counts.
  CellSource source(input);
  if (!source.Grid && n > 0)
  {
    vtkNew<vtkIdList> warm; // initialise lazy cell structures before threading
    input->GetCellPoints(0, warm);
  }
  this->Kinds.assign(n, KindBad);
  this->CornerOffsets.resize(n + 1);
  this->CornerOffsets[0] = 0;
  // Newell planes for the faces of the cells other than tetrahedra (none, and
  // no per-cell offsets, for a tetrahedral mesh).
  auto hasPlanes = [this](vtkIdType c) {
    return this->Kinds[c] != KindBad && this->Kinds[c] != KindTet;
  };
  vtkSMPThreadLocal<vtkIdType> planeCells(0), notLinear(0);
  auto pass1 = [&](vtkIdType begin, vtkIdType end) {
    vtkIdType& withPlanes = planeCells.Local();
    vtkIdType& others = notLinear.Local();
    for (vtkIdType c = begin; c < end; ++c)
    {
      const vtkIdType npts = source.Grid ? source.Grid->GetCells()->GetCellSize(c)
                                         : source.Ids(c)->GetNumberOfIds();
      int corners = 0;
      const int type = source.Type(c);
      this->Kinds[c] = KindOf(type, npts, corners);
      this->CornerOffsets[c + 1] = corners;
      withPlanes += hasPlanes(c);
      others += this->Kinds[c] == KindBad || corners != npts || type == VTK_VOXEL;
    }
  };
  if (source.Grid)
  {
    vtkSMPTools::For(0, n, pass1);
  }
  else
  {
    pass1(0, n);
  }
  // Linear cells of a vtkIdType cell array: their corners are its ids.
  const SharedIds sharedIds = shareCells ? SharedIds::Of(source.Grid) : SharedIds();
  bool linear = sharedIds.Offsets && n > 0;
  for (vtkIdType count : notLinear)
  {
    linear = linear && count == 0;
  }
  if (linear)
  {
    this->SharedCells = source.Grid->GetCells();
    this->SharedOffsets = sharedIds.Offsets;
    this->SharedConnectivity = sharedIds.Connectivity;
    this->CornerStart = sharedIds.Offsets->GetPointer(0);
    this->CornerIds = sharedIds.Connectivity->GetPointer(0);
    std::vector<vtkIdType>().swap(this->CornerOffsets);
    FillBuffer<vtkIdType>().swap(this->Corners);
  }
  else
  {
    this->SharedCells = nullptr;
    this->SharedOffsets = nullptr;
    this->SharedConnectivity = nullptr;
    ParallelRunningSum(this->CornerOffsets.data(), n);
    // (Every corner is written below, in parallel: no serial zeroing first.)
    this->Corners.resize(this->CornerOffsets[n]);
    this->CornerStart = this->CornerOffsets.data();
    this->CornerIds = this->Corners.data();
  }
  vtkIdType planes = 0;
  for (vtkIdType count : planeCells)
  {
    planes += MaxFaces * count;
  }
  this->PlaneOffsets.assign(planes > 0 ? n : 0, -1);
  this->PlaneOffsets.shrink_to_fit();
  for (vtkIdType c = 0, first = 0; planes > 0 && c < n; ++c)
  {
    if (hasPlanes(c))
    {
      this->PlaneOffsets[c] = first;
      first += MaxFaces;
    }
  }
  this->FaceCodes.assign(MaxFaces * n, FaceSkip);
  this->Planes.assign(planes, Plane{});
  this->Planes.shrink_to_fit(); // a tetrahedral mesh after a hexahedral one keeps nothing

  // Pass 2: corners, face orientation and planes.
  // A cell array whose storage is vtkIdType hands out its own ids (no copy,
  // no shared temporary: thread safe). A grid after Initialize() has none.
  vtkCellArray* cells = source.Grid ? source.Grid->GetCells() : nullptr;
  vtkCellArray* shared = cells && cells->IsStorageShareable() ? cells : nullptr;
  struct BadCells
  {
    vtkIdType Count = 0, First = -1;
  };
  vtkSMPThreadLocal<BadCells> badCells;
  auto pass2 = [&](vtkIdType begin, vtkIdType end) {
    BadCells& bad = badCells.Local();
    for (vtkIdType c = begin; c < end; ++c)
    {
      vtkIdType numIds = 0;
      const vtkIdType* ids = nullptr;
      if (shared)
      {
        shared->GetCellAtId(c, numIds, ids);
      }
      else
      {
        vtkIdList* list = source.Ids(c);
        numIds = list->GetNumberOfIds();
        ids = list->GetPointer(0);
      }
      const Kind kind = static_cast<Kind>(this->Kinds[c]);
      if (kind != KindBad && FillCell(*this, c, kind, source.Type(c), ids, numIds, numPoints))
      {
        MarkAxisPlanes(*this, c);
        continue;
      }
      this->Kinds[c] = KindBad;
      if (bad.Count++ == 0 || c < bad.First)
      {
        bad.First = c;
      }
      if (this->SharedCells)
      {
        continue; // built again with own corners
      }
      vtkIdType* corners = this->Corners.data() + this->CornerOffsets[c];
      const vtkIdType count = this->CornerOffsets[c + 1] - this->CornerOffsets[c];
      for (vtkIdType i = 0; i < count; ++i)
      {
        corners[i] = i < numIds && ids[i] >= 0 && ids[i] < numPoints ? ids[i] : -1;
      }
    }
  };
  if (source.Grid)
  {
    vtkSMPTools::For(0, n, pass2);
  }
  else
  {
    pass2(0, n);
  }
  // The number of bad cells and the first: per thread, then combined.
  this->NumberOfBadCells = 0;
  this->FirstBadCell = -1;
  for (const BadCells& bad : badCells)
  {
    this->NumberOfBadCells += bad.Count;
    if (bad.Count > 0 && (this->FirstBadCell < 0 || bad.First < this->FirstBadCell))
    {
      this->FirstBadCell = bad.First;
    }
  }
  // A bad cell's corners are its valid ids and -1: shared ids cannot say so.
  return !(this->SharedCells && this->NumberOfBadCells > 0);
}
}
