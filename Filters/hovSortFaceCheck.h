/**
 * @file hovSortFaceCheck.h
 * @brief Interior-face check of a cell order (used by vtkCellVisibilitySortFilter).
 *
 * For every face shared by exactly two cells (matched by corner point ids),
 * the cell on the far side of the face from the eye must come first in
 * back-to-front order. Faces seen edge-on (within the face's non-planarity and
 * a 1e-9 relative margin), faces entirely behind a perspective eye, and pairs
 * whose cells lie on one side of the face (overlapping or inverted cells) get
 * no verdict. Works for any order (any vtkVisibilitySort); it cannot see errors
 * between cells that share no face (the ray oracle of the tests does).
 * Cell types: tetrahedron, voxel, hexahedron, wedge, pyramid and their
 * quadratic forms (corner vertices). Thread safety: re-entrant; runs the
 * per-face work with vtkSMPTools.
 */
#ifndef hovSortFaceCheck_h
#define hovSortFaceCheck_h

#include "vtkType.h" // vtkIdType

class vtkCamera;
class vtkIdTypeArray;
class vtkMatrix4x4;
class vtkUnstructuredGrid;

namespace hovSort
{
struct FaceCheckResult
{
  vtkIdType Violations = 0; ///< interior faces ordered wrongly
  vtkIdType Checked = 0;    ///< interior faces that got a verdict
};

/// Checks @p backToFront (a permutation of the cell ids of @p input) for the
/// view of @p camera, with the optional object-to-world @p model matrix.
FaceCheckResult CheckInteriorFaces(vtkUnstructuredGrid* input, vtkCamera* camera,
  vtkMatrix4x4* model, vtkIdTypeArray* backToFront);
}

#endif
