/**
 * @file hovSteinGeometry.h
 * @brief View-independent data of vtkSteinVisibilitySort: world-space points,
 *        cell corners and outward-oriented faces with their planes.
 *
 * Cells are reduced to convex polyhedra on their corner vertices (quadratic
 * cells by their corners, voxels renumbered to hexahedron order). Each face is
 * oriented outward independently from the cell centroid (so inverted cells
 * work) and classified:
 * - Exact: a triangle, or a quadrilateral whose four corners are exactly
 *   coplanar; side tests use the exact Orient3d on three of its corners, so
 *   faces shared by two cells give exact zeros.
 * - Newell: a non-planar quadrilateral; plane from Newell's method plus the
 *   maximum deviation of its corners (HIAC 6). A point counts as on the outer
 *   side when value + deviation >= 0: tolerant, so the corners of the face
 *   itself (and of a neighbour sharing it) always count as outside.
 * - Skip: degenerate (collinear corners, or the centroid on the face plane,
 *   i.e. a flat cell); never used in plane tests.
 *
 * Thread safety: Build() is not re-entrant; the built data are read-only.
 */
#ifndef hovSteinGeometry_h
#define hovSteinGeometry_h

#include "hovSteinBuffers.h" // FillBuffer
#include "vtkSmartPointer.h" // SharedCells
#include "vtkType.h"         // vtkIdType

#include <cstdint> // std::uint8_t
#include <vector>  // storage

class vtkDataSet;
class vtkMatrix4x4;

namespace hovStein
{
/// Convex cell shapes (corner topology of the supported VTK types).
enum Kind : std::uint8_t
{
  KindBad = 0, ///< unsupported type, invalid ids or non-finite coordinates
  KindTet,
  KindHex, ///< hexahedra, voxels (renumbered), quadratic and triquadratic hexahedra
  KindWedge,
  KindPyramid
};

/// Local corner topology of a Kind (faces in any orientation).
struct Shape
{
  int NumCorners, NumFaces, NumEdges;
  int FaceSize[6];
  int Faces[6][4];
  int Edges[12][2];
};
extern const Shape* const ShapeTable[5];
inline const Shape& GetShape(int kind)
{
  return *ShapeTable[kind];
}

/// Face codes: bits 0-1 mode, bit 2 reversed orientation, bits 3-4 omitted quad
/// corner; exact faces in an axis-aligned plane (hov::AxisAlignedPlane of
/// their ExactTriple): bits 5-6 the axis + 1, bit 7 set if sigma is -1.
enum FaceMode : std::uint8_t
{
  FaceSkip = 0,
  FaceExact = 1,
  FaceNewell = 2
};
constexpr int MaxFaces = 6;

/// Newell plane n.x + d with the maximum deviation of the face corners.
struct Plane
{
  double N[3], D, Deviation;
};

struct Geometry
{
  Geometry() = default;
  Geometry(const Geometry&) = delete; ///< CornerStart and CornerIds point into it
  Geometry& operator=(const Geometry&) = delete;
  vtkIdType NumberOfCells = 0;
  FillBuffer<double> Points;           ///< world coordinates, 3 per input point
  std::vector<std::uint8_t> Kinds;     ///< per cell
  /// Per cell + 1: where its corners start (CornerOffsets, or the input's
  /// cell offsets: see SharedCells).
  const vtkIdType* CornerStart = nullptr;
  /// Corner point ids (bad cells: their valid point ids, -1 for the others):
  /// Corners, or the input's connectivity (see SharedCells).
  const vtkIdType* CornerIds = nullptr;
  std::vector<vtkIdType> CornerOffsets; ///< own per-cell offsets (empty when shared)
  FillBuffer<vtkIdType> Corners;        ///< own corner ids (empty when shared)
  /// Set when every cell is a valid linear tetrahedron, hexahedron, wedge or
  /// pyramid of a grid whose cell array stores vtkIdType: its offsets and
  /// connectivity are then the corners, read in place (no copy: 80 MB less
  /// for 2M tetrahedra). These keep that cell array and both arrays alive.
  vtkSmartPointer<vtkObjectBase> SharedCells, SharedOffsets, SharedConnectivity;
  std::vector<std::uint8_t> FaceCodes; ///< MaxFaces per cell
  std::vector<Plane> Planes;           ///< MaxFaces per cell with a Newell face
  std::vector<vtkIdType> PlaneOffsets; ///< per cell: first plane, or -1 (empty without planes)
  vtkIdType NumberOfBadCells = 0;
  vtkIdType FirstBadCell = -1;
  double Diagonal = 0; ///< of the world bounding box of the points
  double MaxAbsCoordinate = 0; ///< largest |coordinate| of the finite world points

  /// Build from @p input with points mapped by @p model (object to world; may be null).
  void Build(vtkDataSet* input, vtkMatrix4x4* model);
  /// True if the corners are read from @p input's cell array and it no longer
  /// holds them where they were read (another cell array, storage moved or
  /// resized, other cell count): build again (a grid whose cells are changed
  /// in place need not change its MTime).
  bool SharedCellsMoved(vtkDataSet* input) const;

  const double* Point(vtkIdType id) const { return Points.data() + 3 * id; }
  const vtkIdType* CellCorners(vtkIdType c) const { return CornerIds + CornerStart[c]; }
  int NumberOfCorners(vtkIdType c) const
  {
    return static_cast<int>(CornerStart[c + 1] - CornerStart[c]);
  }
  std::uint8_t FaceCode(vtkIdType c, int f) const { return FaceCodes[MaxFaces * c + f]; }
  /// The three corners (point ids, outward counterclockwise) of an exact face.
  void ExactTriple(vtkIdType c, int f, vtkIdType ids[3]) const
  {
    const Shape& s = GetShape(this->Kinds[c]);
    const vtkIdType* corners = this->CellCorners(c);
    const std::uint8_t code = this->FaceCode(c, f);
    const int* loc = s.Faces[f];
    int t0 = loc[0], t1 = loc[1], t2 = loc[2];
    if (s.FaceSize[f] == 4)
    {
      const int omit = (code >> 3) & 3;
      t0 = loc[(omit + 1) & 3];
      t1 = loc[(omit + 2) & 3];
      t2 = loc[(omit + 3) & 3];
    }
    ids[0] = corners[t0];
    ids[1] = corners[(code & 4) ? t2 : t1];
    ids[2] = corners[(code & 4) ? t1 : t2];
  }
  /// True if the exact face @p f of @p c lies in an axis-aligned plane; then
  /// hov::AxisOrient3d(axis, sigma, a, d) is hov::Orient3d(a, b, c, d) for its
  /// ExactTriple (a, b, c) and every d.
  bool AxisPlane(vtkIdType c, int f, int& axis, int& sigma) const
  {
    const std::uint8_t code = this->FaceCode(c, f);
    axis = ((code >> 5) & 3) - 1;
    sigma = (code & 128) ? -1 : 1;
    return axis >= 0;
  }
  /// The corners of face f in outward counterclockwise order; returns their number.
  int OrientedFace(vtkIdType c, int f, vtkIdType ids[4]) const;
  const Plane& FacePlane(vtkIdType c, int f) const { return Planes[PlaneOffsets[c] + f]; }

private:
  /// Build(), reading the corners from a shared cell array if @p shareCells
  /// and possible; false if it did and found a bad cell (whose corners the
  /// shared ids cannot mark -1: Build() then builds again without sharing).
  bool Build(vtkDataSet* input, vtkMatrix4x4* model, bool shareCells);
};
}

#endif
