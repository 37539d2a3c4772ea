#include "hovRobustnessCase.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <array>   // lattice corners
#include <cmath>   // std::sin
#include <limits>  // NaN, Inf, denormals
#include <random>  // the generator
#include <sstream> // the description
#include <vector>  // connectivity

namespace
{
const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Inf = std::numeric_limits<double>::infinity();
const double Denormal = std::numeric_limits<double>::denorm_min();

/// The draws of one case, with a running description.
struct Draw
{
  std::mt19937_64 Rng;
  std::ostringstream Text;
  explicit Draw(std::uint64_t seed)
    : Rng(seed)
  {
  }
  double Uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(Rng); }
  int Int(int a, int b) { return std::uniform_int_distribution<int>(a, b)(Rng); }
  bool Chance(double p) { return this->Uniform(0.0, 1.0) < p; }
  /// A value that is now and then absurd (NaN, +-Inf, huge, tiny, denormal, 0).
  double Absurd(double usual, double p)
  {
    if (!this->Chance(p))
    {
      return usual;
    }
    const double pool[] = { NaN, Inf, -Inf, 1e300, -1e300, 1e-300, Denormal, 0.0, -usual };
    return pool[this->Int(0, 8)];
  }
};

/// Points of a jittered (n+1)^3 lattice over [0, n]^3, then extra points on demand.
struct Lattice
{
  int N = 2;
  vtkNew<vtkPoints> Points;
  vtkIdType Id(int i, int j, int k) const { return (static_cast<vtkIdType>(k) * (N + 1) + j) * (N + 1) + i; }
  vtkIdType Add(const double x[3]) { return this->Points->InsertNextPoint(x); }
  vtkIdType Mid(vtkIdType a, vtkIdType b, double bulge)
  {
    double pa[3], pb[3], m[3];
    this->Points->GetPoint(a, pa);
    this->Points->GetPoint(b, pb);
    for (int c = 0; c < 3; ++c)
    {
      m[c] = 0.5 * (pa[c] + pb[c]) + (c == 2 ? bulge : 0.0);
    }
    return this->Add(m);
  }
};

