// Topological sort with cycle fallback of vtkSteinVisibilitySort (see hovSteinGraph.h).
#include "hovSteinGraph.h"

#include "hovSteinBuckets.h" // ParallelSelect
#include "hovSteinBuffers.h" // Prefetch

#include <algorithm>
#include <cstdint>

namespace hovStein
{
namespace
{
/// Cells [first, last) back to front by rearmost depth, ties by id.
void SortBackToFront(const Geometry& g, const View& v, vtkIdType* first, vtkIdType* last)
{
  std::vector<std::pair<double, vtkIdType>> keyed(last - first);
  for (vtkIdType* c = first; c != last; ++c)
  {
    keyed[c - first] = { v.RearDepth(g, *c), *c };
  }
  std::sort(keyed.begin(), keyed.end(), [](const std::pair<double, vtkIdType>& a,
                                          const std::pair<double, vtkIdType>& b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  for (vtkIdType* c = first; c != last; ++c)
  {
    *c = keyed[c - first].second;
  }
}

/**
 * Kahn's algorithm: @p queue holds the @p tail sources and has room for every
 * cell of the DAG plus one; appends each cell whose in-degree drops to zero (FIFO) and
 * returns the final tail. The push is branch-free (whether a count reaches
 * zero is a coin flip), and the queue, known ahead, drives prefetches (the
 * loop is otherwise bound by cache misses on cells scattered through memory).
 */
vtkIdType Kahn(Digraph& d, vtkIdType* queue, vtkIdType tail)
{
  std::int32_t* indeg = d.InDegree.data();
  const vtkIdType* offsets = d.FaceOffsets;
  const std::uint8_t* counts = d.FaceCount.data();
  const CellIndex* targets = d.FaceTargets.data();
  const vtkIdType* extraOffsets = d.ExtraOffsets.data();
  const vtkIdType* extraTargets = d.ExtraTargets.data();
  for (vtkIdType head = 0; head < tail; ++head)
  {
    // Edge offsets 16 places on, edges 8 places on, target in-degrees 4 places on.
    if (head + 16 < tail)
    {
      Prefetch(offsets + queue[head + 16]);
      Prefetch(counts + queue[head + 16]);
      Prefetch(extraOffsets + queue[head + 16]);
    }
    if (head + 8 < tail)
    {
      Prefetch(targets + offsets[queue[head + 8]]);
      Prefetch(extraTargets + extraOffsets[queue[head + 8]]);
    }
    if (head + 4 < tail)
    {
      const vtkIdType w = queue[head + 4];
      for (int k = 0; k < counts[w]; ++k)
      {
        Prefetch(indeg + targets[offsets[w] + k]);
      }
      for (vtkIdType e = extraOffsets[w]; e < extraOffsets[w + 1]; ++e)
      {
        Prefetch(indeg + extraTargets[e]);
      }
    }
    const vtkIdType u = queue[head];
    const CellIndex* t = targets + offsets[u];
    for (const CellIndex* last = t + counts[u]; t != last; ++t)
    {
      queue[tail] = *t; // kept only if its count drops to zero
      tail += --indeg[*t] == 0;
    }
    for (vtkIdType e = extraOffsets[u]; e < extraOffsets[u + 1]; ++e)
    {
      queue[tail] = extraTargets[e];
      tail += --indeg[extraTargets[e]] == 0;
    }
  }
  return tail;
}

/**
 * Strongly connected components of the nodes with !done (iterative Tarjan,
 * roots by increasing id). Components are appended to @p comps /
 * @p compStart in emission order, i.e. reverse topological order.
 */
void Tarjan(const Digraph& d, const std::vector<std::uint8_t>& done, std::vector<vtkIdType>& comps,
  std::vector<vtkIdType>& compStart)
{
  const vtkIdType n = static_cast<vtkIdType>(done.size());
  std::vector<vtkIdType> index(n, -1), low(n, 0);
  std::vector<std::uint8_t> onStack(n, 0);
  std::vector<vtkIdType> stack;
  std::vector<std::pair<vtkIdType, vtkIdType>> calls; // node, next edge
  vtkIdType counter = 0;
  for (vtkIdType root = 0; root < n; ++root)
  {
    if (done[root] || index[root] >= 0)
    {
      continue;
    }
    index[root] = low[root] = counter++;
    stack.push_back(root);
    onStack[root] = 1;
    calls.emplace_back(root, 0);
    while (!calls.empty())
    {
      const vtkIdType v = calls.back().first;
      const vtkIdType it = calls.back().second;
      if (it < d.Degree(v))
      {
        calls.back().second = it + 1;
        const vtkIdType w = d.Target(v, it);
        if (done[w])
        {
          continue;
        }
        if (index[w] < 0)
        {
          index[w] = low[w] = counter++;
          stack.push_back(w);
          onStack[w] = 1;
          calls.emplace_back(w, 0);
        }
        else if (onStack[w])
        {
          low[v] = std::min(low[v], index[w]);
        }
        continue;
      }
      calls.pop_back();
      if (!calls.empty())
      {
        const vtkIdType parent = calls.back().first;
        low[parent] = std::min(low[parent], low[v]);
      }
      if (low[v] == index[v])
      {
        compStart.push_back(static_cast<vtkIdType>(comps.size()));
        vtkIdType w;
        do
        {
          w = stack.back();
          stack.pop_back();
          onStack[w] = 0;
          comps.push_back(w);
        } while (w != v);
      }
    }
  }
  compStart.push_back(static_cast<vtkIdType>(comps.size()));
}
}

void TopologicalOrder(Digraph& d, const Geometry& g, const View& v, vtkIdType numOrdered,
  std::vector<vtkIdType>& order, GraphStats& stats)
{
  const vtkIdType n = static_cast<vtkIdType>(d.FaceCount.size());
  // Kahn's algorithm with @p order itself as the FIFO queue.
  const size_t start = order.size();
  ParallelSelect(
    n, [&d, &v](vtkIdType c) { return d.InDegree[c] == 0 && Ordered(v, c); }, order);
  SortBackToFront(g, v, order.data() + start, order.data() + order.size());
  const vtkIdType sources = static_cast<vtkIdType>(order.size() - start);
  order.resize(start + numOrdered + 1); // + 1: Kahn's branch-free push writes one past
  const vtkIdType numDone = Kahn(d, order.data() + start, sources);
  order.resize(start + numDone);
  if (numDone == numOrdered)
  {
    return;
  }
  // Kahn stalled: the rest contains cycles. Output the strongly connected
  // components in topological order of the condensation, each by rearmost depth.
  std::vector<std::uint8_t> done(n, 1);
  for (vtkIdType c = 0; c < n; ++c)
  {
    done[c] = !Ordered(v, c);
  }
  for (size_t k = start; k < order.size(); ++k)
  {
    done[order[k]] = 1;
  }
  std::vector<vtkIdType> comps, compStart;
  Tarjan(d, done, comps, compStart);
  for (size_t k = compStart.size() - 1; k-- > 0;)
  {
    auto first = comps.begin() + compStart[k], last = comps.begin() + compStart[k + 1];
    SortBackToFront(g, v, comps.data() + compStart[k], comps.data() + compStart[k + 1]);
    order.insert(order.end(), first, last);
    if (last - first > 1)
    {
      ++stats.Cycles;
      stats.CycleCells.insert(stats.CycleCells.end(), first, last);
    }
  }
}
}
