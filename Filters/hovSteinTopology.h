/**
 * @file hovSteinTopology.h
 * @brief View-independent face adjacency of vtkSteinVisibilitySort's
 *        ADJACENCY_GRAPH algorithm: interior faces and boundary faces.
 *
 * The faces of all supported cells are matched by their sorted corner point ids
 * (triangles by 3 ids, quadrilaterals by their 4 corners): the faces are
 * bucketed by their smallest point id (a counting sort, O(faces)) and each
 * bucket is sorted and scanned in parallel. Each bucket entry carries its
 * face's other sorted corner ids (computed while the cells are read in order),
 * so the matching reads the bucket, not the cells' tables at random. A face is
 * INTERIOR when exactly two cells A and B share it, both have a usable face code there (not FaceSkip), and
 * B lies on the outer side of A's face: exact faces need every corner of B on
 * the closed outer side (exact Orient3d) and one strictly outside; Newell faces
 * need B's corners off the face outside its deviation slab. Every other face
 * (mesh boundary, sliding interfaces, hanging nodes, duplicated points or cells,
 * flat cells) is a BOUNDARY face; a cell with at least one is a boundary cell.
 *
 * Thread safety: Build() is not re-entrant; the built data are read-only.
 */
#ifndef hovSteinTopology_h
#define hovSteinTopology_h

#include "hovSteinGeometry.h"    // Geometry

#include <cstdint> // std::int32_t, std::uint8_t
#include <vector>  // storage

namespace hovStein
{
/// Cells and interior faces in the adjacency arrays (Topology, Digraph): 32
/// bits, half the memory of vtkIdType (2M tetrahedra: 128 MB less).
/// Topology::Build requires at most MaxIndexedCells cells (6 faces a cell:
/// 2 * interior face + 1 then fits in 32 unsigned bits).
using CellIndex = std::int32_t;
constexpr vtkIdType MaxIndexedCells = 700000000;

struct ChunkMatches; // what Build's face matching finds in a chunk of buckets

struct Topology
{
  /// Interior faces: cells A and B (B on the outer side of face FaceA[i] of A).
  FillBuffer<CellIndex> A, B;
  FillBuffer<std::uint8_t> FaceA;
  /// Per interior face, 3 entries: for an exact face of A, the point ids of
  /// Geometry::ExactTriple(A, FaceA), so that each view's side test reads them
  /// and the points instead of A's tables at random; NoTriple first for
  /// other faces. 12 bytes a face (a filtered plane per face was 48: 190 MB for
  /// 2M tetrahedra). Empty when the point ids do not fit in 32 bits.
  FillBuffer<std::uint32_t> TripleA;
  static constexpr std::uint32_t NoTriple = 0xffffffffu;
  /// Per cell: its interior faces (CSR, in increasing interior face index) as
  /// 2 * index + 1 if the cell is the face's B, 2 * index if it is its A.
  FillBuffer<vtkIdType> CellFaceOffsets; ///< per cell + 1
  FillBuffer<std::uint32_t> CellFaces;
  FillBuffer<CellIndex> CellNeighbours; ///< beside CellFaces: the cell on the other side
  /// Per cell: bit f set when face f is a boundary face.
  std::vector<std::uint8_t> BoundaryFaces;
  vtkIdType NumberOfBoundaryCells = 0;

  /// A boundary face of a supported cell.
  struct BoundaryFace
  {
    vtkIdType Cell;
    std::uint8_t Face, Mode; ///< Mode: FaceCode & 3
  };
  /// The boundary faces in cell order, by face within a cell.
  FillBuffer<BoundaryFace> Boundary;

  /// Distinct for every Build() of any Topology (for caches derived from it).
  unsigned long Generation = 0;

  vtkIdType NumberOfInteriorFaces() const { return static_cast<vtkIdType>(this->A.size()); }
  /// Builds everything from @p g. @p wideEntries: match the faces with 64-bit
  /// entries even where 32-bit ones fit (the same result; for tests).
  void Build(const Geometry& g, bool wideEntries = false);

private:
  /// The matched chunks' interior faces made contiguous; BoundaryFaces.
  void Collect(const Geometry& g, const std::vector<ChunkMatches>& chunks);
  void BuildCellFaces(const Geometry& g);
  /// Boundary and NumberOfBoundaryCells (from BoundaryFaces).
  void BuildBoundary(const Geometry& g);
};
}

#endif
