// Huge-page advice for the Stein sort's large buffers (see hovSteinBuffers.h).
#include "hovSteinBuffers.h"

#include <cstdint> // std::uintptr_t

#if defined(__linux__)
#include <sys/mman.h> // madvise
#include <unistd.h>   // sysconf
#endif

namespace hovStein
{
void AdviseHugePages(void* p, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  static const long pageSize = sysconf(_SC_PAGESIZE);
  if (bytes < LargeBufferBytes || pageSize <= 0)
  {
    return;
  }
  // The whole pages inside the block: the first and last may be shared with
  // other allocations (malloc's header, a neighbour) and keep their advice.
  const std::uintptr_t page = static_cast<std::uintptr_t>(pageSize);
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + page - 1) & ~(page - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(page - 1);
  if (end > begin)
  {
    // Advice only: if the kernel has no huge pages to give, the block keeps
    // its small pages, as without the call.
    (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  }
#else
  (void)p;
  (void)bytes;
#endif
}
}
