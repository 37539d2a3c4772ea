/**
 * @file hovCurvedRayCaster.h
 * @brief Per-ray volume rendering of a mesh of (curved) Lagrange cells: a
 * bounding-volume hierarchy over the cells, all ray-cell intervals
 * (hovCurvedRayCell.h), each integrated with categorization, breakpoint
 * location and exact-depth quadrature (hovCurvedSegment.h), composited front
 * to back in ray order. No global visibility sort: every ray sorts its own
 * segments, so non-convex meshes and rays that leave and re-enter a cell
 * need nothing special. Cells a table makes invisible over their whole
 * field hull (IsCellInvisible) can be left out of a ray's intervals
 * (TraceRay's skipCells).
 *
 * The pure C++ core of issue 6's ray-cast render mode (the VTK adapter,
 * Mapper/RayCast/hovRayCast*, converts a vtkUnstructuredGrid into a
 * CurvedMeshInput, builds pixel rays with hov::ViewRays and calls
 * TraceRay from vtkSMPTools::For).
 *
 * Build(): per cell, its nodes gathered (coordinates, scalars), its
 * boundary patches (BuildCurvedFaces) and its bounding box (the patches'
 * control nets: contains the curved cell); one LagrangeBasis per distinct
 * (type, orders, node count). The cell's second-derivative bounds
 * (ComputeCellDerivativeBounds, the costly part: ~1 ms for an order-4
 * tetrahedron) are computed on the first ray that needs them
 * (std::call_once), so cells no ray reaches cost nothing.
 * Cells whose nodes all lie on one affine map (straight-sided; 41% of
 * the T-junction's tetrahedra) are flagged: their inside interval is the
 * clip of the parametric line pc(t) against the reference cell's faces
 * (exact, no face search). The face nets are built on all cores.
 * BVH: binary, split at the median centroid along the
 * longest axis of the centroids' box, leaves of <= 4 cells.
 * Faces shared by two curved cells are linked (hovCurvedSharedFaces.h):
 * per ray, such a face is searched by the first of its cells the ray meets
 * and its crossings handed to the other.
 * TraceRay(): the cells whose boxes the ray meets (slab test, front to back
 * traversal), their inside intervals, sorted by entry, each part of the
 * ray kept once (a ray in a face shared by two cells, or on an edge shared
 * by several, gets the same interval from each); segments are
 * integrated in that order and composited; the ray stops when its opacity
 * reaches 1 - settings.TerminationTransmittance (default OpacityCutoff,
 * 1e-12). The tolerance is per pixel: when the sum of
 * the segments' error estimates (each weighted by the transmittance in front
 * of it) exceeds Quadrature.Tolerance, the ray is integrated again with the
 * segment tolerance scaled by 0.5 x tolerance / sum (adaptive method only, at
 * most 3 integrations, not below 1e-13). Overlapping intervals (a shared face computed
 * from both sides: ~1e-13 apart) are not an issue at that size.
 *
 * Bad input: cell types other than 71/72/73, node counts or degrees VTK
 * cannot store, and point ids out of range skip the cell (counted, with the
 * first message kept); the rest renders.
 *
 * Measured (TestCurvedRayCaster, TestLagrangeDatasets; GCC 12 Release):
 * against a whole-ray reference (inside intervals by bisection, each
 * integrated by the long-double polynomial-ray reference) on 2x2x2 meshes of
 * order-2/3 hexahedra: max RGBA error 5.6e-16 (affine), 4.7e-16 (curved map
 * x = X + 0.3 Y^2), 8.9e-16 (non-convex: one cell removed, rays re-enter);
 * real order-4 datasets: every cell usable, error estimates <= 1.5e-9.
 * Cost (hovBenchRayCast: 256x256 view along -z, every 16th pixel, all
 * rays counted; medians of 3 runs interleaved with the previous code, GCC 12
 * Release, 2 cores at load 6-8): Build 0.037 s (was 0.061) for 192 Q4
 * hexahedra, 0.27 s (was 0.83) for 3790 P4 tetrahedra; one thread
 * 0.28 ms/ray (was 0.55) on the Q4 plate, 1.7 ms/ray (was 24.5) through
 * the P4 T-junction (12.5 segments per hit ray); first frame with the lazy
 * derivative bounds 0.10 s / 1.25 s (was 0.20 s / 5.96 s). Where it went:
 * the coarse categorization enclosure (hovCurvedSegment.h), the affine
 * path, the equispaced-Lagrange table, sum-factorised hexahedron and
 * templated node-loop interpolation. What remains: the Taylor-model pieces
 * (Newton + field restriction), the curved face search, the lazy bounds.

 * Thread safety: Build() is not thread safe; TraceRay() is (const; the
 * lazily computed bounds are guarded by one std::once_flag per cell).
 * @sa hovCurvedRayCell.h, hovCurvedSegment.h, hovLagrangeBasis.h
 */
