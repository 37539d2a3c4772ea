#include "hovProjectionTetra.h"

#include <algorithm> // std::min, std::max

namespace
{
using Vertex = hov::ProjectionVertex;

/// The tetrahedron in clip and NDC coordinates, its corner scalars clamped to the slab.
struct Projected
{
  glm::dvec4 Clip[4];
  glm::dvec3 Ndc[4];
  double S[4];
  const hov::CellSetup::Tetra* T;
  glm::dvec3 Ref; ///< the field's reference point (vertex 0)
  const hov::ProjectionFrame* F;
  int K;
  double Lo, Hi;

  /// Twice the signed area of the projected triangle (a, b, c).
  double Orient(int a, int b, int c) const
  {
    const glm::dvec3 &p = this->Ndc[a], &q = this->Ndc[b], &r = this->Ndc[c];
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
  }
  /// The cell's affine field at @p x, clamped to the slab.
  double Field(const glm::dvec3& x) const
  {
    const double s = this->T->RefScalar + glm::dot(this->T->Gradient, x - this->Ref);
    return std::min(std::max(s, this->Lo), this->Hi);
  }
};

bool Opposite(double a, double b)
{
  return (a > 0.0 && b < 0.0) || (a < 0.0 && b > 0.0);
}

/**
 * The vertices of one tetrahedron's projection into @p out: the thick vertex
 * at NDC (x, y) with the segment zFront..zBack first, then the corners
 * @p corners[0..n); the triangles (thick, corner i, corner i+1) around it
 * (cyclically). False if the thick vertex is not finite (@p out unchanged).
 */
bool EmitFan(const Projected& p, double x, double y, double zFront, double zBack,
  const int* corners, int n, hov::ProjectionChunk& out)
{
  unsigned int first = 0;
  float* v = out.AddVertices(n + 1, first);
  glm::dvec3 front, back;
  const double w = Vertex::Unproject(*p.F, x, y, zFront, zBack, front, back);
  if (!Vertex::Write(*p.F, p.K, x, y, zFront, w, front, back, p.Field(front), p.Field(back), v))
  {
    out.Vertices.Shrink(static_cast<size_t>(n + 1) * Vertex::FloatsPerVertex);
    return false;
  }
  for (int i = 0; i < n; ++i)
  {
    const int c = corners[i];
    Vertex::WriteCorner(*p.F, p.K, p.Clip[c], p.S[c], v + (i + 1) * Vertex::FloatsPerVertex);
  }
  unsigned int* index = out.Indices.Append(static_cast<size_t>(3 * n));
  for (int i = 0; i < n; ++i)
  {
    index[3 * i] = first;
    index[3 * i + 1] = first + 1 + i;
    index[3 * i + 2] = first + 1 + (i + 1) % n;
  }
  return true;
}

/// Class 2: the projected edges a-b and c-d cross (orientations o1..o4).
int EmitCrossing(const Projected& p, int a, int b, int c, int d, double o1, double o2, double o3,
  double o4, hov::ProjectionChunk& out)
{
  const double alpha = o3 / (o3 - o4); // along a -> b
  const double beta = o1 / (o1 - o2);  // along c -> d
  const glm::dvec3 onAB = p.Ndc[a] + alpha * (p.Ndc[b] - p.Ndc[a]);
  const double zCD = p.Ndc[c].z + beta * (p.Ndc[d].z - p.Ndc[c].z);
  const int corners[4] = { a, c, b, d };
  return EmitFan(p, onAB.x, onAB.y, std::min(onAB.z, zCD), std::max(onAB.z, zCD), corners, 4, out)
    ? 4
    : hov::ProjectionTetra::Degenerate;
}

/// Class 1: corner i projects strictly inside the triangle (j, k, l).
int EmitInside(const Projected& p, int i, int j, int k, int l, hov::ProjectionChunk& out)
{
  const double total = p.Orient(j, k, l);
  const double zFace = (p.Orient(i, k, l) * p.Ndc[j].z + p.Orient(j, i, l) * p.Ndc[k].z +
                         p.Orient(j, k, i) * p.Ndc[l].z) /
    total;
  const double zCorner = p.Ndc[i].z;
  const int corners[3] = { j, k, l };
  return EmitFan(p, p.Ndc[i].x, p.Ndc[i].y, std::min(zCorner, zFace), std::max(zCorner, zFace),
           corners, 3, out)
    ? 3
    : hov::ProjectionTetra::Degenerate;
}
}

int hov::ProjectionTetra::Emit(const hov::CellSetup::Tetra& t,
  const std::vector<glm::dvec3>& points, const hov::ProjectionFrame& f, int k, double lo,
  double hi, hov::ProjectionChunk& out)
{
  Projected p{};
  p.T = &t;
  p.Ref = points[t.Points[0]];
  p.F = &f;
  p.K = k;
  p.Lo = lo;
  p.Hi = hi;
  for (int i = 0; i < 4; ++i)
  {
    const glm::dvec3& x = points[t.Points[i]];
    p.Clip[i] = f.Composite * glm::dvec4(x, 1.0);
    if (!(p.Clip[i].w > 0.0))
    {
      return BehindEye;
    }
    p.Ndc[i] = glm::dvec3(p.Clip[i]) / p.Clip[i].w;
    p.S[i] = p.Field(x);
  }
  static const int pairs[3][4] = { { 0, 1, 2, 3 }, { 0, 2, 1, 3 }, { 0, 3, 1, 2 } };
  for (const auto& e : pairs)
  {
    const double o1 = p.Orient(e[0], e[1], e[2]), o2 = p.Orient(e[0], e[1], e[3]);
    const double o3 = p.Orient(e[2], e[3], e[0]), o4 = p.Orient(e[2], e[3], e[1]);
    if (Opposite(o1, o2) && Opposite(o3, o4))
    {
      return EmitCrossing(p, e[0], e[1], e[2], e[3], o1, o2, o3, o4, out);
    }
  }
  for (int i = 0; i < 4; ++i)
  {
    const int j = (i + 1) % 4, m = (i + 2) % 4, l = (i + 3) % 4;
    const double a = p.Orient(j, m, i), b = p.Orient(m, l, i), c = p.Orient(l, j, i);
    if ((a > 0.0 && b > 0.0 && c > 0.0) || (a < 0.0 && b < 0.0 && c < 0.0))
    {
      return EmitInside(p, i, j, m, l, out);
    }
  }
  return Degenerate;
}
