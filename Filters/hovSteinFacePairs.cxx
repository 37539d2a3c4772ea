// Face pair tests of the Stein sort's boundary pair search (see hovSteinFacePairs.h).
#include "hovSteinFacePairs.h"

#include "hovSteinHulls.h"    // ClipPolygon, HullCapacity
#include "hovSteinRounding.h" // FloatDown, FloatUp

#include <algorithm>
#include <cmath>

namespace hovStein
{
namespace
{
/**
 * A distance margin on the screen for the screen triangles @p d and @p e:
 * @p relative times the largest side of their extents, plus 1e-9 of the
 * magnitude their screen points' rounding is relative to
 * (FaceData::ScreenScale); both rounded up (a larger margin is the safe
 * side). Reads only the faces' first cache line.
 */
double Margin(const FaceData& d, const FaceData& e, double relative)
{
  return relative * std::max(d.Extent, e.Extent) + 1e-9 * std::max(d.ScreenScale, e.ScreenScale);
}

/**
 * Edge k of a screen triangle set up once for side tests with a margin:
 * Side(x) is the signed distance of @p x times |q - p| (positive on the third
 * corner's side); for a margin m, x lies inside by more than m if
 * Side(x) > m * Norm, outside by more if Side(x) < -m * Norm (Norm = |ex| +
 * |ey| >= |q - p|); an edge whose third corner is on its line (Sign 0) has
 * neither.
 */
struct EdgeLine
{
  double PX, PY, EX, EY, Norm, Sign;
  EdgeLine() = default;
  EdgeLine(const double t[3][2], int k)
  {
    const double* p = t[k];
    const double* q = t[(k + 1) % 3];
    const double* r = t[(k + 2) % 3];
    this->PX = p[0];
    this->PY = p[1];
    this->EX = q[0] - p[0];
    this->EY = q[1] - p[1];
    const double c = this->EX * (r[1] - p[1]) - this->EY * (r[0] - p[0]);
    this->Norm = std::abs(this->EX) + std::abs(this->EY);
    this->Sign = c > 0 ? 1.0 : (c < 0 ? -1.0 : 0.0);
  }
  double Side(const double x[2]) const
  {
    return this->Sign * (this->EX * (x[1] - this->PY) - this->EY * (x[0] - this->PX));
  }
};

/**
 * The six edge lines of two screen triangles (@p f's, then @p e's), set up
 * once for both screen tests of a face pair (Apart(), then the points of
 * InFrontOnScreen()).
 */
struct PairLines
{
  const FaceData& F;
  const FaceData& E;
  EdgeLine Lines[6];
  bool Areas = true; ///< both triangles have area, each edge of a triangle the same sign
  PairLines(const FaceData& f, const FaceData& e)
    : F(f)
    , E(e)
  {
    for (int k = 0; k < 6; ++k)
    {
      this->Lines[k] = EdgeLine(k < 3 ? f.Corners : e.Corners, k % 3);
    }
    // A proof needs the three signs of each triangle to agree: a sliver, whose
    // area is rounding, can give its edges different signs, and a point far
    // outside it would then be inside all three lines. Each edge keeps its
    // own sign for Apart(), where any sign is sound (every corner of the
    // other triangle outside one line: that line separates them).
    for (int t = 0; t < 6; t += 3)
    {
      const double s = this->Lines[t].Sign;
      this->Areas = this->Areas && s != 0 && this->Lines[t + 1].Sign == s &&
        this->Lines[t + 2].Sign == s;
    }
  }
  /// ApartOnScreen() with the margin @p margin.
  bool Apart(double margin) const
  {
    for (int k = 0; k < 6; ++k)
    {
      // Every corner of the other triangle outside edge k by more than the margin.
      const EdgeLine& line = this->Lines[k];
      const double(*b)[2] = k < 3 ? this->E.Corners : this->F.Corners;
      const double tol = margin * line.Norm;
      bool apart = line.Sign != 0;
      for (int j = 0; j < 3 && apart; ++j)
      {
        apart = line.Side(b[j]) < -tol;
      }
      if (apart)
      {
        return true;
      }
    }
    return false;
  }
  /// @p x inside both triangles by more than the margin @p margin.
  bool InsideBoth(const double x[2], double margin) const
  {
    for (const EdgeLine& line : this->Lines)
    {
      if (!(line.Side(x) > margin * line.Norm))
      {
        return false;
      }
    }
    return true;
  }
  /// A point of the first four InFrontOnScreen() tries inside both by more than @p margin.
  bool SomePointInside(double margin) const
  {
    double c[2][2], lo[2][2], hi[2][2];
    for (int t = 0; t < 2; ++t)
    {
      const double(*a)[2] = t ? this->E.Corners : this->F.Corners;
      for (int i = 0; i < 2; ++i)
      {
        c[t][i] = (a[0][i] + a[1][i] + a[2][i]) / 3;
        lo[t][i] = std::min({ a[0][i], a[1][i], a[2][i] });
        hi[t][i] = std::max({ a[0][i], a[1][i], a[2][i] });
      }
    }
    for (int t = 0; t < 4; ++t)
    {
      double x[2];
      for (int i = 0; i < 2; ++i)
      {
        // The centroids, their midpoint, the centre of the extents' overlap.
        x[i] = t < 2 ? c[t][i]
          : t == 2   ? 0.5 * (c[0][i] + c[1][i])
                     : 0.5 * (std::max(lo[0][i], lo[1][i]) + std::min(hi[0][i], hi[1][i]));
      }
      if (this->InsideBoth(x, margin))
      {
        return true;
      }
    }
    return false;
  }
};

/// @p t's corners counterclockwise into @p out; false if it has no area.
bool CounterClockwise(const double t[3][2], double out[][2])
{
  const double c = (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) -
    (t[1][1] - t[0][1]) * (t[2][0] - t[0][0]);
  if (!(c != 0))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    const int j = c > 0 ? i : 2 - i;
    out[i][0] = t[j][0];
    out[i][1] = t[j][1];
  }
  return true;
}

/**
 * The area centroid of the intersection of the screen triangles @p a and
 * @p b (ClipPolygon) into @p x; false if it has no area. A candidate point
 * only: the caller checks it.
 */
bool OverlapCentroid(const double a[3][2], const double b[3][2], double x[2])
{
  double poly[HullCapacity][2], clip[3][2];
  if (!CounterClockwise(a, poly) || !CounterClockwise(b, clip))
  {
    return false;
  }
  const int n = ClipPolygon(poly, 3, clip, 3);
  double area = 0, cx = 0, cy = 0;
  for (int i = 0; i < n; ++i)
  {
    // Relative to the first vertex (less cancellation far from the origin).
    const int j = i + 1 < n ? i + 1 : 0;
    const double ux = poly[i][0] - poly[0][0], uy = poly[i][1] - poly[0][1];
    const double vx = poly[j][0] - poly[0][0], vy = poly[j][1] - poly[0][1];
    const double w = ux * vy - vx * uy;
    area += w;
    cx += (ux + vx) * w;
    cy += (uy + vy) * w;
  }
  if (n < 3 || !(area > 0))
  {
    return false;
  }
  x[0] = poly[0][0] + cx / (3 * area);
  x[1] = poly[0][1] + cy / (3 * area);
  return true;
}

bool ScreenTriangles(const FaceData& d, const FaceData& e)
{
  return d.NumIds == 3 && e.NumIds == 3 && d.Screen && e.Screen;
}
}

