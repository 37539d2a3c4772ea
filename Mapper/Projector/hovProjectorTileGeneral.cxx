// The general-cell (non-tetrahedral) part of hov::ProjectorTile: how a
// tile composites hexahedra, wedges, pyramids and quadratic cells in cell
// order and per pixel. Kept apart from the tetrahedra's hot loop
// (hov::ProjectorTile.cxx); the per-cell numerics are in
// hov::GeneralCellTile.
#include "hovProjectorTile.h"

#include "hovCompositing.h" // CompositeBehind

#include <algorithm> // std::max

void hov::ProjectorTile::RenderGeneralCell(
  const Frame& frame, vtkIdType k, Statistics& st)
{
  const hov::GeneralCellTile::FrameData& general = *frame.General;
  const int g = (*general.GeneralOf)[k];
  const auto& hits =
    this->General.Collect(general, g, (*frame.Cells)[k].PixelBox, this->Rows(), this->Done.data());
  const auto& intervals = this->General.Intervals();
  for (const hov::GeneralCellTile::Hit& hit : hits)
  {
    const size_t p = static_cast<size_t>(hit.Pixel);
    const hov::ViewRays::Ray& ray = this->Rays[p];
    // The cell's intervals front to back, then the cell behind the pixel.
    hov::RGBA cell;
    for (int m = hit.First; m < hit.First + hit.Count; ++m)
    {
      hov::CompositeBehind(
        cell, this->General.Integrate(general, g, ray, intervals[m].T0, intervals[m].T1, st.Pieces));
    }
    this->Witness(p, intervals[hit.First].T0, intervals[hit.First + hit.Count - 1].T1, frame.WitnessTol);
    this->Composite(frame, p, cell);
    st.Segments += hit.Count;
  }
}

void hov::ProjectorTile::CollectGeneralFragments(const Frame& frame, vtkIdType k)
{
  const hov::GeneralCellTile::FrameData& general = *frame.General;
  const auto& hits = this->General.Collect(
    general, (*general.GeneralOf)[k], (*frame.Cells)[k].PixelBox, this->Rows(), nullptr);
  const auto& intervals = this->General.Intervals();
  for (const hov::GeneralCellTile::Hit& hit : hits)
  {
    for (int m = hit.First; m < hit.First + hit.Count; ++m)
    {
      if (this->NumFragments == static_cast<int>(this->Fragments.size()))
      {
        this->Fragments.resize(2 * this->Fragments.size() + 1024);
      }
      Fragment& f = this->Fragments[this->NumFragments++];
      f.TIn = intervals[m].T0;
      f.TOut = intervals[m].T1;
      f.SIn = f.SOut = 0.0; // unused: the general path restricts the field itself
      f.Pixel = hit.Pixel;
      f.Order = static_cast<int>(k);
    }
  }
}

void hov::ProjectorTile::CompositeGeneralInterval(const Frame& frame, size_t p,
  double tIn, double tOut, vtkIdType k, Statistics& st)
{
  if (this->Done[p])
  {
    return;
  }
  const hov::GeneralCellTile::FrameData& general = *frame.General;
  const hov::RGBA seg =
    this->General.Integrate(general, (*general.GeneralOf)[k], this->Rays[p], tIn, tOut, st.Pieces);
  this->Witness(p, tIn, tOut, frame.WitnessTol);
  this->Composite(frame, p, seg);
  ++st.Segments;
}

void hov::ProjectorTile::Composite(const Frame& frame, size_t p, const hov::RGBA& seg)
{
  hov::CompositeBehind(this->Accum[p], seg);
  if (1.0 - this->Accum[p].A <= frame.Settings->TerminationTransmittance && !this->Done[p])
  {
    this->Done[p] = 1;
    ++this->DoneInRow[p / static_cast<size_t>(this->W)];
  }
}
