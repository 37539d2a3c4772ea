#include "hovSortMeshes.h"

#include "vtkCell.h"
#include "vtkCellType.h"
#include "vtkGenericCell.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkTransform.h"

#include <array>
#include <cmath>
#include <utility>

namespace hovTest
{
namespace
{
using P3 = std::array<double, 3>;

P3 Sub(const P3& a, const P3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

double Dot(const P3& a, const P3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

P3 Centroid(const MeshBuilder& m, const std::vector<vtkIdType>& ids)
{
  P3 c{ 0, 0, 0 };
  for (vtkIdType id : ids)
  {
    for (int j = 0; j < 3; ++j)
    {
      c[j] += m.Points[id][j] / ids.size();
    }
  }
  return c;
}

/// Newell normal of the polygon @p ids.
P3 Normal(const MeshBuilder& m, const std::vector<vtkIdType>& ids)
{
  P3 n{ 0, 0, 0 };
  for (size_t k = 0; k < ids.size(); ++k)
  {
    const P3& a = m.Points[ids[k]];
    const P3& b = m.Points[ids[(k + 1) % ids.size()]];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

/// Hexahedron with VTK's orientation (base normal towards the top).
void AddHex(MeshBuilder& m, std::vector<vtkIdType> v)
{
  const P3 up = Sub(Centroid(m, { v[4], v[5], v[6], v[7] }), Centroid(m, { v[0], v[1], v[2], v[3] }));
  if (Dot(Normal(m, { v[0], v[1], v[2], v[3] }), up) < 0)
  {
    std::swap(v[1], v[3]);
    std::swap(v[5], v[7]);
  }
  m.AddCell(VTK_HEXAHEDRON, v);
}

/// Wedge with VTK's documented orientation (normal of 0,1,2 away from 3,4,5).
void AddWedge(MeshBuilder& m, std::vector<vtkIdType> v)
{
  const P3 up = Sub(Centroid(m, { v[3], v[4], v[5] }), Centroid(m, { v[0], v[1], v[2] }));
  if (Dot(Normal(m, { v[0], v[1], v[2] }), up) > 0)
  {
    std::swap(v[1], v[2]);
    std::swap(v[4], v[5]);
  }
  m.AddCell(VTK_WEDGE, v);
}

/// Pyramid with VTK's orientation (base normal towards the apex).
void AddPyramid(MeshBuilder& m, std::vector<vtkIdType> v)
{
  const P3 up = Sub(m.Points[v[4]], Centroid(m, { v[0], v[1], v[2], v[3] }));
  if (Dot(Normal(m, { v[0], v[1], v[2], v[3] }), up) < 0)
  {
    std::swap(v[1], v[3]);
  }
  m.AddCell(VTK_PYRAMID, v);
}

vtkIdType AddP(MeshBuilder& m, const P3& p)
{
  return m.AddPoint(p[0], p[1], p[2], DefaultField(p[0], p[1], p[2]));
}

void RotateAll(MeshBuilder& m, double angleDeg, const double axis[3], const double shift[3])
{
  vtkNew<vtkTransform> t;
  t->Translate(shift);
  t->RotateWXYZ(angleDeg, axis);
  for (auto& p : m.Points)
  {
    double q[3];
    t->TransformPoint(p.data(), q);
    p = { q[0], q[1], q[2] };
  }
}

/// A thin triangular prism (wedge) around the segment a-b: width @p w across,
/// height @p h above the segment (in the plane containing a-b and +z).
void AddStick(MeshBuilder& m, const P3& a, const P3& b, double w, double h)
{
  P3 d = Sub(b, a);
  P3 side{ -d[1], d[0], 0 };
  const double len = std::sqrt(Dot(side, side));
  for (double& s : side)
  {
    s *= 0.5 * w / len;
  }
  std::vector<vtkIdType> v;
  for (const P3& e : { a, b })
  {
    v.push_back(AddP(m, { e[0] - side[0], e[1] - side[1], e[2] }));
    v.push_back(AddP(m, { e[0] + side[0], e[1] + side[1], e[2] }));
    v.push_back(AddP(m, { e[0], e[1], e[2] + h }));
  }
  AddWedge(m, v);
}
}

//------------------------------------------------------------------------------
MeshBuilder JitteredTetBlock(int nx, int ny, int nz, const double o[3], const double size[3],
  double jitter, unsigned seed, const std::function<bool(int, int, int)>& keep)
{
  MeshBuilder m;
  const double h[3] = { size[0] / nx, size[1] / ny, size[2] / nz };
  SortRandom rng(seed);
  std::vector<P3> base, offset;
  for (int k = 0; k <= nz; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        base.push_back({ o[0] + h[0] * i, o[1] + h[1] * j, o[2] + h[2] * k });
        offset.push_back({ jitter * h[0] * rng.Uniform(-1, 1), jitter * h[1] * rng.Uniform(-1, 1),
          jitter * h[2] * rng.Uniform(-1, 1) });
      }
    }
  }
  auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  static const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 },
    { 2, 0, 1 }, { 2, 1, 0 } };
  std::vector<std::array<vtkIdType, 4>> tets;
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        if (keep && !keep(i, j, k))
        {
          continue;
        }
        for (const auto& p : perms)
        {
          int c[3] = { i, j, k };
          std::array<vtkIdType, 4> t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s)
          {
            ++c[p[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          tets.push_back(t);
        }
      }
    }
  }
  // Points: base + offset; halve the offsets of tets that lost too much volume.
  for (const P3& b : base)
  {
    m.AddPoint(b[0], b[1], b[2], 0.0);
  }
  auto vol = [&](const std::array<vtkIdType, 4>& t, bool jittered) {
    for (vtkIdType v : t)
    {
      for (int a = 0; a < 3; ++a)
      {
        m.Points[v][a] = base[v][a] + (jittered ? offset[v][a] : 0.0);
      }
    }
    return m.SignedVolume6({ t[0], t[1], t[2], t[3] });
  };
  for (int iter = 0; iter < 30; ++iter)
  {
    bool changed = false;
    for (const auto& t : tets)
    {
      const double v0 = vol(t, false);
      if (std::abs(vol(t, true)) < 0.2 * std::abs(v0) || vol(t, true) * v0 < 0)
      {
        for (vtkIdType v : t)
        {
          for (double& d : offset[v])
          {
            d *= (iter < 29 ? 0.5 : 0.0);
          }
        }
        changed = true;
      }
    }
    if (!changed)
    {
      break;
    }
  }
  for (size_t v = 0; v < base.size(); ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      m.Points[v][a] = base[v][a] + offset[v][a];
    }
    m.Scalars[v] = DefaultField(m.Points[v][0], m.Points[v][1], m.Points[v][2]);
  }
  for (const auto& t : tets)
  {
    m.AddTet(t[0], t[1], t[2], t[3]);
  }
  return m;
}