void FillFaceData(const Geometry& g, const View& v, const ViewFace& vf, FaceData& d)
{
  const vtkIdType c = vf.Cell;
  d.NumIds = static_cast<std::uint8_t>(g.OrientedFace(c, vf.Face, d.Ids));
  d.Exact = (g.FaceCode(c, vf.Face) & 3) == FaceExact && vf.Roles != 3;
  if (d.Exact)
  {
    // The exact plane's corners are corners of the face: their places in Ids.
    vtkIdType triple[3];
    g.ExactTriple(c, vf.Face, triple);
    for (int k = 0; k < 3; ++k)
    {
      const int at = static_cast<int>(std::find(d.Ids, d.Ids + d.NumIds, triple[k]) - d.Ids);
      d.TripleAt[k] = static_cast<std::uint8_t>(at);
      d.Exact = d.Exact && at < d.NumIds; // (always found; if not: no exact plane)
    }
  }
  d.Screen = v.Status[c] == StatusVisible;
  if (!d.Screen)
  {
    std::copy(v.BoxOf(c), v.BoxOf(c) + 4, d.Box);
    d.Front = v.FrontOf(c);
    d.Rear = v.RearOf(c);
    return;
  }
  double box[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  d.Front = VTK_DOUBLE_MAX;
  d.Rear = -VTK_DOUBLE_MAX;
  double scale = v.Frame.Parallel ? 3 * g.MaxAbsCoordinate : 1.0;
  double corners[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int i = 0; i < d.NumIds; ++i)
  {
    const double* p = v.Proj.data() + 3 * d.Ids[i];
    if (i < 3)
    {
      d.Corners[i][0] = p[0];
      d.Corners[i][1] = p[1];
      corners[0] = std::min(corners[0], p[0]);
      corners[1] = std::max(corners[1], p[0]);
      corners[2] = std::min(corners[2], p[1]);
      corners[3] = std::max(corners[3], p[1]);
    }
    if (!v.Frame.Parallel)
    {
      scale = std::max(scale, 1 + std::abs(p[0]) + std::abs(p[1]));
    }
    box[0] = std::min(box[0], p[0]);
    box[1] = std::max(box[1], p[0]);
    box[2] = std::min(box[2], p[1]);
    box[3] = std::max(box[3], p[1]);
    d.Front = std::min(d.Front, p[2]);
    d.Rear = std::max(d.Rear, p[2]);
  }
  d.ScreenScale = FloatUp(scale);
  d.Extent = FloatUp(std::max(corners[1] - corners[0], corners[3] - corners[2]));
  d.Box[0] = FloatDown(box[0]);
  d.Box[1] = FloatUp(box[1]);
  d.Box[2] = FloatDown(box[2]);
  d.Box[3] = FloatUp(box[3]);
}

bool SomeCornerOutside(const Geometry& g, const FaceData& d, const FaceData& other)
{
  if (!d.Exact)
  {
    return true;
  }
  const double* a = g.Point(d.Ids[d.TripleAt[0]]);
  const double* b = g.Point(d.Ids[d.TripleAt[1]]);
  const double* c = g.Point(d.Ids[d.TripleAt[2]]);
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double n[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
    u[0] * w[1] - u[1] * w[0] };
  const double scale = g.Diagonal + std::max({ std::abs(a[0]), std::abs(a[1]), std::abs(a[2]) });
  const double margin = 1e-9 * scale * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int i = 0; i < other.NumIds; ++i)
  {
    const double* p = g.Point(other.Ids[i]);
    if (n[0] * (p[0] - a[0]) + n[1] * (p[1] - a[1]) + n[2] * (p[2] - a[2]) >= -margin)
    {
      return true;
    }
  }
  return false;
}

