// SPDX-License-Identifier: BSD-3-Clause
/* The hot paths (validity, motion and clearance queries of every collision model) never touch the heap once
   warm: fitness and planner loops call them millions of times. Counted with the replaced global operator new
   and, in the normal build, the interposed C allocation functions (AllocationCounter.h); the counter itself
   is tested first: every form of operator new once, the containers' allocations, and the C allocations in
   exactly the builds that count them. */
#include "src/collision/Collision.h"
#include "src/io/Generators.h"
#include "src/io/WorldIO.h"

#include "AllocationCounter.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <random>
#include <string>
#include <vector>

using namespace mhplan;

namespace
{
    /** Make the compiler assume that \e p is used: an allocation whose memory is never read may be left
        out (GCC removes unused new/delete and malloc/free pairs). */
    void escape(const void *p)
    {
        asm volatile("" : : "g"(p) : "memory");
    }

    /** Allocations the counter saw while \e f ran. */
    template <class F> unsigned long countedDuring(F &&f)
    {
        const unsigned long before = test::heapAllocations();
        f();
        return test::heapAllocations() - before;
    }

    /** A type whose alignment exceeds the default new alignment: new takes the aligned forms. */
    struct alignas(64) CacheLine
    {
        double v[8];
    };
    static_assert(alignof(CacheLine) > __STDCPP_DEFAULT_NEW_ALIGNMENT__);

    bool aligned64(const void *p)
    {
        return reinterpret_cast<std::uintptr_t>(p) % 64 == 0;
    }

    /** Allocations during 2000 calls of each query: isValid, segmentValid, clearance, segmentClearance. */
    std::array<long, 4> allocationsDuring(const CollisionModel &model, const Box &b)
    {
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> ux(b.xmin, b.xmax), uy(b.ymin, b.ymax);
        std::vector<Vec2> pts(2000);
        for (auto &p : pts)
            p = {ux(rng), uy(rng)};
        std::array<long, 4> out{};
        double sink = 0.0;
        // Pass 0 warms up (thread-local scratch buffers grow to their working size once); pass 1 counts.
        for (int q = 0; q < 8; ++q)
        {
            const long before = static_cast<long>(test::heapAllocations());
            for (std::size_t i = 0; i + 1 < pts.size(); ++i)
            {
                const Vec2 &a = pts[i];
                // Short segments, as planners check them (a tenth of the world's size at most).
                const Vec2 bb = a + (pts[i + 1] - a) * 0.1;
                switch (q % 4)
                {
                case 0:
                    sink += model.isValid(a) ? 1.0 : 0.0;
                    break;
                case 1:
                    sink += model.segmentValid(a, bb) ? 1.0 : 0.0;
                    break;
                case 2:
                    sink += model.clearance(a);
                    break;
                default:
                    sink += model.segmentClearance(a, bb);
                }
            }
            if (q >= 4)
                out[q - 4] = static_cast<long>(test::heapAllocations()) - before;
        }
        EXPECT_FALSE(std::isnan(sink));
        return out;
    }
} // namespace

TEST(Allocation, CollisionQueriesDoNotAllocate)
{
    const World circles = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/bfo_case2.yaml");
    GeneratorOptions o;
    o.count = 40;
    o.seed = 5;
    const World rects = generateRectangles(o); // convex polygons
    const World grid = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/gms_grid20.yaml");
    o.count = 500;
    const World many = generateCircles(o);
    const std::array<long, 4> none{0, 0, 0, 0};
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(circles, CollisionBackend::Analytic), circles.bounds),
              none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(rects, CollisionBackend::Analytic), rects.bounds), none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(rects, CollisionBackend::FCL), rects.bounds), none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(many, CollisionBackend::FCL), many.bounds), none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(many, CollisionBackend::Hash), many.bounds), none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(rects, CollisionBackend::Hash), rects.bounds), none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(grid, CollisionBackend::Grid), grid.bounds), none);
}

