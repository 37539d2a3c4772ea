// The pair search's screen grid (see hovSteinPairGrid.h).
#include "hovSteinPairGrid.h"

#include "hovSteinView.h" // View

#include <algorithm>
#include <cmath>

namespace hovStein
{
PairGrid MakePairGrid(const View& v, const FillBuffer<FaceData>& data)
{
  double r[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (const FaceData& d : data)
  {
    r[0] = std::min(r[0], double(d.Box[0]));
    r[1] = std::max(r[1], double(d.Box[1]));
    r[2] = std::min(r[2], double(d.Box[2]));
    r[3] = std::max(r[3], double(d.Box[3]));
  }
  const double* win = v.Frame.Window;
  PairGrid grid;
  grid.X0 = std::max(r[0], win[0]);
  grid.Y0 = std::max(r[2], win[2]);
  const double width = std::min(r[1], win[1]) - grid.X0, height = std::min(r[3], win[3]) - grid.Y0;
  double w = 0, h = 0;
  for (const FaceData& d : data)
  {
    w += std::min(double(d.Box[1]) - d.Box[0], width);
    h += std::min(double(d.Box[3]) - d.Box[2], height);
  }
  const double count = std::max<double>(1, static_cast<double>(data.size()));
  w /= count;
  h /= count;
  if (!(width > 0 && height > 0 && w > 0 && h > 0) || !std::isfinite(width * height))
  {
    return grid; // one tile
  }
  double nx = width / w, ny = height / h;
  const double scale = std::sqrt(std::min(1.0, 4 * count / (nx * ny)));
  nx = std::min<double>(MaxGridSide, std::max(1.0, std::floor(nx * scale)));
  ny = std::min<double>(MaxGridSide, std::max(1.0, std::floor(ny * scale)));
  grid.NX = static_cast<int>(nx);
  grid.NY = static_cast<int>(ny);
  grid.DX = width / grid.NX;
  grid.DY = height / grid.NY;
  return grid;
}
}
