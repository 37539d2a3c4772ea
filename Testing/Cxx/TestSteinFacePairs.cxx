// hovStein::ClassifyFacePair (Filters/hovSteinFacePairs.h), the face pair test
// of the Stein sort's boundary pair search, which sets up the six screen lines
// once and tries the proof's cheap points before the apart test. Checked on
// random face pairs (fixed seed) against
// - its definition: NoCandidate if ApartOnScreen(), else ProvedEdge if certify
//   and InFrontOnScreen(), else NeedsTest if SomeCornerOutside() both ways,
//   else NoCandidate (every pair, certify on and off);
// - an independent separating-axis oracle for the screen tests: a pair called
//   apart must have an edge axis on which the triangles' projections are
//   disjoint (for two triangles, disjoint iff one of their edge axes separates
//   them); a proved pair must overlap on all six unit axes by 1e-5 of the
//   larger extent (the proof is a point inside both by 1e-4 of it).
// Pairs: triangles of sizes 1e-3 to 1e3 at offsets up to 1e6 from the
// origin; the second one random nearby, shifted, scaled about the first's
// centroid (nested), a mirror sharing an edge (touching), far away,
// collinear up to rounding, tiny inside, or a needle (two corners a few units
// in the last place apart, the third far: its orientation is rounding);
// random depths (the proof needs the EXIT face in front), exact or not,
// quads, and faces of cells cut by the near plane (not on screen). Each class
// and each oracle case must occur often. Also fixed pairs: two with a
// collinear ENTRY triangle that the original code proved (586c770: per-edge
// signs, no agreement check), and a needle that one sign per triangle
// (31361b4) called apart from a triangle it crosses.
#include "hovSteinFacePairs.h"
#include "hovSteinGeometry.h"
#include "hovSteinRounding.h"
#include "hovTestScenes.h"

#include "vtkCellType.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

using namespace hovTest;

