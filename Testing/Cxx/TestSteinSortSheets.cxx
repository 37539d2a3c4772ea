// vtkSteinVisibilitySort's BoundaryPairCulling (hovSteinSheets.h): boundary
// face pairs that a covering sheet of front-facing boundary faces separates on
// every ray through both are not tested. On finned heatsinks (the benchmark's
// mesh, small: fins one behind the other, the case the culling is for), on
// the grid, with jittered points (bumpy fins: silhouettes inside the fins'
// faces) and jittered far from the origin (3e5: the screen tests' margins
// follow the coordinates), and on the bundled bracket, from random perspective and parallel
// views, along the fins, grazing and from between two fins:
// - with and without the culling, the order passes the independent ray/face
//   oracle (hovSortOracle: every cell once, no violation) with no cycle;
// - the culling drops face pairs (most of them on the heatsinks) and the
//   Obstructs() tests fall accordingly; without it nothing is dropped;
// - a view re-sorted after toggling the setting is sorted again (the setting
//   is part of the sort's cache key);
// - the default, CULLING_AUTO, culls exactly as CULLING_ON or not at all: on
//   the heatsinks' views across the fins, not on the bracket;
// - with the dropped-pair log (every candidate met and counted) and without
//   it (the search skips, per EXIT face and tile, the ENTRY faces behind a
//   covering sheet), the same face pairs are kept, each found once (the kept
//   count is the candidates less the drops), the same cell pairs tested, the
//   same edges made and the order is the same; with the log, the candidates
//   are those of CULLING_OFF;
// - the edges that single face pairs prove without Obstructs() (triangles
//   overlapping on the screen, one entirely in front) are exactly those
//   Obstructs() finds: the same order and edge set with that shortcut off;
// - every dropped face pair is checked on its own (12 rays each, by this
//   test's own ray/triangle intersections): every sampled ray through the
//   EXIT face F and then the ENTRY face G crosses another boundary face
//   strictly between them, so the two cells are never consecutive along it.
#include "hovSortCases.h"
#include "hovSortMeshes.h"
#include "hovSortOracle.h"
#include "hovTestMeshes.h"
#include "hovTestScenes.h"

#include "BenchSortMeshes.h" // hovBench::Heatsink
#include "hovSteinGraph.h"   // GraphSort and its dropped-pair log

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
/// The heatsink with every point moved by up to @p jitter (of the unit grid)
/// in each coordinate: the cells stay valid (Kuhn tetrahedra of unit cubes).
vtkSmartPointer<vtkUnstructuredGrid> JitteredHeatsink(double jitter, unsigned seed)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = hovBench::Heatsink(5, 2, 2, 8, 2, 6);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  vtkPoints* points = grid->GetPoints();
  for (vtkIdType i = 0; jitter > 0 && i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    for (double& c : x)
    {
      c += u(rng);
    }
    points->SetPoint(i, x);
  }
  return grid;
}

struct Totals
{
  vtkIdType Kept[2] = { 0, 0 }, Tests[2] = { 0, 0 }, FacePairs[2] = { 0, 0 };
  int AutoCulled = 0; ///< views CULLING_AUTO culled
};

/// The counters of one sort.
struct Counts
{
  vtkIdType FacePairs, Dropped, Tests, Edges;
  bool operator==(const Counts& o) const
  {
    return this->FacePairs == o.FacePairs && this->Dropped == o.Dropped &&
      this->Tests == o.Tests && this->Edges == o.Edges;
  }
};

Counts GetCounts(vtkSteinVisibilitySort* sort)
{
  return { sort->GetNumberOfBoundaryFacePairs(), sort->GetNumberOfDroppedFacePairs(),
    sort->GetNumberOfObstructsTests(), sort->GetNumberOfGraphEdges() };
}

