// Topological sort with cycle fallback of vtkSteinVisibilitySort (see hovSteinGraph.h).
#include "hovSteinGraph.h"

#include <algorithm>
#include <cstdint>

namespace hovStein
{
namespace
{
/**
 * Strongly connected components of the nodes with !done (iterative Tarjan,
 * roots in the order of @p rough). Components are appended to @p comps /
 * @p compStart in emission order, i.e. reverse topological order.
 */
void Tarjan(const Digraph& d, const std::vector<vtkIdType>& rough,
  const std::vector<std::uint8_t>& done, std::vector<vtkIdType>& comps,
  std::vector<vtkIdType>& compStart)
{
  const vtkIdType n = static_cast<vtkIdType>(d.Offsets.size()) - 1;
  std::vector<vtkIdType> index(n, -1), low(n, 0);
  std::vector<std::uint8_t> onStack(n, 0);
  std::vector<vtkIdType> stack;
  std::vector<std::pair<vtkIdType, vtkIdType>> calls; // node, next edge
  vtkIdType counter = 0;
  for (vtkIdType root : rough)
  {
    if (done[root] || index[root] >= 0)
    {
      continue;
    }
    index[root] = low[root] = counter++;
    stack.push_back(root);
    onStack[root] = 1;
    calls.emplace_back(root, d.Offsets[root]);
    while (!calls.empty())
    {
      const vtkIdType v = calls.back().first;
      const vtkIdType it = calls.back().second;
      if (it < d.Offsets[v + 1])
      {
        calls.back().second = it + 1;
        const vtkIdType w = d.Targets[it];
        if (done[w])
        {
          continue;
        }
        if (index[w] < 0)
        {
          index[w] = low[w] = counter++;
          stack.push_back(w);
          onStack[w] = 1;
          calls.emplace_back(w, d.Offsets[w]);
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

void TopologicalOrder(const Digraph& d, const std::vector<vtkIdType>& rough,
  const std::vector<double>& rear, std::vector<vtkIdType>& order, GraphStats& stats)
{
  const vtkIdType n = static_cast<vtkIdType>(d.Offsets.size()) - 1;
  // Back to front by rearmost depth, ties by id.
  auto behind = [&](vtkIdType a, vtkIdType b) { return rear[a] > rear[b] || (rear[a] == rear[b] && a < b); };
  std::vector<std::int32_t> indeg(n, 0);
  for (vtkIdType t : d.Targets)
  {
    ++indeg[t];
  }
  std::vector<vtkIdType> queue;
  queue.reserve(rough.size());
  for (vtkIdType c : rough)
  {
    if (indeg[c] == 0)
    {
      queue.push_back(c);
    }
  }
  std::sort(queue.begin(), queue.end(), behind);
  for (size_t head = 0; head < queue.size(); ++head)
  {
    const vtkIdType u = queue[head];
    for (vtkIdType e = d.Offsets[u]; e < d.Offsets[u + 1]; ++e)
    {
      if (--indeg[d.Targets[e]] == 0)
      {
        queue.push_back(d.Targets[e]);
      }
    }
  }
  order.insert(order.end(), queue.begin(), queue.end());
  if (queue.size() == rough.size())
  {
    return;
  }
  // Kahn stalled: the rest contains cycles. Output the strongly connected
  // components in topological order of the condensation, each by rearmost depth.
  std::vector<std::uint8_t> done(n, 1);
  for (vtkIdType c : rough)
  {
    done[c] = 0;
  }
  for (vtkIdType c : queue)
  {
    done[c] = 1;
  }
  std::vector<vtkIdType> comps, compStart;
  Tarjan(d, rough, done, comps, compStart);
  for (size_t k = compStart.size() - 1; k-- > 0;)
  {
    auto first = comps.begin() + compStart[k], last = comps.begin() + compStart[k + 1];
    std::sort(first, last, behind);
    order.insert(order.end(), first, last);
    if (last - first > 1)
    {
      ++stats.Cycles;
      stats.CycleCells.insert(stats.CycleCells.end(), first, last);
    }
  }
}
}
