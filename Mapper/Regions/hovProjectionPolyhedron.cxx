#include "hovProjectionPolyhedron.h"

#include "hovCellShapes.h"       // InvertGeometry, InterpolateCellScalar
#include "hovRayCell.h"          // CellFaceCorners
#include "hovTransferFunction.h" // Evaluate

#include <algorithm> // std::sort
#include <cmath>     // std::abs, std::isfinite
#include <limits>    // infinity

namespace
{
constexpr int MaxClip = 2 * hov::ProjectionPolyhedron::MaxFacePoints + 12;
constexpr int Floats = hov::ProjectionVertex::FloatsPerVertex;

/// A number in [0, 4) increasing with the angle of (dx, dy) from the +x axis
/// (counter-clockwise), like atan2 but without transcendental functions.
double PseudoAngle(double dx, double dy)
{
  const double sum = std::abs(dx) + std::abs(dy);
  if (!(sum > 0.0))
  {
    return 0.0;
  }
  const double r = dx / sum;
  return dy >= 0.0 ? 1.0 - r : 3.0 + r;
}

/// Twice the signed area of a 2D polygon (counter-clockwise positive).
double TwiceArea(const glm::dvec2* p, int n)
{
  double a = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const glm::dvec2& u = p[i];
    const glm::dvec2& v = p[(i + 1) % n];
    a += u.x * v.y - u.y * v.x;
  }
  return a;
}

/// Sutherland-Hodgman: @p subject (counter-clockwise, n points) clipped by
/// the convex counter-clockwise @p clipper; result in @p out, returns its size.
int ClipConvex(const glm::dvec2* subject, int n, const glm::dvec2* clipper, int m, glm::dvec2* out)
{
  glm::dvec2 buf[2][MaxClip];
  int count = n;
  for (int i = 0; i < n; ++i)
  {
    buf[0][i] = subject[i];
  }
  int cur = 0;
  for (int e = 0; e < m && count > 0; ++e)
  {
    const glm::dvec2 a = clipper[e], b = clipper[(e + 1) % m];
    const glm::dvec2 d = b - a;
    if (!(glm::dot(d, d) > 0.0))
    {
      continue; // a repeated point: no edge
    }
    const glm::dvec2* in = buf[cur];
    glm::dvec2* res = buf[1 - cur];
    int k = 0;
    for (int i = 0; i < count && k < MaxClip - 1; ++i)
    {
      const glm::dvec2& p = in[i];
      const glm::dvec2& q = in[(i + 1) % count];
      const double sp = d.x * (p.y - a.y) - d.y * (p.x - a.x);
      const double sq = d.x * (q.y - a.y) - d.y * (q.x - a.x);
      if (sp >= 0.0)
      {
        res[k++] = p;
      }
      if ((sp >= 0.0) != (sq >= 0.0) && sp != sq)
      {
        const double t = sp / (sp - sq);
        if (k < MaxClip - 1)
        {
          res[k++] = p + t * (q - p);
        }
      }
    }
    count = k;
    cur = 1 - cur;
  }
  for (int i = 0; i < count; ++i)
  {
    out[i] = buf[cur][i];
  }
  return count;
}
}

bool hov::ProjectionPolyhedron::SetTetra(
  const hov::CellSetup::Tetra& t, const std::vector<glm::dvec3>& points, const Frame& f)
{
  this->NumCorners = 4;
  for (int i = 0; i < 4; ++i)
  {
    const glm::dvec3& x = points[t.Points[i]];
    this->Clip[i] = f.Composite * glm::dvec4(x, 1.0);
    if (!(this->Clip[i].w > 0.0))
    {
      return false;
    }
    this->Gid[i] = t.Points[i];
    this->S[i] = t.RefScalar + glm::dot(t.Gradient, x - points[t.Points[0]]);
  }
  this->Gradient = t.Gradient;
  this->RefPoint = points[t.Points[0]];
  this->RefScalar = t.RefScalar;
  this->SMin = t.ScalarMin;
  this->SMax = t.ScalarMax;
  this->General = nullptr;
  this->SetTopology(hov::CellShape::Tetra);
  return true;
}

