// SPDX-License-Identifier: BSD-3-Clause
/* Counting heap allocations in a test program (for "no heap allocation in the hot path" tests): linking
   AllocationCounter.cpp replaces the global operator new and delete and, where that is sound, interposes the
   C allocation functions.

   What heapAllocations() counts, per build:
   - every build: each call of any form of operator new and new[] (plain, nothrow, aligned, aligned nothrow),
     whatever calls it: std::vector growth, std::make_shared, a std::string beyond its small buffer, ...;
   - builds without a sanitizer that owns malloc (the normal build): also each call of malloc and calloc, and
     of realloc with a size above 0 (an allocation, a move, or a growth in place: a realloc in a hot path is
     heap traffic), made anywhere in the program, shared libraries included (C libraries, libstdc++'s
     exception allocation, glibc's own calls such as strdup's). The interposed functions forward to glibc's
     __libc_malloc, __libc_calloc and __libc_realloc; operator new takes its memory from __libc_malloc too, so
     that a new is counted once, not twice. countsCAllocations() says whether this build counts them.
   - AddressSanitizer builds (scripts/sanitize.sh), and ThreadSanitizer and MemorySanitizer ones: no C
     allocation. The sanitizer's runtime must own malloc (interposing it would hide every allocation from the
     sanitizer and break it), so a malloc in a hot path shows only in the normal build.
   Never counted: aligned_alloc, posix_memalign, memalign, valloc, pvalloc (glibc's own, not interposed),
   mmap, and realloc(p, 0) (a free). Frees are not counted. */
#ifndef MHPLAN_TESTS_ALLOCATION_COUNTER_H
#define MHPLAN_TESTS_ALLOCATION_COUNTER_H

namespace mhplan::test
{
    /** \brief Heap allocations made by this program so far (see above: operator new in every form; malloc,
        calloc and realloc too when countsCAllocations()). */
    unsigned long heapAllocations();

    /** \brief True when heapAllocations() counts malloc, calloc and realloc: in builds without a sanitizer
        that owns malloc (AddressSanitizer, ThreadSanitizer, MemorySanitizer). */
    bool countsCAllocations();
} // namespace mhplan::test

#endif