TEST(Allocation, CounterCountsEveryFormOfOperatorNewOnce)
{
    bool aligned = true; // every aligned form returned memory with the type's alignment
    EXPECT_EQ(countedDuring(
                  []
                  {
                      int *p = new int(3);
                      escape(p);
                      delete p;
                  }),
              1u)
        << "new";
    EXPECT_EQ(countedDuring(
                  []
                  {
                      int *p = new int[7];
                      escape(p);
                      delete[] p;
                  }),
              1u)
        << "new[]";
    EXPECT_EQ(countedDuring(
                  []
                  {
                      int *p = new (std::nothrow) int(3);
                      escape(p);
                      delete p;
                  }),
              1u)
        << "nothrow new";
    EXPECT_EQ(countedDuring(
                  []
                  {
                      int *p = new (std::nothrow) int[7];
                      escape(p);
                      delete[] p;
                  }),
              1u)
        << "nothrow new[]";
    EXPECT_EQ(countedDuring(
                  [&]
                  {
                      CacheLine *p = new CacheLine;
                      escape(p);
                      aligned = aligned && aligned64(p);
                      delete p;
                  }),
              1u)
        << "aligned new";
    EXPECT_EQ(countedDuring(
                  [&]
                  {
                      CacheLine *p = new CacheLine[3];
                      escape(p);
                      aligned = aligned && aligned64(p);
                      delete[] p;
                  }),
              1u)
        << "aligned new[]";
    EXPECT_EQ(countedDuring(
                  [&]
                  {
                      CacheLine *p = new (std::nothrow) CacheLine;
                      escape(p);
                      aligned = aligned && aligned64(p);
                      delete p;
                  }),
              1u)
        << "aligned nothrow new";
    EXPECT_EQ(countedDuring(
                  [&]
                  {
                      CacheLine *p = new (std::nothrow) CacheLine[3];
                      escape(p);
                      aligned = aligned && aligned64(p);
                      delete[] p;
                  }),
              1u)
        << "aligned nothrow new[]";
    EXPECT_EQ(countedDuring(
                  []
                  {
                      void *p = ::operator new(0);
                      escape(p);
                      ::operator delete(p);
                  }),
              1u)
        << "operator new(0)";
    EXPECT_EQ(countedDuring(
                  [&]
                  {
                      void *p = ::operator new(100, std::align_val_t(256));
                      escape(p);
                      aligned = aligned && reinterpret_cast<std::uintptr_t>(p) % 256 == 0;
                      ::operator delete(p, 100, std::align_val_t(256));
                  }),
              1u)
        << "operator new(size, alignment), sized aligned delete";
    EXPECT_TRUE(aligned);
}

TEST(Allocation, CounterSeesTheContainersAllocations)
{
    // A vector allocates once per growth of its capacity, never for a push_back within it.
    std::size_t growths = 0;
    const unsigned long pushing = countedDuring(
        [&]
        {
            std::vector<int> v;
            for (int i = 0; i < 1000; ++i)
            {
                growths += v.size() == v.capacity() ? 1 : 0;
                v.push_back(i);
            }
            escape(v.data());
        });
    EXPECT_GT(growths, 5u);
    EXPECT_EQ(pushing, growths);
    EXPECT_EQ(countedDuring(
                  []
                  {
                      std::vector<int> v;
                      v.reserve(1000);
                      for (int i = 0; i < 1000; ++i)
                          v.push_back(i);
                      escape(v.data());
                  }),
              1u)
        << "reserved vector";
    // make_shared: the object and its control block in one allocation; shared_ptr(new T): two.
    EXPECT_EQ(countedDuring(
                  []
                  {
                      const auto p = std::make_shared<std::array<double, 4>>();
                      escape(p.get());
                  }),
              1u)
        << "make_shared";
    EXPECT_EQ(countedDuring(
                  []
                  {
                      const std::shared_ptr<int> p(new int(5));
                      escape(p.get());
                  }),
              2u)
        << "shared_ptr(new T)";
    EXPECT_EQ(countedDuring(
                  []
                  {
                      const std::string s(100, 'x'); // beyond the small-string buffer
                      escape(s.data());
                  }),
              1u)
        << "long string";
    EXPECT_EQ(countedDuring(
                  []
                  {
                      const std::string s(3, 'x'); // within it
                      escape(s.data());
                  }),
              0u)
        << "short string";
}

