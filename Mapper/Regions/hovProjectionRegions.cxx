#include "hovProjectionRegions.h"

#include "hovProjectionPolyhedron.h" // slab faces, overlay, vertex emission
#include "hovProjectionTetra.h"      // one-slab tetrahedra
#include "hovCellSetup.h"           // the validated cells

#include "hovTransferFunction.h" // the table

#include "vtkSMPTools.h" // parallel cells

#include <algorithm> // std::sort
#include <cstdint>   // uint32_t, uint64_t
#include <cstring>   // std::memcpy
#include <limits>    // infinity

namespace
{
using Poly = hov::ProjectionPolyhedron;
using Statistics = hov::ProjectionRegions::Statistics;

/// Ask for the cache line of @p p (a hint; GCC 12 drops __builtin_prefetch here).
inline void Prefetch(const void* p)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(p)));
#else
  (void)p;
#endif
}
constexpr vtkIdType CellsPerChunk = hov::ProjectionRegions::CellsPerChunk;

/// The slabs of one cell in back-to-front order.
struct SlabOrder
{
  std::vector<std::pair<double, int>> Keys; // (farness, interval index)

  /// Intervals k of @p tf overlapping [smin, smax] with some extinction
  /// (or any, if @p keepTransparent), farthest first.
  void Build(const hov::TransferFunction& tf, double smin, double smax, bool keepTransparent,
    double eyeLevel, int direction)
  {
    this->Keys.clear();
    const std::vector<double>& x = tf.GetNodes();
    const int n = static_cast<int>(x.size());
    const double inf = std::numeric_limits<double>::infinity();
    if (n == 0)
    {
      return;
    }
    if (!(smin < smax)) // constant field: one slab
    {
      this->Keys.emplace_back(0.0, tf.FindIntervalUpward(smin));
      return;
    }
    for (int k = tf.FindIntervalDownward(smin); k < n; ++k)
    {
      const double lo = std::max(k < 0 ? -inf : x[k], smin);
      const double hi = std::min(k + 1 < n ? x[k + 1] : inf, smax);
      if (lo >= smax)
      {
        break;
      }
      if (!(lo < hi))
      {
        continue; // a jump, or the interval ends where the cell starts
      }
      if (!keepTransparent)
      {
        hov::SegmentEnd a, b;
        tf.Evaluate(k, lo, false, a);
        tf.Evaluate(k, hi, false, b);
        if (a.Tau == 0.0 && b.Tau == 0.0)
        {
          continue; // tau is linear on the slab: zero throughout
        }
      }
      double key = 0.0;
      if (direction > 0)
      {
        key = lo;
      }
      else if (direction < 0)
      {
        key = -hi;
      }
      else if (lo > eyeLevel)
      {
        key = lo - eyeLevel;
      }
      else if (hi < eyeLevel)
      {
        key = eyeLevel - hi;
      }
      this->Keys.emplace_back(key, k);
    }
    std::sort(this->Keys.begin(), this->Keys.end(),
      [](const std::pair<double, int>& a, const std::pair<double, int>& b) {
        return a.first > b.first || (a.first == b.first && a.second < b.second);
      });
  }
};
}

namespace
{
/// Per-thread state of Build: the general path's polyhedron and the slab order.
struct CellEmitter
{
  const hov::CellSetup* Setup;
  const hov::TransferFunction* Tf;
  const hov::ProjectionRegions::Settings* Settings;
  const Poly::Frame* Frame;
  SlabOrder Order;
  Poly Polyhedron;

  /**
   * The cells are visited in depth order, which is random in memory: fetch
   * the tetrahedron PrefetchCells ahead and the points of the one half as far
   * ahead (its record has arrived by then) so that Emit does not wait for memory.
   */
  void Prefetch(const std::vector<vtkIdType>& order, vtkIdType i, vtkIdType n) const
  {
    constexpr vtkIdType far = 16, near = 8;
    const auto& tetras = this->Setup->GetTetras();
    const vtkIdType numTetras = static_cast<vtkIdType>(tetras.size());
    if (i + far < n && order[i + far] >= 0 && order[i + far] < numTetras)
    {
      const char* t = reinterpret_cast<const char*>(&tetras[order[i + far]]);
      ::Prefetch(t + 128);
      ::Prefetch(t + 192);
    }
    if (i + near < n && order[i + near] >= 0 && order[i + near] < numTetras)
    {
      const hov::CellSetup::Tetra& t = tetras[order[i + near]];
      for (int k = 0; k < 4; ++k)
      {
        ::Prefetch(&this->Setup->GetPoints()[t.Points[k]]);
      }
    }
  }

