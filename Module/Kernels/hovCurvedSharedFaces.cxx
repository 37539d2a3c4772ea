// Faces shared by two curved cells, searched once per ray: see hovCurvedSharedFaces.h.
#include "hovCurvedSharedFaces.h"

#include <algorithm> // std::sort, std::min
#include <array>     // face keys
#include <cmath>     // std::abs

namespace hov
{
namespace
{
/// Agreement of the two cells' maps on a linked face, relative to the extent.
constexpr double ConformTolerance = 1e-12;

/// Index of the corner node at reference point @p pc, or -1.
int CornerNode(const LagrangeBasis& b, const double pc[3])
{
  const int corners = b.GetShape() == LagrangeShape::Tetra ? 4
    : b.GetShape() == LagrangeShape::Wedge                 ? 6
                                                            : 8;
  for (int i = 0; i < corners; ++i)
  {
    double q[3];
    b.NodeParametricCoords(i, q);
    if (std::abs(q[0] - pc[0]) + std::abs(q[1] - pc[1]) + std::abs(q[2] - pc[2]) < 1e-12)
    {
      return i;
    }
  }
  return -1;
}

/// The corners of face @p k in cyclic order (reference points): 3 or 4.
int FaceCorners(const CurvedCellFaces& f, int k, double pc[4][3])
{
  const CurvedFacePatch& p = f.Faces[f.FaceFirstPatch[k]];
  if (p.Triangle)
  {
    std::copy(p.P00, p.P00 + 3, pc[0]);
    std::copy(p.P10, p.P10 + 3, pc[1]);
    std::copy(p.P01, p.P01 + 3, pc[2]);
    return 3;
  }
  std::copy(p.P00, p.P00 + 3, pc[0]);
  std::copy(p.P10, p.P10 + 3, pc[1]);
  std::copy(p.P11, p.P11 + 3, pc[2]);
  std::copy(p.P01, p.P01 + 3, pc[3]);
  return 4;
}

/// One face of one cell, keyed by its sorted corner point ids.
struct FaceRecord
{
  std::array<std::int64_t, 4> Key;
  int Cell, Face;
  bool operator<(const FaceRecord& o) const
  {
    return this->Key < o.Key || (this->Key == o.Key && this->Cell < o.Cell);
  }
};

/// The canonical frame of a face (see file doc) into @p frame (O, E1, E2).
void CanonicalFrame(const double pc[4][3], const std::int64_t ids[4], int n, double frame[9])
{
  int o = 0;
  for (int i = 1; i < n; ++i)
  {
    o = ids[i] < ids[o] ? i : o;
  }
  int e1 = (o + 1) % n, e2 = (o + n - 1) % n; // a triangle's other two, a quad's neighbours
  if (ids[e2] < ids[e1])
  {
    std::swap(e1, e2);
  }
  std::copy(pc[o], pc[o] + 3, frame);
  std::copy(pc[e1], pc[e1] + 3, frame + 3);
  std::copy(pc[e2], pc[e2] + 3, frame + 6);
}

void FramePoint(const double* frame, double a, double b, double pc[3])
{
  for (int k = 0; k < 3; ++k)
  {
    pc[k] = frame[k] + a * (frame[3 + k] - frame[k]) + b * (frame[6 + k] - frame[k]);
  }
}

/// The two cells' maps agree on the linked face (three points of its frame).
bool Conforming(const SharedFaceCell& p, const double* fp, const SharedFaceCell& q, const double* fq)
{
  static constexpr double samples[3][2] = { { 0.2, 0.3 }, { 0.55, 0.25 }, { 0.3, 0.5 } };
  const double tol =
    ConformTolerance * std::max(LagrangeCellExtent(p.View), LagrangeCellExtent(q.View));
  for (const auto& s : samples)
  {
    double a[3], b[3], xa[3], xb[3];
    FramePoint(fp, s[0], s[1], a);
    FramePoint(fq, s[0], s[1], b);
    EvaluateLagrangePosition(p.View, a, xa);
    EvaluateLagrangePosition(q.View, b, xb);
    for (int k = 0; k < 3; ++k)
    {
      if (!(std::abs(xa[k] - xb[k]) <= tol))
      {
        return false;
      }
    }
  }
  return true;
}
}

int LinkSharedFaces(const std::vector<SharedFaceCell>& cells, std::vector<CellFaceLinks>& links)
{
  links.assign(cells.size(), CellFaceLinks());
  std::vector<FaceRecord> records;
  for (size_t c = 0; c < cells.size(); ++c)
  {
    const SharedFaceCell& cell = cells[c];
    const CurvedCellFaces& f = *cell.Faces;
    const int numFaces = f.FaceFirstPatch.empty() ? 0 : static_cast<int>(f.FaceFirstPatch.size()) - 1;
    links[c].FaceIds.assign(numFaces, -1);
    links[c].Frames.assign(9 * static_cast<size_t>(numFaces), 0.0);
    for (int k = 0; k < numFaces && cell.View.Basis && cell.CornerIds; ++k)
    {
      double pc[4][3];
      std::int64_t ids[4];
      const int n = FaceCorners(f, k, pc);
      bool ok = true;
      for (int i = 0; i < n && ok; ++i)
      {
        const int node = CornerNode(*cell.View.Basis, pc[i]);
        ok = node >= 0;
        ids[i] = ok ? cell.CornerIds[node] : -1;
      }
      if (!ok)
      {
        continue;
      }
      CanonicalFrame(pc, ids, n, &links[c].Frames[9 * static_cast<size_t>(k)]);
      FaceRecord r{ { -1, -1, -1, -1 }, static_cast<int>(c), k };
      std::copy(ids, ids + n, r.Key.begin());
      std::sort(r.Key.begin(), r.Key.begin() + n);
      records.push_back(r);
    }
  }
  std::sort(records.begin(), records.end());
  int shared = 0;
  for (size_t i = 0; i < records.size();)
  {
    size_t j = i + 1;
    while (j < records.size() && records[j].Key == records[i].Key)
    {
      ++j;
    }
    // Exactly two cells on the face (three or more: non-manifold, not shared).
    if (j - i == 2)
    {
      const FaceRecord &p = records[i], &q = records[i + 1];
      const double* fp = &links[p.Cell].Frames[9 * static_cast<size_t>(p.Face)];
      const double* fq = &links[q.Cell].Frames[9 * static_cast<size_t>(q.Face)];
      if (p.Cell != q.Cell && Conforming(cells[p.Cell], fp, cells[q.Cell], fq))
      {
        links[p.Cell].FaceIds[p.Face] = shared;
        links[q.Cell].FaceIds[q.Face] = shared;
        ++shared;
      }
    }
    i = j;
  }
  return shared;
}

void FaceCrossingCache::Clear()
{
  this->Entries.clear();
  this->Points.clear();
}

bool FaceCrossingCache::Take(int id, int cell, const double* frame,
  std::vector<FaceCrossing>& out, bool& complete) const
{
  for (const Entry& e : this->Entries)
  {
    if (e.Face != id)
    {
      continue;
    }
    for (int i = e.First; i < e.First + e.Count; ++i)
    {
      const Point& p = this->Points[i];
      FaceCrossing c;
      c.T = p.T;
      FramePoint(frame, p.A, p.B, c.PC);
      c.Side = e.Cell == cell ? p.Side : -p.Side;
      c.Grazing = p.Grazing;
      out.push_back(c);
    }
    complete = e.Complete;
    return true;
  }
  return false;
}

void FaceCrossingCache::Store(int id, int cell, const double* frame,
  const std::vector<FaceCrossing>& found, size_t first, bool complete)
{
  // (a, b) of each crossing: the least-squares solution of
  // PC - O = a (E1 - O) + b (E2 - O) (exact up to rounding: PC lies on the face).
  double u[3], v[3];
  for (int k = 0; k < 3; ++k)
  {
    u[k] = frame[3 + k] - frame[k];
    v[k] = frame[6 + k] - frame[k];
  }
  const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  const double uv = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const double vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const double det = uu * vv - uv * uv;
  this->Entries.push_back({ id, cell, static_cast<int>(this->Points.size()),
    static_cast<int>(found.size() - first), complete });
  for (size_t i = first; i < found.size(); ++i)
  {
    const FaceCrossing& c = found[i];
    const double w[3] = { c.PC[0] - frame[0], c.PC[1] - frame[1], c.PC[2] - frame[2] };
    const double uw = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
    const double vw = v[0] * w[0] + v[1] * w[1] + v[2] * w[2];
    const double a = det != 0.0 ? (vv * uw - uv * vw) / det : 0.0;
    const double b = det != 0.0 ? (uu * vw - uv * uw) / det : 0.0;
    this->Points.push_back({ a, b, c.T, c.Side, c.Grazing });
  }
}
}