void AddCubeCells(Draw& d, Lattice& l, vtkUnstructuredGrid* grid, int i, int j, int k)
{
  const vtkIdType c[8] = { l.Id(i, j, k), l.Id(i + 1, j, k), l.Id(i + 1, j + 1, k),
    l.Id(i, j + 1, k), l.Id(i, j, k + 1), l.Id(i + 1, j, k + 1), l.Id(i + 1, j + 1, k + 1),
    l.Id(i, j + 1, k + 1) };
  const int kind = d.Int(0, 9);
  std::vector<vtkIdType> ids;
  auto add = [&](int type, std::vector<vtkIdType> pts) {
    if (d.Chance(0.03) && pts.size() > 1)
    {
      std::swap(pts[0], pts[1]); // inverted (or tangled) cell
    }
    if (d.Chance(0.02))
    {
      pts[d.Int(0, static_cast<int>(pts.size()) - 1)] = d.Chance(0.5) ? -7 : 1 << 20; // broken
    }
    grid->InsertNextCell(type, static_cast<vtkIdType>(pts.size()), pts.data());
  };
  switch (kind)
  {
    case 0: // six Kuhn tetrahedra
    case 1:
    {
      const int kuhn[6][4] = { { 0, 1, 2, 6 }, { 0, 2, 3, 6 }, { 0, 3, 7, 6 }, { 0, 7, 4, 6 },
        { 0, 4, 5, 6 }, { 0, 5, 1, 6 } };
      for (const auto& t : kuhn)
      {
        add(VTK_TETRA, { c[t[0]], c[t[1]], c[t[2]], c[t[3]] });
      }
      break;
    }
    case 2:
      add(VTK_HEXAHEDRON, { c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7] });
      break;
    case 3:
      add(VTK_VOXEL, { c[0], c[1], c[3], c[2], c[4], c[5], c[7], c[6] });
      break;
    case 4:
      add(VTK_WEDGE, { c[0], c[1], c[2], c[4], c[5], c[6] });
      add(VTK_WEDGE, { c[0], c[2], c[3], c[4], c[6], c[7] });
      break;
    case 5:
    {
      double centre[3] = { i + 0.5, j + 0.5, k + 0.5 };
      const vtkIdType m = l.Add(centre);
      const int faces[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 },
        { 2, 3, 7, 6 }, { 3, 0, 4, 7 } };
      for (const auto& f : faces)
      {
        add(VTK_PYRAMID, { c[f[0]], c[f[1]], c[f[2]], c[f[3]], m });
      }
      break;
    }
    case 6: // quadratic tetrahedron, its mid-edge nodes possibly bulged (curved)
    {
      const double bulge = d.Chance(0.5) ? d.Uniform(-0.2, 0.2) : 0.0;
      const vtkIdType v[4] = { c[0], c[1], c[2], c[6] };
      const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
      std::vector<vtkIdType> pts(v, v + 4);
      for (const auto& e : edges)
      {
        pts.push_back(l.Mid(v[e[0]], v[e[1]], bulge));
      }
      add(VTK_QUADRATIC_TETRA, pts);
      break;
    }
    case 7: // order-2 Lagrange hexahedron (27 nodes: the corners, then a 3^3 grid's rest)
    {
      std::vector<vtkIdType> pts(c, c + 8);
      const double bulge = d.Chance(0.5) ? d.Uniform(-0.15, 0.15) : 0.0;
      while (pts.size() < 27)
      {
        double x[3] = { i + d.Uniform(0.2, 0.8), j + d.Uniform(0.2, 0.8),
          k + d.Uniform(0.2, 0.8) + bulge };
        pts.push_back(l.Add(x)); // scrambled interior nodes: often tangled, which is the point
      }
      add(VTK_LAGRANGE_HEXAHEDRON, pts);
      break;
    }
    case 8: // 2D and other unsupported cells
      add(d.Chance(0.5) ? VTK_TRIANGLE : VTK_QUAD, { c[0], c[1], c[2], c[3] });
      add(VTK_LINE, { c[4], c[6] });
      break;
    default: // a tetrahedron of random (possibly repeated or out-of-range) ids
    {
      const vtkIdType n = l.Points->GetNumberOfPoints();
      std::vector<vtkIdType> pts;
      for (int v = 0; v < 4; ++v)
      {
        pts.push_back(d.Chance(0.9) ? static_cast<vtkIdType>(d.Int(0, static_cast<int>(n) - 1))
                                    : n + d.Int(0, 5));
      }
      add(VTK_TETRA, pts);
    }
  }
}

