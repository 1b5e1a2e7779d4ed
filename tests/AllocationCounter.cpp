// SPDX-License-Identifier: BSD-3-Clause
/* The replaced global allocation functions behind AllocationCounter.h. Every form of operator new and
   delete is replaced (plain, array, nothrow, aligned, sized), all on malloc/aligned_alloc and free, so that a
   pointer from any form is released by the matching replaced form: nothing from the library's own operator
   new reaches this free() (AddressSanitizer checks the pairing: alloc-dealloc-mismatch). Kept out of line
   (noinline) so that GCC does not pair an inlined free() with operator new. */
#include "AllocationCounter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace
{
    std::atomic<unsigned long> gAllocations{0};

    void *allocate(std::size_t n) noexcept
    {
        ++gAllocations;
        return std::malloc(n == 0 ? 1 : n);
    }

    void *allocateAligned(std::size_t n, std::align_val_t al) noexcept
    {
        ++gAllocations;
        const std::size_t a =
            static_cast<std::size_t>(al) < sizeof(void *) ? sizeof(void *) : static_cast<std::size_t>(al);
        // aligned_alloc needs a size that is a multiple of the alignment.
        const std::size_t size = n == 0 ? a : (n + a - 1) / a * a;
        return std::aligned_alloc(a, size);
    }

    void *orThrow(void *p)
    {
        if (p == nullptr)
            throw std::bad_alloc();
        return p;
    }
} // namespace

unsigned long mhplan::test::heapAllocations()
{
    return gAllocations.load();
}

[[gnu::noinline]] void *operator new(std::size_t n)
{
    return orThrow(allocate(n));
}
[[gnu::noinline]] void *operator new[](std::size_t n)
{
    return orThrow(allocate(n));
}
[[gnu::noinline]] void *operator new(std::size_t n, const std::nothrow_t &) noexcept
{
    return allocate(n);
}
[[gnu::noinline]] void *operator new[](std::size_t n, const std::nothrow_t &) noexcept
{
    return allocate(n);
}
[[gnu::noinline]] void *operator new(std::size_t n, std::align_val_t al)
{
    return orThrow(allocateAligned(n, al));
}
[[gnu::noinline]] void *operator new[](std::size_t n, std::align_val_t al)
{
    return orThrow(allocateAligned(n, al));
}
[[gnu::noinline]] void *operator new(std::size_t n, std::align_val_t al, const std::nothrow_t &) noexcept
{
    return allocateAligned(n, al);
}
[[gnu::noinline]] void *operator new[](std::size_t n, std::align_val_t al, const std::nothrow_t &) noexcept
{
    return allocateAligned(n, al);
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
[[gnu::noinline]] void operator delete(void *p, const std::nothrow_t &) noexcept
{
    std::free(p);
}
[[gnu::noinline]] void operator delete[](void *p, const std::nothrow_t &) noexcept
{
    std::free(p);
}
[[gnu::noinline]] void operator delete(void *p, std::align_val_t) noexcept
{
    std::free(p);
}
[[gnu::noinline]] void operator delete[](void *p, std::align_val_t) noexcept
{
    std::free(p);
}
[[gnu::noinline]] void operator delete(void *p, std::size_t, std::align_val_t) noexcept
{
    std::free(p);
}
[[gnu::noinline]] void operator delete[](void *p, std::size_t, std::align_val_t) noexcept
{
    std::free(p);
}
[[gnu::noinline]] void operator delete(void *p, std::align_val_t, const std::nothrow_t &) noexcept
{
    std::free(p);
}
[[gnu::noinline]] void operator delete[](void *p, std::align_val_t, const std::nothrow_t &) noexcept
{
    std::free(p);
}
