/**
 * @file hovTestMixed.h
 * @brief Shared by TestMixed* and TestClip*: unit cubes split into every cell
 * type of the CPU path (hexahedra, voxels, wedges, pyramids, tetrahedra and
 * their straight-edged quadratic forms), positively oriented, and the
 * mapper's image in double precision.
 */
#ifndef hovTestMixed_h
#define hovTestMixed_h

#include "hovTestImages.h"
#include "hovTestMeshes.h"

#include <array>
#include <functional>

class vtkCamera;
class vtkHighOrderVolumeMapper;
class vtkVolume;

namespace hovTest
{
/// How a cube is split.
enum class CubeSplit
{
  Hexahedron,
  QuadraticHexahedron,    ///< 20 nodes
  TriQuadraticHexahedron, ///< 27 nodes
  Voxel,
  Wedges,          ///< 2 wedges along the diagonal plane through edges 0-4 and 2-6
  QuadraticWedges, ///< the same, 15 nodes each
  Pyramids,        ///< 6 pyramids with their apex at the cube centre (a new point)
  QuadraticPyramids,
  Tetras,         ///< 6 Kuhn tetrahedra along the diagonal 0-6
  QuadraticTetras ///< the same, 10 nodes each
};

const char* CubeSplitName(CubeSplit split);

using Field = std::function<double(double, double, double)>;

/**
 * Adds the cube whose 8 corner point ids are @p c (hexahedron order: c0..c3
 * the bottom face counterclockwise seen from above, c4..c7 above them; any
 * convex hexahedron works, e.g. a parallelepiped) split as @p split. New
 * points (pyramid apex, quadratic nodes at their straight-edged positions)
 * get the scalar @p f. Every cell is positively oriented (VTK's reference
 * orientation).
 */
void AddCube(MeshBuilder& m, const std::array<vtkIdType, 8>& c, CubeSplit split, const Field& f);

/// Adds the points of an (nx+1)(ny+1)(nz+1) lattice x = o + A (i, j, k) and
/// returns their ids, index (i, j, k) at i + (nx+1) (j + (ny+1) k).
std::vector<vtkIdType> AddLattice(MeshBuilder& m, int nx, int ny, int nz, const double o[3],
  const double a[3][3], const Field& f);

/// The corner ids of lattice cube (i, j, k) in hexahedron order.
std::array<vtkIdType, 8> LatticeCube(
  const std::vector<vtkIdType>& ids, int nx, int ny, int i, int j, int k);

/// RenderImage and the double-precision image (GetDoubleImage); status in @p status.
Image RenderDouble(vtkHighOrderVolumeMapper* mapper, vtkCamera* cam, vtkVolume* vol, int w,
  int h, int* status = nullptr);

/**
 * Where the orthographic ray of pixel (i, j) of an n x n image of @p cam
 * (built from the camera's parameters, not the module's rays) crosses the
 * plane x[axis] = level: the point's coordinates in @p p.
 */
void OrthoRayPlaneCrossing(vtkCamera* cam, int n, int i, int j, int axis, double level, double p[3]);
}

#endif
