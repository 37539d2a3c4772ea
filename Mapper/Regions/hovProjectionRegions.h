/**
 * @class   hov::ProjectionRegions
 * @brief   CPU side of the OpenGL cell projection (HIAC section 7): the
 *          homogeneous regions of every projected convex cell and transfer-
 *          function slab, as triangles with per-vertex (L, tau_avg, colour).
 *
 * For each cell, in the back-to-front order given, and for each slab of it
 * between consecutive transfer-function nodes (HIAC Fig. 3; for linear
 * tetrahedra the field is affine, so a slab is the convex polyhedron cut by
 * the planes s = node; for GPU-compatible semantics the table given is
 * vtkHighOrderTransferFunction's linear-opacity table: opacity linear in s on
 * every slab, the fragment shader's extinction exact from it),
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
 * hov::ProjectionPolyhedron). Slabs of a general cell are ordered by
 * the least-squares affine fit of its corner scalars.
 *
 * A linear tetrahedron with no transfer-function node strictly inside its
 * scalar range (one slab: most cells of a smooth field) takes the fast path
 * hov::ProjectionTetra (Shirley-Tuchman classification: the same
 * regions, 3 or 4 triangles, 4 or 5 vertices) and falls back to the general
 * path only if its projection is degenerate.
 *
 * Cells with a corner on or behind the eye plane (clip w <= 0) are skipped
 * and counted. Output: indexed triangles (hov::ProjectionVertex
 * records) in chunks of consecutive cells, each chunk's indices local to it;
 * Geometry::VertexOffsets / IndexOffsets place the chunks in one buffer.
 * Build() takes a range of the order, so that a caller can build and draw
 * the cells group by group (hov::ProjectionRenderer).
 *
 * Thread safety: Build() runs the cells in parallel (vtkSMPTools, one chunk
 * per CellsPerChunk cells, concatenated in order: the output does not depend
 * on the thread count); it reads the tetrahedra a few cells ahead into the
 * cache (the order is random in memory).
 * @sa hov::ProjectionRenderer, hovProjectionColor.h, vtkHighOrderVolumeMapper
 */
#ifndef hovProjectionRegions_h
#define hovProjectionRegions_h

#include "hovProjectionColor.h"           // ProjectionColorMethod, SegmentColorTable
#include "hovProjectionVertex.h" // chunks

#include "vtkType.h" // vtkIdType

#include <glm/glm.hpp> // dvec3, dmat4

#include <cstdint> // uint64_t
#include <vector>  // buffers

namespace hov
{
class CellSetup;
}
namespace hov
{
class TransferFunction;
}

namespace hov
{
class ProjectionRegions
{
public:
  static constexpr int FloatsPerVertex = hov::ProjectionVertex::FloatsPerVertex;
  static constexpr long long CellsPerChunk = 512;

  /// The triangles of a frame; the chunks keep their storage across frames.
  struct Geometry
  {
    std::vector<hov::ProjectionChunk> Chunks;
    std::vector<size_t> VertexOffsets; ///< first vertex of each chunk, then the total
    std::vector<size_t> IndexOffsets;  ///< first index of each chunk, then the total
    size_t GetNumberOfVertices() const { return this->VertexOffsets.empty() ? 0 : this->VertexOffsets.back(); }
    size_t GetNumberOfIndices() const { return this->IndexOffsets.empty() ? 0 : this->IndexOffsets.back(); }
    void Clear()
    {
      this->VertexOffsets.assign(1, 0);
      this->IndexOffsets.assign(1, 0);
      for (auto& chunk : this->Chunks)
      {
        chunk.Clear();
      }
    }
  };

  struct Settings
  {
    hov::ProjectionColorMethod Method = hov::ProjectionColorMethod::ExactColor;
    hov::EmissionModel Emission = hov::EmissionModel::WilliamsMax;
    glm::dmat4 Composite{ 1.0 }; ///< dataset coordinates -> clip coordinates
    bool Parallel = false;
    glm::dvec3 Eye{ 0.0 };       ///< perspective: camera position (dataset coordinates)
    glm::dvec3 Direction{ 0.0 }; ///< parallel: direction of projection (dataset coordinates)
    /// GPU-compatible semantics: the refined extinction table (Build()'s table
    /// is then the linear-opacity one; hov::ProjectionFrame).
    const hov::TransferFunction* ExtinctionTf = nullptr;
    double InverseUnit = 1.0;
  };

  struct Statistics
  {
    vtkIdType Cells = 0;
    vtkIdType Slabs = 0;
    vtkIdType Triangles = 0;
    vtkIdType BehindEye = 0;  ///< cells skipped: a corner on or behind the eye plane
    vtkIdType CutGeneral = 0; ///< non-tetrahedral cells cut by transfer-function nodes (approximate)
    vtkIdType FastTetras = 0; ///< tetrahedra drawn by hov::ProjectionTetra

    void Add(const Statistics& other)
    {
      this->Cells += other.Cells;
      this->Slabs += other.Slabs;
      this->Triangles += other.Triangles;
      this->BehindEye += other.BehindEye;
      this->CutGeneral += other.CutGeneral;
      this->FastTetras += other.FastTetras;
    }
  };

  /**
   * Triangles of the rendered cells backToFront[begin .. end) of @p setup
   * (rendered-cell indices, back to front) into @p geometry (cleared first).
   */
  Statistics Build(const hov::CellSetup& setup, const std::vector<vtkIdType>& backToFront,
    vtkIdType begin, vtkIdType end, const hov::TransferFunction& tf, const Settings& settings,
    Geometry& geometry) const;

  /**
   * The approximate order (for interaction): rendered cells sorted back to
   * front by the distance of their corner centroid from the eye (perspective)
   * or its depth along the direction of projection (parallel), as a float
   * (cells closer than its resolution count as tied); ties by index. Keys in
   * parallel, then a radix sort (linear time); storage kept across frames.
   * At most 2^32 cells.
   */
  void CentroidOrder(const hov::CellSetup& setup, const Settings& settings,
    std::vector<vtkIdType>& backToFront);

private:
  hov::SegmentColorTable ColorTable;
  std::vector<uint64_t> OrderItems, OrderScratch; ///< (key bits << 32 | cell)
};
}

#endif
