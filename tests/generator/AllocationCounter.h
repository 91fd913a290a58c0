#pragma once
// Counts heap allocations (operator new and malloc) made by this thread while counting is on.
// Include in exactly one translation unit per executable: it replaces the global allocators or,
// under AddressSanitizer (which owns malloc), installs the sanitizer's allocation hook instead.

#include <cstdlib>
#include <new>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RBDGEN_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define RBDGEN_TEST_ASAN 1
#endif

#if defined(RBDGEN_TEST_ASAN)
// The sanitizer runtime's hook (declared here: g++ ships no <sanitizer/allocator_interface.h>).
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void *, std::size_t),
                                                         void (*free_hook)(const volatile void *));
#else
extern "C" void * __libc_malloc(std::size_t size); // glibc's own malloc, for the interposed one
extern "C" void __libc_free(void * p);
#endif

namespace rbdgentest
{
inline thread_local bool countAllocations = false;
inline thread_local long allocationCount = 0;

/// RAII: count allocations in a scope; `count()` reads the number so far.
struct AllocationScope
{
  AllocationScope()
  {
    allocationCount = 0;
    countAllocations = true;
  }
  ~AllocationScope() { countAllocations = false; }
  long count() const { return allocationCount; }
};
} // namespace rbdgentest

#if defined(RBDGEN_TEST_ASAN)
// Every allocation (malloc, new) goes through the sanitizer's allocator, which calls this hook.
namespace rbdgentest
{
inline void onAllocation(const volatile void *, std::size_t)
{
  if(countAllocations) ++allocationCount;
}
inline void onFree(const volatile void *) {}
inline const int allocationHookInstalled = __sanitizer_install_malloc_and_free_hooks(onAllocation, onFree);
} // namespace rbdgentest
#else
extern "C" void * malloc(std::size_t size)
{
  if(rbdgentest::countAllocations) ++rbdgentest::allocationCount;
  return __libc_malloc(size);
}

void * operator new(std::size_t size)
{
  if(rbdgentest::countAllocations) ++rbdgentest::allocationCount;
  if(void * p = __libc_malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void * operator new[](std::size_t size)
{
  return operator new(size);
}
void operator delete(void * p) noexcept
{
  __libc_free(p);
}
void operator delete[](void * p) noexcept
{
  __libc_free(p);
}
void operator delete(void * p, std::size_t) noexcept
{
  __libc_free(p);
}
void operator delete[](void * p, std::size_t) noexcept
{
  __libc_free(p);
}
#endif
