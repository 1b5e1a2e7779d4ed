#include "Geometry.h"

#include <gtest/gtest.h>

using namespace mhplan;

TEST(Geometry, PointSegmentDistance)
{
    EXPECT_DOUBLE_EQ(pointSegmentDistance({0, 1}, {-1, 0}, {1, 0}), 1.0);
    EXPECT_DOUBLE_EQ(pointSegmentDistance({3, 4}, {0, 0}, {0, 0}), 5.0);
    EXPECT_DOUBLE_EQ(pointSegmentDistance({2, 1}, {-1, 0}, {1, 0}), std::sqrt(2.0));
}
