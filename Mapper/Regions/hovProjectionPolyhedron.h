/**
 * @class   hov::ProjectionPolyhedron
 * @brief   One convex cell of the OpenGL projection: its transfer-function
 *          slabs as convex polyhedra, their homogeneous projected regions and
 *          the triangles with per-vertex attributes (HIAC section 7).
 *
 * A cell is set once (corners in clip coordinates, faces, edges, its field);
 * EmitSlab(k) then builds the slab of transfer-function interval k: the
 * cell's faces cut to lo <= s <= hi (corners inside and the crossings of the
 * face's edges with the levels; an edge crossing is computed from the edge's
 * end with the smaller global point id, so neighbouring cells get
 * bit-identical points) and the two caps s = lo, s = hi through the
 * crossings of all edges. For a linear tetrahedron this is the exact slab
 * (affine field). For a voxel, hexahedron, wedge or pyramid (the corner
 * cell of quadratic types too) with no node inside its corner scalar range
 * it is the whole cell, exact up to the planarity of its faces (a non-planar
 * quadrilateral gets the plane of Newell's normal through its centroid); with
 * a node inside, the caps are the polygons through the edge crossings (the
 * level surface of a trilinear field is curved: an approximation). The
 * scalar at the region vertices is always the cell's own field (Newton
 * inversion of the corner map for non-tetrahedral cells), clamped to the
 * slab. The faces are
 * projected to NDC, sorted counter-clockwise, given their NDC plane z = a x +
 * b y + c and classified front (the interior lies behind) or back; faces seen
 * edge-on are dropped. Every front face is clipped against every back face
 * (Sutherland-Hodgman on convex polygons): the pieces are the regions of
 * the subdivision by all projected edges; they are fan-triangulated and each
 * vertex gets its attributes (hov::ProjectionVertex). Tetrahedra in
 * one slab take the faster hov::ProjectionTetra instead.
 *
 * Thread safety: one object per thread.
 * @sa hov::ProjectionRegions
 */
#ifndef hovProjectionPolyhedron_h
#define hovProjectionPolyhedron_h

#include "hovProjectionVertex.h" // frame, chunk, vertex record
#include "hovCellSetup.h"       // Tetra, general cells

#include <glm/glm.hpp> // dvec, dmat4

#include <vector> // points

namespace hov
{
class ProjectionPolyhedron
{
public:
  static constexpr int MaxFaces = 8;
  static constexpr int MaxFacePoints = 10;
  static constexpr int MaxCorners = 8;

  using Frame = hov::ProjectionFrame;

  /// A linear tetrahedron; false if a corner is on or behind the eye plane.
  bool SetTetra(
    const hov::CellSetup::Tetra& t, const std::vector<glm::dvec3>& points, const Frame& f);

  /// A non-tetrahedral cell (its corners); false if a corner is on or behind the eye plane.
  bool SetGeneral(const hov::GeneralCells& cells, const hov::GeneralCells::Cell& c,
    const Frame& f);

  /// Range of the corner scalars (the slabs that can be non-empty).
  double GetScalarMin() const { return this->SMin; }
  double GetScalarMax() const { return this->SMax; }
  /// Level of the field's affine part at @p eye (dataset coordinates), and the
  /// sign of its gradient along @p direction.
  double EyeLevel(const glm::dvec3& eye) const { return this->AffineField(eye); }
  int LevelDirection(const glm::dvec3& direction) const
  {
    const double d = glm::dot(this->Gradient, direction);
    return d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
  }

  /**
   * Triangles of the slab of transfer-function interval @p k (-1 .. n-1, as
   * hov::TransferFunction::FindIntervalUpward) appended to @p out (each
   * region's vertices once, fan-triangulated by indices); returns their number.
   */
  int EmitSlab(int k, const Frame& f, hov::ProjectionChunk& out);

private:
  struct Face2D
  {
    int N = 0;
    glm::dvec2 P[MaxFacePoints * 2];
    double A = 0, B = 0, C = 0; ///< NDC plane z = A x + B y + C
  };

  void AddPoint(int face, const glm::dvec4& clip);
  void AddEdgeLevelPoints(int face, int i, int j, double lo, double hi, bool once = false);
  /// Faces -> front/back Face2D lists; false if nothing is visible.
  bool Classify();
  int Overlay(int k, double lo, double hi, const Frame& f, hov::ProjectionChunk& out);
  /// False if a value is not finite.
  bool EmitVertex(const glm::dvec2& p, const Face2D& front, const Face2D& back, int k, double lo,
    double hi, const Frame& f, float* out) const;
  double AffineField(const glm::dvec3& x) const
  {
    return this->RefScalar + glm::dot(this->Gradient, x - this->RefPoint);
  }
  /// The cell's field at @p x (affine for tetrahedra; else the cell's interpolant).
  double Field(const glm::dvec3& x) const;
  void SetTopology(hov::CellShape shape);

  // The cell.
  int NumCorners = 0;
  glm::dvec4 Clip[MaxCorners];
  double S[MaxCorners];
  vtkIdType Gid[MaxCorners];
  glm::dvec3 Gradient{ 0.0 }, RefPoint{ 0.0 }; ///< affine field (a fit for general cells)
  double RefScalar = 0, SMin = 0, SMax = 0;
  int NumCellFaces = 0;
  int CellFaceSize[MaxFaces];
  int CellFaces[MaxFaces][4];
  int NumEdges = 0;
  int Edges[12][2];
  // General cells: the cell's own field.
  const hov::GeneralCells::Cell* General = nullptr;
  const double* Nodes = nullptr;
  const double* NodeScalars = nullptr;

  // The current slab's faces (NDC points) and their classification.
  int NumFaces = 0;
  int FaceSize[MaxFaces];
  glm::dvec3 Faces[MaxFaces][MaxFacePoints];
  glm::dvec3 Centroid{ 0.0 };
  int NumFront = 0, NumBack = 0;
  Face2D Front[MaxFaces], Back[MaxFaces];
};
}

#endif