  /// The triangles of rendered cell @p cell into @p out.
  void Emit(vtkIdType cell, hov::ProjectionChunk& out, Statistics& st)
  {
    const auto& tetras = this->Setup->GetTetras();
    const hov::GeneralCells& general = this->Setup->GetGeneralCells();
    const vtkIdType numTetras = static_cast<vtkIdType>(tetras.size());
    ++st.Cells;
    if (cell < 0 || cell >= numTetras + static_cast<vtkIdType>(general.GetCells().size()))
    {
      return;
    }
    const bool wvg = this->Settings->Emission == hov::EmissionModel::WilhelmsVanGelder;
    if (cell < numTetras && this->EmitFastTetra(tetras[cell], wvg, out, st))
    {
      return;
    }
    Poly& poly = this->Polyhedron;
    const bool ok = cell < numTetras
      ? poly.SetTetra(tetras[cell], this->Setup->GetPoints(), *this->Frame)
      : poly.SetGeneral(general, general.GetCells()[cell - numTetras], *this->Frame);
    if (!ok)
    {
      ++st.BehindEye;
      return;
    }
    const int direction =
      this->Settings->Parallel ? poly.LevelDirection(this->Settings->Direction) : 0;
    this->Order.Build(*this->Tf, poly.GetScalarMin(), poly.GetScalarMax(), wvg,
      poly.EyeLevel(this->Settings->Eye), direction);
    if (cell >= numTetras && this->Order.Keys.size() > 1)
    {
      ++st.CutGeneral; // cut by levels (approximate caps)
    }
    for (const auto& key : this->Order.Keys)
    {
      ++st.Slabs;
      st.Triangles += poly.EmitSlab(key.second, *this->Frame, out);
    }
  }

  /// A tetrahedron in at most one visible slab by hov::ProjectionTetra;
  /// false if it needs the general path.
  bool EmitFastTetra(const hov::CellSetup::Tetra& t, bool wvg,
    hov::ProjectionChunk& out, Statistics& st)
  {
    const double smin = t.ScalarMin, smax = t.ScalarMax;
    this->Order.Build(*this->Tf, smin, smax, wvg, 0.0, 1); // no sorting needed for one slab
    if (this->Order.Keys.size() > 1)
    {
      return false;
    }
    if (this->Order.Keys.empty())
    {
      return true; // transparent throughout
    }
    const int k = this->Order.Keys[0].second;
    const std::vector<double>& x = this->Tf->GetNodes();
    const double lo = k < 0 ? smin : std::max(x[k], smin);
    const double hi = k + 1 < static_cast<int>(x.size()) ? std::min(x[k + 1], smax) : smax;
    const int n = hov::ProjectionTetra::Emit(
      t, this->Setup->GetPoints(), *this->Frame, k, lo, hi, out);
    if (n == hov::ProjectionTetra::Degenerate)
    {
      return false;
    }
    if (n == hov::ProjectionTetra::BehindEye)
    {
      ++st.BehindEye;
      return true;
    }
    ++st.Slabs;
    ++st.FastTetras;
    st.Triangles += n;
    return true;
  }
};
}

hov::ProjectionRegions::Statistics hov::ProjectionRegions::Build(
  const hov::CellSetup& setup, const std::vector<vtkIdType>& backToFront, vtkIdType begin,
  vtkIdType end, const hov::TransferFunction& tf, const Settings& settings,
  Geometry& geometry) const
{
  begin = std::max<vtkIdType>(begin, 0);
  end = std::min(end, static_cast<vtkIdType>(backToFront.size()));
  const vtkIdType numCells = std::max<vtkIdType>(end - begin, 0);
  const vtkIdType numChunks = (numCells + CellsPerChunk - 1) / CellsPerChunk;
  geometry.Clear();
  if (static_cast<vtkIdType>(geometry.Chunks.size()) < numChunks)
  {
    geometry.Chunks.resize(numChunks);
  }
  std::vector<Statistics> stats(numChunks);

  Poly::Frame frame;
  frame.Composite = settings.Composite;
  frame.Inverse = glm::inverse(settings.Composite);
  frame.Table = &this->ColorTable;
  frame.Tf = &tf;
  frame.Method = settings.Method;
  frame.Emission = settings.Emission;
  frame.Parallel = settings.Parallel;
  frame.Eye = settings.Eye;
  frame.ExtinctionTf = settings.ExtinctionTf;
  frame.InverseUnit = settings.InverseUnit;

  vtkSMPTools::For(0, numChunks, [&](vtkIdType first, vtkIdType last) {
    CellEmitter emitter{ &setup, &tf, &settings, &frame, {}, {} };
    for (vtkIdType chunk = first; chunk < last; ++chunk)
    {
      const vtkIdType stop = begin + std::min(numCells, (chunk + 1) * CellsPerChunk);
      for (vtkIdType i = begin + chunk * CellsPerChunk; i < stop; ++i)
      {
        emitter.Prefetch(backToFront, i, end);
        emitter.Emit(backToFront[i], geometry.Chunks[chunk], stats[chunk]);
      }
    }
  });

  Statistics total;
  geometry.VertexOffsets.resize(numChunks + 1);
  geometry.IndexOffsets.resize(numChunks + 1);
  for (vtkIdType c = 0; c < numChunks; ++c)
  {
    const hov::ProjectionChunk& chunk = geometry.Chunks[c];
    geometry.VertexOffsets[c + 1] = geometry.VertexOffsets[c] + chunk.NumberOfVertices();
    geometry.IndexOffsets[c + 1] = geometry.IndexOffsets[c] + chunk.Indices.Size();
    total.Add(stats[c]);
  }
  return total;
}

