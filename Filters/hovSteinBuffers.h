/**
 * @file hovSteinBuffers.h
 * @brief Per-view buffers of the Stein sort that every step fills completely:
 *        std::vector whose resize() leaves trivial elements uninitialised
 *        and whose largest blocks ask for transparent huge pages; a prefetch
 *        hint for the steps that read them at random.
 *
 * A value-initialising resize() zeroes the new memory on one thread, touching
 * (and faulting in) every page before the parallel fill touches it again; on
 * the 2M-cell heatsink, whose re-sorts allocate their buffers anew, that cost
 * more than the fill. With this allocator the first touch is the fill's, on
 * all threads. Only for element types with a trivial default constructor
 * whose every element the caller writes before reading.
 *
 * A block of LargeBufferBytes or more is also advised for transparent huge
 * pages (AdviseHugePages): one fault per 2 MiB instead of 512, and fewer TLB
 * misses where a step reads at random (measured in the README). glibc
 * normally gives a block of that size a mapping of its own, so the advice
 * ends with the block instead of staying on memory malloc hands out later.
 * Where the kernel gives huge pages only to advised memory ("madvise" mode),
 * blocks from HeapBufferBytes on are advised too, and every advised block
 * has the advice withdrawn when it is freed (WithdrawHugePageAdvice): one that
 * lies in malloc's heap does not pass it on to memory malloc hands out later.
 * (Huge pages already backing such memory stay until it is unmapped; the mode
 * is read once per process; kernels whose per-size settings give smaller huge
 * pages to all memory in "madvise" mode do not give them to withdrawn ranges.)
 */
#ifndef hovSteinBuffers_h
#define hovSteinBuffers_h

#include <cstddef>     // std::size_t
#include <memory>      // std::allocator, std::allocator_traits
#include <new>         // placement new
#include <type_traits> // std::is_trivially_default_constructible
#include <utility>     // std::forward
#include <vector>

namespace hovStein
{
/**
 * Blocks from this size on are advised for transparent huge pages: glibc's
 * largest threshold for giving a block a mapping of its own (its threshold
 * rises towards it as mapped blocks are freed, never above it).
 */
constexpr std::size_t LargeBufferBytes = std::size_t(32) << 20;

/**
 * If @p bytes >= LargeBufferBytes (or >= HeapBufferBytes where
 * HugePagesOnlyWhereAdvised()), asks the kernel to back the whole pages of
 * [@p p, @p p + @p bytes) with transparent huge pages where it can (Linux:
 * madvise MADV_HUGEPAGE; nothing elsewhere, or where the kernel refuses).
 * The pages holding the block's first and last bytes are left as they are
 * unless the block covers them whole. Contents are unchanged. For allocators:
 * the block must pass through WithdrawHugePageAdvice() before it is freed.
 */
void AdviseHugePages(void* p, std::size_t bytes);

/**
 * Where huge pages go only to advised memory (HugePagesOnlyWhereAdvised()),
 * blocks from this size on are advised as well, and every advised block has
 * its advice withdrawn when it is freed.
 */
constexpr std::size_t HeapBufferBytes = std::size_t(4) << 20;

/// True if the kernel's transparent huge pages are in "madvise" mode (Linux:
/// /sys/kernel/mm/transparent_hugepage/enabled; read once). False elsewhere.
bool HugePagesOnlyWhereAdvised();

/**
 * Before a block of [@p p, @p p + @p bytes) that AdviseHugePages() saw is
 * freed: if @p bytes >= HeapBufferBytes and HugePagesOnlyWhereAdvised(),
 * marks its whole pages MADV_NOHUGEPAGE, which in that mode is how memory
 * never advised behaves, so the advice does not stay on heap memory that
 * malloc hands out later. Nothing otherwise.
 */
void WithdrawHugePageAdvice(void* p, std::size_t bytes);

/// std::allocator that default-initialises (no zeroing) on resize(), advises
/// large blocks for huge pages, and withdraws the advice where it must.
template <class T>
struct DefaultInitAllocator : std::allocator<T>
{
  static_assert(std::is_trivially_default_constructible<T>::value,
    "only for elements that may stay uninitialised");
  using std::allocator<T>::allocator;
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept
  {
  }
  template <class U>
  struct rebind
  {
    using other = DefaultInitAllocator<U>;
  };
  [[nodiscard]] T* allocate(std::size_t n)
  {
    T* p = std::allocator<T>::allocate(n); // n * sizeof(T) fits: it succeeded
    AdviseHugePages(p, n * sizeof(T));
    return p;
  }
  void deallocate(T* p, std::size_t n)
  {
    WithdrawHugePageAdvice(p, n * sizeof(T));
    std::allocator<T>::deallocate(p, n);
  }
  template <class U>
  void construct(U* p) noexcept
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// A hint to fetch the cache line of @p p (no effect where unsupported).
inline void Prefetch(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

/// A vector filled completely by its user after each resize().
template <class T>
using FillBuffer = std::vector<T, DefaultInitAllocator<T>>;

/**
 * Sizes @p buffer to @p n elements whose old values are not needed: when it
 * must grow, the old storage is freed first (nothing is copied, no two
 * copies at once) and 1/8 more is reserved for the next views.
 */
template <class T>
void Refill(FillBuffer<T>& buffer, size_t n)
{
  if (n > buffer.capacity())
  {
    FillBuffer<T>().swap(buffer);
    buffer.reserve(n + n / 8);
  }
  buffer.resize(n);
}
}

#endif