vtkSmartPointer<vtkUnstructuredGrid> MakeGrid(Draw& d)
{
  Lattice l;
  l.N = d.Int(1, 3);
  const double jitter = d.Chance(0.5) ? d.Uniform(0.0, 0.2) : 0.0;
  for (int k = 0; k <= l.N; ++k)
  {
    for (int j = 0; j <= l.N; ++j)
    {
      for (int i = 0; i <= l.N; ++i)
      {
        const double x[3] = { i + d.Uniform(-jitter, jitter), j + d.Uniform(-jitter, jitter),
          k + d.Uniform(-jitter, jitter) };
        l.Add(x);
      }
    }
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->Allocate(64);
  const bool empty = d.Chance(0.03);
  for (int k = 0; k < l.N && !empty; ++k)
  {
    for (int j = 0; j < l.N; ++j)
    {
      for (int i = 0; i < l.N; ++i)
      {
        AddCubeCells(d, l, grid, i, j, k);
      }
    }
  }
  const vtkIdType numPoints = l.Points->GetNumberOfPoints();
  if (d.Chance(0.15)) // bad points
  {
    for (int b = d.Int(1, 3); b > 0; --b)
    {
      const vtkIdType id = d.Int(0, static_cast<int>(numPoints) - 1);
      double x[3];
      l.Points->GetPoint(id, x);
      x[d.Int(0, 2)] = d.Absurd(1.0, 1.0);
      l.Points->SetPoint(id, x);
    }
  }
  if (d.Chance(0.05)) // a collapsed point: degenerate cells
  {
    double x[3];
    l.Points->GetPoint(0, x);
    l.Points->SetPoint(1, x);
  }
  grid->SetPoints(l.Points);
  d.Text << "grid: " << grid->GetNumberOfCells() << " cells, " << numPoints << " points"
         << (empty ? " (no cells)" : "") << "\n";
  return grid;
}

void AddScalars(Draw& d, vtkUnstructuredGrid* grid)
{
  const int style = d.Int(0, 24);
  const bool cell = style == 0;
  const vtkIdType n = cell ? grid->GetNumberOfCells() : grid->GetNumberOfPoints();
  const int components = d.Chance(0.15) ? 3 : 1;
  vtkSmartPointer<vtkDataArray> a;
  const int type = d.Int(0, 5);
  if (type == 0)
  {
    a = vtkSmartPointer<vtkIntArray>::New();
  }
  else if (type == 1)
  {
    a = vtkSmartPointer<vtkFloatArray>::New();
  }
  else
  {
    a = vtkSmartPointer<vtkDoubleArray>::New();
  }
  a->SetName("s");
  a->SetNumberOfComponents(components);
  const vtkIdType tuples = d.Chance(0.03) ? n / 2 : n; // too short now and then
  a->SetNumberOfTuples(tuples);
  const double scale = d.Chance(0.1) ? d.Absurd(1.0, 1.0) : d.Uniform(0.1, 10.0);
  const bool constant = d.Chance(0.1);
  for (vtkIdType t = 0; t < tuples; ++t)
  {
    double x[3] = { 0.0, 0.0, 0.0 };
    if (!cell && t < grid->GetNumberOfPoints())
    {
      grid->GetPoint(t, x);
    }
    for (int c = 0; c < components; ++c)
    {
      const double v = constant ? 0.5 : std::sin(x[0] + 2.0 * x[1] - x[2] + c) + 0.3 * x[2];
      a->SetComponent(t, c, d.Absurd(scale * v, 0.01));
    }
  }
  if (style == 24)
  {
    d.Text << "scalars: none\n";
    return;
  }
  if (cell)
  {
    grid->GetCellData()->SetScalars(a);
  }
  else
  {
    grid->GetPointData()->SetScalars(a);
  }
  // A second array for the colour / isosurface fields.
  vtkNew<vtkDoubleArray> c;
  c->SetName("c");
  c->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType t = 0; t < grid->GetNumberOfPoints(); ++t)
  {
    c->SetValue(t, d.Absurd(d.Uniform(0.0, 1.0), 0.01));
  }
  grid->GetPointData()->AddArray(c);
  double range[2] = { 0.0, 0.0 };
  a->GetRange(range, -1);
  d.Text << "scalars: " << (cell ? "cell" : "point") << ", type " << type << ", " << components
         << " component(s), " << tuples << " of " << n << " tuples, scale " << scale
         << ", range [" << range[0] << ", " << range[1] << "]\n";
}

