/**
 * @class   vtkHighOrderProjectionRegions
 * @brief   CPU side of the OpenGL cell projection (HIAC section 7): the
 *          homogeneous regions of every projected convex cell and transfer-
 *          function slab, as triangles with per-vertex (L, tau_avg, colour).
 *
 * For each cell, in the back-to-front order given, and for each slab of it
 * between consecutive transfer-function nodes (HIAC Fig. 3; for linear
 * tetrahedra the field is affine, so a slab is the convex polyhedron cut by
 * the planes s = node; for GPU-compatible semantics the nodes include the
 * refinement nodes of the table, so extinction is linear in s on every slab),
 * the slab polyhedron's faces are projected to normalised device
 * coordinates (NDC) and classified front or back by their NDC plane. The
 * overlay of every front face with every back face (convex polygon clipping)
 * is the subdivision of the projection by all projected edges: on each of its
 * regions the ray enters through one planar face and leaves through one, so
 * the segment length L and the average extinction tau_avg are linear over the
 * region for a parallel projection (for a perspective projection they are
 * evaluated exactly at the region vertices and interpolated perspective-
 * correctly on the front face, an O((cell depth / eye distance)^2) relative
 * approximation inside the region). Each region is fan-triangulated. At
 * every region vertex the front and back points are unprojected exactly (in
 * double), L is measured in dataset coordinates (as in the CPU path), the
 * scalar is the cell's affine field at both points and the transfer function
 * table gives the segment ends; hov::ComputeProjectionVertex gives alpha and
 * colour per method M0-M3. Slabs are ordered back to front within a cell by
 * the distance of their scalar interval from the eye's level of the field
 * (rays from the eye cross the parallel level planes in that order).
 *
 * Non-tetrahedral cells (voxel, hexahedron, wedge, pyramid; the corner
 * cells of the quadratic types) are projected without tetrahedralization:
 * whole from their faces when no transfer-function node lies strictly inside
 * their corner scalar range, with the scalar at the front and back points
 * from the cell's own field; a node inside cuts them into slabs whose caps
 * pass through the edge crossings (approximate: counted in CutGeneral; see
 * vtkHighOrderProjectionPolyhedron). Slabs of a general cell are ordered by
 * the least-squares affine fit of its corner scalars.
 *
 * Cells with a corner on or behind the eye plane (clip w <= 0) are skipped
 * and counted. Output vertex layout: FloatsPerVertex floats: clip position
 * (x, y, z, w); ray (parallel: L, 0, 0, 0; perspective: P, mu); extinction
 * (parallel: 0, tau_avg; perspective: tauFront, tauBack mu); colour (r, g,
 * b); alpha (M0).
 *
 * Thread safety: Build() runs the cells in parallel (vtkSMPTools, chunks
 * concatenated in order: the output does not depend on the thread count).
 * @sa vtkHighOrderProjectionRenderer, hovProjectionColor.h, vtkHighOrderVolumeMapper
 */
#ifndef vtkHighOrderProjectionRegions_h
#define vtkHighOrderProjectionRegions_h

#include "hovProjectionColor.h" // ProjectionColorMethod, SegmentColorTable

#include "vtkType.h" // vtkIdType

#include <glm/glm.hpp> // dvec3, dmat4

#include <vector> // buffers

class vtkHighOrderTetraSetup;
namespace hov
{
class TransferFunction;
}

class vtkHighOrderProjectionRegions
{
public:
  static constexpr int FloatsPerVertex = 14;

  struct Settings
  {
    hov::ProjectionColorMethod Method = hov::ProjectionColorMethod::ExactColor;
    hov::EmissionModel Emission = hov::EmissionModel::WilliamsMax;
    glm::dmat4 Composite{ 1.0 }; ///< dataset coordinates -> clip coordinates
    bool Parallel = false;
    glm::dvec3 Eye{ 0.0 };       ///< perspective: camera position (dataset coordinates)
    glm::dvec3 Direction{ 0.0 }; ///< parallel: direction of projection (dataset coordinates)
  };

  struct Statistics
  {
    vtkIdType Cells = 0;
    vtkIdType Slabs = 0;
    vtkIdType Triangles = 0;
    vtkIdType BehindEye = 0;  ///< cells skipped: a corner on or behind the eye plane
    vtkIdType CutGeneral = 0; ///< non-tetrahedral cells cut by transfer-function nodes (approximate)
  };

  /**
   * Triangles of all rendered cells of @p setup in the order @p backToFront
   * (rendered-cell indices) into @p vertices (resized).
   */
  Statistics Build(const vtkHighOrderTetraSetup& setup, const std::vector<vtkIdType>& backToFront,
    const hov::TransferFunction& tf, const Settings& settings, std::vector<float>& vertices) const;

  /**
   * The approximate order (for interaction): rendered cells sorted back to
   * front by the distance of their corner centroid from the eye (perspective)
   * or its depth along the direction of projection (parallel); ties by index.
   */
  static void CentroidOrder(const vtkHighOrderTetraSetup& setup, const Settings& settings,
    std::vector<vtkIdType>& backToFront);

private:
  hov::SegmentColorTable ColorTable;
};

#endif
