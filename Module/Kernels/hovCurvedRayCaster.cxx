// Per-ray volume rendering of curved Lagrange meshes: see hovCurvedRayCaster.h.
#include "hovCurvedRayCaster.h"

#include "hovCurvedRayCell.h"     // inside intervals
#include "hovRayClip.h"           // ClipRayToBox
#include "hovTransferFunction.h"  // TraceRay's table
#include "hovCurvedShadedSegment.h" // shaded segments
#include "hovVolumeShading.h"       // VolumeShadingSettings::Shade

#include <algorithm> // std::nth_element, std::sort, std::min, std::max
#include <atomic>    // Build()'s work counter
#include <cmath>     // std::isfinite, std::abs
#include <limits>    // infinity
#include <thread>    // Build()'s face-net pass

namespace hov
{
namespace
{
/// Cells per BVH leaf.
constexpr int LeafSize = 4;
/// Intervals per ray and cell kept.
constexpr int MaxIntervalsPerCell = 16;
/// Build(): cells per work item and the thread cap of the face-net pass.
constexpr size_t FaceBatch = 32;
constexpr unsigned MaxBuildThreads = 16;
/// TraceRay: integrations of one ray at most (the first plus re-integrations
/// with tighter segment tolerances), and the tightest segment tolerance.
constexpr int MaxTolerancePasses = 3;
constexpr double MinSegmentTolerance = 1e-13;
/// TraceRay: an interval ending within this (relative) of what earlier
/// intervals cover adds nothing and is dropped.
constexpr double CoverTolerance = 1e-10;

void MergeBox(double into[6], const double box[6])
{
  for (int k = 0; k < 3; ++k)
  {
    into[2 * k] = std::min(into[2 * k], box[2 * k]);
    into[2 * k + 1] = std::max(into[2 * k + 1], box[2 * k + 1]);
  }
}

}

bool CurvedRayCaster::Build(const CurvedMeshInput& input, std::string* message)
{
  this->Bases.clear();
  this->Hulls.clear();
  this->Cells.clear();
  this->CellOrder.clear();
  this->Nodes.clear();
  this->Skipped = 0;
  std::string first;
  auto skip = [&](std::int64_t c, const std::string& why) {
    if (this->Skipped++ == 0)
    {
      first = "cell " + std::to_string(c) + ": " + why;
    }
  };
  if (!input.Points || !input.Scalars || !input.CellTypes || !input.Offsets || !input.Connectivity)
  {
    if (message)
    {
      *message = "incomplete mesh input (points, scalars, cell types or connectivity missing)";
    }
    return false;
  }
  std::vector<std::int64_t> inputIds; // input cell id of each kept cell
  for (std::int64_t c = 0; c < input.NumberOfCells; ++c)
  {
    const int type = input.CellTypes[c];
    const std::int64_t begin = input.Offsets[c], n = input.Offsets[c + 1] - begin;
    const int* degrees = input.Degrees ? input.Degrees + 3 * c : nullptr;
    if (type < 71 || type > 73)
    {
      skip(c, "type " + std::to_string(type) + " is not a Lagrange tetrahedron/hexahedron/wedge");
      continue;
    }
    const LagrangeShape shape = static_cast<LagrangeShape>(type);
    int basis = -1;
    for (size_t b = 0; b < this->Bases.size() && basis < 0; ++b)
    {
      const LagrangeBasis& B = this->Bases[b];
      const bool sameOrders = !degrees || shape == LagrangeShape::Tetra || B.IsSpecial() ||
        (B.GetOrder()[0] == degrees[0] && B.GetOrder()[1] == degrees[1] && B.GetOrder()[2] == degrees[2]);
      basis = (B.GetShape() == shape && B.GetNodeCount() == n && sameOrders) ? static_cast<int>(b) : -1;
    }
    if (basis < 0)
    {
      LagrangeBasis B;
      std::string why;
      if (!B.Initialize(shape, static_cast<int>(n), degrees, &why))
      {
        skip(c, why);
        continue;
      }
      this->Bases.push_back(B);
      this->Hulls.emplace_back();
      this->Hulls.back().Initialize(B); // false for the special cells: see FieldHull
      basis = static_cast<int>(this->Bases.size()) - 1;
    }
    Cell cell;
    cell.Basis = basis;
    cell.Points.resize(3 * n);
    cell.Scalars.resize(n);
    bool ok = true;
    for (std::int64_t i = 0; i < n && ok; ++i)
    {
      const std::int64_t id = input.Connectivity[begin + i];
      ok = id >= 0 && id < input.NumberOfPoints;
      for (int k = 0; k < 3 && ok; ++k)
      {
        cell.Points[3 * i + k] = input.Points[3 * id + k];
        ok = std::isfinite(cell.Points[3 * i + k]);
      }
      cell.Scalars[i] = ok ? input.Scalars[id] : 0.0;
      ok = ok && std::isfinite(cell.Scalars[i]);
    }
    cell.BoundsOnce = std::make_unique<std::once_flag>();
    const int corners = shape == LagrangeShape::Tetra ? 4 : shape == LagrangeShape::Wedge ? 6 : 8;
    cell.CornerIds.assign(input.Connectivity + begin, input.Connectivity + begin + std::min<std::int64_t>(corners, n));
    if (!ok)
    {
      skip(c, "point id out of range or non-finite point/scalar");
      continue;
    }
    this->Cells.push_back(std::move(cell));
    inputIds.push_back(c);
  }
  // The face nets (the costly part of Build), on all cores: cells are independent.
  std::vector<char> built(this->Cells.size(), 0);
  std::atomic<size_t> next{ 0 };
  auto work = [&]() {
    for (size_t i = next.fetch_add(FaceBatch); i < this->Cells.size(); i = next.fetch_add(FaceBatch))
    {
      for (size_t j = i; j < std::min(i + FaceBatch, this->Cells.size()); ++j)
      {
        Cell& cell = this->Cells[j];
        cell.Trilinear = IsLagrangeGeometryTrilinear(this->View(cell));
        const LagrangeCellView view = this->View(cell);
        built[j] = BuildCurvedFaces(view, cell.Faces) ? 1 : 0;
        this->FieldHull(cell);
      }
    }
  };
  const unsigned threads = std::max(1u,
    std::min({ std::thread::hardware_concurrency(), MaxBuildThreads,
      static_cast<unsigned>(this->Cells.size() / FaceBatch) }));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t)
  {
    pool.emplace_back(work);
  }
  work();
  for (std::thread& t : pool)
  {
    t.join();
  }
  for (Cell& cell : this->Cells)
  {
    this->DetectAffine(cell);
  }
  size_t kept = 0;
  for (size_t j = 0; j < this->Cells.size(); ++j)
  {
    if (!built[j])
    {
      skip(inputIds[j], "face patches could not be built");
      continue;
    }
    if (kept != j)
    {
      this->Cells[kept] = std::move(this->Cells[j]);
    }
    ++kept;
  }
  this->Cells.resize(kept);
  this->Links.clear();
  this->SharedFaces = 0;
  if (this->ShareFaces)
  {
    std::vector<SharedFaceCell> linkCells(this->Cells.size());
    for (size_t c = 0; c < this->Cells.size(); ++c)
    {
      const Cell& cell = this->Cells[c];
      linkCells[c].View = this->View(cell);
      linkCells[c].Faces = &cell.Faces;
      linkCells[c].CornerIds = cell.CornerIds.data();
    }
    this->SharedFaces = LinkSharedFaces(linkCells, this->Links);
  }
  if (message)
  {
    *message = this->Skipped
      ? std::to_string(this->Skipped) + " cell(s) skipped; first: " + first
      : std::string();
  }
  if (this->Cells.empty())
  {
    return false;
  }
  std::vector<double> centroids(3 * this->Cells.size());
  for (size_t c = 0; c < this->Cells.size(); ++c)
  {
    const double* b = this->Cells[c].Faces.Bounds;
    for (int k = 0; k < 3; ++k)
    {
      centroids[3 * c + k] = 0.5 * (b[2 * k] + b[2 * k + 1]);
    }
    this->CellOrder.push_back(static_cast<int>(c));
  }
  this->BuildNode(0, static_cast<int>(this->Cells.size()), centroids);
  std::copy(this->Nodes[0].Box, this->Nodes[0].Box + 6, this->Bounds);
  return true;
}

