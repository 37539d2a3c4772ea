// The Stein sort's FillBuffer (hovSteinBuffers.h): a block of LargeBufferBytes
// or more is advised for transparent huge pages (on Linux: the "hg" flag of
// the memory it lies in, /proc/self/smaps) except the page holding its first
// byte, which malloc's header shares; a smaller block is not advised; and the
// advice changes no element: buffers filled, grown (resize keeps the old
// elements) and refilled (Refill keeps none) hold what was written.
#include "hovSteinBuffers.h"
#include "hovTestScenes.h"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#if defined(__linux__)
#include <unistd.h> // sysconf
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
  // Below the threshold, allocated first (a fresh process: malloc maps it on
  // its own, so no neighbour's advice can reach it).
  FillBuffer<char> small(threshold / 2);
  // The same size from plain std::allocator: if the environment advises it
  // (a malloc tuned for huge pages), the negative check means nothing.
  std::vector<char> control(threshold / 2);

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
  const double* middle = large.data() + large.size() / 2;
  ck.Check(HugeAdvised(middle),
    "a " + std::to_string(large.size() * sizeof(double) >> 20) +
      " MiB buffer lies in memory advised for huge pages (VmFlags:" + FlagsAt(middle) + ")");
  // malloc's header precedes the block on its first page: that page is not
  // the block's alone and keeps its own advice.
  if (reinterpret_cast<std::uintptr_t>(large.data()) %
      static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE)) !=
    0)
  {
    ck.Check(!HugeAdvised(large.data()),
      "the page holding the buffer's first byte (shared with malloc's header) is not advised");
  }
  FillBuffer<std::uint8_t> exact(threshold);
  ck.Check(HugeAdvised(exact.data() + exact.size() / 2),
    "a buffer of exactly LargeBufferBytes is advised for huge pages");
  if (HugeAdvised(control.data() + control.size() / 2))
  {
    std::cout << "Memory from std::allocator is advised here already: the smaller buffer's "
                 "absence of advice is not checked.\n";
  }
  else
  {
    const std::string flags = FlagsAt(small.data() + small.size() / 2);
    ck.Check(!flags.empty() && flags.find(" hg ") == std::string::npos,
      "a " + std::to_string(small.size() >> 20) +
        " MiB buffer is not advised for huge pages (VmFlags:" + flags + ")");
  }
#endif
  return ck.Result();
}