namespace
{
/// An unsigned integer with the order of the float @p f, reversed (larger first).
uint32_t FarthestFirstBits(float f)
{
  uint32_t u = 0;
  std::memcpy(&u, &f, sizeof(u));
  const uint32_t ascending = (u & 0x80000000u) ? ~u : (u | 0x80000000u);
  return ~ascending;
}

/**
 * One stable counting pass of an LSD radix sort on the 8-bit digit at
 * @p shift: @p blocks consecutive blocks histogrammed and scattered in
 * parallel (block b's items of digit d go after those of the blocks before
 * it). False (nothing moved) if every item has the same digit.
 */
bool RadixPass(const std::vector<uint64_t>& items, std::vector<uint64_t>& out, int shift,
  vtkIdType blocks)
{
  const vtkIdType n = static_cast<vtkIdType>(items.size());
  std::vector<size_t> count(static_cast<size_t>(blocks) * 256, 0);
  auto range = [&](vtkIdType b, vtkIdType& first, vtkIdType& last) {
    first = n * b / blocks;
    last = n * (b + 1) / blocks;
  };
  vtkSMPTools::For(0, blocks, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType b = b0, first, last; b < b1; ++b)
    {
      range(b, first, last);
      size_t* c = count.data() + 256 * b;
      for (vtkIdType i = first; i < last; ++i)
      {
        ++c[(items[i] >> shift) & 0xff];
      }
    }
  });
  size_t offset = 0;
  for (int d = 0; d < 256; ++d)
  {
    const size_t before = offset;
    for (vtkIdType b = 0; b < blocks; ++b)
    {
      const size_t c = count[256 * b + d];
      count[256 * b + d] = offset;
      offset += c;
    }
    if (offset - before == static_cast<size_t>(n))
    {
      return false; // every key has this digit: nothing to do
    }
  }
  vtkSMPTools::For(0, blocks, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType b = b0, first, last; b < b1; ++b)
    {
      range(b, first, last);
      size_t* c = count.data() + 256 * b;
      for (vtkIdType i = first; i < last; ++i)
      {
        out[c[(items[i] >> shift) & 0xff]++] = items[i];
      }
    }
  });
  return true;
}

/**
 * Sort @p items (key bits << 32 | index) ascending by their key bits: LSD
 * radix sort, 4 stable passes of 8 bits (in parallel blocks), so equal keys
 * keep their (index) order. @p scratch is resized.
 */
void RadixSortByKey(std::vector<uint64_t>& items, std::vector<uint64_t>& scratch)
{
  scratch.resize(items.size());
  // Fixed by the size (not the thread count), so the result is deterministic.
  const vtkIdType blocks =
    std::max<vtkIdType>(1, std::min<vtkIdType>(64, static_cast<vtkIdType>(items.size()) / 512));
  for (int shift = 32; shift < 64; shift += 8)
  {
    if (RadixPass(items, scratch, shift, blocks))
    {
      items.swap(scratch);
    }
  }
}
}

void hov::ProjectionRegions::CentroidOrder(
  const hov::CellSetup& setup, const Settings& settings, std::vector<vtkIdType>& backToFront)
{
  const std::vector<hov::CellSetup::Tetra>& tetras = setup.GetTetras();
  const auto& general = setup.GetGeneralCells();
  const vtkIdType numTetras = static_cast<vtkIdType>(tetras.size());
  const vtkIdType n = setup.GetNumberOfRenderedCells();
  const std::vector<glm::dvec3>& points = setup.GetPoints();
  std::vector<uint64_t>& items = this->OrderItems;
  items.resize(n);
  vtkSMPTools::For(0, n, [&](vtkIdType first, vtkIdType last) {
    for (vtkIdType i = first; i < last; ++i)
    {
      glm::dvec3 c(0.0);
      if (i < numTetras)
      {
        for (int k = 0; k < 4; ++k)
        {
          c += points[tetras[i].Points[k]];
        }
        c *= 0.25;
      }
      else
      {
        const auto& cell = general.GetCells()[i - numTetras];
        const double* nodes = general.GetNodes(cell);
        for (int k = 0; k < cell.NodeCount; ++k)
        {
          c += glm::dvec3(nodes[3 * k], nodes[3 * k + 1], nodes[3 * k + 2]);
        }
        c /= static_cast<double>(std::max(cell.NodeCount, 1));
      }
      const glm::dvec3 d = c - settings.Eye;
      const double key = settings.Parallel ? glm::dot(c, settings.Direction) : glm::dot(d, d);
      items[i] = (uint64_t(FarthestFirstBits(static_cast<float>(key))) << 32) | uint64_t(i);
    }
  });
  RadixSortByKey(items, this->OrderScratch);
  backToFront.resize(n);
  vtkSMPTools::For(0, n, [&](vtkIdType first, vtkIdType last) {
    for (vtkIdType i = first; i < last; ++i)
    {
      backToFront[i] = static_cast<vtkIdType>(items[i] & 0xffffffffu);
    }
  });
}
