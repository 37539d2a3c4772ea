/**
 * @class   hov::GeneralCells
 * @brief   View-independent preparation of the non-tetrahedral cells ("general
 *          cells") of the accurate CPU path: voxels, hexahedra, wedges,
 *          pyramids and the quadratic cells (types 11-14, 24-27, 29).
 *
 * Linear tetrahedra have their own fast path (hov::CellSetup); every
 * other cell type of hov::CellShape is kept here: its type, the coordinates
 * and scalars of ALL its nodes (copied into flat pools, VTK node order), the
 * global point ids of its corners (for the bit-identical shared-face crossing
 * times of hov::RayCellIntervals) and its scalar range.
 *
 * Geometry is the straight-edged cell of the corners (hovCellShapes.h,
 * GeometryShape); the scalar is the cell's own interpolant (all nodes) in its
 * reference coordinates, so a quadratic cell whose mid-edge/face nodes lie
 * off the straight-edged positions is rendered straight-edged with its
 * quadratic field. Such cells are counted (Statistics::Curved) with their
 * largest node deviation relative to the cell size (the longest corner to
 * corner distance); deviations up to CurvedRelativeTolerance (float-rounded
 * straight meshes) are not counted. Curved geometry is the ray caster's job.
 *
 * Validation (counted, reported by the mapper, never fatal): broken
 * connectivity or non-finite node coordinates, non-finite node (or cell)
 * scalars, and degenerate cells are skipped. Degenerate: the Jacobian
 * determinant of the corner map at the parametric centre is at most
 * DegenerateRelativeVolume x (cell size)^3 in magnitude (no volume), or the
 * determinant at a corner (the pyramid apex excepted, where it always
 * vanishes) has the opposite sign to the centre's beyond that tolerance (a
 * tangled cell, which no ray interval test can render faithfully). Cells
 * whose centre determinant has the opposite sign of a valid cell in VTK's
 * convention (the one vtkCellValidator checks: that of VTK's reference cell,
 * except the wedge, whose (0,1,2) normal points away from (3,4,5), opposite
 * to its parametric map) are inverted (mirrored node order): rendered (the
 * ray and restriction kernels do not depend on orientation) and counted.
 *
 * View-independent per-cell data for the per-pixel work: the planarity of
 * each face (hov::PlanarFaceMask: the exact predicates are not repeated per
 * ray) and, for affine cells (hov::IsGeometryAffine), the inverse Jacobian of
 * the corner map, so that the parametric line of a ray comes without Newton
 * iterations (hov::GeneralCellTile).
 *
 * Thread safety: Build() runs in parallel internally (vtkSMPTools) and is not
 * re-entrant; the built arrays are read-only afterwards.
 * @sa hov::CellSetup, hov::GeneralCellTile, hovCellShapes.h
 */
#ifndef hovGeneralCells_h
#define hovGeneralCells_h

#include "hovCellRestriction.h" // RestrictedPiece
#include "hovCellShapes.h"      // CellShape

#include "vtkType.h" // vtkIdType

#include <glm/glm.hpp> // dvec3

#include <cstdint> // std::int64_t corner ids
#include <vector>  // storage

class vtkUnstructuredGridBase;

namespace hov
{
class GeneralCells
{
public:
  /// |det J| at the centre below this times (cell size)^3: degenerate.
  static constexpr double DegenerateRelativeVolume = 1e-12;
  /// Node deviation from the straight-edged position above this times the
  /// cell size: a curved cell (rendered straight-edged, counted).
  static constexpr double CurvedRelativeTolerance = 1e-6;

  struct Cell
  {
    hov::CellShape Shape;
    int NodeCount;
    vtkIdType CellId;
    vtkIdType NodeOffset;        ///< first node in the pools
    std::int64_t CornerIds[8];   ///< global point ids of the corners
    double ScalarMin, ScalarMax; ///< over all nodes
    unsigned PlanarFaces;        ///< hov::PlanarFaceMask (view-independent)
    bool Affine;                 ///< hov::IsGeometryAffine: the field is a polynomial along rays
    double InverseJacobian[9];   ///< affine cells: d(pcoords)/dx, row-major
    double Field[27];            ///< affine cells: hov::AffineFieldCoefficients
  };

  struct Statistics
  {
    vtkIdType Rendered = 0;
    vtkIdType NonFinitePoints = 0; ///< or broken connectivity
    vtkIdType NonFiniteScalars = 0;
    vtkIdType Degenerate = 0;
    vtkIdType Inverted = 0;
    vtkIdType Curved = 0;
    double MaxCurvature = 0.0; ///< largest node deviation / cell size
  };

  /**
   * Prepare the cells @p cellIds of @p grid (each of a supported non-tetra
   * type). @p points are all input points, @p values one scalar per point
   * (or per cell if @p cellScalars). Cells are kept in the order given.
   */
  void Build(vtkUnstructuredGridBase* grid, const std::vector<glm::dvec3>& points,
    const std::vector<double>& values, bool cellScalars, const std::vector<vtkIdType>& cellIds);

  const std::vector<Cell>& GetCells() const { return this->Cells; }
  /// Coordinates of the cell's nodes (3 doubles per node, VTK order).
  const double* GetNodes(const Cell& c) const { return this->Nodes.data() + 3 * c.NodeOffset; }
  /// Scalars of the cell's nodes (the cell value repeated for cell scalars).
  const double* GetScalars(const Cell& c) const { return this->Scalars.data() + c.NodeOffset; }
  /// Global point ids of the cell's nodes.
  const vtkIdType* GetNodeIds(const Cell& c) const { return this->NodeIds.data() + c.NodeOffset; }
  const Statistics& GetStatistics() const { return this->Stats; }

  /**
   * An affine cell's parametric line of the ray @p o + t @p d from @p t0:
   * pc(t0 + tau) = @p start + tau @p step, with pc at corner 0 and the kept
   * inverse Jacobian (no Newton iterations). With the cell's Field
   * (hov::RestrictAffineField) the scalar along the ray; with
   * hov::AffineGradientAlongLine its gradient.
   */
  static void AffineLine(const Cell& cell, const double* nodes, const double o[3],
    const double d[3], double t0, double start[3], double step[3]);

  /**
   * hov::RestrictCellScalar's exact affine path for an affine cell's own
   * scalar (the kept Field and inverse Jacobian): @p piece is s on
   * [@p t0, @p t1] as one polynomial in tau = t - t0, exact to rounding.
   */
  static void RestrictAffine(const Cell& cell, const double* nodes, const double o[3],
    const double d[3], double t0, double t1, hov::RestrictedPiece& piece);

private:
  std::vector<Cell> Cells;
  std::vector<double> Nodes;
  std::vector<double> Scalars;
  std::vector<vtkIdType> NodeIds;
  Statistics Stats;
};
}

#endif