vtkSmartPointer<vtkUnstructuredGrid> JitteredHexBlock(int n, double jitter)
{
  MeshBuilder m;
  auto id = [n](int i, int j, int k) { return static_cast<vtkIdType>((k * (n + 1) + j) * (n + 1) + i); };
  unsigned s = 1;
  auto rnd = [&s]() {
    s = s * 1103515245u + 12345u;
    return ((s >> 8) & 0xffff) / 65535.0 - 0.5;
  };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        m.AddPoint(i + jitter * rnd(), j + jitter * rnd(), k + jitter * rnd(), 0);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        m.AddCell(VTK_HEXAHEDRON, { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
          id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1) });
  return m.Grid(false);
}

vtkSmartPointer<vtkUnstructuredGrid> RandomTetMesh(int n, unsigned seed)
{
  const double o[3] = { 0, 0, 0 }, s[3] = { 1, 1, 1 };
  return JitteredTetBlock(n, n, n, o, s, 0.3, seed).Grid();
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> MixedMesh(unsigned seed)
{
  const int nx = 7, ny = 5, nz = 5;
  SortRandom rng(seed);
  std::vector<double> c[3];
  const int n[3] = { nx, ny, nz };
  for (int a = 0; a < 3; ++a)
  {
    c[a].push_back(0.0);
    for (int i = 0; i < n[a]; ++i)
    {
      c[a].push_back(c[a].back() + rng.Uniform(0.6, 1.4) / n[a]);
    }
  }
  MeshBuilder m;
  std::vector<vtkIdType> ids;
  for (int k = 0; k <= nz; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        ids.push_back(AddP(m, { c[0][i], c[1][j], c[2][k] }));
      }
    }
  }
  auto P = [&](int i, int j, int k) { return ids[(k * (ny + 1) + j) * (nx + 1) + i]; };
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        if (i <= 3 && (i + j) % 3 == 0)
        {
          // Wedge column: both wedges split by the vertical diagonal plane (i,j)-(i+1,j+1).
          AddWedge(m, { P(i, j, k), P(i + 1, j, k), P(i + 1, j + 1, k), P(i, j, k + 1),
                        P(i + 1, j, k + 1), P(i + 1, j + 1, k + 1) });
          AddWedge(m, { P(i, j, k), P(i + 1, j + 1, k), P(i, j + 1, k), P(i, j, k + 1),
                        P(i + 1, j + 1, k + 1), P(i, j + 1, k + 1) });
        }
        else if (i <= 3 && (i + j + k) % 2 == 0)
        {
          m.AddCell(VTK_VOXEL, { P(i, j, k), P(i + 1, j, k), P(i, j + 1, k), P(i + 1, j + 1, k),
                                 P(i, j, k + 1), P(i + 1, j, k + 1), P(i, j + 1, k + 1),
                                 P(i + 1, j + 1, k + 1) });
        }
        else if (i <= 3)
        {
          AddHex(m, { P(i, j, k), P(i + 1, j, k), P(i + 1, j + 1, k), P(i, j + 1, k),
                      P(i, j, k + 1), P(i + 1, j, k + 1), P(i + 1, j + 1, k + 1),
                      P(i, j + 1, k + 1) });
        }
        else if (i == 4)
        {
          // 5 pyramids around the centre + 2 tets towards the Kuhn tets at x = i+1
          // (diagonal (j,k)-(j+1,k+1) like the Kuhn cubes' face).
          const vtkIdType ctr = AddP(m, { 0.5 * (c[0][i] + c[0][i + 1]),
                                          0.5 * (c[1][j] + c[1][j + 1]), 0.5 * (c[2][k] + c[2][k + 1]) });
          AddPyramid(m, { P(i, j, k), P(i, j + 1, k), P(i, j + 1, k + 1), P(i, j, k + 1), ctr });
          AddPyramid(m, { P(i, j, k), P(i + 1, j, k), P(i + 1, j, k + 1), P(i, j, k + 1), ctr });
          AddPyramid(m, { P(i, j + 1, k), P(i + 1, j + 1, k), P(i + 1, j + 1, k + 1),
                          P(i, j + 1, k + 1), ctr });
          AddPyramid(m, { P(i, j, k), P(i + 1, j, k), P(i + 1, j + 1, k), P(i, j + 1, k), ctr });
          AddPyramid(m, { P(i, j, k + 1), P(i + 1, j, k + 1), P(i + 1, j + 1, k + 1),
                          P(i, j + 1, k + 1), ctr });
          m.AddTet(ctr, P(i + 1, j, k), P(i + 1, j + 1, k), P(i + 1, j + 1, k + 1));
          m.AddTet(ctr, P(i + 1, j, k), P(i + 1, j, k + 1), P(i + 1, j + 1, k + 1));
        }
        else
        {
          static const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 },
            { 2, 0, 1 }, { 2, 1, 0 } };
          for (const auto& p : perms)
          {
            int q[3] = { i, j, k };
            vtkIdType v[4];
            v[0] = P(q[0], q[1], q[2]);
            for (int s = 0; s < 3; ++s)
            {
              ++q[p[s]];
              v[s + 1] = P(q[0], q[1], q[2]);
            }
            m.AddTet(v[0], v[1], v[2], v[3]);
          }
        }
      }
    }
  }
  const double axis[3] = { 1, 2, 3 }, shift[3] = { 0, 0, 0 };
  RotateAll(m, 29.0, axis, shift);
  for (size_t v = 0; v < m.Points.size(); ++v)
  {
    m.Scalars[v] = DefaultField(m.Points[v][0], m.Points[v][1], m.Points[v][2]);
  }
  return m.Grid();
}