void hov::ProjectionPolyhedron::SetTopology(hov::CellShape shape)
{
  this->NumCellFaces = std::min(hov::CellFaceCount(shape), MaxFaces - 2);
  this->NumEdges = 0;
  for (int f = 0; f < this->NumCellFaces; ++f)
  {
    int* corners = this->CellFaces[f];
    const int n = this->CellFaceSize[f] = hov::CellFaceCorners(shape, f, corners);
    for (int i = 0; i < n; ++i)
    {
      const int a = std::min(corners[i], corners[(i + 1) % n]);
      const int b = std::max(corners[i], corners[(i + 1) % n]);
      bool known = false;
      for (int e = 0; e < this->NumEdges && !known; ++e)
      {
        known = this->Edges[e][0] == a && this->Edges[e][1] == b;
      }
      if (!known && this->NumEdges < 12)
      {
        this->Edges[this->NumEdges][0] = a;
        this->Edges[this->NumEdges][1] = b;
        ++this->NumEdges;
      }
    }
  }
}

bool hov::ProjectionPolyhedron::SetGeneral(
  const hov::GeneralCells& cells, const hov::GeneralCells::Cell& c, const Frame& f)
{
  const hov::CellShape geometry = hov::GeometryShape(c.Shape);
  this->NumCorners = std::min(hov::CellCornerCount(geometry), MaxCorners);
  this->General = &c;
  this->Nodes = cells.GetNodes(c);
  this->NodeScalars = cells.GetScalars(c);
  glm::dvec3 mean(0.0);
  double meanS = 0.0;
  this->SMin = std::numeric_limits<double>::infinity();
  this->SMax = -this->SMin;
  glm::dvec3 x[MaxCorners];
  for (int i = 0; i < this->NumCorners; ++i)
  {
    x[i] = glm::dvec3(this->Nodes[3 * i], this->Nodes[3 * i + 1], this->Nodes[3 * i + 2]);
    this->Clip[i] = f.Composite * glm::dvec4(x[i], 1.0);
    if (!(this->Clip[i].w > 0.0))
    {
      return false;
    }
    this->Gid[i] = static_cast<vtkIdType>(c.CornerIds[i]);
    this->S[i] = this->NodeScalars[i];
    this->SMin = std::min(this->SMin, this->S[i]);
    this->SMax = std::max(this->SMax, this->S[i]);
    mean += x[i];
    meanS += this->S[i];
  }
  mean /= static_cast<double>(this->NumCorners);
  meanS /= this->NumCorners;
  // Least-squares affine fit of the corner scalars: only orders the slabs.
  glm::dmat3 cov(0.0);
  glm::dvec3 rhs(0.0);
  for (int i = 0; i < this->NumCorners; ++i)
  {
    const glm::dvec3 d = x[i] - mean;
    cov += glm::outerProduct(d, d);
    rhs += (this->S[i] - meanS) * d;
  }
  const double det = glm::determinant(cov);
  this->Gradient = std::abs(det) > 0.0 ? glm::inverse(cov) * rhs : glm::dvec3(0.0);
  this->RefPoint = mean;
  this->RefScalar = meanS;
  this->SetTopology(geometry);
  return true;
}

double hov::ProjectionPolyhedron::Field(const glm::dvec3& x) const
{
  if (!this->General)
  {
    return this->AffineField(x);
  }
  double pc[3];
  hov::CellParametricCenter(this->General->Shape, pc);
  const double xx[3] = { x.x, x.y, x.z };
  hov::InvertGeometry(this->General->Shape, this->Nodes, xx, pc); // best iterate if it fails
  return hov::InterpolateCellScalar(this->General->Shape, this->NodeScalars, pc);
}

void hov::ProjectionPolyhedron::AddPoint(int face, const glm::dvec4& clip)
{
  int& n = this->FaceSize[face];
  if (n < MaxFacePoints)
  {
    this->Faces[face][n++] = glm::dvec3(clip) / clip.w;
  }
}

