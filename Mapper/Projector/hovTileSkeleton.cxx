#include "hovTileSkeleton.h"

#include "vtkSMPTools.h" // parallel projection and binning

void hov::ProjectedPoints::Project(const ViewRays& rays, const std::vector<glm::dvec3>& points)
{
  this->Window.resize(points.size());
  this->Projectable.resize(points.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(points.size()), [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType i = b; i < e; ++i)
    {
      double x = 0.0, y = 0.0;
      this->Projectable[i] = rays.Project(points[i], x, y);
      this->Window[i] = glm::dvec2(x, y);
    }
  });
}

void hov::TileBins::Build(const std::vector<CellBox>& boxes, int width, int height, int tileSize)
{
  this->Size = tileSize;
  this->TilesX = (width + tileSize - 1) / tileSize;
  this->TilesY = (height + tileSize - 1) / tileSize;
  const int numTiles = this->TilesX * this->TilesY;
  auto forTiles = [&](const CellBox& b, auto&& f) {
    if (b[0] > b[1] || b[2] > b[3])
    {
      return;
    }
    for (int ty = b[2] / tileSize; ty <= b[3] / tileSize; ++ty)
    {
      for (int tx = b[0] / tileSize; tx <= b[1] / tileSize; ++tx)
      {
        f(ty * this->TilesX + tx);
      }
    }
  };
  // In parallel over a fixed number of cell chunks (the result does not
  // depend on the threads): count per chunk and tile, offsets per tile in
  // chunk order, then each chunk fills its slots; every tile's list stays in
  // cell order.
  const vtkIdType numCells = static_cast<vtkIdType>(boxes.size());
  const vtkIdType chunk = (numCells + Chunks - 1) / Chunks;
  this->Fill.assign(static_cast<size_t>(Chunks) * numTiles, 0);
  vtkSMPTools::For(0, Chunks, 1, [&](vtkIdType c0, vtkIdType c1) {
    for (vtkIdType c = c0; c < c1; ++c)
    {
      vtkIdType* count = this->Fill.data() + c * numTiles;
      for (vtkIdType k = c * chunk; k < std::min(numCells, (c + 1) * chunk); ++k)
      {
        forTiles(boxes[k], [&](int t) { ++count[t]; });
      }
    }
  });
  this->Start.assign(numTiles + 1, 0);
  vtkIdType next = 0;
  for (int t = 0; t < numTiles; ++t)
  {
    this->Start[t] = next;
    for (int c = 0; c < Chunks; ++c)
    {
      const vtkIdType n = this->Fill[static_cast<size_t>(c) * numTiles + t];
      this->Fill[static_cast<size_t>(c) * numTiles + t] = next; // becomes the write position
      next += n;
    }
  }
  this->Start[numTiles] = next;
  this->Cells.resize(next);
  vtkSMPTools::For(0, Chunks, 1, [&](vtkIdType c0, vtkIdType c1) {
    for (vtkIdType c = c0; c < c1; ++c)
    {
      vtkIdType* fill = this->Fill.data() + c * numTiles;
      for (vtkIdType k = c * chunk; k < std::min(numCells, (c + 1) * chunk); ++k)
      {
        forTiles(boxes[k], [&](int t) { this->Cells[fill[t]++] = k; });
      }
    }
  });
}

void hov::TilePixels::InitPixels(
  const ViewRays& rays, const float* depth, const TileBins& bins, int tileIndex)
{
  const int width = rays.GetWidth();
  this->X0 = (tileIndex % bins.TilesX) * bins.Size;
  this->Y0 = (tileIndex / bins.TilesX) * bins.Size;
  this->W = std::min(bins.Size, width - this->X0);
  this->H = std::min(bins.Size, rays.GetHeight() - this->Y0);
  const size_t n = static_cast<size_t>(this->W) * this->H;
  this->Rays.resize(n);
  this->TMax.resize(n);
  this->Accum.assign(n, RGBA());
  this->MaxExit.assign(n, -1e300);
  this->Violated.assign(n, 0);
  this->Done.assign(n, 0);
  if (!depth && !rays.HasClipping())
  {
    // The common case: TracedPixelRay() is PixelRay(), a row at a time.
    for (int j = 0; j < this->H; ++j)
    {
      const size_t p = static_cast<size_t>(j) * this->W;
      rays.RowRays(this->X0, this->Y0 + j, this->W, this->Rays.data() + p);
      for (int i = 0; i < this->W; ++i)
      {
        this->TMax[p + i] = this->Rays[p + i].TFar;
      }
    }
    return;
  }
  for (int j = 0; j < this->H; ++j)
  {
    for (int i = 0; i < this->W; ++i)
    {
      const int pi = this->X0 + i, pj = this->Y0 + j;
      const size_t p = static_cast<size_t>(j) * this->W + i;
      const double z = depth ? depth[static_cast<size_t>(pj) * width + pi] : 1.0;
      this->Rays[p] = rays.TracedPixelRay(pi, pj, z, this->TMax[p]);
    }
  }
}

void hov::TilePixels::WritePixels(
  std::vector<double>& rgba, int width, ProjectorStatistics& stats) const
{
  for (int j = 0; j < this->H; ++j)
  {
    for (int i = 0; i < this->W; ++i)
    {
      const size_t p = static_cast<size_t>(j) * this->W + i;
      double* out = &rgba[4 * (static_cast<size_t>(this->Y0 + j) * width + this->X0 + i)];
      out[0] = this->Accum[p].R;
      out[1] = this->Accum[p].G;
      out[2] = this->Accum[p].B;
      out[3] = this->Accum[p].A;
      stats.WitnessViolations += this->Violated[p];
    }
  }
}

std::array<int, 4> hov::TileBins::ContentBox(int width, int height) const
{
  int box[4] = { INT_MAX, 0, INT_MAX, 0 };
  for (int t = 0; t < this->NumberOfTiles(); ++t)
  {
    if (this->Start[t + 1] > this->Start[t])
    {
      const int x0 = (t % this->TilesX) * this->Size, y0 = (t / this->TilesX) * this->Size;
      box[0] = std::min(box[0], x0);
      box[1] = std::max(box[1], std::min(width, x0 + this->Size));
      box[2] = std::min(box[2], y0);
      box[3] = std::max(box[3], std::min(height, y0 + this->Size));
    }
  }
  if (box[0] >= box[1] || box[2] >= box[3])
  {
    return { 0, 0, 0, 0 };
  }
  return { box[0], box[1], box[2], box[3] };
}

void hov::TilePixels::WriteEmptyTile(
  const TileBins& bins, int width, int height, int tileIndex, std::vector<double>& rgba)
{
  const int x0 = (tileIndex % bins.TilesX) * bins.Size;
  const int y0 = (tileIndex / bins.TilesX) * bins.Size;
  const int w = std::min(bins.Size, width - x0);
  const int h = std::min(bins.Size, height - y0);
  for (int j = 0; j < h; ++j)
  {
    double* row = &rgba[4 * (static_cast<size_t>(y0 + j) * width + x0)];
    std::fill(row, row + 4 * static_cast<size_t>(w), 0.0);
  }
}
