/**
 * @file hovSteinBuckets.h
 * @brief A counting sort in parallel for the Stein sort's set-up: items
 *        bucketed by integer keys (faces by point), in item order within
 *        each bucket whatever the number of threads; a running sum in parallel
 *        (CSR offsets) and parallel appends (lists per item, selections of indices).
 *
 * The items are cut into at most 4 blocks (2 per thread), each with its own
 * count per key: counting and scattering run in parallel, and the buckets
 * hold their items in increasing item order (the blocks are laid out block
 * after block inside each bucket). The counts take numBlocks times the keys.
 *
 * Thread safety: the callbacks run concurrently on disjoint item ranges.
 */
#ifndef hovSteinBuckets_h
#define hovSteinBuckets_h

#include "hovSteinBuffers.h" // FillBuffer

#include "vtkSMPTools.h"
#include "vtkType.h" // vtkIdType

#include <algorithm> // std::min, std::max
#include <vector>

namespace hovStein
{
/**
 * Running sum in place, in parallel over blocks: @p a has @p n + 1 entries,
 * a[0] the start and a[i + 1] the count of item i; afterwards a[i + 1] is
 * a[i] plus that count (offsets of a CSR). The same sums for every thread count.
 */
template <class T>
void ParallelRunningSum(T* a, vtkIdType n)
{
  constexpr vtkIdType MinBlock = 1 << 16;
  const vtkIdType threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  const vtkIdType numBlocks = std::max<vtkIdType>(1, std::min(n / MinBlock, 4 * threads));
  auto first = [&](vtkIdType block) { // (64-bit product: no overflow with 32-bit ids)
    return static_cast<vtkIdType>(static_cast<long long>(block) * n / numBlocks);
  };
  std::vector<T> base(numBlocks + 1, 0);
  base[0] = a[0];
  if (numBlocks > 1)
  {
    vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
      for (vtkIdType block = b0; block < b1; ++block)
      {
        T sum = 0;
        for (vtkIdType i = first(block); i < first(block + 1); ++i)
        {
          sum += a[i + 1];
        }
        base[block + 1] = sum;
      }
    });
  }
  for (vtkIdType block = 0; block + 1 < numBlocks; ++block)
  {
    base[block + 1] += base[block];
  }
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType block = b0; block < b1; ++block)
    {
      T sum = base[block];
      for (vtkIdType i = first(block); i < first(block + 1); ++i)
      {
        sum += a[i + 1];
        a[i + 1] = sum;
      }
    }
  });
}

/**
 * Appends to @p out, item after item for i in [0, @p n), the @p count(i)
 * elements that @p write(i, to) writes from @p to on (returning the end):
 * counted per block, then written, in parallel. Both are called once per i
 * and must agree.
 */
template <class Out, class Count, class Write>
void ParallelAppend(vtkIdType n, const Count& count, const Write& write, Out& out)
{
  constexpr vtkIdType Block = 16384;
  const vtkIdType numBlocks = (n + Block - 1) / Block;
  std::vector<vtkIdType> start(numBlocks + 1, 0);
  start[0] = static_cast<vtkIdType>(out.size());
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      vtkIdType total = 0;
      for (vtkIdType i = blk * Block; i < std::min(n, (blk + 1) * Block); ++i)
      {
        total += count(i);
      }
      start[blk + 1] = total;
    }
  });
  ParallelRunningSum(start.data(), numBlocks);
  out.resize(start[numBlocks]);
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      auto to = out.data() + start[blk];
      for (vtkIdType i = blk * Block; i < std::min(n, (blk + 1) * Block); ++i)
      {
        to = write(i, to);
      }
    }
  });
}

/**
 * Appends to @p out, in increasing order, every i in [0, @p n) with
 * @p keep(i) true, in parallel (ParallelAppend). keep(i) is called twice per
 * i and must give the same answer both times.
 */
template <class Keep>
void ParallelSelect(vtkIdType n, const Keep& keep, std::vector<vtkIdType>& out)
{
  ParallelAppend(
    n, [&keep](vtkIdType i) { return keep(i) ? 1 : 0; },
    [&keep](vtkIdType i, vtkIdType* to) {
      if (keep(i))
      {
        *to++ = i;
      }
      return to;
    },
    out);
}

/**
 * Buckets items [0, @p numItems) by keys in [0, @p numKeys): @p items(begin,
 * end, emit) calls emit(key, value) for each key of each item of [begin,
 * end), in item order, where value() makes the stored element (called only
 * when scattering). Bucket k is out[start[k], start[k + 1]).
 */
template <class T, class ItemsFn>
void ParallelBuckets(vtkIdType numItems, vtkIdType numKeys, const ItemsFn& items,
  std::vector<vtkIdType>& start, FillBuffer<T>& out)
{
  const vtkIdType threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  const vtkIdType numBlocks =
    std::max<vtkIdType>(1, std::min<vtkIdType>(std::min<vtkIdType>(numItems, 2 * threads), 4));
  auto first = [&](vtkIdType block) {
    return static_cast<vtkIdType>(static_cast<long long>(block) * numItems / numBlocks);
  };
  // count[block * numKeys + k]: the block's items in bucket k, then its cursor
  // there (each block zeroes and counts its own row).
  FillBuffer<vtkIdType> count(static_cast<size_t>(numBlocks) * numKeys);
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType block = b0; block < b1; ++block)
    {
      vtkIdType* mine = count.data() + block * numKeys;
      std::fill(mine, mine + numKeys, 0);
      items(first(block), first(block + 1), [mine](vtkIdType key, auto&&) { ++mine[key]; });
    }
  });
  // Bucket sizes, their running sum, then each block's cursor per bucket
  // (the blocks' items one after another within a bucket), in parallel over keys.
  start.resize(numKeys + 1);
  start[0] = 0;
  vtkSMPTools::For(0, numKeys, 16384, [&](vtkIdType k0, vtkIdType k1) {
    for (vtkIdType k = k0; k < k1; ++k)
    {
      vtkIdType size = 0;
      for (vtkIdType block = 0; block < numBlocks; ++block)
      {
        size += count[block * numKeys + k];
      }
      start[k + 1] = size;
    }
  });
  ParallelRunningSum(start.data(), numKeys);
  const vtkIdType total = start[numKeys];
  vtkSMPTools::For(0, numKeys, 16384, [&](vtkIdType k0, vtkIdType k1) {
    for (vtkIdType k = k0; k < k1; ++k)
    {
      vtkIdType at = start[k];
      for (vtkIdType block = 0; block < numBlocks; ++block)
      {
        const vtkIdType c = count[block * numKeys + k];
        count[block * numKeys + k] = at;
        at += c;
      }
    }
  });
  out.resize(total);
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType block = b0; block < b1; ++block)
    {
      vtkIdType* cursor = count.data() + block * numKeys;
      items(first(block), first(block + 1),
        [cursor, &out](vtkIdType key, auto&& value) { out[cursor[key]++] = value(); });
    }
  });
}
}

#endif
