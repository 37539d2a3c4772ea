/**
 * @class   hov::CellSetup
 * @brief   View-independent preparation of the cells of the accurate CPU
 *          path: linear tetrahedra for exact ray clipping (the fast path),
 *          the other supported types in hov::GeneralCells.
 *
 * For every valid tetrahedron of the input: its point ids and its linear
 * scalar field s(x) = s0 + g.(x - x0). Built once per input/array change and
 * reused for every view. Its four face planes n.x <= h (outward normals) are
 * computed from the points when a frame needs them (FacePlanes(): 128 bytes a
 * tetrahedron not kept, 256 MB for 2M tetrahedra; the CPU projector copies
 * them into its per-frame cell records anyway).
 *
 * Face planes are computed canonically: from the face's three global point ids
 * in ascending order, then oriented outward by negation. Two tetrahedra that
 * share a face therefore hold bit-identical planes up to sign, and a ray's
 * exit parameter from one equals its entry parameter into the other exactly:
 * no crack and no overlap between neighbouring cells, by construction.
 *
 * Rendered cells are numbered tetrahedra first (0 .. GetTetras().size()-1),
 * then the general cells (voxel, hexahedron, wedge, pyramid, quadratic
 * types: GetGeneralCells(), in input order); GetSortGrid() holds them all in
 * that numbering with their own cell types.
 *
 * Validation (counted, reported by the mapper, never fatal): cell types the
 * CPU path does not support (hov::IsSupportedCellType false: polyhedra,
 * Lagrange/Bezier cells, 2D cells, ...), broken connectivity, non-finite point
 * coordinates, non-finite scalars, degenerate tetrahedra (|6V| <= 1e-12
 * times the cube of the longest edge: no volume to render) are skipped;
 * inverted tetrahedra (negative VTK orientation) are rendered, since the
 * planes do not depend on vertex order, and counted.
 *
 * Thread safety: Build() runs in parallel internally (vtkSMPTools) and is not
 * re-entrant; the built arrays are read-only afterwards.
 * @sa hov::CellProjector
 */
#ifndef hovCellSetup_h
#define hovCellSetup_h

#include "hovGeneralCells.h" // the non-tetrahedral cells

#include "vtkDataSet.h"      // For SortGrid
#include "vtkSmartPointer.h" // For SortGrid
#include "vtkType.h"         // vtkIdType

#include <glm/glm.hpp> // dvec3

#include <string> // error message
#include <vector> // storage

class vtkDataArray;
class vtkPoints;
class vtkUnstructuredGridBase;

namespace hov
{
class CellSetup
{
public:
  struct Tetra
  {
    /// Scalar gradient (0 for cell scalars): s(x) = RefScalar + Gradient . (x - RefPoint(tet)).
    glm::dvec3 Gradient;
    double RefScalar;     ///< scalar at vertex 0 (the cell value for cell scalars)
    double ScalarMin;     ///< smallest vertex scalar
    double ScalarMax;     ///< largest vertex scalar
    vtkIdType Points[4];
    vtkIdType CellId;
  };

  struct Statistics
  {
    vtkIdType Cells = 0;
    vtkIdType Rendered = 0;
    vtkIdType General = 0;     ///< rendered non-tetrahedral cells (in Rendered)
    vtkIdType Unsupported = 0; ///< cells of types the CPU path does not render
    vtkIdType NonFinitePoints = 0;
    vtkIdType NonFiniteScalars = 0;
    vtkIdType Degenerate = 0;
    vtkIdType Inverted = 0;        ///< tetrahedra
    vtkIdType InvertedGeneral = 0; ///< other cells
    vtkIdType Curved = 0;      ///< quadratic cells rendered straight-edged
    double MaxCurvature = 0.0; ///< their largest node deviation / cell size
    int FirstUnsupportedType = -1;
  };

  /**
   * Prepare every cell of @p grid. @p scalars is a point array (or a cell
   * array if @p cellScalars); @p component selects a component, -1 the
   * magnitude. Returns false if nothing can be rendered; @p error then says
   * why if the input itself is unusable (e.g. an array shorter than the
   * number of points).
   */
  bool Build(vtkUnstructuredGridBase* grid, vtkDataArray* scalars, bool cellScalars, int component,
    std::string* error = nullptr);

  /**
   * The rendered cells as a grid (input points, cell k = rendered cell k):
   * what a vtkVisibilitySort is given, so that it never sees invalid cells and
   * the ids it returns are rendered-cell indices. The input itself when every
   * input cell is a rendered tetrahedron (no copy).
   */
  vtkDataSet* GetSortGrid() const { return this->SortGrid; }

  const std::vector<Tetra>& GetTetras() const { return this->Tetras; }
  /// The rendered non-tetrahedral cells (rendered cell GetTetras().size() + g is cell g).
  const hov::GeneralCells& GetGeneralCells() const { return this->General; }
  /// Rendered cells: tetrahedra plus general cells.
  vtkIdType GetNumberOfRenderedCells() const
  {
    return static_cast<vtkIdType>(this->Tetras.size() + this->General.GetCells().size());
  }
  /**
   * The canonical face planes of @p tet (see the class doc), face k opposite
   * vertex k: inside iff nx[k] x + ny[k] y + nz[k] z <= offset[k], the normals
   * outward and not normalised. The same bits on every call.
   */
  void FacePlanes(const Tetra& tet, double nx[4], double ny[4], double nz[4], double offset[4]) const;

  /// The reference point of @p tet's field: its vertex 0 (not stored: 48 MB for 2M tetrahedra).
  const glm::dvec3& RefPoint(const Tetra& tet) const { return this->Points[tet.Points[0]]; }

  /// All input points (dataset coordinates), indexed by point id.
  const std::vector<glm::dvec3>& GetPoints() const { return this->Points; }
  const Statistics& GetStatistics() const { return this->Stats; }

  /// Why @p scalars cannot give one value per point (per cell if
  /// @p cellScalars) of @p grid: "scalar array 'name' has T tuples for N
  /// points"; empty if it has enough tuples. Every render mode's check.
  static std::string ShortScalars(vtkDataSet* grid, vtkDataArray* scalars, bool cellScalars);

private:
  /// The scalar per point (or cell) into @p values and the points; false (and
  /// @p error) if the array is too short.
  bool ReadInput(vtkUnstructuredGridBase* grid, vtkDataArray* scalars, bool cellScalars,
    int component, std::vector<double>& values, std::string* error);
  /// The grid of the rendered cells given to visibility sorts.
  void BuildSortGrid(vtkUnstructuredGridBase* grid);

  std::vector<Tetra> Tetras;
  std::vector<glm::dvec3> Points;
  hov::GeneralCells General;
  vtkSmartPointer<vtkDataSet> SortGrid;
  Statistics Stats;
};
}

#endif
