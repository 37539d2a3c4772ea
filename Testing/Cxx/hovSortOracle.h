/**
 * @file hovSortOracle.h
 * @brief An independent oracle for visibility orders (shares no code with
 * vtkSteinVisibilitySort or vtkCellVisibilitySortFilter).
 *
 * Given a grid of convex cells, a vtkCamera (perspective or parallel), an
 * optional model transform and a back-to-front sequence of cell ids:
 *  1. every cell exactly once;
 *  2. ray casting: a grid of RaysX x RaysY pixel-centre rays over the
 *     screen-space bounding box of the mesh (clamped to +-3 in tan units for
 *     perspective) plus RandomRays uniformly jittered rays. Each convex cell
 *     is the intersection of its supporting half-spaces, found from the
 *     corners alone (every corner triple whose plane has all other corners
 *     on one side). A ray is clipped against each candidate cell (a bucket
 *     grid over the screen-space boxes keeps this linear); hits of positive
 *     length (> RelTol x scene size) are sorted by entry. For every pair of
 *     hits on a ray that do not overlap (exit of the nearer <= entry of the
 *     farther + tolerance), the farther cell must come first back to front;
 *     distinct wrong cell pairs are counted. Pairs overlapping by more than
 *     the tolerance are counted separately (the mesh intersects itself).
 *     Perspective rays start at the eye; parallel rays are whole lines.
 *  3. interior faces: every face (set of >= 3 coplanar corners of a
 *     supporting plane) shared by exactly two cells; if the eye is strictly on
 *     one side of the plane (relative tolerance 1e-7) and the face is not
 *     entirely behind the eye, the cell on the far side must come first.
 * All arithmetic in plain doubles, in world coordinates.
 */
#ifndef hovSortOracle_h
#define hovSortOracle_h

#include "vtkType.h"

#include <string>
#include <utility>
#include <vector>

class vtkCamera;
class vtkMatrix4x4;
class vtkUnstructuredGrid;

namespace hovTest
{
struct OracleOptions
{
  int RaysX = 160;
  int RaysY = 160;
  int RandomRays = 6000;
  unsigned Seed = 12345;
  double RelTol = 1e-7;
};

struct OracleResult
{
  // 1. permutation
  vtkIdType Missing = 0, Duplicates = 0, OutOfRange = 0;
  bool EveryCellOnce() const { return Missing == 0 && Duplicates == 0 && OutOfRange == 0; }
  // 2. rays
  vtkIdType Rays = 0, Hits = 0;
  vtkIdType PairsChecked = 0;     // ordered hit pairs examined (with repetitions)
  vtkIdType RayViolations = 0;    // distinct wrongly ordered cell pairs
  vtkIdType RaysWithViolation = 0;
  vtkIdType OverlappingPairs = 0; // distinct pairs of cells overlapping on a ray
  std::vector<std::pair<vtkIdType, vtkIdType>> Examples; // (front, back) wrongly ordered
  // 3. faces
  vtkIdType FacesChecked = 0, FaceViolations = 0;
  std::string Str() const;
};

/// Checks @p backToFront (input cell ids, rearmost first) for @p camera and
/// the model transform @p model (nullptr = identity).
OracleResult CheckVisibilityOrder(vtkUnstructuredGrid* grid, vtkCamera* camera,
  vtkMatrix4x4* model, const std::vector<vtkIdType>& backToFront,
  const OracleOptions& options = OracleOptions());
}

#endif
