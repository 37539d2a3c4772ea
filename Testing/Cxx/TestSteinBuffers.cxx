// The Stein sort's FillBuffer (hovSteinBuffers.h): a block of LargeBufferBytes
// or more is advised for transparent huge pages (on Linux: the "hg" flag of
// the memory it lies in, /proc/self/smaps), from its first whole page to its
// last, but not the pages holding its first and last bytes when it shares
// them (malloc's header). In the kernel's "madvise" mode a block from
// HeapBufferBytes on is advised too, and once freed its pages (kept in
// malloc's heap here, where mallopt allows) carry "nh" instead of "hg", but
// the page it shares does not; in the other modes it is not advised. A block
// below HeapBufferBytes never is. The advice changes no element: buffers
// filled, grown (resize keeps the old elements) and refilled (Refill keeps
// none) hold what was written. The checks that a page is not advised are
// skipped where plain std::allocator memory is.
#include "hovSteinBuffers.h"
#include "hovTestScenes.h"

#include <cstdint>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#if defined(__linux__)
#include <unistd.h> // sysconf
#endif
#if defined(__GLIBC__)
#include <malloc.h> // mallopt: keep a freed block in the heap
#endif

using namespace hovTest;

namespace
{
/// The VmFlags of the mapping holding @p p, with a space at both ends ("" if
/// not found, or no VmFlags line: not Linux, or an old kernel).
std::string FlagsAt(const void* p)
{
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line))
  {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-')
    {
      inside = lo <= at && at < hi; // a mapping's first line
    }
    else if (inside && line.compare(0, 8, "VmFlags:") == 0)
    {
      return line.substr(8) + " ";
    }
  }
  return "";
}

bool HugeAdvised(const void* p)
{
  return FlagsAt(p).find(" hg ") != std::string::npos;
}
}

int TestSteinBuffers(int, char*[])
{
  Checker ck;
  using hovStein::FillBuffer;
  constexpr std::size_t threshold = hovStein::LargeBufferBytes;
  constexpr std::size_t heapThreshold = hovStein::HeapBufferBytes;
  // Below both thresholds, allocated first (a fresh process: malloc maps it
  // on its own, so no neighbour's advice can reach it).
  FillBuffer<char> small(heapThreshold / 2);
  // The same size from plain std::allocator: if the environment advises it
  // (a malloc tuned for huge pages), the negative check means nothing.
  std::vector<char> control(heapThreshold / 2);
  // Between the thresholds, also mapped on its own.
  FillBuffer<char> middle(2 * heapThreshold);

  // Elements written and read back; the advice must not change any.
  const std::size_t n = 5 * threshold / 4 / sizeof(double);
  FillBuffer<double> large;
  large.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    large[i] = 0.5 * static_cast<double>(i);
  }
  large.resize(2 * n); // grows: the old elements are moved to the new block
  bool kept = true;
  for (std::size_t i = 0; i < n; ++i)
  {
    kept = kept && large[i] == 0.5 * static_cast<double>(i);
  }
  ck.Check(kept, "a grown buffer keeps its elements");
  hovStein::Refill(large, 3 * n);
  for (std::size_t i = 0; i < 3 * n; ++i)
  {
    large[i] = static_cast<double>(3 * n - i);
  }
  bool written = true;
  for (std::size_t i = 0; i < 3 * n; ++i)
  {
    written = written && large[i] == static_cast<double>(3 * n - i);
  }
  ck.Check(written, "a refilled buffer holds what was written");

