// The Stein sort's FillBuffer (hovSteinBuffers.h): a block of LargeBufferBytes
// or more is advised for transparent huge pages (on Linux: the "hg" flag of
// the memory it lies in, /proc/self/smaps), a smaller one is left alone when
// it is a mapping of its own, and the advice changes no element: buffers
// filled, grown (Refill keeps nothing, resize keeps the old elements) and
// read back hold what was written.
#include "hovSteinBuffers.h"
#include "hovTestScenes.h"

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

using namespace hovTest;

namespace
{
/// The VmFlags of the mapping holding @p p ("" if not found or not Linux).
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
  // Below the threshold, allocated first: a fresh mapping of its own (larger
  // than malloc's initial mmap threshold of 128 KiB, which a process raises
  // only after freeing a mapped block).
  FillBuffer<char> small(hovStein::LargeBufferBytes / 2);
  // Elements written and read back; the advice must not change any.
  const size_t n = 3 * hovStein::LargeBufferBytes / sizeof(double); // 12 MiB
  FillBuffer<double> large;
  large.resize(n);
  for (size_t i = 0; i < n; ++i)
  {
    large[i] = 0.5 * static_cast<double>(i);
  }
  large.resize(2 * n); // grows: the old elements are moved to the new block
  bool kept = true;
  for (size_t i = 0; i < n; ++i)
  {
    kept = kept && large[i] == 0.5 * static_cast<double>(i);
  }
  ck.Check(kept, "a grown buffer keeps its elements");
  hovStein::Refill(large, 3 * n);
  for (size_t i = 0; i < 3 * n; ++i)
  {
    large[i] = static_cast<double>(3 * n - i);
  }
  bool written = true;
  for (size_t i = 0; i < 3 * n; ++i)
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
  // The middle of the block: its whole pages are advised.
  ck.Check(HugeAdvised(large.data() + large.size() / 2),
    "a " + std::to_string(large.size() * sizeof(double) >> 20) +
      " MiB buffer lies in memory advised for huge pages (VmFlags:" +
      FlagsAt(large.data() + large.size() / 2) + ")");
  FillBuffer<std::uint8_t> bytes(hovStein::LargeBufferBytes); // exactly the threshold
  ck.Check(HugeAdvised(bytes.data() + bytes.size() / 2),
    "a buffer of exactly LargeBufferBytes is advised for huge pages");
  const std::string flags = FlagsAt(small.data() + small.size() / 2);
  ck.Check(!flags.empty() && flags.find(" hg ") == std::string::npos,
    "a 2 MiB buffer is not advised for huge pages (VmFlags:" + flags + ")");
#endif
  return ck.Result();
}