TEST(Allocation, CounterCountsCAllocationsInTheBuildsThatCanCountThem)
{
    // The normal build counts malloc, calloc and realloc; the AddressSanitizer build cannot (its runtime owns
    // malloc; AllocationCounter.h).
#if defined(__SANITIZE_ADDRESS__)
    EXPECT_FALSE(test::countsCAllocations());
#else
    EXPECT_TRUE(test::countsCAllocations());
#endif
    const unsigned long c = test::countsCAllocations() ? 1u : 0u;
    void *p = nullptr;
    EXPECT_EQ(countedDuring(
                  [&]
                  {
                      p = std::malloc(24);
                      escape(p);
                  }),
              c)
        << "malloc";
    EXPECT_EQ(countedDuring(
                  [&]
                  {
                      p = std::realloc(p, 1 << 16); // grows: moves or extends
                      escape(p);
                  }),
              c)
        << "realloc";
    EXPECT_EQ(countedDuring(
                  [&]
                  {
                      p = std::realloc(p, 0); // frees (glibc)
                      escape(p);
                  }),
              0u)
        << "realloc(p, 0)";
    std::free(p);
    EXPECT_EQ(countedDuring(
                  [&]
                  {
                      p = std::realloc(nullptr, 16); // a malloc
                      escape(p);
                      std::free(p);
                  }),
              c)
        << "realloc(nullptr, n)";
    EXPECT_EQ(countedDuring(
                  []
                  {
                      void *q = std::calloc(4, 8);
                      escape(q);
                      std::free(q);
                  }),
              c)
        << "calloc";
    // The C library's own allocations count too: strdup, called through a pointer so that the compiler
    // cannot expand it into malloc and memcpy here.
    char *(*volatile duplicate)(const char *) = ::strdup;
    EXPECT_EQ(countedDuring(
                  [&]
                  {
                      char *q = duplicate("a string");
                      escape(q);
                      std::free(q);
                  }),
              c)
        << "strdup in libc";
    // new takes its memory from the C allocator without passing through the counting malloc: counted once.
    EXPECT_EQ(countedDuring(
                  []
                  {
                      double *q = new double[4];
                      escape(q);
                      delete[] q;
                  }),
              1u)
        << "new[] counted once";
}

// A world of 10^4 queries is read without yaml-cpp's node tree for its queries (src/io/QueryList.h): a tree
// takes about 100 heap allocations and 5 KB per query (10^5 queries: 470 MB, 2.3 s of CPU before a campaign
// could list them). The queries' parse events, the queries and their names take a handful per query.
TEST(Allocation, AWorldOfManyQueriesIsReadWithoutATreeOfItsQueries)
{
    constexpr std::size_t kQueries = 10000;
    std::string text = "name: many\nbounds: {xmin: 0, xmax: 100, ymin: 0, ymax: 100}\nrobot: {radius: 0.1}\n"
                       "obstacles:\n  - circle: {center: [90, 10], radius: 3}\nqueries:\n";
    for (std::size_t i = 0; i < kQueries; ++i)
    {
        const std::size_t a = (i * 37) % 50 + 1, b = (i * 53) % 50 + 1;
        text += "  - {start: [" + std::to_string(a) + ", " + std::to_string(b) + "], goal: [" +
                std::to_string(99 - a) + ", " + std::to_string(99 - b) + "]}\n";
    }
    World world;
    const unsigned long allocations = countedDuring([&] { world = parseWorldYaml(text, "many.yaml"); });
    ASSERT_EQ(world.queries.size(), kQueries);
    EXPECT_EQ(world.queries.back().name, "q9999");
    if (!test::countsCAllocations())
        GTEST_SKIP() << "this build counts operator new only";
    // Measured: 8 per query (the tree: 100).
    EXPECT_LT(allocations, 20 * kQueries) << allocations / kQueries << " per query";
}