#ifndef hovCurvedRayCaster_h
#define hovCurvedRayCaster_h

#include "hovBlendModes.h" // TraceRayBlend
#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovCurvedFaces.h"
#include "hovCurvedSharedFaces.h" // CellFaceLinks
#include "hovCurvedSegment.h"
#include "hovEnclosure.h"
#include "hovLagrangeBasis.h"
#include "hovLagrangeHull.h"

#include <cstdint> // point ids
#include <memory>  // per-cell once flags
#include <mutex>   // std::call_once
#include <string>  // Build() messages
#include <vector>  // mesh storage

namespace hov
{
class TransferFunction;

/// A mesh in VTK's layout (not owned; read during Build() only).
struct CurvedMeshInput
{
  const double* Points = nullptr;  ///< 3 per point
  std::int64_t NumberOfPoints = 0;
  const double* Scalars = nullptr; ///< 1 per point
  const unsigned char* CellTypes = nullptr;
  const std::int64_t* Offsets = nullptr; ///< NumberOfCells + 1 entries into Connectivity
  const std::int64_t* Connectivity = nullptr;
  std::int64_t NumberOfCells = 0;
  const int* Degrees = nullptr; ///< 3 per cell (HigherOrderDegrees), may be null
};

struct CurvedRayStats
{
  int CandidateCells = 0; ///< boxes hit
  int Segments = 0;       ///< inside intervals integrated
  int Breakpoints = 0;
  int Samples = 0;        ///< field samples of the fixed-sample rules (CurvedSegmentResult::Samples)
  bool Converged = true;
  /// Integrations of the ray (1; more when the summed error estimate
  /// exceeded the tolerance and the ray was integrated again, tighter).
  int TolerancePasses = 0;
};

class HOV_EXPORT CurvedRayCaster
{
public:
  /// The default transmittance at which a ray stops
  /// (CurvedSegmentSettings::TerminationTransmittance).
  static constexpr double OpacityCutoff = 1e-12;

  /**
   * Prepare the mesh (see file doc). Returns false if no cell is usable;
   * @p message receives a summary of skipped cells (if any).
   */
  bool Build(const CurvedMeshInput& input, std::string* message = nullptr);

  std::int64_t GetNumberOfCells() const { return static_cast<std::int64_t>(this->Cells.size()); }
  std::int64_t GetNumberOfSkippedCells() const { return this->Skipped; }
  /// Bounds (xmin, xmax, ymin, ymax, zmin, zmax) of all usable cells.
  const double* GetBounds() const { return this->Bounds; }
  /// Faces shared by two curved cells, searched once per ray (default on;
  /// hovCurvedSharedFaces.h). Set before Build().
  void SetShareFaces(bool share) { this->ShareFaces = share; }
  /// The number of faces linked by the last Build().
  int GetNumberOfSharedFaces() const { return this->SharedFaces; }
  /// Cells of the last Build whose geometry is the trilinear map of their
  /// corners (IsLagrangeGeometryTrilinear; not affine): evaluated as that map,
  /// with bilinear face patches.
  int GetNumberOfTrilinearCells() const
  {
    int n = 0;
    for (const Cell& cell : this->Cells)
    {
      n += cell.Trilinear && !cell.Affine ? 1 : 0;
    }
    return n;
  }

  /**
   * Whether cell @p cell (0 .. GetNumberOfCells() - 1) can add nothing to a
   * composite ray under @p tf: CategorizeSegment over the cell's rigorous
   * field hull is Empty (no extinction on the whole hull, and under
   * Wilhelms-Van Gelder no colour either). IntegrateCurvedSegment returns
   * exactly zero for every segment of such a cell; so does the shaded
   * integral under Williams-Max (emission = shaded colour x extinction, and
   * gradient opacity scales a zero extinction), but not under Wilhelms-Van
   * Gelder, where the specular term glows without colour or extinction.
   */
  bool IsCellInvisible(std::int64_t cell, const TransferFunction& tf, EmissionModel emission) const;

  /**
   * Premultiplied RGBA of the ray o + t d, t in [@p tMin, @p tMax] (t = 0
   * at the eye side), and the summed error estimate in @p errorEstimate.
   * With @p skipCells (one flag per cell; ignored for shaded or
   * gradient-opacity rays under Wilhelms-Van Gelder: IsCellInvisible), the
   * flagged cells' intervals are not computed (no face search, no inversion)
   * and the field error budget is spread over the other segments only.
   */
  RGBA TraceRay(const double origin[3], const double direction[3], double tMin, double tMax,
    const TransferFunction& tf, const CurvedSegmentSettings& settings, double* errorEstimate = nullptr,
    CurvedRayStats* stats = nullptr, const unsigned char* skipCells = nullptr) const;

