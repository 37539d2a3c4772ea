/**
 * @file hovSteinBuffers.h
 * @brief Per-view buffers of the Stein sort that every step fills completely:
 *        std::vector whose resize() leaves trivial elements uninitialised;
 *        a prefetch hint for the steps that read them at random.
 *
 * A value-initialising resize() zeroes the new memory on one thread, touching
 * (and faulting in) every page before the parallel fill touches it again; on
 * the 2M-cell heatsink, whose re-sorts allocate their buffers anew, that cost
 * more than the fill. With this allocator the first touch is the fill's, on
 * all threads. Only for element types with a trivial default constructor
 * whose every element the caller writes before reading.
 */
#ifndef hovSteinBuffers_h
#define hovSteinBuffers_h

#include <memory>      // std::allocator, std::allocator_traits
#include <new>         // placement new
#include <type_traits> // std::is_trivially_default_constructible
#include <utility>     // std::forward
#include <vector>

namespace hovStein
{
/// std::allocator that default-initialises (no zeroing) on resize().
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
