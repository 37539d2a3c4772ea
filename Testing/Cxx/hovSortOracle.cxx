#include "hovSortOracle.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkIdList.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace hovTest
{
namespace
{
using V3 = std::array<double, 3>;

V3 Sub(const V3& a, const V3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
double Dot(const V3& a, const V3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V3 Cross(const V3& a, const V3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
V3 Unit(const V3& a)
{
  const double l = std::sqrt(Dot(a, a));
  return l > 0 ? V3{ a[0] / l, a[1] / l, a[2] / l } : a;
}

int Corners(int type)
{
  switch (type)
  {
    case VTK_TETRA:
    case VTK_QUADRATIC_TETRA:
      return 4;
    case VTK_PYRAMID:
    case VTK_QUADRATIC_PYRAMID:
      return 5;
    case VTK_WEDGE:
    case VTK_QUADRATIC_WEDGE:
      return 6;
    case VTK_VOXEL:
    case VTK_HEXAHEDRON:
    case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_HEXAHEDRON:
      return 8;
    default:
      return 0;
  }
}

/// Supporting half-space n.x + off <= 0 and the corners lying on it.
struct HalfSpace
{
  V3 N;
  double Off;
  std::array<vtkIdType, 4> Key; // sorted global point ids, -1 padded (Size > 4: no key)
  int Size;
};

struct CellGeometry
{
  std::vector<V3> P;
  std::vector<HalfSpace> H;
  V3 Centroid{ 0, 0, 0 };
};

CellGeometry BuildCell(const std::vector<V3>& world, const vtkIdType* ids, int nc, double tol)
{
  CellGeometry g;
  for (int k = 0; k < nc; ++k)
  {
    g.P.push_back(world[ids[k]]);
    for (int j = 0; j < 3; ++j)
    {
      g.Centroid[j] += world[ids[k]][j] / nc;
    }
  }
  std::vector<unsigned> seenMasks;
  for (int a = 0; a < nc; ++a)
    for (int b = a + 1; b < nc; ++b)
      for (int c = b + 1; c < nc; ++c)
      {
        const V3 e1 = Sub(g.P[b], g.P[a]), e2 = Sub(g.P[c], g.P[a]);
        const V3 n = Cross(e1, e2);
        if (Dot(n, n) <= 1e-18 * Dot(e1, e1) * Dot(e2, e2))
        {
          continue; // collinear corners
        }
        const V3 u = Unit(n);
        int pos = 0, neg = 0;
        unsigned mask = 0;
        for (int m = 0; m < nc; ++m)
        {
          const double d = Dot(u, Sub(g.P[m], g.P[a]));
          pos += d > tol;
          neg += d < -tol;
          mask |= std::abs(d) <= tol ? 1u << m : 0u;
        }
        if ((pos && neg) || std::find(seenMasks.begin(), seenMasks.end(), mask) != seenMasks.end())
        {
          continue;
        }
        seenMasks.push_back(mask);
        HalfSpace h;
        h.N = pos ? V3{ -u[0], -u[1], -u[2] } : u; // outward
        h.Off = -Dot(h.N, g.P[a]);
        h.Key.fill(-1);
        h.Size = 0;
        for (int m = 0; m < nc; ++m)
        {
          if (mask & (1u << m))
          {
            if (h.Size < 4)
            {
              h.Key[h.Size] = ids[m];
            }
            ++h.Size;
          }
        }
        std::sort(h.Key.begin(), h.Key.begin() + std::min(h.Size, 4));
        g.H.push_back(h);
      }
  return g;
}

/// Deterministic uniform number in [0,1) from (seed, ray, axis).
double Hash01(unsigned seed, vtkIdType ray, int axis)
{
  unsigned long long z = (static_cast<unsigned long long>(seed) << 32) ^
    (static_cast<unsigned long long>(ray) * 3 + axis) * 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
}

struct Hit
{
  double T0, T1;
  vtkIdType Cell;
};

struct RayLocal
{
  std::vector<std::pair<vtkIdType, vtkIdType>> Wrong, Overlap;
  vtkIdType Hits = 0, Pairs = 0, RaysWrong = 0;
  std::vector<Hit> Buffer;
};
}

std::string OracleResult::Str() const
{
  std::ostringstream s;
  s << "missing " << Missing << ", duplicates " << Duplicates << ", out of range " << OutOfRange
    << "; rays " << Rays << ", hits " << Hits << ", pairs " << PairsChecked
    << ", ray violations (cell pairs) " << RayViolations << " on " << RaysWithViolation
    << " rays, overlapping pairs " << OverlappingPairs << "; faces " << FacesChecked
    << ", face violations " << FaceViolations;
  return s.str();
}

OracleResult CheckVisibilityOrder(vtkUnstructuredGrid* grid, vtkCamera* camera,
  vtkMatrix4x4* model, const std::vector<vtkIdType>& order, const OracleOptions& opt)
{
  OracleResult r;
  const vtkIdType n = grid->GetNumberOfCells();
  // 1. Permutation.
  std::vector<vtkIdType> rank(static_cast<size_t>(n), -1);
  for (size_t i = 0; i < order.size(); ++i)
  {
    const vtkIdType c = order[i];
    if (c < 0 || c >= n)
    {
      ++r.OutOfRange;
    }
    else if (rank[c] >= 0)
    {
      ++r.Duplicates;
    }
    else
    {
      rank[c] = static_cast<vtkIdType>(i);
    }
  }
  r.Missing = std::count(rank.begin(), rank.end(), -1);

  // World points and scene size.
  std::vector<V3> world(static_cast<size_t>(grid->GetNumberOfPoints()));
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double p[4] = { 0, 0, 0, 1 }, q[4];
    grid->GetPoint(i, p);
    p[3] = 1;
    if (model)
    {
      model->MultiplyPoint(p, q);
    }
    else
    {
      std::copy(p, p + 4, q);
    }
    world[i] = { q[0] / q[3], q[1] / q[3], q[2] / q[3] };
    for (int j = 0; j < 3; ++j)
    {
      lo[j] = std::min(lo[j], world[i][j]);
      hi[j] = std::max(hi[j], world[i][j]);
    }
  }
  const double scale =
    std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
      (hi[2] - lo[2]) * (hi[2] - lo[2]));
  const double tol = opt.RelTol * scale;

  // Cells.
  std::vector<CellGeometry> cells(static_cast<size_t>(n));
  vtkSMPTools::For(0, n, [&](vtkIdType b, vtkIdType e) {
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = b; c < e; ++c)
    {
      const int nc = Corners(grid->GetCellType(c));
      grid->GetCellPoints(c, ids);
      if (nc > 0 && ids->GetNumberOfIds() >= nc)
      {
        cells[c] = BuildCell(world, ids->GetPointer(0), nc, tol);
      }
    }
  });

  // Camera frame.
  double tmp[3];
  camera->GetPosition(tmp);
  const V3 eye{ tmp[0], tmp[1], tmp[2] };
  camera->GetDirectionOfProjection(tmp);
  const V3 f = Unit({ tmp[0], tmp[1], tmp[2] });
  camera->GetViewUp(tmp);
  V3 up{ tmp[0], tmp[1], tmp[2] };
  const double uf = Dot(up, f);
  up = Unit({ up[0] - uf * f[0], up[1] - uf * f[1], up[2] - uf * f[2] });
  const V3 right = Cross(f, up);
  const bool persp = !camera->GetParallelProjection();
  const double epsDepth = 1e-9 * scale;

  // Screen boxes and buckets.
  std::vector<std::array<double, 4>> box(static_cast<size_t>(n));
  std::vector<char> kind(static_cast<size_t>(n), 0); // 0 invisible, 1 boxed, 2 everywhere
  double win[4] = { 1e300, -1e300, 1e300, -1e300 };
  for (vtkIdType c = 0; c < n; ++c)
  {
    const CellGeometry& g = cells[c];
    if (g.H.empty())
    {
      continue;
    }
    std::array<double, 4> bx{ 1e300, -1e300, 1e300, -1e300 };
    int front = 0;
    for (const V3& p : g.P)
    {
      const V3 q = Sub(p, eye);
      const double depth = Dot(q, f);
      if (persp && depth <= epsDepth)
      {
        continue;
      }
      ++front;
      const double a = Dot(q, right) / (persp ? depth : 1.0);
      const double b = Dot(q, up) / (persp ? depth : 1.0);
      bx = { std::min(bx[0], a), std::max(bx[1], a), std::min(bx[2], b), std::max(bx[3], b) };
    }
    kind[c] = front == 0 ? 0 : (front < static_cast<int>(g.P.size()) ? 2 : 1);
    box[c] = bx;
    if (kind[c] == 1)
    {
      win[0] = std::min(win[0], bx[0]);
      win[1] = std::max(win[1], bx[1]);
      win[2] = std::min(win[2], bx[2]);
      win[3] = std::max(win[3], bx[3]);
    }
  }
  const bool anyEverywhere = std::count(kind.begin(), kind.end(), 2) > 0;
  if (persp)
  {
    const double t = anyEverywhere ? 3.0 : 1e300;
    win[0] = anyEverywhere ? -t : std::max(win[0], -3.0);
    win[1] = anyEverywhere ? t : std::min(win[1], 3.0);
    win[2] = anyEverywhere ? -t : std::max(win[2], -3.0);
    win[3] = anyEverywhere ? t : std::min(win[3], 3.0);
  }
  if (!(win[1] > win[0] && win[3] > win[2]))
  {
    win[0] = win[2] = -1;
    win[1] = win[3] = 1;
  }
  const int G = 96;
  std::vector<std::vector<vtkIdType>> bucket(G * G);
  std::vector<vtkIdType> everywhere;
  auto cellOf = [&](double v, int axis) {
    const double x = (v - win[2 * axis]) / (win[2 * axis + 1] - win[2 * axis]) * G;
    return std::min(G - 1, std::max(0, static_cast<int>(std::floor(x))));
  };
  for (vtkIdType c = 0; c < n; ++c)
  {
    if (kind[c] == 2)
    {
      everywhere.push_back(c);
    }
    else if (kind[c] == 1)
    {
      if (box[c][1] < win[0] || box[c][0] > win[1] || box[c][3] < win[2] || box[c][2] > win[3])
      {
        continue;
      }
      for (int j = cellOf(box[c][2], 1); j <= cellOf(box[c][3], 1); ++j)
        for (int i = cellOf(box[c][0], 0); i <= cellOf(box[c][1], 0); ++i)
          bucket[j * G + i].push_back(c);
    }
  }

  // 2. Rays.
  const vtkIdType gridRays = static_cast<vtkIdType>(opt.RaysX) * opt.RaysY;
  r.Rays = gridRays + opt.RandomRays;
  vtkSMPThreadLocal<RayLocal> locals;
  vtkSMPTools::For(0, r.Rays, [&](vtkIdType b, vtkIdType e) {
    RayLocal& L = locals.Local();
    for (vtkIdType ray = b; ray < e; ++ray)
    {
      double ua, ub;
      if (ray < gridRays)
      {
        ua = (ray % opt.RaysX + 0.5) / opt.RaysX;
        ub = (ray / opt.RaysX + 0.5) / opt.RaysY;
      }
      else
      {
        ua = Hash01(opt.Seed, ray, 0);
        ub = Hash01(opt.Seed, ray, 1);
      }
      const double a = win[0] + ua * (win[1] - win[0]);
      const double bb = win[2] + ub * (win[3] - win[2]);
      V3 o = eye, d = f;
      for (int j = 0; j < 3; ++j)
      {
        if (persp)
          d[j] = f[j] + a * right[j] + bb * up[j];
        else
          o[j] = eye[j] + a * right[j] + bb * up[j];
      }
      const double tolT = tol / std::sqrt(Dot(d, d));
      L.Buffer.clear();
      auto clip = [&](vtkIdType c) {
        double t0 = persp ? 0.0 : -1e300, t1 = 1e300;
        for (const HalfSpace& h : cells[c].H)
        {
          const double s = Dot(h.N, o) + h.Off, den = Dot(h.N, d);
          if (den == 0.0)
          {
            if (s > 0)
              return;
            continue;
          }
          const double t = -s / den;
          if (den > 0)
            t1 = std::min(t1, t);
          else
            t0 = std::max(t0, t);
          if (t1 - t0 <= tolT)
            return;
        }
        L.Buffer.push_back({ t0, t1, c });
      };
      for (vtkIdType c : bucket[cellOf(bb, 1) * G + cellOf(a, 0)])
        clip(c);
      for (vtkIdType c : everywhere)
        clip(c);
      std::sort(L.Buffer.begin(), L.Buffer.end(),
        [](const Hit& x, const Hit& y) { return x.T0 < y.T0; });
      L.Hits += static_cast<vtkIdType>(L.Buffer.size());
      bool wrong = false;
      for (size_t i = 0; i < L.Buffer.size(); ++i)
        for (size_t j = i + 1; j < L.Buffer.size(); ++j)
        {
          const Hit& nearer = L.Buffer[i];
          const Hit& farther = L.Buffer[j];
          ++L.Pairs;
          if (nearer.T1 <= farther.T0 + tolT)
          {
            if (rank[farther.Cell] > rank[nearer.Cell])
            {
              L.Wrong.emplace_back(nearer.Cell, farther.Cell);
              wrong = true;
            }
          }
          else
          {
            L.Overlap.emplace_back(
              std::min(nearer.Cell, farther.Cell), std::max(nearer.Cell, farther.Cell));
          }
        }
      L.RaysWrong += wrong;
    }
  });
  std::vector<std::pair<vtkIdType, vtkIdType>> wrong, overlap;
  for (RayLocal& L : locals)
  {
    wrong.insert(wrong.end(), L.Wrong.begin(), L.Wrong.end());
    overlap.insert(overlap.end(), L.Overlap.begin(), L.Overlap.end());
    r.Hits += L.Hits;
    r.PairsChecked += L.Pairs;
    r.RaysWithViolation += L.RaysWrong;
  }
  for (auto* v : { &wrong, &overlap })
  {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  r.RayViolations = static_cast<vtkIdType>(wrong.size());
  r.OverlappingPairs = static_cast<vtkIdType>(overlap.size());
  r.Examples.assign(wrong.begin(), wrong.begin() + std::min<size_t>(wrong.size(), 5));

  // 3. Interior faces.
  struct FaceRef
  {
    std::array<vtkIdType, 4> Key;
    vtkIdType Cell;
    int H;
  };
  std::vector<FaceRef> faces;
  for (vtkIdType c = 0; c < n; ++c)
    for (size_t h = 0; h < cells[c].H.size(); ++h)
      if (cells[c].H[h].Size >= 3 && cells[c].H[h].Size <= 4)
        faces.push_back({ cells[c].H[h].Key, c, static_cast<int>(h) });
  std::sort(faces.begin(), faces.end(),
    [](const FaceRef& x, const FaceRef& y) { return x.Key < y.Key; });
  for (size_t i = 0; i < faces.size();)
  {
    size_t j = i;
    while (j < faces.size() && faces[j].Key == faces[i].Key)
      ++j;
    if (j - i == 2 && rank[faces[i].Cell] >= 0 && rank[faces[i + 1].Cell] >= 0)
    {
      const HalfSpace& h = cells[faces[i].Cell].H[faces[i].H]; // outward from cell A
      double sEye, sTol;
      if (persp)
      {
        sEye = Dot(h.N, eye) + h.Off;
        sTol = 1e-7 * std::sqrt(Dot(Sub(eye, cells[faces[i].Cell].Centroid),
                                  Sub(eye, cells[faces[i].Cell].Centroid)));
      }
      else
      {
        sEye = -Dot(h.N, f);
        sTol = 1e-7;
      }
      bool visible = !persp;
      for (int k = 0; k < h.Size && !visible; ++k)
        visible = Dot(Sub(world[h.Key[k]], eye), f) > 0;
      if (std::abs(sEye) > sTol && visible)
      {
        // Eye outside A across this face: A is behind, B in front -> A first.
        const vtkIdType back = sEye > 0 ? faces[i].Cell : faces[i + 1].Cell;
        const vtkIdType front = sEye > 0 ? faces[i + 1].Cell : faces[i].Cell;
        ++r.FacesChecked;
        r.FaceViolations += rank[back] > rank[front];
      }
    }
    i = j;
  }
  return r;
}
}
