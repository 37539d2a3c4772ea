// Convex polygons and the hull cache of vtkSteinVisibilitySort (see hovSteinHulls.h).
#include "hovSteinHulls.h"

#include "hovGeometricPredicates.h" // exact Orient2d

#include "vtkSMPTools.h"

#include <algorithm>
#include <array>

namespace hovStein
{
int Hull2d(const double* xyz, int n, double hull[][2])
{
  std::array<double, 2> p[MaxVisiblePoints];
  for (int i = 0; i < n; ++i)
  {
    p[i] = { xyz[3 * i], xyz[3 * i + 1] };
  }
  std::sort(p, p + n);
  int k = 0;
  for (int i = 0; i < n; ++i)
  {
    while (k >= 2 && hov::Orient2d(hull[k - 2], hull[k - 1], p[i].data()) <= 0)
    {
      --k;
    }
    hull[k][0] = p[i][0];
    hull[k++][1] = p[i][1];
  }
  const int lower = k + 1;
  for (int i = n - 2; i >= 0; --i)
  {
    while (k >= lower && hov::Orient2d(hull[k - 2], hull[k - 1], p[i].data()) <= 0)
    {
      --k;
    }
    hull[k][0] = p[i][0];
    hull[k++][1] = p[i][1];
  }
  return std::max(k - 1, 0);
}

double Area(const double poly[][2], int n)
{
  double a = 0;
  for (int i = 0; i < n; ++i)
  {
    const int j = (i + 1) % n;
    a += poly[i][0] * poly[j][1] - poly[j][0] * poly[i][1];
  }
  return 0.5 * a;
}

bool InHull(const double hull[][2], int n, const double* x)
{
  if (n < 3)
  {
    return false;
  }
  for (int i = 0; i < n; ++i)
  {
    if (hov::Orient2d(hull[i], hull[(i + 1) % n], x) < 0)
    {
      return false;
    }
  }
  return true;
}

int ClipPolygon(double poly[][2], int n, const double clip[][2], int m)
{
  // Each vertex's side once per clip edge; edges with every vertex inside
  // leave the polygon as it is; two buffers in turn instead of copies.
  double buffer[HullCapacity][2], side[HullCapacity];
  double(*in)[2] = poly;
  double(*out)[2] = buffer;
  n = std::min(n, MaxVisiblePoints);
  for (int e = 0; e < m && n > 0; ++e)
  {
    const double* a = clip[e];
    const double* b = clip[e + 1 < m ? e + 1 : 0];
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    bool inside = true;
    for (int i = 0; i < n; ++i)
    {
      side[i] = dx * (in[i][1] - a[1]) - dy * (in[i][0] - a[0]);
      inside = inside && side[i] >= 0;
    }
    if (inside)
    {
      continue;
    }
    int k = 0;
    for (int i = 0; i < n && k < 2 * MaxVisiblePoints - 2; ++i)
    {
      const int j = i + 1 < n ? i + 1 : 0;
      const double su = side[i], sv = side[j];
      if (su >= 0)
      {
        out[k][0] = in[i][0];
        out[k++][1] = in[i][1];
      }
      if ((su >= 0) != (sv >= 0))
      {
        const double t = su / (su - sv);
        out[k][0] = in[i][0] + t * (in[j][0] - in[i][0]);
        out[k++][1] = in[i][1] + t * (in[j][1] - in[i][1]);
      }
    }
    n = std::min(k, MaxVisiblePoints);
    std::swap(in, out);
  }
  if (in != poly)
  {
    std::copy(&in[0][0], &in[0][0] + 2 * n, &poly[0][0]);
  }
  return n;
}

void HullCache::Build(const Geometry& g, const View& v, const std::vector<vtkIdType>& cells)
{
  const vtkIdType numCells = static_cast<vtkIdType>(cells.size());
  this->Slot.assign(g.NumberOfCells, -1);
  this->Entries.resize(numCells);
  vtkIdType start = 0;
  for (vtkIdType k = 0; k < numCells; ++k)
  {
    const vtkIdType c = cells[k];
    this->Slot[c] = static_cast<int>(k);
    const int clip = v.Clip(c);
    const vtkIdType bound = clip >= 0 ? static_cast<vtkIdType>(v.Clipped[clip].size() / 3)
                                      : g.NumberOfCorners(c);
    this->Entries[k].Start = start;
    start += bound; // a hull has at most as many points
  }
  this->Points.resize(2 * start);
  vtkSMPTools::For(0, numCells, 256, [&](vtkIdType begin, vtkIdType end) {
    double xyz[3 * MaxVisiblePoints], hull[HullCapacity][2];
    for (vtkIdType k = begin; k < end; ++k)
    {
      const int size = Hull2d(xyz, v.VisiblePoints(g, cells[k], xyz), hull);
      Entry& e = this->Entries[k];
      std::copy(&hull[0][0], &hull[0][0] + 2 * size, this->Points.data() + 2 * e.Start);
      e.Size = size;
      e.Area = Area(hull, size);
    }
  });
}

const double (*HullCache::Find(vtkIdType c, int& size, double& area) const)[2]
{
  const int k = this->Slot.empty() ? -1 : this->Slot[c];
  if (k < 0)
  {
    return nullptr;
  }
  const Entry& e = this->Entries[k];
  size = e.Size;
  area = e.Area;
  return reinterpret_cast<const double(*)[2]>(this->Points.data() + 2 * e.Start);
}
}
