// SPDX-License-Identifier: BSD-3-Clause
/* The replaced global allocation functions behind AllocationCounter.h. Kept out of line (noinline) so that
   GCC does not pair an inlined free() with operator new. */
#include "AllocationCounter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace
{
    std::atomic<unsigned long> gAllocations{0};
} // namespace

unsigned long mhplan::test::heapAllocations()
{
    return gAllocations.load();
}

[[gnu::noinline]] void *operator new(std::size_t n)
{
    ++gAllocations;
    if (void *p = std::malloc(n == 0 ? 1 : n))
        return p;
    throw std::bad_alloc();
}
[[gnu::noinline]] void *operator new[](std::size_t n)
{
    return operator new(n);
}
[[gnu::noinline]] void operator delete(void *p) noexcept
{
    std::free(p);
}
[[gnu::noinline]] void operator delete[](void *p) noexcept
{
    std::free(p);
}
[[gnu::noinline]] void operator delete(void *p, std::size_t) noexcept
{
    std::free(p);
}
[[gnu::noinline]] void operator delete[](void *p, std::size_t) noexcept
{
    std::free(p);
}