int CurvedRayCaster::BuildNode(int first, int count, std::vector<double>& centroids)
{
  const int index = static_cast<int>(this->Nodes.size());
  this->Nodes.emplace_back();
  double box[6] = { 1e300, -1e300, 1e300, -1e300, 1e300, -1e300 };
  double cbox[6] = { 1e300, -1e300, 1e300, -1e300, 1e300, -1e300 };
  for (int i = first; i < first + count; ++i)
  {
    const int c = this->CellOrder[i];
    MergeBox(box, this->Cells[c].Faces.Bounds);
    const double p[6] = { centroids[3 * c], centroids[3 * c], centroids[3 * c + 1],
      centroids[3 * c + 1], centroids[3 * c + 2], centroids[3 * c + 2] };
    MergeBox(cbox, p);
  }
  std::copy(box, box + 6, this->Nodes[index].Box);
  if (count <= LeafSize)
  {
    this->Nodes[index].First = first;
    this->Nodes[index].Count = count;
    return index;
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
  {
    axis = (cbox[2 * k + 1] - cbox[2 * k] > cbox[2 * axis + 1] - cbox[2 * axis]) ? k : axis;
  }
  const int half = count / 2;
  std::nth_element(this->CellOrder.begin() + first, this->CellOrder.begin() + first + half,
    this->CellOrder.begin() + first + count,
    [&](int a, int b) { return centroids[3 * a + axis] < centroids[3 * b + axis]; });
  const int left = this->BuildNode(first, half, centroids);
  const int right = this->BuildNode(first + half, count - half, centroids);
  this->Nodes[index].Left = left;
  this->Nodes[index].Right = right;
  return index;
}

void CurvedRayCaster::CollectCandidates(
  const double o[3], const double d[3], double tMin, double tMax, std::vector<int>& out) const
{
  out.clear();
  if (this->Nodes.empty())
  {
    return;
  }
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[stack[--top]];
    double t0, t1;
    if (!ClipRayToBox(node.Box, o, d, tMin, tMax, t0, t1))
    {
      continue;
    }
    if (node.Left < 0)
    {
      for (int i = node.First; i < node.First + node.Count; ++i)
      {
        out.push_back(this->CellOrder[i]);
      }
      continue;
    }
    if (top + 2 <= 128)
    {
      stack[top++] = node.Right;
      stack[top++] = node.Left;
    }
  }
}