#if defined(__linux__)
  std::ifstream thp("/sys/kernel/mm/transparent_hugepage/enabled");
  if (!thp || FlagsAt(&ck).empty())
  {
    std::cout << "No transparent huge pages or no VmFlags here: advice not checked.\n";
    return ck.Result();
  }
  // Memory from plain std::allocator advised already (a malloc tuned for huge
  // pages advises whole mappings): then only the positive checks mean something.
  const bool environmentAdvises = HugeAdvised(control.data() + control.size() / 2);
  if (environmentAdvises)
  {
    std::cout << "Memory from std::allocator is advised here already: the pages that must "
                 "keep their own advice are not checked.\n";
  }
  const std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const auto first = reinterpret_cast<std::uintptr_t>(large.data());
  const std::uintptr_t last = first + large.capacity() * sizeof(double) - 1; // the block's
  ck.Check(HugeAdvised(large.data() + large.size() / 2),
    "a " + std::to_string(large.capacity() * sizeof(double) >> 20) +
      " MiB buffer lies in memory advised for huge pages");
  ck.Check(HugeAdvised(reinterpret_cast<const void*>((first + page - 1) & ~(page - 1))),
    "the buffer's first whole page is advised");
  ck.Check(HugeAdvised(reinterpret_cast<const void*>(((last + 1) & ~(page - 1)) - page)),
    "the buffer's last whole page is advised");
  // The pages holding the block's first and last bytes, unless it covers them
  // whole, are shared (malloc's header, a neighbour) and keep their advice.
  if (!environmentAdvises && first % page != 0)
  {
    ck.Check(!HugeAdvised(large.data()), "the page holding the buffer's first byte is not advised");
  }
  if (!environmentAdvises && (last + 1) % page != 0)
  {
    ck.Check(!HugeAdvised(reinterpret_cast<const void*>(last)),
      "the page holding the buffer's last byte is not advised");
  }
  FillBuffer<std::uint8_t> exact(threshold);
  ck.Check(HugeAdvised(exact.data() + exact.size() / 2),
    "a buffer of exactly LargeBufferBytes is advised for huge pages");
  if (!environmentAdvises)
  {
    const std::string flags = FlagsAt(small.data() + small.size() / 2);
    ck.Check(!flags.empty() && flags.find(" hg ") == std::string::npos,
      "a " + std::to_string(small.size() >> 20) +
        " MiB buffer is not advised for huge pages (VmFlags:" + flags + ")");
  }
  const bool advisedOnly = hovStein::HugePagesOnlyWhereAdvised();
  std::cout << "Huge pages only where advised (\"madvise\" mode): " << (advisedOnly ? "yes" : "no")
            << "\n";
  if (!advisedOnly)
  {
    if (!environmentAdvises)
    {
      ck.Check(!HugeAdvised(middle.data() + middle.size() / 2),
        "outside \"madvise\" mode a " + std::to_string(middle.size() >> 20) +
          " MiB buffer is not advised");
    }
    return ck.Result();
  }
  ck.Check(HugeAdvised(middle.data() + middle.size() / 2),
    "in \"madvise\" mode a " + std::to_string(middle.size() >> 20) +
      " MiB buffer is advised for huge pages");
  FillBuffer<std::uint8_t> atHeapThreshold(heapThreshold);
  ck.Check(HugeAdvised(atHeapThreshold.data() + heapThreshold / 2),
    "in \"madvise\" mode a buffer of exactly HeapBufferBytes is advised");
#if defined(__GLIBC__)
  // A block in malloc's heap: from here on no block below 32 MiB gets a
  // mapping of its own (a value every 64-bit glibc accepts). A later
  // allocation above it keeps it off the heap's top, so freeing it returns
  // nothing to the system: its pages stay mapped, with the advice withdrawn.
  if (mallopt(M_MMAP_THRESHOLD, static_cast<int>(threshold)) != 1)
  {
    std::cout << "mallopt refused the threshold (e.g. under a sanitizer): withdrawal not "
                 "checked.\n";
    return ck.Result();
  }
  auto heapBlock = std::make_unique<FillBuffer<char>>(3 * heapThreshold);
  std::vector<char> later(heapThreshold / 4);
  const auto heapFirst = reinterpret_cast<std::uintptr_t>(heapBlock->data());
  const std::uintptr_t heapEnd = heapFirst + heapBlock->size();
  const std::uintptr_t mid = (heapFirst + heapBlock->size() / 2) & ~(page - 1);
  const bool below = heapEnd <= reinterpret_cast<std::uintptr_t>(later.data());
  ck.Check(HugeAdvised(reinterpret_cast<const void*>(mid)),
    "a " + std::to_string(heapBlock->size() >> 20) + " MiB buffer in malloc's heap is advised");
  heapBlock.reset(); // freed: malloc keeps the block, the pages stay mapped
  const std::string flags = FlagsAt(reinterpret_cast<const void*>(mid));
  if (!below || flags.empty())
  {
    std::cout << "The freed block " << (below ? "was unmapped" : "lies above the later allocation")
              << ": withdrawal not checked.\n";
    return ck.Result();
  }
  ck.Check(flags.find(" hg ") == std::string::npos && flags.find(" nh ") != std::string::npos,
    "a freed buffer's pages are no longer advised (VmFlags:" + flags + ")");
  if (heapFirst % page != 0)
  {
    ck.Check(FlagsAt(reinterpret_cast<const void*>(heapFirst)).find(" nh ") == std::string::npos,
      "the page holding the freed buffer's first byte keeps its flags");
  }
#endif
#endif
  return ck.Result();
}