void Run(Checker& ck, const std::string& mesh, vtkUnstructuredGrid* grid, const SortView& view,
  const OracleOptions& options, Totals& totals)
{
  vtkNew<vtkCamera> cam;
  view.Apply(cam);
  vtkNew<vtkSteinVisibilitySort> sort;
  Counts counts[2];
  for (const int culling : { 1, 0 })
  {
    sort->SetBoundaryPairCulling(culling ? vtkSteinVisibilitySort::CULLING_ON
                                         : vtkSteinVisibilitySort::CULLING_OFF);
    const std::vector<vtkIdType> order =
      FullOrder(sort, grid, cam, nullptr, vtkVisibilitySort::BACK_TO_FRONT);
    const OracleResult r = CheckVisibilityOrder(grid, cam, nullptr, order, options);
    const std::string what = mesh + " / " + view.Name + (culling ? " / culling" : " / all pairs");
    const Counts c = GetCounts(sort);
    counts[culling] = c;
    std::cout << "  " << what << ": " << r.Str() << ", face pairs met " << c.FacePairs
              << ", dropped " << c.Dropped << ", tests " << c.Tests << ", edges " << c.Edges
              << "\n";
    ck.Check(r.EveryCellOnce(), what + ": every cell once");
    ck.Check(r.RayViolations == 0 && r.FaceViolations == 0, what + ": no oracle violation");
    ck.Check(r.OverlappingPairs == 0, what + ": the mesh is valid (no overlapping cells)");
    ck.Check(sort->GetNumberOfCycles() == 0, what + ": no cycle reported");
    ck.Check(r.PairsChecked > 0, what + ": the oracle saw overlapping cells along rays");
    if (!culling)
    {
      ck.Check(c.Dropped == 0, what + ": nothing dropped");
    }
    totals.Kept[culling] += c.FacePairs - c.Dropped;
    totals.Tests[culling] += c.Tests;
    totals.FacePairs[culling] += c.FacePairs;
  }
  // The default decides by the depth of the overlap: as CULLING_ON or as CULLING_OFF.
  vtkNew<vtkSteinVisibilitySort> automatic;
  FullOrder(automatic, grid, cam, nullptr, vtkVisibilitySort::BACK_TO_FRONT);
  const Counts a = GetCounts(automatic);
  totals.AutoCulled += a == counts[1] && a.Tests < counts[0].Tests;
  ck.Check(a == counts[0] || a == counts[1],
    mesh + " / " + view.Name + ": CULLING_AUTO culls as CULLING_ON or not at all");
}

