// SPDX-License-Identifier: BSD-3-Clause
/* The replaced global allocation functions behind AllocationCounter.h. Every form of operator new and
   delete is replaced (plain, array, nothrow, aligned, sized), all on one C allocator and free, so that a
   pointer from any form is released by the matching replaced form: nothing from the library's own operator
   new reaches this free() (AddressSanitizer checks the pairing: alloc-dealloc-mismatch). Kept out of line
   (noinline) so that GCC does not pair an inlined free() with operator new.

   Without a sanitizer that owns malloc, malloc, calloc and realloc are interposed too (a definition in the
   program preempts glibc's for every shared library, as glibc's manual describes for replacing malloc): each
   counts and forwards to glibc's allocator (__libc_malloc, ...), so glibc's own free, aligned_alloc,
   posix_memalign and malloc_usable_size, which are not replaced, still fit every pointer. operator new takes
   its memory from __libc_malloc, bypassing the counting malloc: one new, one count. */
#include "AllocationCounter.h"

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define MHPLAN_SANITIZER_OWNS_MALLOC 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define MHPLAN_SANITIZER_OWNS_MALLOC 1
#endif
#endif

#ifndef MHPLAN_SANITIZER_OWNS_MALLOC
// glibc's allocator under its own names (exported by libc.so.6 since GLIBC_2.2.5, declared in no header).
extern "C"
{
    void *__libc_malloc(std::size_t size);
    void *__libc_calloc(std::size_t count, std::size_t size);
    void *__libc_realloc(void *p, std::size_t size);
}
#endif

namespace
{
    std::atomic<unsigned long> gAllocations{0};

    /** Memory for operator new, not counted again by the interposed malloc. */
    void *uncountedMalloc(std::size_t n) noexcept
    {
#ifdef MHPLAN_SANITIZER_OWNS_MALLOC
        return std::malloc(n);
#else
        return __libc_malloc(n);
#endif
    }

    void *allocate(std::size_t n) noexcept
    {
        ++gAllocations;
        return uncountedMalloc(n == 0 ? 1 : n);
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

bool mhplan::test::countsCAllocations()
{
#ifdef MHPLAN_SANITIZER_OWNS_MALLOC
    return false;
#else
    return true;
#endif
}

#ifndef MHPLAN_SANITIZER_OWNS_MALLOC
extern "C"
{
    [[gnu::noinline]] void *malloc(std::size_t size) noexcept
    {
        ++gAllocations;
        return __libc_malloc(size);
    }
    [[gnu::noinline]] void *calloc(std::size_t count, std::size_t size) noexcept
    {
        ++gAllocations;
        return __libc_calloc(count, size);
    }
    [[gnu::noinline]] void *realloc(void *p, std::size_t size) noexcept
    {
        if (size > 0 || p == nullptr) // realloc(p, 0) frees p
            ++gAllocations;
        return __libc_realloc(p, size);
    }
}
#endif

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
