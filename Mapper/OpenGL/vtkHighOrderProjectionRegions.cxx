#include "vtkHighOrderProjectionRegions.h"

#include "vtkHighOrderProjectionPolyhedron.h" // slab faces, overlay, vertex emission
#include "vtkHighOrderTetraSetup.h"           // the validated cells

#include "hovTransferFunction.h" // the table

#include "vtkSMPTools.h" // parallel cells

#include <algorithm> // std::sort
#include <cstring>   // std::memcpy
#include <limits>    // infinity
#include <numeric>   // std::iota

namespace
{
using Poly = vtkHighOrderProjectionPolyhedron;
constexpr vtkIdType CellsPerChunk = 256;

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

vtkHighOrderProjectionRegions::Statistics vtkHighOrderProjectionRegions::Build(
  const vtkHighOrderTetraSetup& setup, const std::vector<vtkIdType>& backToFront,
  const hov::TransferFunction& tf, const Settings& settings, std::vector<float>& vertices) const
{
  const vtkIdType numCells = static_cast<vtkIdType>(backToFront.size());
  const vtkIdType numChunks = (numCells + CellsPerChunk - 1) / CellsPerChunk;
  std::vector<std::vector<float>> buffers(numChunks);
  std::vector<Statistics> stats(numChunks);
  const std::vector<vtkHighOrderTetraSetup::Tetra>& tetras = setup.GetTetras();
  const vtkIdType numTetras = static_cast<vtkIdType>(tetras.size());
  const vtkHighOrderGeneralCells& general = setup.GetGeneralCells();
  const vtkIdType numGeneral = static_cast<vtkIdType>(general.GetCells().size());
  const bool wvg = settings.Emission == hov::EmissionModel::WilhelmsVanGelder;

  Poly::Frame frame;
  frame.Composite = settings.Composite;
  frame.Inverse = glm::inverse(settings.Composite);
  frame.Table = &this->ColorTable;
  frame.Tf = &tf;
  frame.Method = settings.Method;
  frame.Emission = settings.Emission;
  frame.Parallel = settings.Parallel;
  frame.Eye = settings.Eye;

  vtkSMPTools::For(0, numChunks, [&](vtkIdType first, vtkIdType last) {
    SlabOrder order;
    Poly poly;
    for (vtkIdType chunk = first; chunk < last; ++chunk)
    {
      std::vector<float>& out = buffers[chunk];
      Statistics& st = stats[chunk];
      const vtkIdType end = std::min(numCells, (chunk + 1) * CellsPerChunk);
      for (vtkIdType i = chunk * CellsPerChunk; i < end; ++i)
      {
        const vtkIdType cell = backToFront[i];
        ++st.Cells;
        if (cell < 0 || cell >= numTetras + numGeneral)
        {
          continue;
        }
        const bool ok = cell < numTetras
          ? poly.SetTetra(tetras[cell], setup.GetPoints(), frame)
          : poly.SetGeneral(general, general.GetCells()[cell - numTetras], frame);
        if (!ok)
        {
          ++st.BehindEye;
          continue;
        }
        const int direction = settings.Parallel ? poly.LevelDirection(settings.Direction) : 0;
        order.Build(tf, poly.GetScalarMin(), poly.GetScalarMax(), wvg, poly.EyeLevel(settings.Eye),
          direction);
        if (cell >= numTetras && order.Keys.size() > 1)
        {
          ++st.CutGeneral; // cut by levels (approximate caps)
        }
        for (const auto& key : order.Keys)
        {
          ++st.Slabs;
          st.Triangles += poly.EmitSlab(key.second, frame, out);
        }
      }
    }
  });

  Statistics total;
  std::vector<size_t> offsets(numChunks + 1, 0);
  for (vtkIdType c = 0; c < numChunks; ++c)
  {
    offsets[c + 1] = offsets[c] + buffers[c].size();
    total.Cells += stats[c].Cells;
    total.Slabs += stats[c].Slabs;
    total.Triangles += stats[c].Triangles;
    total.BehindEye += stats[c].BehindEye;
    total.CutGeneral += stats[c].CutGeneral;
  }
  vertices.resize(offsets[numChunks]);
  vtkSMPTools::For(0, numChunks, [&](vtkIdType first, vtkIdType last) {
    for (vtkIdType c = first; c < last; ++c)
    {
      if (!buffers[c].empty())
      {
        std::memcpy(vertices.data() + offsets[c], buffers[c].data(), buffers[c].size() * sizeof(float));
      }
    }
  });
  return total;
}

void vtkHighOrderProjectionRegions::CentroidOrder(const vtkHighOrderTetraSetup& setup,
  const Settings& settings, std::vector<vtkIdType>& backToFront)
{
  const std::vector<vtkHighOrderTetraSetup::Tetra>& tetras = setup.GetTetras();
  const auto& general = setup.GetGeneralCells();
  const vtkIdType numTetras = static_cast<vtkIdType>(tetras.size());
  const vtkIdType n = setup.GetNumberOfRenderedCells();
  std::vector<double> key(n);
  const std::vector<glm::dvec3>& points = setup.GetPoints();
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
      key[i] = settings.Parallel ? glm::dot(c, settings.Direction) : glm::dot(d, d);
    }
  });
  backToFront.resize(n);
  std::iota(backToFront.begin(), backToFront.end(), vtkIdType(0));
  std::sort(backToFront.begin(), backToFront.end(),
    [&key](vtkIdType a, vtkIdType b) { return key[a] > key[b] || (key[a] == key[b] && a < b); });
}