bool CurvedRayCaster::IsCellInvisible(
  std::int64_t cell, const TransferFunction& tf, EmissionModel emission) const
{
  if (cell < 0 || cell >= static_cast<std::int64_t>(this->Cells.size()))
  {
    return false;
  }
  const Cell& c = this->Cells[static_cast<size_t>(cell)];
  return CategorizeSegment(tf, c.FieldLo, c.FieldHi, emission).Category == SegmentCategory::Empty;
}

void CurvedRayCaster::CollectSegments(const double origin[3], const double direction[3],
  double tMin, double tMax, std::vector<Segment>& segments, CurvedRayStats& st,
  const unsigned char* skip) const
{
  segments.clear();
  std::vector<int> candidates;
  this->CollectCandidates(origin, direction, tMin, tMax, candidates);
  st.CandidateCells = static_cast<int>(candidates.size());
  std::vector<FaceCrossing> scratch;
  thread_local FaceCrossingCache cache; // this ray's searched shared faces
  cache.Clear();
  for (int c : candidates)
  {
    if (skip && skip[c])
    {
      continue; // invisible over its whole field hull (IsCellInvisible)
    }
    const Cell& cell = this->Cells[c];
    double t0, t1;
    if (!ClipRayToBox(cell.Faces.Bounds, origin, direction, tMin, tMax, t0, t1))
    {
      continue;
    }
    if (cell.Affine)
    {
      double ta, tb, pc[3];
      if (this->AffineInterval(cell, origin, direction, t0, t1, ta, tb, pc))
      {
        segments.push_back({ ta, tb, c, { pc[0], pc[1], pc[2] } });
      }
      continue;
    }
    // Finite points and their extent known (Build): inversions skip both checks.
    const LagrangeCellView view = this->View(cell);
    CurvedRayInterval iv[MaxIntervalsPerCell];
    const SharedFaceContext shared{ this->Links.empty() ? nullptr : &this->Links[c], &cache, c };
    const int n = RayCurvedCellIntervals(view, cell.Faces, origin, direction, t0, t1, iv,
      MaxIntervalsPerCell, {}, nullptr, &scratch, &shared);
    for (int i = 0; i < n; ++i)
    {
      segments.push_back({ iv[i].T0, iv[i].T1, c, { iv[i].PC0[0], iv[i].PC0[1], iv[i].PC0[2] },
        { iv[i].PC1[0], iv[i].PC1[1], iv[i].PC1[2] } });
    }
  }
  std::sort(segments.begin(), segments.end(),
    [](const Segment& a, const Segment& b) { return a.T0 < b.T0 || (a.T0 == b.T0 && a.T1 < b.T1); });
  // Each part of the ray once: a ray lying in a face shared by two cells (or
  // on an edge shared by several) gets the same interval from every one of
  // them, and a ray in a plane of coplanar faces partitions differently on
  // either side. Keep what is not yet covered, trimming starts (the entry
  // point stays a Newton guess).
  {
    size_t kept = 0;
    double covered = -std::numeric_limits<double>::infinity();
    for (Segment s : segments)
    {
      s.T0 = std::max(s.T0, covered);
      // Nothing new, or a sliver at the rounding level (a ray through a
      // cell's edge or corner, or a shared face computed from both sides):
      // no contribution, except that an opaque medium would turn the pixel
      // opaque on a length that is only rounding.
      if (s.T1 - s.T0 <= CoverTolerance * (1.0 + std::abs(s.T1)))
      {
        continue;
      }
      covered = s.T1;
      segments[kept++] = s;
    }
    segments.resize(kept);
  }
}