bool ApartOnScreen(const FaceData& d, const FaceData& e)
{
  return ScreenTriangles(d, e) && PairLines(d, e).Apart(Margin(d, e, 1e-9));
}

namespace
{
/// InFrontOnScreen()'s conditions but the point inside both triangles.
bool MayProve(const FaceData& f, double fAfter, const FaceData& e, double eBefore)
{
  return fAfter < eBefore && ScreenTriangles(f, e) && f.Exact && e.Exact;
}

/// The last point InFrontOnScreen() tries, inside both by more than @p margin.
bool OverlapInside(const PairLines& lines, double margin)
{
  double x[2];
  return OverlapCentroid(lines.F.Corners, lines.E.Corners, x) && lines.InsideBoth(x, margin);
}
}

bool InFrontOnScreen(const FaceData& f, double fAfter, const FaceData& e, double eBefore)
{
  if (!MayProve(f, fAfter, e, eBefore))
  {
    return false;
  }
  // Inside by 1e-4 of the extents: the overlap holds a disc far larger than
  // what Obstructs() treats as touching (1e-10 of the cells' hull areas).
  const double margin = Margin(f, e, 1e-4);
  const PairLines lines(f, e);
  // A triangle without area, or whose edges disagree on its orientation
  // (Areas), proves nothing.
  return lines.Areas && (lines.SomePointInside(margin) || OverlapInside(lines, margin));
}

int ClassifyFacePair(const Geometry& g, const FaceData& f, double fAfter, const FaceData& e,
  double eBefore, bool certify)
{
  // The same as !ApartOnScreen() && InFrontOnScreen() for a proved edge, with
  // the lines set up once and the cheap points of the proof tried before the
  // apart test: a point inside both triangles by 1e-4 of the extents (inside
  // all six lines, each triangle's three with one sign: Areas) cannot exist
  // when an edge of one has the other's corners outside by 1e-9 (the side is
  // affine, the point a convex combination of those corners).
  if (ScreenTriangles(f, e))
  {
    const PairLines lines(f, e);
    const bool prove = certify && lines.Areas && MayProve(f, fAfter, e, eBefore);
    const double proofMargin = Margin(f, e, 1e-4);
    if (prove && lines.SomePointInside(proofMargin))
    {
      return ProvedEdge;
    }
    if (lines.Apart(Margin(f, e, 1e-9)))
    {
      return NoCandidate;
    }
    if (prove && OverlapInside(lines, proofMargin))
    {
      return ProvedEdge;
    }
  }
  return SomeCornerOutside(g, f, e) && SomeCornerOutside(g, e, f) ? NeedsTest : NoCandidate;
}
}
