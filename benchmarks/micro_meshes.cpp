// SPDX-License-Identifier: BSD-3-Clause
/* mhplan micro-benchmarks of mesh collision (docs/meshes.md): one robot-environment collision check and one
   clearance (FCL distance) at 1k, 10k and 100k environment triangles, and the cost of validating a motion
   per metre and per radian with the certified validator beside OMPL's discrete validator. The environment is
   a bumpy height field of 2 k^2 triangles over [-10, 10]^2, the robot the 1.6 x 0.5 x 0.5 rod of
   environments/omplapp; poses and motions are drawn before the timed loops.
   Run: mhplan_mesh_microbench --benchmark_min_time=0.2 */
#include "src/collision/MeshRigidBody.h"

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/util/Console.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

using namespace mhplan;
namespace ob = ompl::base;

namespace
{
    double height(double x, double y)
    {
        return 0.6 * std::sin(0.9 * x) * std::cos(0.7 * y);
    }

    /** A height field of k x k cells over [-10, 10]^2: 2 k^2 triangles. */
    TriangleMesh heightField(int k)
    {
        TriangleMesh m;
        m.source = "height field";
        for (int j = 0; j <= k; ++j)
            for (int i = 0; i <= k; ++i)
            {
                const double x = -10.0 + 20.0 * i / k, y = -10.0 + 20.0 * j / k;
                m.vertices.emplace_back(x, y, height(x, y));
            }
        const auto at = [k](int i, int j) { return static_cast<std::uint32_t>(j * (k + 1) + i); };
        for (int j = 0; j < k; ++j)
            for (int i = 0; i < k; ++i)
            {
                m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        return m;
    }

    TriangleMesh rod()
    {
        TriangleMesh m;
        m.source = "rod";
        for (int c = 0; c < 8; ++c)
            m.vertices.emplace_back((c & 1) ? 0.8 : -0.8, (c & 2) ? 0.25 : -0.25, (c & 4) ? 0.25 : -0.25);
        m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                       {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
        return m;
    }

    int cellsFor(int triangles)
    {
        return static_cast<int>(std::lround(std::sqrt(triangles / 2.0)));
    }

    /** Poses above the field, half of them close enough to touch it. */
    std::vector<Eigen::Isometry3d> poses(std::size_t n)
    {
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> xy(-8.0, 8.0), dz(-0.3, 1.5), angle(-M_PI, M_PI);
        std::vector<Eigen::Isometry3d> out;
        for (std::size_t i = 0; i < n; ++i)
        {
            Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
            const double x = xy(rng), y = xy(rng);
            t.translation() = Eigen::Vector3d(x, y, height(x, y) + dz(rng));
            t.linear() = (Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitZ()) *
                          Eigen::AngleAxisd(0.3 * angle(rng), Eigen::Vector3d::UnitX()))
                             .toRotationMatrix();
            out.push_back(t);
        }
        return out;
    }

    void BM_MeshCollide(benchmark::State &state)
    {
        const MeshRigidModel model(heightField(cellsFor(static_cast<int>(state.range(0)))), rod(), false);
        const auto ps = poses(1024);
        std::size_t i = 0, hits = 0;
        for (auto _ : state)
        {
            hits += model.collides(ps[i++ & 1023]) ? 1 : 0;
            benchmark::DoNotOptimize(hits);
        }
        state.counters["triangles"] = static_cast<double>(model.environmentTriangles());
        state.counters["in_contact"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
    }

    void BM_MeshClearance(benchmark::State &state)
    {
        const MeshRigidModel model(heightField(cellsFor(static_cast<int>(state.range(0)))), rod(), false);
        const auto ps = poses(1024);
        std::size_t i = 0;
        for (auto _ : state)
            benchmark::DoNotOptimize(model.clearance(ps[i++ & 1023]));
        state.counters["triangles"] = static_cast<double>(model.environmentTriangles());
    }

    /** Motions from free poses 0.3 to 1.5 above the 10k-triangle field, of one unit each: range(1) 0: a
        translation of 1 m, 1: a rotation of 1 rad in place (about z), 2: 1 m and 0.5 rad together; so the
        time per motion is the cost per metre, per radian, per (metre + half a radian). range(0): 0 the
        certified validator, 1 OMPL's discrete validator at longest_valid_segment_fraction 0.01 (OMPL.app's
        default). "accepted" is the share of motions each accepts (the discrete one may accept motions that
        clip the field between its checks). */
    void BM_MotionValidator(benchmark::State &state)
    {
        MeshProblemSpec spec;
        spec.model = std::make_shared<MeshRigidModel>(heightField(cellsFor(10000)), rod(), false);
        spec.volume = Eigen::AlignedBox3d(Eigen::Vector3d(-10, -10, -2), Eigen::Vector3d(10, 10, 4));
        spec.start.position = {0, 0, 2.5};
        spec.goal.position = {1, 1, 2.5};
        spec.motionValidator = state.range(0) == 0 ? "certified" : "discrete";
        const auto ss = makeMeshSetup(spec);
        const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
        std::mt19937_64 rng(9);
        std::uniform_real_distribution<double> xy(-7.0, 7.0), dz(0.3, 1.5), angle(-M_PI, M_PI);
        std::vector<ob::ScopedState<ob::SE3StateSpace>> from, to;
        while (from.size() < 256)
        {
            ob::ScopedState<ob::SE3StateSpace> a(si->getStateSpace()), b(si->getStateSpace());
            const double x = xy(rng), y = xy(rng), heading = angle(rng);
            a->setXYZ(x, y, height(x, y) + dz(rng));
            a->rotation().setAxisAngle(0, 0, 1, heading);
            const double metres = state.range(1) == 1 ? 0.0 : 1.0;
            const double turn = state.range(1) == 0 ? 0.0 : (state.range(1) == 1 ? 1.0 : 0.5);
            b->setXYZ(x + metres * std::cos(heading), y + metres * std::sin(heading), a->getZ());
            b->rotation().setAxisAngle(0, 0, 1, heading + turn);
            if (si->isValid(a.get()) && si->isValid(b.get()))
            {
                from.push_back(a);
                to.push_back(b);
            }
        }
        std::size_t i = 0, valid = 0;
        for (auto _ : state)
        {
            valid += si->checkMotion(from[i & 255].get(), to[i & 255].get()) ? 1 : 0;
            ++i;
        }
        state.counters["accepted"] = static_cast<double>(valid) / static_cast<double>(state.iterations());
    }
} // namespace

BENCHMARK(BM_MeshCollide)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MeshClearance)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MotionValidator)
    ->ArgNames({"discrete", "motion"})
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->Unit(benchmark::kMicrosecond);

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    return 0;
}
