// SPDX-License-Identifier: BSD-3-Clause
/* Test support: the factor by which a test's wall-clock safety limits grow in a slower build. The sanitizer
   pass (scripts/sanitize.sh) sets MHPLAN_TEST_TIME_SCALE (ASan + UBSan run 3-5 times slower); it scales only
   limits that are safety nets, never a limit whose result a test compares. */
#ifndef MHPLAN_TESTS_TIME_SCALE_H
#define MHPLAN_TESTS_TIME_SCALE_H

#include <cstdlib>

namespace mhplan::test
{
    inline double timeScale()
    {
        const char *s = std::getenv("MHPLAN_TEST_TIME_SCALE");
        const double v = s != nullptr ? std::atof(s) : 1.0;
        return v >= 1.0 ? v : 1.0;
    }
} // namespace mhplan::test

#endif