namespace
{
constexpr int NumPoints = 64;

/// Screen data of a triangle (or of a quad whose first three corners are
/// @p t) as hovStein::FillFaceData sets it; corner ids drawn from the points.
hovStein::FaceData MakeFace(const double t[3][2], std::mt19937_64& rng)
{
  std::uniform_int_distribution<int> point(0, NumPoints - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  hovStein::FaceData d{};
  d.NumIds = unit(rng) < 0.1 ? 4 : 3;
  for (int i = 0; i < d.NumIds; ++i)
  {
    d.Ids[i] = point(rng);
  }
  d.Exact = unit(rng) < 0.9;
  for (int k = 0; k < 3; ++k)
  {
    d.TripleAt[k] = static_cast<std::uint8_t>(k);
  }
  d.Screen = unit(rng) < 0.95;
  double lo[2] = { t[0][0], t[0][1] }, hi[2] = { t[0][0], t[0][1] };
  double scale = 1.0;
  for (int i = 0; i < 3; ++i)
  {
    for (int c = 0; c < 2; ++c)
    {
      d.Corners[i][c] = t[i][c];
      lo[c] = std::min(lo[c], t[i][c]);
      hi[c] = std::max(hi[c], t[i][c]);
    }
    scale = std::max(scale, 1 + std::abs(t[i][0]) + std::abs(t[i][1]));
  }
  d.ScreenScale = hovStein::FloatUp(scale);
  d.Extent = hovStein::FloatUp(std::max(hi[0] - lo[0], hi[1] - lo[1]));
  d.Box[0] = hovStein::FloatDown(lo[0]);
  d.Box[1] = hovStein::FloatUp(hi[0]);
  d.Box[2] = hovStein::FloatDown(lo[1]);
  d.Box[3] = hovStein::FloatUp(hi[1]);
  d.Front = unit(rng);
  d.Rear = d.Front + unit(rng);
  return d;
}

/// The separating-axis oracle: the smallest overlap of the projections of
/// the triangles @p a and @p b on the unit normals of their six edges
/// (negative: an axis separates them; a zero-length edge counts as an overlap of 0).
double LeastOverlap(const double a[3][2], const double b[3][2])
{
  double least = VTK_DOUBLE_MAX;
  for (int t = 0; t < 2; ++t)
  {
    const double(*p)[2] = t ? b : a;
    for (int k = 0; k < 3; ++k)
    {
      double nx = -(p[(k + 1) % 3][1] - p[k][1]), ny = p[(k + 1) % 3][0] - p[k][0];
      const double length = std::hypot(nx, ny);
      if (!(length > 0))
      {
        least = std::min(least, 0.0);
        continue;
      }
      nx /= length;
      ny /= length;
      double loA = VTK_DOUBLE_MAX, hiA = -VTK_DOUBLE_MAX, loB = VTK_DOUBLE_MAX,
             hiB = -VTK_DOUBLE_MAX;
      for (int i = 0; i < 3; ++i)
      {
        const double sa = nx * a[i][0] + ny * a[i][1], sb = nx * b[i][0] + ny * b[i][1];
        loA = std::min(loA, sa);
        hiA = std::max(hiA, sa);
        loB = std::min(loB, sb);
        hiB = std::max(hiB, sb);
      }
      least = std::min(least, std::min(hiA, hiB) - std::max(loA, loB));
    }
  }
  return least;
}

/// The second triangle @p e of a pair with the first @p f (see the file doc).
void Partner(const double f[3][2], int kind, double size, std::mt19937_64& rng, double e[3][2])
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double cx = (f[0][0] + f[1][0] + f[2][0]) / 3, cy = (f[0][1] + f[1][1] + f[2][1]) / 3;
  const double sx = unit(rng) * size, sy = unit(rng) * size, s = 1.0 + unit(rng);
  for (int i = 0; i < 3; ++i)
  {
    switch (kind)
    {
      case 0: // random nearby
        e[i][0] = cx + 1.5 * size * unit(rng);
        e[i][1] = cy + 1.5 * size * unit(rng);
        break;
      case 1: // shifted
        e[i][0] = f[i][0] + 0.5 * sx;
        e[i][1] = f[i][1] + 0.5 * sy;
        break;
      case 2: // scaled about the centroid (nested one way or the other)
        e[i][0] = cx + s * (f[i][0] - cx);
        e[i][1] = cy + s * (f[i][1] - cy);
        break;
      case 3: // the mirror of the third corner across edge 0-1: touching along it
        e[i][0] = i < 2 ? f[i][0] : f[0][0] + f[1][0] - f[2][0];
        e[i][1] = i < 2 ? f[i][1] : f[0][1] + f[1][1] - f[2][1];
        break;
      case 4: // far away
        e[i][0] = f[i][0] + 5 * size;
        e[i][1] = f[i][1] - 3 * size;
        break;
      case 5: // collinear corners up to rounding (a sliver of rounding-level area)
        e[i][0] = cx + (i == 0 ? -1.0 : i == 1 ? 1.0 / 3 : 1.0) * sx;
        e[i][1] = cy + (i == 0 ? -1.0 : i == 1 ? 1.0 / 3 : 1.0) * sy;
        break;
      case 6: // tiny, inside (about the centroid)
        e[i][0] = cx + 1e-3 * (f[i][0] - cx);
        e[i][1] = cy + 1e-3 * (f[i][1] - cy);
        break;
      default: // a needle through the centroid: corners 1 and 2 a few ulps apart
      {
        // Corner 1 outside f's extents (3 sizes from its centroid), corner 0
        // opposite it: the needle crosses f.
        const double h = std::hypot(sx, sy) > 0 ? std::hypot(sx, sy) : 1.0;
        const double ux = sx / h, uy = sy / h;
        if (i < 2)
        {
          const double r = i == 0 ? -3 * size : 3 * size;
          e[i][0] = cx + r * ux;
          e[i][1] = cy + r * uy;
        }
        else
        {
          e[2][0] = e[1][0];
          e[2][1] = e[1][1];
          for (int c = 0; c < 2; ++c)
          {
            const int steps = std::uniform_int_distribution<int>(1, 8)(rng);
            for (int u = 0; u < steps; ++u)
            {
              e[2][c] = std::nextafter(e[2][c], sx > 0 ? VTK_DOUBLE_MAX : -VTK_DOUBLE_MAX);
            }
          }
        }
        break;
      }
    }
  }
}

/// A screen triangle of a visible cell with an exact plane (corner ids 0-2).
hovStein::FaceData FixedFace(const double t[3][2])
{
  std::mt19937_64 rng(1);
  hovStein::FaceData d = MakeFace(t, rng);
  d.NumIds = 3;
  d.Exact = 1;
  d.Screen = 1;
  return d;
}
}

