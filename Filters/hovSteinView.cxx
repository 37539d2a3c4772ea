// Per-view data of vtkSteinVisibilitySort (see hovSteinView.h).
#include "hovSteinView.h"

#include "hovSteinRounding.h" // FloatDown, FloatUp

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace hovStein
{
namespace
{
inline double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
}

void ViewFrame::FromCamera(vtkCamera* camera, double diagonal)
{
  this->Parallel = camera->GetParallelProjection() != 0;
  camera->GetPosition(this->Eye);
  camera->GetDirectionOfProjection(this->Dop);
  vtkMath::Normalize(this->Dop);
  double up[3];
  camera->GetViewUp(up);
  vtkMath::Cross(this->Dop, up, this->Right);
  if (vtkMath::Normalize(this->Right) == 0)
  {
    // View-up parallel to the view direction: any perpendicular will do.
    vtkMath::Perpendiculars(this->Dop, this->Right, nullptr, 0);
  }
  vtkMath::Cross(this->Right, this->Dop, this->Up);
  vtkMath::Normalize(this->Up);
  this->Near = 1e-6 * std::max(diagonal, 1e-300);
  if (this->Parallel)
  {
    double fp[3];
    camera->GetFocalPoint(fp);
    const double cx = Dot(fp, this->Right), cy = Dot(fp, this->Up);
    const double s = 4 * std::max(camera->GetParallelScale(), 1e-300);
    this->Window[0] = cx - 2 * s; // unknown aspect: allow up to 2:1
    this->Window[1] = cx + 2 * s;
    this->Window[2] = cy - s;
    this->Window[3] = cy + s;
  }
  else
  {
    const double t = 4 * std::tan(vtkMath::RadiansFromDegrees(
                           std::min(std::max(camera->GetViewAngle(), 1e-3), 179.0)) / 2);
    this->Window[0] = -2 * t;
    this->Window[1] = 2 * t;
    this->Window[2] = -t;
    this->Window[3] = t;
  }
}

double View::Depth(const double* x) const
{
  const ViewFrame& f = this->Frame;
  if (f.Parallel)
  {
    return Dot(x, f.Dop);
  }
  const double v[3] = { x[0] - f.Eye[0], x[1] - f.Eye[1], x[2] - f.Eye[2] };
  return Dot(v, f.Dop);
}

int View::VisiblePoints(const Geometry& g, vtkIdType c, double* xyz) const
{
  if (this->Clip(c) >= 0)
  {
    const std::vector<double>& pts = this->Clipped[this->Clip(c)];
    std::copy(pts.begin(), pts.end(), xyz);
    return static_cast<int>(pts.size() / 3);
  }
  const int n = g.NumberOfCorners(c);
  const vtkIdType* ids = g.CellCorners(c);
  for (int i = 0; i < n; ++i)
  {
    std::copy(this->Proj.data() + 3 * ids[i], this->Proj.data() + 3 * ids[i] + 3, xyz + 3 * i);
  }
  return n;
}

namespace
{
/// The visible part of a straddling cell: visible corners and edge/near-plane crossings.
std::vector<double> ClipCell(const Geometry& g, const View& v, vtkIdType c)
{
  const ViewFrame& f = v.Frame;
  const Shape& s = GetShape(g.Kinds[c]);
  const vtkIdType* ids = g.CellCorners(c);
  std::vector<double> out;
  for (int i = 0; i < s.NumCorners; ++i)
  {
    if (v.Valid[ids[i]])
    {
      out.insert(out.end(), v.Proj.begin() + 3 * ids[i], v.Proj.begin() + 3 * ids[i] + 3);
    }
  }
  for (int e = 0; e < s.NumEdges; ++e)
  {
    const double* a = g.Point(ids[s.Edges[e][0]]);
    const double* b = g.Point(ids[s.Edges[e][1]]);
    const double za = v.Depth(a), zb = v.Depth(b);
    if ((za > f.Near) == (zb > f.Near))
    {
      continue;
    }
    const double t = (f.Near - za) / (zb - za);
    double p[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = a[k] + t * (b[k] - a[k]) - f.Eye[k];
    }
    out.push_back(Dot(p, f.Right) / f.Near);
    out.push_back(Dot(p, f.Up) / f.Near);
    out.push_back(f.Near);
  }
  return out;
}
}

void View::CellExtents(const Geometry& g, vtkIdType begin, vtkIdType end)
{
  // Local pointers: the byte stores to Status would otherwise make the
  // compiler reload every vector's data pointer after each cell.
  const double* proj = this->Proj.data();
  const std::uint8_t* valid = this->Valid.data();
  const vtkIdType* offsets = g.CornerStart;
  const vtkIdType* corners = g.CornerIds;
  const std::uint8_t* kinds = g.Kinds.data();
  std::uint8_t* status = this->Status.data();
  double* front = this->Front.data();
  double* rear = this->Rear.data();
  float* boxes = this->Box.data();
  for (vtkIdType c = begin; c < end; ++c)
  {
    const vtkIdType* ids = corners + offsets[c];
    const int m = static_cast<int>(offsets[c + 1] - offsets[c]);
    double zmin = VTK_DOUBLE_MAX, zmax = -VTK_DOUBLE_MAX;
    double box[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    int numValid = 0;
    for (int i = 0; i < m; ++i)
    {
      if (ids[i] < 0)
      {
        continue;
      }
      const double* p = proj + 3 * ids[i];
      zmin = std::min(zmin, p[2]);
      zmax = std::max(zmax, p[2]);
      if (valid[ids[i]])
      {
        ++numValid;
        box[0] = std::min(box[0], p[0]);
        box[1] = std::max(box[1], p[0]);
        box[2] = std::min(box[2], p[1]);
        box[3] = std::max(box[3], p[1]);
      }
    }
    front[c] = zmin;
    rear[c] = std::isnan(zmax) ? VTK_DOUBLE_MAX : zmax;
    status[c] = kinds[c] == KindBad ? StatusBad
      : numValid == m               ? StatusVisible
      : numValid == 0               ? StatusHidden
                                    : StatusStraddle;
    float* b = boxes + 4 * c;
    b[0] = FloatDown(box[0]);
    b[1] = FloatUp(box[1]);
    b[2] = FloatDown(box[2]);
    b[3] = FloatUp(box[3]);
  }
}

void View::CellStatus(const Geometry& g, vtkIdType begin, vtkIdType end, bool allValid)
{
  const std::uint8_t* kinds = g.Kinds.data();
  std::uint8_t* status = this->Status.data();
  if (allValid)
  {
    for (vtkIdType c = begin; c < end; ++c)
    {
      status[c] = kinds[c] == KindBad ? StatusBad : StatusVisible;
    }
    return;
  }
  const std::uint8_t* valid = this->Valid.data();
  for (vtkIdType c = begin; c < end; ++c)
  {
    const vtkIdType* ids = g.CellCorners(c);
    const int m = g.NumberOfCorners(c);
    int numValid = 0;
    for (int i = 0; i < m; ++i)
    {
      numValid += ids[i] >= 0 && valid[ids[i]];
    }
    status[c] = kinds[c] == KindBad ? StatusBad
      : numValid == m               ? StatusVisible
      : numValid == 0               ? StatusHidden
                                    : StatusStraddle;
  }
}

void View::DepthRange(const Geometry& g, vtkIdType c, double& front, double& rear) const
{
  if (this->HasCellExtents || this->Clip(c) >= 0)
  {
    front = this->FrontOf(c);
    rear = this->RearOf(c);
    return;
  }
  // As CellExtents.
  const vtkIdType* ids = g.CellCorners(c);
  const int m = g.NumberOfCorners(c);
  double zmin = VTK_DOUBLE_MAX, zmax = -VTK_DOUBLE_MAX;
  for (int i = 0; i < m; ++i)
  {
    if (ids[i] >= 0)
    {
      zmin = std::min(zmin, this->Proj[3 * ids[i] + 2]);
      zmax = std::max(zmax, this->Proj[3 * ids[i] + 2]);
    }
  }
  front = zmin;
  rear = std::isnan(zmax) ? VTK_DOUBLE_MAX : zmax;
}

void View::Setup(const Geometry& g, vtkCamera* camera, bool cellExtents)
{
  this->Frame.FromCamera(camera, g.Diagonal);
  this->ProjectPoints(g);
  const vtkIdType n = g.NumberOfCells;
  this->Status.resize(n);
  // Per cell only for the merge (the adjacency graph needs them only for the
  // straddling cells: 64 MB less to touch per view for 2M cells).
  this->Front.resize(cellExtents ? n : 0);
  this->Rear.resize(cellExtents ? n : 0);
  this->Box.resize(cellExtents ? 4 * n : 0);
  if (!cellExtents && this->Front.capacity() >= static_cast<size_t>(n))
  {
    // Per-cell arrays left by a merge's view: freed (not every view).
    std::vector<double>().swap(this->Front);
    std::vector<double>().swap(this->Rear);
    std::vector<float>().swap(this->Box);
  }
  this->Clipped.clear();
  this->HasCellExtents = cellExtents;
  // Every point in front of the near plane and no bad cell: all cells visible.
  const bool allValid = std::find(this->Valid.begin(), this->Valid.end(), 0) == this->Valid.end();
  this->AllOrdered = allValid && g.NumberOfBadCells == 0;
  if (allValid)
  {
    this->ClipIndex.clear(); // no cell straddles the near plane
  }
  else
  {
    this->ClipIndex.assign(n, -1);
  }
  if (cellExtents)
  {
    vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) { this->CellExtents(g, begin, end); });
  }
  else
  {
    vtkSMPTools::For(
      0, n, [&](vtkIdType begin, vtkIdType end) { this->CellStatus(g, begin, end, allValid); });
  }
  if (!allValid) // else no cell straddles the near plane
  {
    this->ClipStraddling(g, cellExtents);
  }
}