  /**
   * The blend modes (hovBlendModes.h): every segment of the ray o + t d,
   * t in [@p tMin, @p tMax], accumulated into @p state (no compositing, no
   * early termination): the field's pieces (RepresentFieldOnSegment, with
   * their error bound e_i) as polynomials of degree <= 8 (ApproximateBernstein,
   * bisected while its bound exceeds FieldTolerance x the field scale; its
   * bound added to e_i) in the world length along the ray; a cell with equal
   * node scalars (cell scalars) is one exact constant segment. Implemented in
   * hovCurvedRayBlend.cxx.
   */
  void TraceRayBlend(const double origin[3], const double direction[3], double tMin, double tMax,
    const TransferFunction& table, const BlendSettings& blend,
    const CurvedSegmentSettings& settings, RayBlendState& state,
    CurvedRayStats* stats = nullptr) const;

private:
  /// One ray segment: an inside interval of one cell.
  struct Segment
  {
    double T0, T1;
    int Cell;
    double PC0[3], PC1[3]; ///< parametric coordinates at T0 and T1
  };
  /// The ray's inside intervals, sorted, each part of the ray once (file doc);
  /// cells flagged in @p skip (may be null) are left out.
  void CollectSegments(const double origin[3], const double direction[3], double tMin,
    double tMax, std::vector<Segment>& segments, CurvedRayStats& st,
    const unsigned char* skip = nullptr) const;

  struct Cell
  {
    int Basis = 0;
    std::vector<double> Points;
    std::vector<double> Scalars;
    std::vector<std::int64_t> CornerIds; ///< point ids of the corner nodes
    CurvedCellFaces Faces;
    /// A hexahedron whose nodes lie on the trilinear map of its corners
    /// (IsLagrangeGeometryTrilinear): its view evaluates that map.
    bool Trilinear = false;
    /// Affine geometry map x = X0 + J pc at every node (straight-sided cell
    /// of a simplex-like shape or a parallelepiped): intervals by clipping
    /// pc(t) = X0inv + t Dinv against the reference cell's half-spaces.
    bool Affine = false;
    double X0[3] = { 0.0, 0.0, 0.0 };
    double InverseJ[9] = {}; ///< J^-1, row-major
    /// Rigorous hull of the field over the cell (LagrangeHull; the special
    /// cells: the derivative bounds' FieldMin/FieldMax) and its scale.
    double FieldLo = 0.0, FieldHi = 0.0, FieldScale = 1.0;
    /// Computed on first use by TraceRay (std::call_once: thread safe).
    mutable CellDerivativeBounds Bounds;
    mutable std::unique_ptr<std::once_flag> BoundsOnce;
  };
  const CellDerivativeBounds& CellBounds(const Cell& cell) const;
  struct Node
  {
    double Box[6];
    int Left = -1, Right = -1; ///< children (inner nodes)
    int First = 0, Count = 0;  ///< range in CellOrder (leaves)
  };
  int BuildNode(int first, int count, std::vector<double>& centroids);
  void DetectAffine(Cell& cell) const;
  /// The cell bound to its basis (with the extent once the faces are built).
  LagrangeCellView View(const Cell& cell) const
  {
    LagrangeCellView view{ &this->Bases[cell.Basis], cell.Points.data(), cell.Scalars.data(),
      cell.Faces.Extent };
    view.Trilinear = cell.Trilinear;
    return view;
  }
  /// FieldLo, FieldHi, FieldScale of @p cell.
  void FieldHull(Cell& cell) const;
  int AffineInterval(const Cell& cell, const double o[3], const double d[3], double t0, double t1,
    double& ta, double& tb, double pc[3]) const;
  void CollectCandidates(const double o[3], const double d[3], double tMin, double tMax,
    std::vector<int>& out) const;

  std::vector<LagrangeBasis> Bases;
  std::vector<LagrangeHull> Hulls; ///< per basis (not initialised for the special cells)
  std::vector<Cell> Cells;
  std::vector<int> CellOrder;
  std::vector<Node> Nodes;
  std::vector<CellFaceLinks> Links; ///< per cell (empty: faces not shared)
  bool ShareFaces = true;
  int SharedFaces = 0;
  std::int64_t Skipped = 0;
  double Bounds[6] = { 0, -1, 0, -1, 0, -1 };
};
}

#endif
