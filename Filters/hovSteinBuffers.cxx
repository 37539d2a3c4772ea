// Huge-page advice for the Stein sort's large buffers (see hovSteinBuffers.h).
#include "hovSteinBuffers.h"

#include <cstdint> // std::uintptr_t
#include <fstream> // the kernel's huge-page mode
#include <string>

#if defined(__linux__)
#include <sys/mman.h> // madvise
#include <unistd.h>   // sysconf
#endif

namespace hovStein
{
#if defined(__linux__) && defined(MADV_HUGEPAGE) && defined(MADV_NOHUGEPAGE)
namespace
{
/// madvise(@p advice) on the whole pages inside [@p p, @p p + @p bytes): the
/// first and last may be shared with other allocations (malloc's header, a
/// neighbour) and keep their advice. Advice only: where the kernel has no
/// huge pages to give, the block keeps its small pages, as without the call.
void AdviseWholePages(void* p, std::size_t bytes, int advice)
{
  static const long pageSize = sysconf(_SC_PAGESIZE);
  if (pageSize <= 0)
  {
    return;
  }
  const std::uintptr_t page = static_cast<std::uintptr_t>(pageSize);
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + page - 1) & ~(page - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(page - 1);
  if (end > begin)
  {
    (void)madvise(reinterpret_cast<void*>(begin), end - begin, advice);
  }
}
}

bool HugePagesOnlyWhereAdvised()
{
  static const bool advisedOnly = []
  {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    return std::getline(in, line) && line.find("[madvise]") != std::string::npos;
  }();
  return advisedOnly;
}

void AdviseHugePages(void* p, std::size_t bytes)
{
  if (bytes >= LargeBufferBytes || (bytes >= HeapBufferBytes && HugePagesOnlyWhereAdvised()))
  {
    AdviseWholePages(p, bytes, MADV_HUGEPAGE);
  }
}

void WithdrawHugePageAdvice(void* p, std::size_t bytes)
{
  // In "madvise" mode memory advised MADV_NOHUGEPAGE is treated as memory
  // never advised (no huge pages, khugepaged leaves it alone). Also for
  // blocks of LargeBufferBytes or more: malloc may have taken one from its
  // heap, and for a block with a mapping of its own the call only precedes
  // its unmapping.
  if (bytes >= HeapBufferBytes && HugePagesOnlyWhereAdvised())
  {
    AdviseWholePages(p, bytes, MADV_NOHUGEPAGE);
  }
}
#else
bool HugePagesOnlyWhereAdvised()
{
  return false;
}

void AdviseHugePages(void*, std::size_t) {}

void WithdrawHugePageAdvice(void*, std::size_t) {}
#endif
}