void View::ProjectPoints(const Geometry& g)
{
  const ViewFrame& f = this->Frame;
  const vtkIdType numPoints = static_cast<vtkIdType>(g.Points.size() / 3);
  this->Proj.resize(3 * numPoints);
  this->Valid.resize(numPoints);
  vtkSMPTools::For(0, numPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      const double* x = g.Point(i);
      double* p = this->Proj.data() + 3 * i;
      if (f.Parallel)
      {
        p[0] = Dot(x, f.Right);
        p[1] = Dot(x, f.Up);
        p[2] = Dot(x, f.Dop);
        this->Valid[i] = 1;
        continue;
      }
      const double v[3] = { x[0] - f.Eye[0], x[1] - f.Eye[1], x[2] - f.Eye[2] };
      const double z = Dot(v, f.Dop);
      p[2] = z;
      this->Valid[i] = z > f.Near;
      p[0] = this->Valid[i] ? Dot(v, f.Right) / z : 0.0;
      p[1] = this->Valid[i] ? Dot(v, f.Up) / z : 0.0;
    }
  });
}

void View::ClipStraddling(const Geometry& g, bool cellExtents)
{
  const ViewFrame& f = this->Frame;
  const vtkIdType n = g.NumberOfCells;
  for (vtkIdType c = 0; c < n; ++c)
  {
    if (this->Status[c] != StatusStraddle)
    {
      continue;
    }
    if (!cellExtents)
    {
      // Its own slots: Rear from the corners (DepthRange() before the clip
      // index is set), Front and Box below.
      double front, rear;
      this->DepthRange(g, c, front, rear);
      this->Front.push_back(f.Near);
      this->Rear.push_back(rear);
      this->Box.resize(this->Box.size() + 4);
    }
    this->ClipIndex[c] = static_cast<int>(this->Clipped.size());
    this->Clipped.push_back(ClipCell(g, *this, c));
    const std::vector<double>& pts = this->Clipped.back();
    double box[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    for (size_t i = 0; i < pts.size(); i += 3)
    {
      box[0] = std::min(box[0], pts[i]);
      box[1] = std::max(box[1], pts[i]);
      box[2] = std::min(box[2], pts[i + 1]);
      box[3] = std::max(box[3], pts[i + 1]);
    }
    const vtkIdType at = this->ExtentSlot(c);
    float* b = this->Box.data() + 4 * at;
    b[0] = FloatDown(box[0]);
    b[1] = FloatUp(box[1]);
    b[2] = FloatDown(box[2]);
    b[3] = FloatUp(box[3]);
    this->Front[at] = f.Near;
  }
}
}