/// Ray (o + t d) and triangle: t, or NaN if it misses (slightly exclusive).
double Hit(const double o[3], const double d[3], const double* a, const double* b, const double* c)
{
  double e1[3], e2[3], s[3], p[3], q[3];
  for (int k = 0; k < 3; ++k)
  {
    e1[k] = b[k] - a[k];
    e2[k] = c[k] - a[k];
    s[k] = o[k] - a[k];
  }
  p[0] = d[1] * e2[2] - d[2] * e2[1];
  p[1] = d[2] * e2[0] - d[0] * e2[2];
  p[2] = d[0] * e2[1] - d[1] * e2[0];
  const double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
  if (std::abs(det) < 1e-300)
  {
    return NAN;
  }
  const double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
  q[0] = s[1] * e1[2] - s[2] * e1[1];
  q[1] = s[2] * e1[0] - s[0] * e1[2];
  q[2] = s[0] * e1[1] - s[1] * e1[0];
  const double w = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
  constexpr double eps = 1e-9;
  if (u < eps || w < eps || u + w > 1 - eps)
  {
    return NAN;
  }
  return (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
}

/// The sort's geometry, topology and view of @p grid seen by @p cam.
struct SortSetup
{
  hovStein::Geometry G;
  hovStein::Topology T;
  hovStein::View V;
  SortSetup(vtkUnstructuredGrid* grid, vtkCamera* cam)
  {
    this->G.Build(grid, nullptr);
    this->T.Build(this->G);
    this->V.Setup(this->G, cam, false);
  }
};

/**
 * Sorts one view with and without the edges that face pairs prove
 * (InFrontOnScreen): the same order and Obstructs() edges must come out
 * (a proved edge is one Obstructs() finds), with fewer tests. Returns
 * whether they do; @p saved: the tests saved.
 */
bool SameWithoutCertificates(vtkUnstructuredGrid* grid, vtkCamera* cam, vtkIdType& saved)
{
  const SortSetup setup(grid, cam);
  const hovStein::Geometry& g = setup.G;
  const hovStein::Topology& t = setup.T;
  const hovStein::View& v = setup.V;
  hovStein::GraphSort with, without;
  without.SetCertifiedEdges(false);
  std::vector<vtkIdType> order[2];
  hovStein::GraphStats stats[2];
  with.Sort(g, t, v, order[0], stats[0]);
  without.Sort(g, t, v, order[1], stats[1]);
  saved = stats[1].Tests - stats[0].Tests;
  auto withEdges = with.GetObstructEdges(), withoutEdges = without.GetObstructEdges();
  std::sort(withEdges.begin(), withEdges.end());
  std::sort(withoutEdges.begin(), withoutEdges.end());
  return order[0] == order[1] && withEdges == withoutEdges && stats[0].Tests <= stats[1].Tests;
}

/// The dropped face pairs of one view and their check.
struct DropCheck
{
  vtkIdType Candidates = 0, Drops = 0, Logged = 0; ///< with the log: every candidate met
  vtkIdType SkippingMet = 0; ///< without the log: the candidates met
  vtkIdType Rays = 0, Wrong = 0;
  bool SameAsSkipping = false; ///< kept pairs, tests and order as without the log
};

/**
 * Checks the dropped face pairs of one view of @p grid with the sort's own
 * geometry and topology: rays from the eye through random points of F that
 * go on through G must cross another boundary face strictly between
 * (DropCheck::Wrong counts those that cross none). Also sorts without the
 * log (the search then skips the ENTRY faces behind covering sheets) and
 * compares.
 */
DropCheck CheckDrops(vtkUnstructuredGrid* grid, vtkCamera* cam)
{
  const SortSetup setup(grid, cam);
  const hovStein::Geometry& g = setup.G;
  const hovStein::Topology& t = setup.T;
  const hovStein::View& v = setup.V;
  hovStein::GraphSort sorter, skipping;
  sorter.SetSheetCulling(hovStein::BoundaryPairs::CullAlways);
  skipping.SetSheetCulling(hovStein::BoundaryPairs::CullAlways);
  std::vector<hovStein::BoundaryPairs::FacePair> log;
  sorter.SetDroppedLog(&log);
  std::vector<vtkIdType> order, skippingOrder;
  hovStein::GraphStats stats, skippingStats;
  sorter.Sort(g, t, v, order, stats);
  skipping.Sort(g, t, v, skippingOrder, skippingStats);
  DropCheck check;
  check.Candidates = stats.FacePairs;
  check.Drops = stats.DroppedFacePairs;
  check.Logged = static_cast<vtkIdType>(log.size());
  check.SkippingMet = skippingStats.FacePairs;
  // Each kept pair found once: the kept count is the candidates less the
  // drops (every candidate is met while logging), with and without skipping.
  check.SameAsSkipping = order == skippingOrder && stats.Tests == skippingStats.Tests &&
    sorter.GetObstructEdges() == skipping.GetObstructEdges() &&
    stats.KeptFacePairs == stats.FacePairs - stats.DroppedFacePairs &&
    skippingStats.KeptFacePairs == stats.KeptFacePairs &&
    skippingStats.FacePairs - skippingStats.DroppedFacePairs == stats.KeptFacePairs &&
    skippingStats.FacePairs <= stats.FacePairs;
  // Every boundary face as a triangle fan of its corners.
  std::vector<std::array<vtkIdType, 4>> boundary;
  std::vector<int> sizes;
  for (const auto& bf : t.Boundary)
  {
    std::array<vtkIdType, 4> ids;
    sizes.push_back(g.OrientedFace(bf.Cell, bf.Face, ids.data()));
    boundary.push_back(ids);
  }
  auto faceHit = [&](const vtkIdType* ids, int n, const double o[3], const double d[3]) {
    for (int k = 1; k + 1 < n; ++k)
    {
      const double h = Hit(o, d, g.Point(ids[0]), g.Point(ids[k]), g.Point(ids[k + 1]));
      if (!std::isnan(h))
      {
        return h;
      }
    }
    return double(NAN);
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.02, 0.98);
  const hovStein::ViewFrame& f = v.Frame;
  const size_t step = 1;
  for (size_t i = 0; i < log.size(); i += step)
  {
    vtkIdType idsF[4], idsG[4];
    const int nF = g.OrientedFace(log[i][0], static_cast<int>(log[i][1]), idsF);
    const int nG = g.OrientedFace(log[i][2], static_cast<int>(log[i][3]), idsG);
    for (int r = 0; r < 12; ++r)
    {
      // A random point of F's first triangle, and the ray through it.
      double a = u(rng), b = u(rng);
      if (a + b > 1)
      {
        a = 1 - a;
        b = 1 - b;
      }
      double x[3], o[3], d[3];
      for (int k = 0; k < 3; ++k)
      {
        const double p0 = g.Point(idsF[0])[k], p1 = g.Point(idsF[1])[k], p2 = g.Point(idsF[2])[k];
        x[k] = p0 + a * (p1 - p0) + b * (p2 - p0);
        o[k] = f.Parallel ? x[k] - 1e3 * g.Diagonal * f.Dop[k] : f.Eye[k];
        d[k] = f.Parallel ? f.Dop[k] : x[k] - f.Eye[k];
      }
      const double tF = faceHit(idsF, nF, o, d), tG = faceHit(idsG, nG, o, d);
      if (std::isnan(tF) || std::isnan(tG) || !(tG > tF))
      {
        continue; // this ray does not go through F and then G
      }
      ++check.Rays;
      const double margin = 1e-7 * (tG - tF);
      bool between = false;
      for (size_t k = 0; k < boundary.size() && !between; ++k)
      {
        const double h = faceHit(boundary[k].data(), sizes[k], o, d);
        between = h > tF + margin && h < tG - margin;
      }
      check.Wrong += !between;
    }
  }
  return check;
}

/// Views of the heatsink (fins along y, stacked along x, up z).
std::vector<SortView> HeatsinkViews(const double b[6])
{
  std::vector<SortView> views = RandomViews(b, 4, 2024);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double span = b[1] - b[0];
  auto add = [&](const std::string& name, double dx, double dy, double dz, bool parallel) {
    SortView v;
    v.Name = name;
    v.Parallel = parallel;
    v.Position[0] = c[0] + dx * span;
    v.Position[1] = c[1] + dy * span;
    v.Position[2] = c[2] + dz * span;
    std::copy(c, c + 3, v.FocalPoint);
    v.ViewUp[0] = v.ViewUp[1] = 0;
    v.ViewUp[2] = 1;
    views.push_back(v);
  };
  add("across the fins", -2.0, -0.6, 0.8, false);  // fin behind fin
  add("across, grazing", -2.5, -0.3, 0.05, false); // low: the fins' tops edge-on
  add("across, parallel", -2.0, -0.9, 1.1, true);
  // In the gap between the first two fins, in front of their ends, off the
  // grid's planes.
  const double eye[3] = { b[0] + 3.1, b[2] - 3.3, b[4] + 5.3 };
  const double focal[3] = { b[1], b[3], b[4] + 2.2 };
  views.push_back(InsideView("between two fins", eye, focal));
  // In the air gap between the first two fins, half way along them, looking
  // across the other fins (every fin's front and back around the eye), and
  // inside the first fin (cells cut by the near plane).
  const double gap[3] = { b[0] + 3.1, b[2] + 4.2, b[4] + 5.3 };
  const double across[3] = { b[1], b[2] + 3.1, b[4] + 2.6 };
  views.push_back(InsideView("in the gap", gap, across));
  const double fin[3] = { b[0] + 1.05, b[2] + 4.3, b[4] + 5.2 };
  views.push_back(InsideView("inside a fin", fin, across));
  return views;
}
}

