// The pair search's screen grid (see hovSteinPairGrid.h).
#include "hovSteinPairGrid.h"

#include "hovSteinView.h" // View

#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace hovStein
{
PairGrid MakePairGrid(const View& v, const FillBuffer<FaceData>& data)
{
  // In parallel over fixed chunks, each chunk's partial results combined in
  // chunk order: the grid does not depend on the number of threads.
  const vtkIdType n = static_cast<vtkIdType>(data.size());
  constexpr vtkIdType Chunk = 8192;
  const vtkIdType numChunks = (n + Chunk - 1) / Chunk;
  std::vector<std::array<double, 4>> partial(numChunks);
  auto forChunks = [&](auto&& fn) {
    vtkSMPTools::For(0, numChunks, 1, [&](vtkIdType c0, vtkIdType c1) {
      for (vtkIdType c = c0; c < c1; ++c)
      {
        fn(c * Chunk, std::min(n, (c + 1) * Chunk), partial[c]);
      }
    });
  };
  forChunks([&](vtkIdType begin, vtkIdType end, std::array<double, 4>& r) {
    r = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    for (vtkIdType i = begin; i < end; ++i)
    {
      const float* box = data[i].Box;
      r[0] = std::min(r[0], double(box[0]));
      r[1] = std::max(r[1], double(box[1]));
      r[2] = std::min(r[2], double(box[2]));
      r[3] = std::max(r[3], double(box[3]));
    }
  });
  double r[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (const std::array<double, 4>& p : partial)
  {
    r[0] = std::min(r[0], p[0]);
    r[1] = std::max(r[1], p[1]);
    r[2] = std::min(r[2], p[2]);
    r[3] = std::max(r[3], p[3]);
  }
  const double* win = v.Frame.Window;
  PairGrid grid;
  grid.X0 = std::max(r[0], win[0]);
  grid.Y0 = std::max(r[2], win[2]);
  const double width = std::min(r[1], win[1]) - grid.X0, height = std::min(r[3], win[3]) - grid.Y0;
  forChunks([&](vtkIdType begin, vtkIdType end, std::array<double, 4>& sum) {
    sum = { 0, 0, 0, 0 };
    for (vtkIdType i = begin; i < end; ++i)
    {
      const float* box = data[i].Box;
      sum[0] += std::min(double(box[1]) - box[0], width);
      sum[1] += std::min(double(box[3]) - box[2], height);
    }
  });
  double w = 0, h = 0;
  for (const std::array<double, 4>& sum : partial)
  {
    w += sum[0];
    h += sum[1];
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