void SetupTransferFunction(Draw& d, vtkVolumeProperty* p)
{
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  // Now and then no node at all, or many.
  const int nc = d.Chance(0.03) ? 0 : d.Int(1, 6);
  const int no = d.Chance(0.03) ? 0 : d.Int(1, d.Chance(0.05) ? 60 : 8);
  for (int i = 0; i < nc; ++i)
  {
    color->AddRGBPoint(d.Absurd(d.Uniform(-1.5, 1.5), 0.03), d.Absurd(d.Uniform(0, 1), 0.03),
      d.Uniform(0, 1), d.Uniform(0, 1));
  }
  for (int i = 0; i < no; ++i)
  {
    const double x = d.Absurd(d.Uniform(-1.5, 1.5), 0.03);
    opacity->AddPoint(x, d.Absurd(d.Uniform(0, 1), 0.05));
    if (d.Chance(0.1))
    {
      opacity->AddPoint(x, d.Uniform(0, 1)); // a jump
    }
  }
  p->SetColor(color);
  p->SetScalarOpacity(opacity);
  const double unit = d.Absurd(d.Uniform(0.05, 3.0), 0.05);
  p->SetScalarOpacityUnitDistance(unit);
  p->SetShade(d.Chance(0.3));
  p->SetIndependentComponents(d.Chance(0.5));
  if (d.Chance(0.2))
  {
    p->SetInterpolationTypeToNearest();
  }
  d.Text << "transfer function: " << nc << " colour, " << no << " opacity nodes, unit " << unit
         << "; opacity";
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    double v[4];
    opacity->GetNodeValue(i, v);
    d.Text << " (" << v[0] << ", " << v[1] << ")";
  }
  d.Text << "\n";
}

void SetupCamera(Draw& d, vtkCamera* cam, double n)
{
  const double centre = 0.5 * n;
  cam->SetFocalPoint(centre, centre, centre);
  double dir[3] = { d.Uniform(-1, 1), d.Uniform(-1, 1), d.Uniform(-1, 1) };
  const double dist = d.Uniform(1.5, 6.0) * n;
  cam->SetPosition(centre + dist * dir[0], centre + dist * dir[1], centre + dist * dir[2] + 1e-3);
  cam->SetViewUp(d.Uniform(-1, 1), d.Uniform(-1, 1), d.Uniform(-1, 1));
  cam->SetViewAngle(d.Chance(0.1) ? d.Absurd(30.0, 1.0) : d.Uniform(5.0, 90.0));
  cam->SetParallelProjection(d.Chance(0.3));
  cam->SetParallelScale(d.Absurd(n, 0.1));
  cam->SetClippingRange(d.Absurd(0.01 * n, 0.05), d.Absurd(20.0 * n, 0.05));
  if (d.Chance(0.04)) // a degenerate camera
  {
    switch (d.Int(0, 3))
    {
      case 0:
        cam->SetViewUp(dir);
        break;
      case 1:
        cam->SetFocalPoint(NaN, centre, centre);
        break;
      case 2:
        cam->SetPosition(centre, centre, centre);
        break;
      default:
        cam->SetPosition(Inf, 0, 0);
    }
  }
  const double* p = cam->GetPosition();
  const double* r = cam->GetClippingRange();
  d.Text << "camera: position (" << p[0] << ", " << p[1] << ", " << p[2] << "), angle "
         << cam->GetViewAngle() << ", parallel " << cam->GetParallelProjection() << " scale "
         << cam->GetParallelScale() << ", clipping [" << r[0] << ", " << r[1] << "]\n";
}