int TestSteinFacePairs(int, char*[])
{
  Checker ck;
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  // The corners' world points, for SomeCornerOutside(): random tetrahedra.
  vtkNew<vtkPoints> points;
  for (int i = 0; i < NumPoints; ++i)
  {
    const double x = unit(rng), y = unit(rng), z = unit(rng); // in this order
    points->InsertNextPoint(x, y, z);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  for (vtkIdType c = 0; c < NumPoints / 4; ++c)
  {
    const vtkIdType ids[4] = { 4 * c, 4 * c + 1, 4 * c + 2, 4 * c + 3 };
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  hovStein::Geometry g;
  g.Build(grid, nullptr);

  long long pairs = 0, classified = 0, mismatches = 0, classes[3] = { 0, 0, 0 };
  long long apart = 0, apartOverlapping = 0, proved = 0, provedDisjoint = 0;
  long long provedByKind[8] = { 0, 0, 0, 0, 0, 0, 0, 0 }, needlesOnScreen = 0;
  std::string firstMismatch;
  for (const double offset : { 0.0, 1e3, 1e6 })
  {
    for (const double size : { 1e-3, 1.0, 1e3 })
    {
      for (int i = 0; i < 3000; ++i)
      {
        double f[3][2], e[3][2];
        const double ox = offset * unit(rng), oy = offset * unit(rng);
        for (int k = 0; k < 3; ++k)
        {
          f[k][0] = ox + size * unit(rng);
          f[k][1] = oy + size * unit(rng);
        }
        const int kind = i % 8;
        Partner(f, kind, size, rng, e);
        const hovStein::FaceData df = MakeFace(f, rng), de = MakeFace(e, rng);
        // The proof needs the EXIT face's far depth before the ENTRY face's near one.
        const bool inOrder = std::uniform_real_distribution<double>(0.0, 1.0)(rng) < 0.8;
        const double fAfter = df.Rear, eBefore = inOrder ? fAfter + 0.5 : fAfter - 0.5;
        const bool isApart = hovStein::ApartOnScreen(df, de);
        const bool inFront = hovStein::InFrontOnScreen(df, fAfter, de, eBefore);
        for (const bool certify : { true, false })
        {
          const int expected = isApart ? hovStein::NoCandidate
            : certify && inFront       ? hovStein::ProvedEdge
            : hovStein::SomeCornerOutside(g, df, de) && hovStein::SomeCornerOutside(g, de, df)
            ? hovStein::NeedsTest
            : hovStein::NoCandidate;
          const int got = hovStein::ClassifyFacePair(g, df, fAfter, de, eBefore, certify);
          ++classified;
          ++classes[got + 1];
          if (got != expected && mismatches++ == 0)
          {
            firstMismatch = " (first: kind " + std::to_string(kind) + ", size " +
              std::to_string(size) + ", offset " + std::to_string(offset) + ": " +
              std::to_string(got) + " instead of " + std::to_string(expected) + ")";
          }
        }
        ++pairs;
        const double overlap = LeastOverlap(f, e);
        apart += isApart;
        apartOverlapping += isApart && !(overlap < 0);
        proved += inFront;
        // A proof is a disc of radius 1e-4 of the larger extent inside both:
        // every unit axis overlaps by twice that (1e-5 leaves room for rounding).
        provedDisjoint += inFront && !(overlap > 1e-5 * std::max(df.Extent, de.Extent));
        provedByKind[kind] += inFront;
        needlesOnScreen += kind == 7 && df.Screen && de.Screen && df.NumIds == 3 &&
          de.NumIds == 3;
      }
    }
  }
  ck.Check(mismatches == 0,
    "ClassifyFacePair as its definition in " + std::to_string(classified) +
      " classifications (" + std::to_string(pairs) + " pairs, certify on and off): " +
      std::to_string(mismatches) + " differ" + firstMismatch);
  ck.Check(apartOverlapping == 0,
    std::to_string(apart) + " pairs apart on screen, of which " +
      std::to_string(apartOverlapping) + " not separated by an edge axis");
  ck.Check(provedDisjoint == 0,
    std::to_string(proved) + " pairs proved on screen, of which " +
      std::to_string(provedDisjoint) + " do not overlap by 1e-5 of the extents on every edge axis");
  // Not vacuous: each class often, proofs among nested, shifted and tiny pairs.
  const std::string names[3] = { "NoCandidate", "NeedsTest", "ProvedEdge" };
  for (int k = 0; k < 3; ++k)
  {
    ck.Check(classes[k] > classified / 20,
      names[k] + ": " + std::to_string(classes[k]) + " of " + std::to_string(classified));
  }
  ck.Check(apart > pairs / 20 && proved > pairs / 20,
    std::to_string(apart) + " apart and " + std::to_string(proved) + " proved pairs");
  std::string byKind;
  for (int k = 0; k < 8; ++k)
  {
    byKind += (k ? ", " : "") + std::to_string(provedByKind[k]);
  }
  ck.Check(provedByKind[1] > 0 && provedByKind[2] > 0 && provedByKind[6] > 0 &&
      provedByKind[3] == 0 && provedByKind[4] == 0 && provedByKind[5] == 0 &&
      provedByKind[7] == 0,
    "proved by kind (nearby, shifted, nested, touching, far, collinear, tiny, needle): " +
      byKind + " (touching, far, collinear and needles: none); " +
      std::to_string(needlesOnScreen) + " needle pairs of two screen triangles");
  ck.Check(needlesOnScreen > pairs / 20,
    std::to_string(needlesOnScreen) + " needle pairs of two screen triangles");

  // The pairs the original code proved (size 1e3 at offsets 0 and 1e3).
  const double fixed[2][2][3][2] = {
    { { { -131.81038233326646, -387.85541002620852 }, { 296.47646058679334, 205.34981061191669 },
        { -705.48448733473526, -582.54790729388924 } },
      { { -1167.6241331580695, -529.64956861318967 }, { 148.84430701659716, -163.47392455479505 },
        { 807.07852710393047, 19.613897474402279 } } },
    { { { 32.42204860394213, -19.757048535252068 }, { -30.451997175644351, -19.251540496089774 },
        { 436.15710375192396, -1015.2914870449684 } },
      { { 586.11840866561238, 162.66679546529485 }, { -0.64962280843892017, -522.80007674456942 },
        { -294.03363854546461, -865.53351284950168 } } }
  };
  // The needle that one sign per triangle called apart (size 1e-3 at offset 0).
  const double needle[2][3][2] = { { { 0.00015613023791965453, 0.00049824903986727385 },
                                     { -0.00065196578930710807, 0.00028278203016138769 },
                                     { -0.00020516622065066393, 0.00093345882249119393 } },
    { { -0.0022318565644616336, -0.0016661895609503315 },
      { 0.0017645220497695556, 0.0028091828226302351 },
      { 0.0017645220497695571, 0.0028091828226302364 } } };
  const bool needleApart =
    hovStein::ApartOnScreen(FixedFace(needle[0]), FixedFace(needle[1]));
  const double needleOverlap = LeastOverlap(needle[0], needle[1]);
  ck.Check(!needleApart && needleOverlap >= 0,
    std::string("fixed needle crossing a triangle (") +
      (needleOverlap >= 0 ? "no separating axis" : "separated?") +
      "): " + (needleApart ? "apart" : "not apart"));
  for (int k = 0; k < 2; ++k)
  {
    const hovStein::FaceData df = FixedFace(fixed[k][0]), de = FixedFace(fixed[k][1]);
    const bool inFront = hovStein::InFrontOnScreen(df, 1.0, de, 2.0);
    const int kind = hovStein::ClassifyFacePair(g, df, 1.0, de, 2.0, true);
    ck.Check(!inFront && kind != hovStein::ProvedEdge,
      "fixed pair " + std::to_string(k) + " (a collinear ENTRY triangle): " +
        (inFront ? "proved" : "not proved") + ", class " + std::to_string(kind));
  }
  return ck.Result();
}
