#pragma once
// Counts heap allocations (operator new and malloc) made by this thread while counting is on.
// Include in exactly one translation unit per executable: it replaces the global allocators.

#include <cstdlib>
#include <new>

extern "C" void * __libc_malloc(std::size_t size); // glibc's own malloc, for the interposed one
extern "C" void __libc_free(void * p);

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