void SetupMapper(Draw& d, vtkHighOrderVolumeMapper* m, double n)
{
  m->SetRenderMode(d.Int(0, 2));
  m->SetOpacitySemantics(d.Int(0, 2));
  m->SetEmissionModel(d.Int(0, 1));
  m->SetEmissionScale(d.Absurd(1.0, 0.1));
  m->SetIntegrationMethod(d.Int(0, 1));
  m->SetCellOrdering(d.Int(0, 1));
  m->SetTerminationTransmittance(d.Absurd(1e-9, 0.05));
  m->SetGPUOpacityTolerance(d.Chance(0.1) ? d.Absurd(1e-4, 1.0) : 1e-4);
  m->SetTileSize(d.Int(1, 300));
  m->SetProjectionColorMethod(d.Int(0, 3));
  m->SetProjectionOrder(d.Int(0, 1));
  m->SetProjectionOpacityLookup(d.Int(0, 1));
  m->SetRayCastTolerance(d.Chance(0.1) ? d.Absurd(1e-3, 1.0) : d.Uniform(1e-3, 0.05));
  m->SetVectorMode(d.Int(0, 1));
  m->SetVectorComponent(d.Int(-1, 4));
  m->SetScalarModeToDefault();
  for (int k = d.Chance(0.2) ? d.Int(1, 3) : 0; k > 0; --k)
  {
    m->AddIsosurface(d.Absurd(d.Uniform(-1, 1), 0.05), d.Uniform(0, 1), d.Uniform(0, 1),
      d.Uniform(0, 1), d.Absurd(d.Uniform(0, 1), 0.1));
  }
  const char* names[] = { nullptr, "c", "missing", "s" };
  if (d.Chance(0.15))
  {
    m->SetColorArrayName(names[d.Int(0, 3)]);
    m->SetColorArrayComponent(d.Int(-1, 2));
  }
  if (d.Chance(0.15))
  {
    m->SetIsosurfaceArrayName(names[d.Int(0, 3)]);
  }
  m->SetSplatting(d.Chance(0.15));
  m->SetSplatPixelThreshold(d.Absurd(2.0, 0.1));
  for (int k = d.Chance(0.2) ? d.Int(1, 2) : 0; k > 0; --k)
  {
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(d.Uniform(0, n), d.Uniform(0, n), d.Uniform(0, n));
    plane->SetNormal(d.Absurd(d.Uniform(-1, 1), 0.1), d.Uniform(-1, 1), d.Uniform(-1, 1));
    m->AddClippingPlane(plane);
  }
  if (d.Chance(0.1))
  {
    m->SetViewDepthClipping(true);
    m->SetViewDepthRange(d.Absurd(d.Uniform(0, 3 * n), 0.1), d.Absurd(d.Uniform(0, 9 * n), 0.1));
  }
  m->SetUseDepthBuffer(d.Chance(0.8));
  d.Text << "mapper: mode " << m->GetRenderMode() << ", semantics " << m->GetOpacitySemantics()
         << ", emission " << m->GetEmissionModel() << " x" << m->GetEmissionScale()
         << ", integration " << m->GetIntegrationMethod() << ", ordering " << m->GetCellOrdering()
         << ", isosurfaces " << m->GetNumberOfIsosurfaces() << ", splatting " << m->GetSplatting()
         << ", clip planes "
         << (m->GetClippingPlanes() ? m->GetClippingPlanes()->GetNumberOfItems() : 0)
         << ", view-depth " << m->GetViewDepthClipping() << "\n"
         << "tolerances: GPU opacity " << m->GetGPUOpacityTolerance() << ", ray cast "
         << m->GetRayCastTolerance() << ", termination " << m->GetTerminationTransmittance()
         << ", tile " << m->GetTileSize() << "\n";
}
}

void hovRobustness::Build(std::uint64_t seed, Case& c)
{
  Draw d(seed);
  c.Seed = seed;
  c.Grid = MakeGrid(d);
  AddScalars(d, c.Grid);
  const double n = c.Grid->GetNumberOfPoints() > 0 ? 3.0 : 1.0;
  SetupTransferFunction(d, c.Property);
  SetupCamera(d, c.Camera, n);
  SetupMapper(d, c.Mapper, n);
  c.Mapper->SetInputData(c.Grid);
  c.Volume->SetMapper(c.Mapper);
  c.Volume->SetProperty(c.Property);
  const int sizes[] = { 1, 2, 7, 16, 24, 33, 48 };
  c.Width = sizes[d.Int(0, 6)];
  c.Height = d.Chance(0.5) ? c.Width : sizes[d.Int(0, 6)];
  c.InWindow = d.Chance(0.3);
  // Drawn last, so that the cases recorded before this draw existed keep
  // every earlier draw (and reproduce with --case).
  c.Mapper->SetSkipTransparentCells(d.Chance(0.8));
  d.Text << "image: " << c.Width << " x " << c.Height << (c.InWindow ? " in a window" : "")
         << ", skip transparent cells " << c.Mapper->GetSkipTransparentCells() << "\n";
  c.Description = d.Text.str();
}