void hov::ProjectionPolyhedron::AddEdgeLevelPoints(
  int face, int i, int j, double lo, double hi, bool once)
{
  if (this->Gid[j] < this->Gid[i])
  {
    std::swap(i, j); // canonical direction: neighbours compute the same point
  }
  const double si = this->S[i], sj = this->S[j];
  for (double c : { lo, hi })
  {
    if ((si < c && c < sj) || (sj < c && c < si))
    {
      const double t = (c - si) / (sj - si);
      this->AddPoint(face, this->Clip[i] + t * (this->Clip[j] - this->Clip[i]));
      if (once)
      {
        return;
      }
    }
  }
}

int hov::ProjectionPolyhedron::EmitSlab(int k, const Frame& f, hov::ProjectionChunk& out)
{
  const std::vector<double>& x = f.Tf->GetNodes();
  const int n = static_cast<int>(x.size());
  const double inf = std::numeric_limits<double>::infinity();
  const double lo = k < 0 ? -inf : x[k];
  const double hi = k + 1 < n ? x[k + 1] : inf;
  // The cell's faces cut to the slab, then the caps.
  this->NumFaces = 0;
  for (int cf = 0; cf < this->NumCellFaces; ++cf)
  {
    const int face = this->NumFaces++;
    this->FaceSize[face] = 0;
    const int* corners = this->CellFaces[cf];
    const int m = this->CellFaceSize[cf];
    for (int i = 0; i < m; ++i)
    {
      const int a = corners[i], b = corners[(i + 1) % m];
      if (this->S[a] >= lo && this->S[a] <= hi)
      {
        this->AddPoint(face, this->Clip[a]);
      }
      this->AddEdgeLevelPoints(face, a, b, lo, hi);
    }
  }
  for (double level : { lo, hi })
  {
    if (!(level > this->SMin && level < this->SMax))
    {
      continue;
    }
    const int face = this->NumFaces++;
    this->FaceSize[face] = 0;
    for (int i = 0; i < this->NumCorners; ++i)
    {
      if (this->S[i] == level)
      {
        this->AddPoint(face, this->Clip[i]);
      }
    }
    for (int e = 0; e < this->NumEdges; ++e)
    {
      this->AddEdgeLevelPoints(face, this->Edges[e][0], this->Edges[e][1], level, level, true);
    }
  }
  if (!this->Classify())
  {
    return 0;
  }
  return this->Overlay(k, std::max(lo, this->SMin), std::min(hi, this->SMax), f, out);
}