RGBA CurvedRayCaster::TraceRay(const double origin[3], const double direction[3], double tMin,
  double tMax, const TransferFunction& tf, const CurvedSegmentSettings& settings,
  double* errorEstimate, CurvedRayStats* stats, const unsigned char* skipCells) const
{
  RGBA accum;
  double error = 0.0;
  CurvedRayStats st;
  std::vector<Segment> segments;
  const bool shaded = (settings.Shading && settings.Shading->Shade) || settings.GradientOpacity;
  // A shaded medium glows without colour or extinction under Wilhelms-Van
  // Gelder (the specular term): invisible cells are exactly zero otherwise.
  const bool skip =
    !shaded || settings.Quadrature.Emission == EmissionModel::WilliamsMax;
  this->CollectSegments(
    origin, direction, tMin, tMax, segments, st, skip ? skipCells : nullptr);
  // The tolerance is per pixel: each segment is integrated to it, and if the
  // transmittance-weighted sum of the segments' estimates exceeds it (many
  // segments along the ray), the ray is integrated again with every segment's
  // tolerance scaled by 0.5 x tolerance / sum (at most MaxTolerancePasses).
  const bool adaptive =
    settings.Method == CurvedQuadrature::LocatedBreakpoints && settings.Samples <= 0;
  CurvedSegmentSettings pass = settings;
  if (pass.FieldBudgetLength <= 0.0)
  {
    // The field error budget is spread over the whole ray's length in the mesh.
    const double speed = std::sqrt(
      direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
    for (const Segment& s : segments)
    {
      pass.FieldBudgetLength += (s.T1 - s.T0) * speed;
    }
  }
  for (int attempt = 0; attempt < MaxTolerancePasses; ++attempt)
  {
    accum = RGBA();
    error = 0.0;
    double fieldError = 0.0;
    CurvedRayStats passStats = st;
    for (const Segment& s : segments)
    {
      if (accum.A >= 1.0 - pass.TerminationTransmittance)
      {
        break;
      }
      const Cell& cell = this->Cells[s.Cell];
      const LagrangeCellView view = this->View(cell);
      CurvedSegmentResult r;
      if (shaded)
      {
        r = IntegrateCurvedShadedSegment(
          view, this->CellBounds(cell), tf, origin, direction, s.T0, s.T1, s.PC0, pass);
      }
      else
      {
        CurvedCellInfo info;
        info.FieldLo = cell.FieldLo;
        info.FieldHi = cell.FieldHi;
        info.FieldScale = cell.FieldScale;
        info.Affine = cell.Affine;
        std::copy(cell.X0, cell.X0 + 3, info.X0);
        std::copy(cell.InverseJ, cell.InverseJ + 9, info.InverseJ);
        info.Bounds = [this, &cell]() -> const CellDerivativeBounds& { return this->CellBounds(cell); };
        r = IntegrateCurvedSegment(
          view, info, tf, origin, direction, s.T0, s.T1, s.PC0, pass, s.PC1);
      }
      error += (1.0 - accum.A) * r.ErrorEstimate;
      fieldError += (1.0 - accum.A) * r.FieldErrorEstimate;
      CompositeBehind(accum, r.Color);
      ++passStats.Segments;
      passStats.Breakpoints += r.Breakpoints;
      passStats.Samples += r.Samples;
      passStats.Converged = passStats.Converged && r.Converged;
    }
    const double target = settings.Quadrature.Tolerance;
    // Another pass tightens only the quadrature: not worth it (each pass costs
    // more than the last) when the field's part of the estimate dominates
    // (e.g. next to an opaque node, where it is the colour slope times the
    // field error; hovRobustness seed 7, case 7007761).
    const double quadrature = error - fieldError;
    const bool last = !adaptive || !(error > target) || !(quadrature > 0.5 * target) ||
      attempt + 1 == MaxTolerancePasses || pass.Quadrature.Tolerance <= MinSegmentTolerance;
    if (last)
    {
      passStats.TolerancePasses = attempt + 1;
      st = passStats;
      break;
    }
    pass.Quadrature.Tolerance =
      std::max(MinSegmentTolerance, pass.Quadrature.Tolerance * 0.5 * target / quadrature);
  }
  if (errorEstimate)
  {
    *errorEstimate = error;
  }
  if (stats)
  {
    *stats = st;
  }
  return accum;
}
}
