// De-duplication and decision of the Stein sort's boundary cell pairs (see hovSteinPairEdges.h).
#include "hovSteinPairEdges.h"

#include "hovSteinBuckets.h"   // ParallelRunningSum, ParallelSelect
#include "hovSteinObstructs.h" // Obstruction
#include "hovSteinTopology.h"  // MaxIndexedCells

#include "vtkSMPTools.h"

#include <algorithm>

namespace hovStein
{
static_assert(MaxIndexedCells <= VTK_ID_MAX / 2, "cell pairs carry 2 * cell + 1");

/*
 * Bucketing and sorting each bucket on its own gives the same pairs in the
 * same order as sorting all of them and removing repeats, in about half the
 * time on the heatsink 0.5M (measured side by side: 45-57 ms against 79-97
 * ms; counting and scattering in parallel over chunks of blocks saved only
 * another ~7%, so they stay serial).
 */
void PairEdges::Collect(const std::vector<CellPairs>& blocks, const std::vector<CellRange>& ranges)
{
  vtkIdType lo = VTK_ID_MAX, hi = -1;
  for (const auto& range : ranges)
  {
    lo = std::min(lo, range.first);
    hi = std::max(hi, range.second);
  }
  this->Kept.clear();
  this->Lo = lo;
  if (hi < lo)
  {
    return;
  }
  const vtkIdType nb = hi - lo + 1;
  FillBuffer<vtkIdType>& end = this->End;
  end.assign(nb + 1, 0); // the counts, then each bucket's start, then its end
  for (const CellPairs& block : blocks)
  {
    for (const auto& p : block)
    {
      ++end[p.first - lo + 1];
    }
  }
  for (vtkIdType i = 0; i < nb; ++i)
  {
    end[i + 1] += end[i];
  }
  this->Second.resize(end[nb]);
  for (const CellPairs& block : blocks) // end[i] becomes the end of bucket i
  {
    for (const auto& p : block)
    {
      this->Second[end[p.first - lo]++] = p.second;
    }
  }
  this->Kept.resize(nb);
  vtkSMPTools::For(0, nb, 4096, [&](vtkIdType begin, vtkIdType stop) {
    for (vtkIdType i = begin; i < stop; ++i)
    {
      vtkIdType* first = this->Second.data() + (i == 0 ? 0 : end[i - 1]);
      vtkIdType* last = this->Second.data() + end[i];
      std::sort(first, last);
      // One entry per second cell, marked if any of its entries is (2c + 1 sorts after 2c).
      vtkIdType* out = first;
      for (vtkIdType* it = first; it != last; ++it)
      {
        if (out != first && (out[-1] >> 1) == (*it >> 1))
        {
          out[-1] = *it;
        }
        else
        {
          *out++ = *it;
        }
      }
      this->Kept[i] = static_cast<std::uint32_t>(out - first);
    }
  });
}

vtkIdType PairEdges::Decide(const Geometry& g, const View& v, FillBuffer<vtkIdType>& offsets,
  FillBuffer<vtkIdType>& targets)
{
  const vtkIdType n = g.NumberOfCells;
  const vtkIdType nb = static_cast<vtkIdType>(this->Kept.size());
  const vtkIdType lo = this->Lo;
  this->Used.assign(n, 0);
  vtkIdType tests = 0;
  for (vtkIdType i = 0; i < nb; ++i)
  {
    const vtkIdType* second = this->Bucket(i);
    for (std::uint32_t k = 0; k < this->Kept[i]; ++k)
    {
      if (!(second[k] & 1))
      {
        this->Used[lo + i] = this->Used[second[k] >> 1] = 1;
        ++tests;
      }
    }
  }
  this->Cells.clear();
  ParallelSelect(n, [this](vtkIdType c) { return this->Used[c] != 0; }, this->Cells);
  this->Hulls.Build(g, v, this->Cells);
  // Each bucket's edges, kept at its beginning (Kept becomes their count).
  // (Most buckets are empty or hold one or two pairs: chunks of 256 balance the tests.)
  vtkSMPTools::For(0, nb, 256, [&](vtkIdType begin, vtkIdType end) {
    Obstruction ob(g, v, &this->Hulls);
    for (vtkIdType i = begin; i < end; ++i)
    {
      vtkIdType* second = this->Bucket(i);
      std::uint32_t hits = 0;
      for (std::uint32_t k = 0; k < this->Kept[i]; ++k)
      {
        const vtkIdType a = second[k] >> 1;
        if ((second[k] & 1) || ob.Obstructs(a, lo + i))
        {
          second[hits++] = a;
        }
      }
      this->Kept[i] = hits;
    }
  });
  offsets.resize(n + 1);
  offsets[0] = 0;
  vtkSMPTools::For(0, n, 16384, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType c = begin; c < end; ++c)
    {
      offsets[c + 1] = c >= lo && c - lo < nb ? this->Kept[c - lo] : 0;
    }
  });
  ParallelRunningSum(offsets.data(), n);
  targets.resize(offsets[n]);
  vtkSMPTools::For(0, nb, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      std::copy(this->Bucket(i), this->Bucket(i) + this->Kept[i], targets.data() + offsets[lo + i]);
    }
  });
  return tests;
}
}
