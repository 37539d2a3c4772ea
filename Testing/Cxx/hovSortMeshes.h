/**
 * @file hovSortMeshes.h
 * @brief Test meshes and cameras for the visibility-sort property tests
 * (TestSort*.cxx): random jittered tetrahedral blocks, conforming mixed
 * meshes, the configurations of HIAC Fig. 5 and Fig. 6, interleaved long thin
 * cells, non-convex meshes (hole, notch), disconnected pieces, a sliding
 * interface, a cyclic triple and views from inside a hole. The meshes are in
 * hovSortMeshes.cxx, the random numbers, views and cameras in hovSortViews.cxx.
 *
 * Every generator is deterministic (fixed seeds, std::mt19937 with explicit
 * arithmetic, no std:: distributions whose output varies between libraries).
 * All cells are convex with planar faces (jitter moves only tetrahedra
 * vertices), non-intersecting and positively oriented, so the ray oracle
 * (hovSortOracle.h) applies to all of them.
 */
#ifndef hovSortMeshes_h
#define hovSortMeshes_h

#include "hovTestMeshes.h" // MeshBuilder

#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h" // returned by the generators

#include <functional>
#include <string>
#include <vector>

class vtkCamera;
class vtkMatrix4x4;

namespace hovTest
{
/// A small deterministic random generator (uniform doubles in [0, 1)).
struct SortRandom
{
  explicit SortRandom(unsigned seed);
  double Uniform();
  double Uniform(double a, double b) { return a + (b - a) * this->Uniform(); }
  unsigned long long State;
};

/// Kuhn tetrahedra (6 per cube) over the cubes (i,j,k) of an nx x ny x nz
/// lattice over [o, o+size] for which @p keep is true (all if empty); every
/// point is jittered by up to @p jitter lattice steps per axis and the jitter
/// is halved where a tetrahedron would get less than 20% of its volume.
MeshBuilder JitteredTetBlock(int nx, int ny, int nz, const double o[3], const double size[3],
  double jitter, unsigned seed, const std::function<bool(int, int, int)>& keep = {});

/// n^3 unit hexahedra over [0, n]^3 with every point moved by up to
/// +-jitter/2 per axis (non-planar faces); jitter 0: an axis-aligned grid.
vtkSmartPointer<vtkUnstructuredGrid> JitteredHexBlock(int n, double jitter);

/// Random jittered tetrahedral cube [0,1]^3 of n^3 Kuhn cubes (6 n^3 tets).
vtkSmartPointer<vtkUnstructuredGrid> RandomTetMesh(int n, unsigned seed);

/// Conforming mixed mesh on a rectilinear, non-uniformly spaced, rotated
/// grid: hexahedra and voxels, columns of wedge pairs, a layer of cubes split
/// into 5 pyramids + 2 tetrahedra, and Kuhn tetrahedra.
vtkSmartPointer<vtkUnstructuredGrid> MixedMesh(unsigned seed);

/// HIAC Fig. 5 (a): two tetrahedra whose screen projections (view along -z)
/// are disjoint although their x and y extents overlap.
vtkSmartPointer<vtkUnstructuredGrid> Fig5aMesh();
/// HIAC Fig. 5 (b): the projection of the small tetrahedron (cell 1) lies
/// inside the projection of the large one (cell 0) with no edge crossings;
/// the small one is in front.
vtkSmartPointer<vtkUnstructuredGrid> Fig5bMesh();
/// HIAC Fig. 6: as Fig. 5 (b), but the small tetrahedron (cell 1) is behind
/// the large one (cell 0) although its rearmost z is nearer than the large
/// one's, so the rough sort puts the large one first.
vtkSmartPointer<vtkUnstructuredGrid> Fig6Mesh();
/// The camera for the Fig. 5/6 meshes (looking down -z at the origin).
void FigureCamera(vtkCamera* cam, bool parallel);

/// Long thin triangular prisms (wedges) in a log pile: @p layers layers of
/// @p perLayer sticks, alternately along x and y, slightly tilted.
vtkSmartPointer<vtkUnstructuredGrid> InterleavedSticks(int layers, int perLayer);

/// A jittered tetrahedral block with a square hole through it along z.
vtkSmartPointer<vtkUnstructuredGrid> HoledBlock(int n, unsigned seed);
/// A jittered tetrahedral U: a block with a notch cut from the top (+y) face.
vtkSmartPointer<vtkUnstructuredGrid> NotchedBlock(int n, unsigned seed);
/// Several separated jittered blocks, some behind others along most views.
vtkSmartPointer<vtkUnstructuredGrid> DisconnectedBlocks(unsigned seed);
/// Two tetrahedral blocks sharing the plane x = 1 with non-conforming
/// triangulations (4^3 cubes against 3^3 cubes, no shared points).
vtkSmartPointer<vtkUnstructuredGrid> SlidingInterface(unsigned seed);
/// Three long thin wedges each lying over the next around a triangle (a
/// visibility cycle when seen along -z), not intersecting.
vtkSmartPointer<vtkUnstructuredGrid> CyclicTriple();
/// The same three sticks, each split into 3 tetrahedra (for the mapper,
/// which renders tetrahedra only).
vtkSmartPointer<vtkUnstructuredGrid> CyclicTripleTets();

/// A named camera for the property tests.
struct SortView
{
  std::string Name;
  bool Parallel = false;
  double Position[3] = { 0, 0, 1 };
  double FocalPoint[3] = { 0, 0, 0 };
  double ViewUp[3] = { 0, 1, 0 };
  double ViewAngle = 30;
  void Apply(vtkCamera* cam) const;
};

/// @p count views of the box @p bounds from random directions at 2.5-4 radii,
/// alternating perspective and parallel.
std::vector<SortView> RandomViews(const double bounds[6], int count, unsigned seed);

/// A perspective view from @p eye looking at @p focal (inside views).
SortView InsideView(const std::string& name, const double eye[3], const double focal[3]);

/// A rigid motion plus a non-uniform scale (a model transform for the tests).
void TestModelTransform(vtkMatrix4x4* m);

/// @p fn(cell, point ids) for every face of every cell of @p grid, as VTK's
/// own cells give them (vtkCell::GetFace): an independent reference for the
/// sort's face tables.
void ForEachVTKFace(vtkUnstructuredGrid* grid,
  const std::function<void(vtkIdType, const std::vector<vtkIdType>&)>& fn);
}

#endif
