// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/population/Genetic.h"
#include "src/base/Parameters.h"
#include "src/collision/GridCollision.h"
#include "src/collision/Validity.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kCrossoverRate{"crossover_rate", 0, 0.05, 1, "crossover probability"};
        constexpr ParamRange kMutationRate{"mutation_rate", 0, 0.05, 1, "mutation probability per offspring"};
        constexpr ParamRange kInsertDeleteRate{"insert_delete_rate", 0, 0.01, 0.5,
                                               "probability of an insert (and of a delete) mutation"};
        constexpr ParamRange kTournamentSize{"tournament_size", 1, 1, 100,
                                             "individuals per selection tournament"};
        constexpr ParamRange kReplaceFraction{
            "replace_fraction", 0, 0.05, 1,
            "share of the population replaced by fresh individuals each generation"};
        constexpr ParamRange kCommonNodeTolerance{"common_node_tolerance", 0, 0.005, 1,
                                                  "crossover: two nodes are common when within this fraction "
                                                  "of the bounds' larger side (off grids)"};
    } // namespace

    Genetic::Genetic(const ob::SpaceInformationPtr &si, const std::string &name)
        : PopulationPlanner(si, name, PopulationDefaults{50, 100, 5, PathDecoding::Polyline})
    {
        setFitness("gms");
        declareRanged<double>(params(), this, kCrossoverRate, &Genetic::setCrossoverRate,
                              &Genetic::getCrossoverRate);
        declareRanged<double>(params(), this, kMutationRate, &Genetic::setMutationRate,
                              &Genetic::getMutationRate);
        declareRanged<double>(params(), this, kInsertDeleteRate, &Genetic::setInsertDeleteRate,
                              &Genetic::getInsertDeleteRate);
        declareRanged<unsigned int>(params(), this, kTournamentSize, &Genetic::setTournamentSize,
                                    &Genetic::getTournamentSize);
        declareRanged<double>(params(), this, kReplaceFraction, &Genetic::setReplaceFraction,
                              &Genetic::getReplaceFraction);
        declareRanged<double>(params(), this, kCommonNodeTolerance, &Genetic::setCommonNodeTolerance,
                              &Genetic::getCommonNodeTolerance);
        declareSwitch(params(), this, "node_improvement", &Genetic::setNodeImprovement,
                      &Genetic::getNodeImprovement, "apply node improvement to the offspring");
        declareChoice(params(), this, "initialisation", &Genetic::setInitialisation,
                      &Genetic::getInitialisation, "nodes,walk",
                      "initial paths: random free nodes repaired ([GMS]), or random lattice walks (GA-WALK)");
    }

    Genetic::~Genetic() = default;

    void Genetic::setup()
    {
        // Planar only: refuse any other space before the base class accepts it as a state space
        // (docs/spaces.md).
        const ob::StateSpacePtr &space = si_->getStateSpace();
        if (dynamic_cast<const ob::RealVectorStateSpace *>(space.get()) == nullptr)
            refuseSetup(
                "needs a 2-dimensional RealVectorStateSpace: the [GMS] node encoding and its operators "
                "are planar; got the state space '" +
                space->getName() +
                "' (SE(2), Dubins, Reeds-Shepp and other spaces are not supported). Use SMA, LRSMA or "
                "MGO on those (docs/spaces.md).");
        PopulationPlanner::setup();
        if (spaceDimension() != 2)
            refuseSetup("needs a 2-dimensional RealVectorStateSpace: the [GMS] node encoding and its repair, "
                        "revision and node-improvement operators are planar (grid maps); got dimension " +
                        std::to_string(spaceDimension()) + ". Use SMA, LRSMA or MGO in R^k.");
    }

    void Genetic::setCrossoverRate(double r)
    {
        storeChecked(kCrossoverRate, crossoverRate_, r);
    }

    void Genetic::setMutationRate(double r)
    {
        storeChecked(kMutationRate, mutationRate_, r);
    }

    void Genetic::setInsertDeleteRate(double r)
    {
        storeChecked(kInsertDeleteRate, insertDeleteRate_, r);
    }

    void Genetic::setTournamentSize(unsigned int k)
    {
        storeChecked(kTournamentSize, tournamentSize_, k);
    }

    void Genetic::setReplaceFraction(double f)
    {
        storeChecked(kReplaceFraction, replaceFraction_, f);
    }

    void Genetic::setCommonNodeTolerance(double f)
    {
        storeChecked(kCommonNodeTolerance, commonTolerance_, f);
    }

    bool Genetic::sameNode(const Vec2 &p, const Vec2 &q, double tolerance, const OccupancyGrid *grid)
    {
        if (grid != nullptr)
            return grid->cellX(p.x) == grid->cellX(q.x) && grid->cellY(p.y) == grid->cellY(q.y);
        return distance(p, q) <= tolerance;
    }

    bool Genetic::findCommonNode(const Individual &a, const Individual &b, std::size_t offset,
                                 double tolerance, const OccupancyGrid *grid, std::size_t &ia,
                                 std::size_t &ib)
    {
        if (a.size() < 3 || b.size() < 3)
            return false;
        const std::size_t interior = a.size() - 2;
        for (std::size_t s = 0; s < interior; ++s)
        {
            const std::size_t i = 1 + (offset + s) % interior;
            for (std::size_t j = 1; j + 1 < b.size(); ++j)
                if (sameNode(a[i], b[j], tolerance, grid))
                {
                    ia = i;
                    ib = j;
                    return true;
                }
        }
        return false;
    }

    void Genetic::clearPopulation()
    {
        pop_.clear();
        next_.clear();
        fit_.clear();
        nextFit_.clear();
        ops_.reset();
    }

    void Genetic::setInitialisation(const std::string &mode)
    {
        if (mode != "nodes" && mode != "walk")
            throw std::invalid_argument(
                getName() + ": parameter 'initialisation' must be 'nodes' or 'walk' (got '" + mode + "')");
        walk_ = mode == "walk";
    }

    void Genetic::randomIndividual(Individual &ind)
    {
        if (walk_ && ops_->randomLatticePath(ind, startPoint(), goalPoint(), 20000))
        {
            ops_->simplify(ind);
            return;
        }
        ind.clear();
        ind.push_back(startPoint());
        const int k = rng_.uniformInt(1, static_cast<int>(getWaypoints()));
        for (int i = 0; i < k; ++i)
            ind.push_back(ops_->randomFreePoint());
        ind.push_back(goalPoint());
        repair(ind, true);
    }

    void Genetic::repair(Individual &ind, bool improve)
    {
        ops_->repairNodes(ind);
        ops_->repairSegments(ind);
        ops_->revise(ind);
        ops_->simplify(ind);
        if (improve && nodeImprovement_)
            ops_->improveNodes(ind);
    }

    bool Genetic::initialisePopulation()
    {
        const unsigned int n = getPopulationSize();
        const Box box{lower(0), upper(0), lower(1), upper(1)};
        ops_ =
            std::make_unique<PathOperators>(fitness(), rng_, box, 0.01 * std::max(box.width(), box.height()));
        grid_ = nullptr;
        if (const auto *checker =
                dynamic_cast<const WorldValidityChecker *>(si_->getStateValidityChecker().get()))
            if (const auto *g = dynamic_cast<const GridCollisionModel *>(checker->model().get()))
                grid_ = &g->grid();
        tolerance_ = commonTolerance_ * std::max(box.width(), box.height());
        pop_.assign(n, Individual());
        next_.assign(n, Individual());
        fit_.assign(n, 0.0);
        nextFit_.assign(n, 0.0);
        order_.resize(n);
        for (unsigned int i = 0; i < n; ++i)
        {
            if (stopRequested())
                return false;
            randomIndividual(pop_[i]);
            fit_[i] = evaluatePath(pop_[i]);
        }
        return true;
    }

    unsigned int Genetic::tournament()
    {
        const int n = static_cast<int>(getPopulationSize());
        auto best = static_cast<unsigned int>(rng_.uniformInt(0, n - 1));
        for (unsigned int k = 1; k < tournamentSize_; ++k)
        {
            const auto c = static_cast<unsigned int>(rng_.uniformInt(0, n - 1));
            if (fit_[c] < fit_[best])
                best = c;
        }
        return best;
    }

    void Genetic::crossover(const Individual &a, const Individual &b, Individual &c1, Individual &c2)
    {
        // A common interior node, if any (the first one found from a random starting point of a).
        std::size_t ia = 0, ib = 0;
        bool common = false;
        if (a.size() > 2 && b.size() > 2)
        {
            const auto offset =
                static_cast<std::size_t>(rng_.uniformInt(0, static_cast<int>(a.size() - 2) - 1));
            common = findCommonNode(a, b, offset, tolerance_, grid_, ia, ib);
        }
        if (!common)
        {
            // Random cut points: c1 = a[0..ia] + b[ib..], c2 = b[0..ib-1] + a[ia+1..].
            ia = static_cast<std::size_t>(rng_.uniformInt(0, static_cast<int>(a.size()) - 2));
            ib = static_cast<std::size_t>(rng_.uniformInt(1, static_cast<int>(b.size()) - 1));
            c1.assign(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(ia + 1));
            c1.insert(c1.end(), b.begin() + static_cast<std::ptrdiff_t>(ib), b.end());
            c2.assign(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(ib));
            c2.insert(c2.end(), a.begin() + static_cast<std::ptrdiff_t>(ia + 1), a.end());
            return;
        }
        c1.assign(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(ia));
        c1.insert(c1.end(), b.begin() + static_cast<std::ptrdiff_t>(ib), b.end());
        c2.assign(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(ib));
        c2.insert(c2.end(), a.begin() + static_cast<std::ptrdiff_t>(ia), a.end());
    }

    void Genetic::mutate(Individual &ind)
    {
        const double u = rng_.uniform01();
        if (u < insertDeleteRate_ || ind.size() < 3)
        {
            const auto at = static_cast<std::ptrdiff_t>(rng_.uniformInt(1, static_cast<int>(ind.size()) - 1));
            ind.insert(ind.begin() + at, ops_->randomFreePoint());
        }
        else if (u < 2.0 * insertDeleteRate_)
            ind.erase(ind.begin() + rng_.uniformInt(1, static_cast<int>(ind.size()) - 2));
        else
            ind[static_cast<std::size_t>(rng_.uniformInt(1, static_cast<int>(ind.size()) - 2))] =
                ops_->randomFreePoint();
    }

    bool Genetic::iterate(unsigned int /*t*/)
    {
        const unsigned int n = getPopulationSize();
        // Elitism: the best individual survives unchanged.
        const auto elite =
            static_cast<unsigned int>(std::min_element(fit_.begin(), fit_.end()) - fit_.begin());
        next_[0] = pop_[elite];
        nextFit_[0] = fit_[elite];
        unsigned int filled = 1;
        Individual c1, c2;
        while (filled < n)
        {
            const Individual &p1 = pop_[tournament()];
            const Individual &p2 = pop_[tournament()];
            if (rng_.uniform01() < crossoverRate_)
                crossover(p1, p2, c1, c2);
            else
            {
                c1 = p1;
                c2 = p2;
            }
            for (Individual *c : {&c1, &c2})
            {
                if (filled >= n)
                    break;
                if (rng_.uniform01() < mutationRate_)
                    mutate(*c);
                repair(*c, true);
                if (stopRequested())
                    return false;
                nextFit_[filled] = evaluatePath(*c);
                next_[filled].swap(*c);
                ++filled;
            }
        }
        // Replacement: the worst replace_fraction by fresh repaired random individuals.
        const auto replace = static_cast<unsigned int>(std::ceil(replaceFraction_ * n - 1e-9));
        std::iota(order_.begin(), order_.end(), 0u);
        std::stable_sort(order_.begin(), order_.end(),
                         [&](unsigned int a, unsigned int b) { return nextFit_[a] < nextFit_[b]; });
        for (unsigned int k = 0; k < replace && k + 1 < n; ++k)
        {
            const unsigned int i = order_[n - 1 - k];
            randomIndividual(next_[i]);
            if (stopRequested())
                return false;
            nextFit_[i] = evaluatePath(next_[i]);
        }
        pop_.swap(next_);
        fit_.swap(nextFit_);
        return true;
    }
} // namespace mhplan
