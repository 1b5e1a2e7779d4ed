// SPDX-License-Identifier: BSD-3-Clause
/* Counting heap allocations in a test program: linking AllocationCounter.cpp replaces the global operator
   new/delete with versions that count every allocation (for "no heap allocation in the hot path" tests). */
#ifndef MHPLAN_TESTS_ALLOCATION_COUNTER_H
#define MHPLAN_TESTS_ALLOCATION_COUNTER_H

namespace mhplan::test
{
    /** \brief Heap allocations (operator new, any form) made by this program so far. */
    unsigned long heapAllocations();
} // namespace mhplan::test

#endif