bool hov::ProjectionPolyhedron::Classify()
{
  glm::dvec3 centroid(0.0);
  int count = 0;
  for (int face = 0; face < this->NumFaces; ++face)
  {
    for (int i = 0; i < this->FaceSize[face]; ++i)
    {
      centroid += this->Faces[face][i];
      ++count;
    }
  }
  if (count == 0)
  {
    return false;
  }
  centroid /= static_cast<double>(count);
  this->NumFront = this->NumBack = 0;
  for (int face = 0; face < this->NumFaces; ++face)
  {
    const int n = this->FaceSize[face];
    if (n < 3)
    {
      continue;
    }
    const glm::dvec3* p = this->Faces[face];
    glm::dvec3 c(0.0);
    for (int i = 0; i < n; ++i)
    {
      c += p[i];
    }
    c /= static_cast<double>(n);
    // Counter-clockwise order in the image plane (the face is convex).
    std::pair<double, int> order[MaxFacePoints];
    for (int i = 0; i < n; ++i)
    {
      order[i] = { PseudoAngle(p[i].x - c.x, p[i].y - c.y), i };
    }
    std::sort(order, order + n);
    double extent = 0.0;
    for (int i = 0; i < n; ++i)
    {
      extent = std::max(extent, std::max(std::abs(p[i].x - c.x), std::abs(p[i].y - c.y)));
    }
    // Drop points that repeat their predecessor up to rounding (a level
    // crossing a rounding error away from a corner): they would make
    // arbitrary tiny edges for the clipper.
    const double tolerance = 1e-9 * extent;
    int sorted[MaxFacePoints];
    int m = 0;
    for (int i = 0; i < n; ++i)
    {
      const glm::dvec3& u = p[order[i].second];
      if (m == 0 || std::abs(u.x - p[sorted[m - 1]].x) + std::abs(u.y - p[sorted[m - 1]].y) > tolerance)
      {
        sorted[m++] = order[i].second;
      }
    }
    while (m > 1 &&
      std::abs(p[sorted[m - 1]].x - p[sorted[0]].x) + std::abs(p[sorted[m - 1]].y - p[sorted[0]].y) <=
        tolerance)
    {
      --m;
    }
    if (m < 3)
    {
      continue;
    }
    Face2D face2;
    face2.N = m;
    glm::dvec3 normal(0.0); // Newell's normal of the sorted 3D polygon
    for (int i = 0; i < m; ++i)
    {
      const glm::dvec3& u = p[sorted[i]];
      const glm::dvec3& v = p[sorted[(i + 1) % m]];
      face2.P[i] = glm::dvec2(u.x, u.y);
      normal += glm::cross(u - c, v - c);
    }
    // Seen edge-on (no projected area): no region of the overlay.
    if (!(normal.z > 1e-9 * glm::length(normal)) || !(normal.z > 1e-12 * extent * extent))
    {
      continue;
    }
    face2.A = -normal.x / normal.z;
    face2.B = -normal.y / normal.z;
    face2.C = glm::dot(normal, c) / normal.z;
    const bool front = face2.A * centroid.x + face2.B * centroid.y + face2.C < centroid.z;
    (front ? this->Front[this->NumFront++] : this->Back[this->NumBack++]) = face2;
  }
  return this->NumFront > 0 && this->NumBack > 0;
}

int hov::ProjectionPolyhedron::Overlay(
  int k, double lo, double hi, const Frame& f, hov::ProjectionChunk& out)
{
  int triangles = 0;
  glm::dvec2 region[MaxClip];
  for (int a = 0; a < this->NumFront; ++a)
  {
    const Face2D& front = this->Front[a];
    for (int b = 0; b < this->NumBack; ++b)
    {
      const Face2D& back = this->Back[b];
      const int n = ClipConvex(front.P, front.N, back.P, back.N, region);
      if (n < 3 || !(TwiceArea(region, n) > 0.0))
      {
        continue;
      }
      unsigned int first = 0;
      float* v = out.AddVertices(n, first);
      bool finite = true;
      for (int i = 0; i < n && finite; ++i)
      {
        finite = this->EmitVertex(region[i], front, back, k, lo, hi, f, v + i * Floats);
      }
      if (!finite)
      {
        out.Vertices.Shrink(static_cast<size_t>(n) * Floats);
        continue;
      }
      unsigned int* index = out.Indices.Append(static_cast<size_t>(n - 2) * 3);
      for (int i = 1; i + 1 < n; ++i, index += 3)
      {
        index[0] = first;
        index[1] = first + i;
        index[2] = first + i + 1;
      }
      triangles += n - 2;
    }
  }
  return triangles;
}

bool hov::ProjectionPolyhedron::EmitVertex(const glm::dvec2& p, const Face2D& front,
  const Face2D& back, int k, double lo, double hi, const Frame& f, float* out) const
{
  const double zFront = front.A * p.x + front.B * p.y + front.C;
  const double zBack = std::max(zFront, back.A * p.x + back.B * p.y + back.C);
  glm::dvec3 pf, pb;
  const double w = hov::ProjectionVertex::Unproject(f, p.x, p.y, zFront, zBack, pf, pb);
  const double sFront = std::min(std::max(this->Field(pf), lo), hi);
  const double sBack = std::min(std::max(this->Field(pb), lo), hi);
  return hov::ProjectionVertex::Write(f, k, p.x, p.y, zFront, w, pf, pb, sFront, sBack, out);
}
