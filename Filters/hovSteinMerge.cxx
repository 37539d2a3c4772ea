// Rough sort and multitiled merge of vtkSteinVisibilitySort (see hovSteinMerge.h).
#include "hovSteinMerge.h"

#include "hovSteinObstructs.h" // Obstruction
#include "hovSteinPairGrid.h"  // PairGrid: the tiles (the pair search's grid)

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace hovStein
{
namespace
{
/// Rear depth as a float rounded towards the back (so the early stop stays valid).
inline float RearKey(double rear)
{
  if (!(rear < std::numeric_limits<float>::max()))
  {
    return std::numeric_limits<float>::infinity(); // also NaN
  }
  float f = static_cast<float>(rear);
  return f < rear ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

struct Entry
{
  std::int32_t Rank, Next, Prev;
  float Rear;
  float Box[4];
};

/// Tile region: the extents of all ordered cells, within the view's window.
PairGrid MakeGrid(const View& v, const std::vector<vtkIdType>& cells, int nx, int ny)
{
  double r[4] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkIdType c : cells)
  {
    const float* b = v.Box.data() + 4 * c;
    r[0] = std::min(r[0], double(b[0]));
    r[1] = std::max(r[1], double(b[1]));
    r[2] = std::min(r[2], double(b[2]));
    r[3] = std::max(r[3], double(b[3]));
  }
  const double* w = v.Frame.Window;
  PairGrid grid;
  grid.NX = nx;
  grid.NY = ny;
  grid.X0 = std::max(r[0], w[0]);
  grid.Y0 = std::max(r[2], w[2]);
  grid.DX = (std::min(r[1], w[1]) - grid.X0) / nx;
  grid.DY = (std::min(r[3], w[3]) - grid.Y0) / ny;
  if (!(grid.DX > 0) || !std::isfinite(grid.DX))
  {
    grid.DX = 1;
    grid.NX = 1;
  }
  if (!(grid.DY > 0) || !std::isfinite(grid.DY))
  {
    grid.DY = 1;
    grid.NY = 1;
  }
  return grid;
}
}

void RadixSortDescending(std::vector<vtkIdType>& ids, const std::vector<float>& keys)
{
  const size_t n = ids.size();
  if (n < 2)
  {
    return; // nothing to sort (and no 65537-entry histograms to clear)
  }
  std::vector<std::uint64_t> a(n), b(n);
  for (size_t i = 0; i < n; ++i)
  {
    std::uint32_t u;
    const float k = std::isnan(keys[i]) ? std::numeric_limits<float>::infinity() : keys[i];
    std::memcpy(&u, &k, 4);
    u = (u & 0x80000000u) ? ~u : (u | 0x80000000u); // ascending order of floats
    a[i] = (static_cast<std::uint64_t>(~u) << 32) | i; // descending
  }
  for (int shift = 32; shift < 64; shift += 16)
  {
    std::vector<size_t> count(65537, 0);
    for (size_t i = 0; i < n; ++i)
    {
      ++count[((a[i] >> shift) & 0xffff) + 1];
    }
    for (int d = 0; d < 65536; ++d)
    {
      count[d + 1] += count[d];
    }
    for (size_t i = 0; i < n; ++i)
    {
      b[count[(a[i] >> shift) & 0xffff]++] = a[i];
    }
    a.swap(b);
  }
  std::vector<vtkIdType> sorted(n);
  for (size_t i = 0; i < n; ++i)
  {
    sorted[i] = ids[a[i] & 0xffffffffu];
  }
  ids.swap(sorted);
}

namespace
{
/// The Tile Sorting Lists and per-rank data of the merge.
struct Tiles
{
  PairGrid Grid;
  std::vector<Entry> Entries;
  std::vector<std::int32_t> Head;        ///< per tile: first remaining entry, or -1
  std::vector<std::int32_t> RankEntries; ///< entries of each rank (rectangle order)
  std::vector<std::int64_t> RankOffsets; ///< per rank: offset in RankEntries
  std::vector<std::int16_t> Rect;        ///< per rank: ix0, ix1, iy0, iy1

  /// Most tile entries for @p n cells: 16 per cell (the default tiling makes
  /// 1-4), at least 2^20 (36 MB with their back links), at most what 32-bit
  /// links address.
  static std::int64_t MaxEntries(vtkIdType n)
  {
    return std::min<std::int64_t>(std::numeric_limits<std::int32_t>::max(),
      std::max<std::int64_t>(std::int64_t(1) << 20, 16 * static_cast<std::int64_t>(n)));
  }

  /// The tile lists of nx x ny tiles; false (nothing built) if they would
  /// hold more than MaxEntries().
  bool Build(const View& v, const std::vector<vtkIdType>& gsl, int nx, int ny)
  {
    this->Grid = MakeGrid(v, gsl, nx, ny);
    const vtkIdType n = static_cast<vtkIdType>(gsl.size());
    const int nt = this->Grid.NX * this->Grid.NY;
    if (nt > MaxEntries(n))
    {
      return false; // more tiles than entries: per-tile arrays alone would be the cost
    }
    this->Rect.resize(4 * n);
    this->RankOffsets.resize(n + 1);
    std::int64_t total = 0;
    for (vtkIdType r = 0; r < n; ++r)
    {
      const float* b = v.Box.data() + 4 * gsl[r];
      std::int16_t* q = this->Rect.data() + 4 * r;
      q[0] = static_cast<std::int16_t>(this->Grid.IX(b[0]));
      q[1] = static_cast<std::int16_t>(this->Grid.IX(b[1]));
      q[2] = static_cast<std::int16_t>(this->Grid.IY(b[2]));
      q[3] = static_cast<std::int16_t>(this->Grid.IY(b[3]));
      this->RankOffsets[r] = total;
      total += static_cast<std::int64_t>(q[1] - q[0] + 1) * (q[3] - q[2] + 1);
    }
    this->RankOffsets[n] = total;
    // Checked before any per-entry work: 4096 x 4096 tiles over cells that
    // cover much of the view would ask for billions of entries (36 bytes
    // each) and as many steps.
    if (total > MaxEntries(n))
    {
      return false;
    }
    std::vector<std::int64_t> start(nt + 1, 0);
    for (vtkIdType r = 0; r < n; ++r)
    {
      const std::int16_t* q = this->Rect.data() + 4 * r;
      for (int iy = q[2]; iy <= q[3]; ++iy)
      {
        for (int ix = q[0]; ix <= q[1]; ++ix)
        {
          ++start[iy * this->Grid.NX + ix + 1];
        }
      }
    }
    for (int t = 0; t < nt; ++t)
    {
      start[t + 1] += start[t];
    }
    this->Entries.resize(total);
    this->Head.assign(nt, -1);
    std::vector<std::int64_t> cursor(start.begin(), start.end() - 1);
    std::vector<std::int32_t> where(total);
    for (vtkIdType r = 0; r < n; ++r)
    {
      const vtkIdType c = gsl[r];
      const std::int16_t* q = this->Rect.data() + 4 * r;
      std::int64_t k = this->RankOffsets[r];
      for (int iy = q[2]; iy <= q[3]; ++iy)
      {
        for (int ix = q[0]; ix <= q[1]; ++ix)
        {
          const int t = iy * this->Grid.NX + ix;
          const std::int64_t e = cursor[t]++;
          Entry& en = this->Entries[e];
          en.Rank = static_cast<std::int32_t>(r);
          en.Next = e + 1 < start[t + 1] ? static_cast<std::int32_t>(e + 1) : -1;
          en.Prev = e > start[t] ? static_cast<std::int32_t>(e - 1) : -1;
          en.Rear = RearKey(v.Rear[c]);
          std::copy(v.Box.data() + 4 * c, v.Box.data() + 4 * c + 4, en.Box);
          where[k++] = static_cast<std::int32_t>(e);
        }
      }
    }
    for (int t = 0; t < nt; ++t)
    {
      this->Head[t] = start[t] < start[t + 1] ? static_cast<std::int32_t>(start[t]) : -1;
    }
    this->RankEntries.swap(where);
    return true;
  }

  /// Remove rank r from all its tile lists.
  void Unlink(vtkIdType r)
  {
    const std::int16_t* q = this->Rect.data() + 4 * r;
    std::int64_t k = this->RankOffsets[r];
    for (int iy = q[2]; iy <= q[3]; ++iy)
    {
      for (int ix = q[0]; ix <= q[1]; ++ix)
      {
        const std::int32_t e = this->RankEntries[k++];
        const Entry& en = this->Entries[e];
        if (en.Prev >= 0)
        {
          this->Entries[en.Prev].Next = en.Next;
        }
        else
        {
          this->Head[iy * this->Grid.NX + ix] = en.Next;
        }
        if (en.Next >= 0)
        {
          this->Entries[en.Next].Prev = en.Prev;
        }
      }
    }
  }
};

inline bool Disjoint(const float* a, const float* b)
{
  return a[1] <= b[0] || b[1] <= a[0] || a[3] <= b[2] || b[3] <= a[2];
}
}

namespace
{
/// Steps 5-8 of HIAC 6.2 on the GSL @p gsl (ranks = positions in it).
void Merge(const Geometry& g, const View& v, const std::vector<vtkIdType>& gsl, Tiles& tiles,
  std::vector<vtkIdType>& order, MergeStats& stats)
{
  const std::int32_t n = static_cast<std::int32_t>(gsl.size());
  Obstruction obstruction(g, v);
  std::vector<std::int32_t> last(n, -1);     // last P found not to obstruct this Q
  std::vector<std::int32_t> stackPos(n, -1); // position on the head stack
  std::vector<std::uint8_t> done(n, 0), inCycle(n, 0);
  std::vector<std::int32_t> stack;
  std::int32_t next = 0; // next rank of the rough order not yet taken
  std::int32_t output = 0;
  while (output < n)
  {
    if (stack.empty())
    {
      while (done[next])
      {
        ++next;
      }
      stackPos[next] = 0;
      stack.push_back(next++);
    }
    const std::int32_t p = stack.back();
    const vtkIdType cellP = gsl[p];
    const double frontP = v.Front[cellP];
    const float* boxP = v.Box.data() + 4 * cellP;
    std::int32_t obstructed = -1;
    const std::int16_t* rect = tiles.Rect.data() + 4 * p;
    for (int iy = rect[2]; iy <= rect[3] && obstructed < 0; ++iy)
    {
      for (int ix = rect[0]; ix <= rect[1] && obstructed < 0; ++ix)
      {
        for (std::int32_t e = tiles.Head[iy * tiles.Grid.NX + ix]; e >= 0;)
        {
          const Entry& en = tiles.Entries[e];
          if (en.Rear < frontP)
          {
            break; // this Q and all after it lie entirely in front of P
          }
          const std::int32_t q = en.Rank;
          e = en.Next;
          if (q == p || last[q] == p || Disjoint(boxP, en.Box))
          {
            continue;
          }
          ++stats.Tests;
          if (obstruction.Obstructs(cellP, gsl[q]))
          {
            obstructed = q;
            break;
          }
          last[q] = p;
        }
      }
    }
    if (obstructed >= 0 && stackPos[obstructed] < 0)
    {
      // Move Q to the head of the GSL (tagged: it is on the stack until output).
      ++stats.Moves;
      stackPos[obstructed] = static_cast<std::int32_t>(stack.size());
      stack.push_back(obstructed);
      continue;
    }
    if (obstructed >= 0)
    {
      // Q is already at the head: a cycle Q -> ... -> P -> Q. Output P anyway.
      ++stats.Cycles;
      for (size_t i = stackPos[obstructed]; i < stack.size(); ++i)
      {
        if (!inCycle[stack[i]])
        {
          inCycle[stack[i]] = 1;
          stats.CycleCells.push_back(gsl[stack[i]]);
        }
      }
    }
    stack.pop_back();
    assert(!done[p]);
    done[p] = 1;
    tiles.Unlink(p);
    order.push_back(cellP);
    ++output;
  }
}
}

void SortBackToFront(const Geometry& g, const View& v, int tilesX, int tilesY,
  std::vector<vtkIdType>& order, MergeStats& stats)
{
  const vtkIdType n = g.NumberOfCells;
  stats = MergeStats();
  order.clear();
  order.reserve(n);
  std::vector<vtkIdType> first, gsl;
  for (vtkIdType c = 0; c < n; ++c)
  {
    (v.Status[c] == StatusVisible || v.Status[c] == StatusStraddle ? gsl : first).push_back(c);
  }
  for (std::vector<vtkIdType>* list : { &first, &gsl })
  {
    std::vector<float> keys(list->size());
    for (size_t i = 0; i < list->size(); ++i)
    {
      keys[i] = RearKey(v.Rear[(*list)[i]]);
    }
    RadixSortDescending(*list, keys);
  }
  order.insert(order.end(), first.begin(), first.end());
  if (gsl.empty())
  {
    return;
  }
  const int dflt = static_cast<int>(std::ceil(std::pow(double(gsl.size()), 1.0 / 6.0) - 1e-9));
  int nx = tilesX > 0 ? tilesX : std::max(dflt, 1);
  int ny = tilesY > 0 ? tilesY : std::max(dflt, 1);
  Tiles tiles;
  while (!tiles.Build(v, gsl, nx, ny))
  {
    nx = std::max(1, nx / 2); // too many tile entries (MaxEntries)
    ny = std::max(1, ny / 2);
  }
  stats.TilesX = tiles.Grid.NX;
  stats.TilesY = tiles.Grid.NY;
  Merge(g, v, gsl, tiles, order, stats);
}
}