//------------------------------------------------------------------------------
namespace
{
vtkSmartPointer<vtkUnstructuredGrid> TwoTets(const double p[4][3], const double q[4][3])
{
  MeshBuilder m;
  const double s[4] = { 0, 0.5, 1, 1.5 };
  m.AddLooseTet(p, s);
  m.AddLooseTet(q, s);
  return m.Grid();
}
}

vtkSmartPointer<vtkUnstructuredGrid> Fig5aMesh()
{
  const double p[4][3] = { { 0, 0, 0 }, { 10, 0, 0 }, { 0, 10, 0 }, { 1, 1, -3 } };
  const double q[4][3] = { { 10, 10, -1 }, { 10, 4, -1 }, { 4, 10, -1 }, { 9, 9, -4 } };
  return TwoTets(p, q);
}

vtkSmartPointer<vtkUnstructuredGrid> Fig5bMesh()
{
  const double p[4][3] = { { -10, -10, 0 }, { 10, -10, 0 }, { 0, 10, 0 }, { 0, 0, -10 } };
  const double q[4][3] = { { 5.5, -8.5, 1 }, { 6.5, -8.5, 1 }, { 6, -7.5, 1 }, { 6, -8.2, 2 } };
  return TwoTets(p, q);
}

vtkSmartPointer<vtkUnstructuredGrid> Fig6Mesh()
{
  // P's back face over (6,-8) is at z = -10 (y + 10) in [-25, -15]; Q lies
  // below it, but Q's rearmost z (-40) is nearer than P's (-100).
  const double p[4][3] = { { -10, -10, 0 }, { 10, -10, 0 }, { 0, 10, 0 }, { 0, 0, -100 } };
  const double q[4][3] = { { 5.5, -8.5, -30 }, { 6.5, -8.5, -30 }, { 6, -7.5, -30 },
    { 6, -8.2, -40 } };
  return TwoTets(p, q);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> InterleavedSticks(int layers, int perLayer)
{
  MeshBuilder m;
  const double half = 0.25 * perLayer;
  for (int l = 0; l < layers; ++l)
  {
    const double z = 0.3 * l;
    for (int s = 0; s < perLayer; ++s)
    {
      const double off = -half + 0.5 * s + 0.25;
      const double tilt = (s % 2 ? 0.05 : -0.05) * (l % 3 == 2 ? -1 : 1);
      P3 a, b;
      if (l % 2 == 0)
      {
        a = { -half, off, z - tilt };
        b = { half, off + 0.1 * (s % 3 - 1), z + tilt };
      }
      else
      {
        a = { off, -half, z - tilt };
        b = { off + 0.1 * (s % 3 - 1), half, z + tilt };
      }
      AddStick(m, a, b, 0.12, 0.1);
    }
  }
  return m.Grid();
}

vtkSmartPointer<vtkUnstructuredGrid> HoledBlock(int n, unsigned seed)
{
  const double o[3] = { 0, 0, 0 }, s[3] = { 1, 1, 1 };
  const int a = n / 3, b = n - n / 3;
  return JitteredTetBlock(n, n, n, o, s, 0.25, seed,
    [=](int i, int j, int) { return !(i >= a && i < b && j >= a && j < b); })
    .Grid();
}

vtkSmartPointer<vtkUnstructuredGrid> NotchedBlock(int n, unsigned seed)
{
  const double o[3] = { 0, 0, 0 }, s[3] = { 1, 1, 1 };
  const int a = n / 3, b = n - n / 3;
  return JitteredTetBlock(n, n, n, o, s, 0.25, seed,
    [=](int i, int j, int) { return !(i >= a && i < b && j >= a); })
    .Grid();
}

vtkSmartPointer<vtkUnstructuredGrid> DisconnectedBlocks(unsigned seed)
{
  MeshBuilder all;
  const double origins[4][3] = { { 0, 0, 0 }, { 0.3, 0.2, 1.4 }, { 1.5, 0.1, 0.4 },
    { 0.8, 1.3, 0.7 } };
  for (int b = 0; b < 4; ++b)
  {
    const double size[3] = { 1.0, 0.8 + 0.1 * b, 0.5 + 0.2 * b };
    MeshBuilder m = JitteredTetBlock(3, 3, 3, origins[b], size, 0.3, seed + 17 * b);
    all.Append(m);
  }
  return all.Grid();
}

vtkSmartPointer<vtkUnstructuredGrid> SlidingInterface(unsigned seed)
{
  // Jitter 0: the shared plane x = 1 must stay planar on both sides.
  (void)seed;
  const double o1[3] = { 0, 0, 0 }, s1[3] = { 1, 1, 1 };
  const double o2[3] = { 1, 0, 0 }, s2[3] = { 0.8, 1, 1 };
  MeshBuilder a = JitteredTetBlock(4, 4, 4, o1, s1, 0.0, 1);
  MeshBuilder b = JitteredTetBlock(3, 3, 3, o2, s2, 0.0, 2);
  a.Append(b);
  // A shear keeps the interface planar but not axis-aligned.
  for (auto& p : a.Points)
  {
    p = { p[0] + 0.2 * p[1], p[1] + 0.1 * p[2], p[2] };
  }
  return a.Grid();
}

vtkSmartPointer<vtkUnstructuredGrid> CyclicTripleTets()
{
  vtkSmartPointer<vtkUnstructuredGrid> wedges = CyclicTriple();
  MeshBuilder m;
  for (vtkIdType i = 0; i < wedges->GetNumberOfPoints(); ++i)
  {
    double p[3];
    wedges->GetPoint(i, p);
    AddP(m, { p[0], p[1], p[2] });
  }
  for (vtkIdType c = 0; c < wedges->GetNumberOfCells(); ++c)
  {
    const vtkIdType* v;
    vtkIdType n;
    wedges->GetCellPoints(c, n, v);
    // Prism a0 a1 a2 / b0 b1 b2 = [a0 a1 a2 b0] + [a1 a2 b0 b1] + [a2 b0 b1 b2].
    m.AddTet(v[0], v[1], v[2], v[3]);
    m.AddTet(v[1], v[2], v[3], v[4]);
    m.AddTet(v[2], v[3], v[4], v[5]);
  }
  return m.Grid();
}

vtkSmartPointer<vtkUnstructuredGrid> CyclicTriple()
{
  MeshBuilder m;
  const double h = 0.5;
  P3 corner[3];
  for (int i = 0; i < 3; ++i)
  {
    const double t = vtkMath::Pi() / 2 + 2 * vtkMath::Pi() * i / 3;
    corner[i] = { std::cos(t), std::sin(t), 0 };
  }
  for (int i = 0; i < 3; ++i)
  {
    const P3& c0 = corner[i];
    const P3& c1 = corner[(i + 1) % 3];
    const P3 d = Sub(c1, c0);
    const P3 a{ c0[0] - 0.3 * d[0], c0[1] - 0.3 * d[1], h };
    const P3 b{ c1[0] + 0.3 * d[0], c1[1] + 0.3 * d[1], -h };
    AddStick(m, a, b, 0.1, 0.1);
  }
  return m.Grid();
}

void ForEachVTKFace(vtkUnstructuredGrid* grid,
  const std::function<void(vtkIdType, const std::vector<vtkIdType>&)>& fn)
{
  vtkNew<vtkGenericCell> cell;
  std::vector<vtkIdType> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    grid->GetCell(c, cell);
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      vtkCell* face = cell->GetFace(f);
      ids.resize(face->GetNumberOfPoints());
      for (size_t i = 0; i < ids.size(); ++i)
      {
        ids[i] = face->GetPointId(static_cast<vtkIdType>(i));
      }
      fn(c, ids);
    }
  }
}
}