int TestSteinSortSheets(int argc, char* argv[])
{
  Checker ck;
  OracleOptions options;
  options.RaysX = options.RaysY = 110;
  options.RandomRays = 3000;
  for (const int variant : { 0, 1, 2 })
  {
    const double jitter = variant ? 0.12 : 0.0;
    const std::string name =
      variant == 2 ? "far jittered heatsink" : (variant ? "jittered heatsink" : "heatsink");
    vtkSmartPointer<vtkUnstructuredGrid> mesh = JitteredHeatsink(jitter, 77);
    if (variant == 2)
    {
      // Far from the origin: the screen tests' margins must follow the
      // coordinates' magnitude (parallel views project them unshifted).
      vtkPoints* points = mesh->GetPoints();
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double x[3];
        points->GetPoint(i, x);
        points->SetPoint(i, x[0] + 3.0e5, x[1] - 1.25e5, x[2] + 2.0e5);
      }
      mesh->GetPoints()->Modified();
    }
    double b[6];
    mesh->GetBounds(b);
    Totals totals;
    DropCheck all;
    vtkIdType acrossPairs = 0, acrossDropped = 0; ///< "across the fins", every candidate met
    vtkIdType certified = 0;                      ///< tests saved by proved edges
    for (const SortView& view : HeatsinkViews(b))
    {
      Run(ck, name, mesh, view, options, totals);
      vtkNew<vtkCamera> cam;
      view.Apply(cam);
      const DropCheck d = CheckDrops(mesh, cam);
      const std::string what = name + " / " + view.Name;
      ck.Check(d.SameAsSkipping,
        what + ": skipping the faces behind covering sheets keeps the same pairs and order");
      ck.Check(d.Logged == d.Drops, what + ": the log has every dropped pair");
      vtkIdType saved = 0;
      ck.Check(SameWithoutCertificates(mesh, cam, saved),
        what + ": the edges proved by face pairs are those Obstructs() finds");
      certified += saved;
      all.Candidates += d.Candidates;
      all.Drops += d.Drops;
      all.SkippingMet += d.SkippingMet;
      all.Rays += d.Rays;
      all.Wrong += d.Wrong;
      if (view.Name == "across the fins")
      {
        acrossPairs += d.Candidates;
        acrossDropped += d.Drops;
      }
    }
    std::cout << name << ": CULLING_AUTO culled in " << totals.AutoCulled << " views\n";
    ck.Check(totals.AutoCulled >= 3, name + ": CULLING_AUTO culls in the views across the fins");
    std::cout << name << ": " << all.Drops << " dropped face pairs, " << all.Rays
              << " sampled rays through both faces, " << all.Wrong << " with nothing between\n";
    ck.Check(all.Rays > 1000 && all.Wrong == 0,
      name + ": every sampled ray through a dropped pair crosses a boundary face between");
    std::cout << name << " (" << mesh->GetNumberOfCells() << " cells): face pairs "
              << all.Candidates << ", dropped " << all.Drops << ", tests " << totals.Tests[1]
              << " with the culling, " << totals.Tests[0] << " without\n";
    ck.Check(all.Candidates == totals.FacePairs[0], name + ": the same candidate face pairs");
    std::cout << name << ": without the log the search met " << all.SkippingMet
              << " face pairs of " << all.Candidates << "\n";
    ck.Check(all.SkippingMet < all.Candidates - all.Drops / 2,
      name + ": without the log the search skips most dropped pairs");
    ck.Check(totals.Kept[1] == totals.FacePairs[0] - all.Drops,
      name + ": CULLING_ON keeps the candidates less the dropped ones");
    ck.Check(acrossDropped > acrossPairs / 4,
      name + ", across the fins: the culling drops more than a quarter of the face pairs");
    ck.Check(totals.Tests[1] < totals.Tests[0], name + ": fewer Obstructs() tests");
    std::cout << name << ": " << certified << " tests saved by edges proved by face pairs\n";
    ck.Check(certified > 0, name + ": face pairs prove edges");
  }
  vtkSmartPointer<vtkUnstructuredGrid> bracket = LoadBracket(argc, argv);
  ck.Check(bracket && bracket->GetNumberOfCells() > 50000, "bracket: loaded");
  if (bracket)
  {
    double b[6];
    bracket->GetBounds(b);
    OracleOptions bracketOptions;
    bracketOptions.RaysX = bracketOptions.RaysY = 100;
    bracketOptions.RandomRays = 2000;
    Totals totals;
    vtkIdType certified = 0;
    for (const SortView& view : RandomViews(b, 2, 311))
    {
      Run(ck, "bracket", bracket, view, bracketOptions, totals);
      vtkNew<vtkCamera> cam;
      view.Apply(cam);
      vtkIdType saved = 0;
      ck.Check(SameWithoutCertificates(bracket, cam, saved),
        "bracket / " + view.Name + ": the edges proved by face pairs are those Obstructs() finds");
      certified += saved;
    }
    std::cout << "bracket: " << certified << " tests saved by edges proved by face pairs\n";
    ck.Check(certified > 0, "bracket: face pairs prove edges");
    ck.Check(totals.Kept[1] < totals.FacePairs[0], "bracket: the culling drops face pairs");
    std::cout << "bracket: CULLING_AUTO culled in " << totals.AutoCulled << " views\n";
    ck.Check(totals.AutoCulled == 0, "bracket: CULLING_AUTO does not cull (shallow overlap)");
  }
  return ck.Result();
}
