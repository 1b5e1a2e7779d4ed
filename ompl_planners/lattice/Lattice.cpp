// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/lattice/Lattice.h"
#include "ompl_planners/lattice/LatticePlanner.h"
#include "ompl_planners/common/PlannerSupport.h"

#include "src/collision/GridCollision.h"
#include "src/base/Parameters.h"
#include "src/collision/Validity.h"

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Exception.h>
#include <ompl/util/String.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kResolution{"resolution", 0, 0.01, 1000000,
                                         "spacing of a sampled lattice; 0 = automatic"};
    } // namespace

    namespace
    {
        constexpr LatticeNode kNoParent = 0xFFFFFFFFu;
    } // namespace

    // ---------------------------------------------------------------------------------------------------
    // Lattice

    Lattice::~Lattice()
    {
        releaseStates();
    }

    void Lattice::releaseStates()
    {
        if (si_ && stateA_ != nullptr)
        {
            si_->freeState(stateA_);
            si_->freeState(stateB_);
        }
        stateA_ = stateB_ = nullptr;
    }

    void Lattice::buildFromGrid(const ob::SpaceInformationPtr &si, const OccupancyGrid &grid)
    {
        releaseStates();
        si_ = si;
        stateA_ = si_->allocState();
        stateB_ = si_->allocState();
        kind_ = LatticeKind::GridCells;
        width_ = grid.width();
        height_ = grid.height();
        spacing_ = grid.cellSize();
        base_ = grid.origin();
        offset_ = 0.5;
        initialFlags_.assign(static_cast<std::size_t>(width_ + 2) * (height_ + 2), kBlocked);
        for (int j = 0; j < height_; ++j)
            for (int i = 0; i < width_; ++i)
                initialFlags_[id(i, j)] = grid.blocked(i, j) ? kBlocked : kFree;
        flags_ = initialFlags_;
        resetCounts();
    }

    void Lattice::buildSampled(const ob::SpaceInformationPtr &si, const Vec2 &origin, double spacing,
                               double nx, double ny)
    {
        if (!(spacing > 0.0) || !(nx >= 1.0) || !(ny >= 1.0) ||
            (nx + 2.0) * (ny + 2.0) > static_cast<double>(kMaxNodes))
        {
            std::ostringstream msg;
            msg << "lattice of " << nx << " x " << ny << " nodes (spacing " << spacing
                << ") is empty or exceeds " << kMaxNodes << " nodes: choose a coarser resolution";
            throw std::invalid_argument(msg.str());
        }
        releaseStates();
        si_ = si;
        stateA_ = si_->allocState();
        stateB_ = si_->allocState();
        kind_ = LatticeKind::Sampled;
        width_ = static_cast<int>(nx);
        height_ = static_cast<int>(ny);
        spacing_ = spacing;
        base_ = origin;
        offset_ = 0.0;
        initialFlags_.assign(static_cast<std::size_t>(width_ + 2) * (height_ + 2), kBlocked);
        for (int j = 0; j < height_; ++j)
            std::fill_n(initialFlags_.begin() + id(0, j), width_, std::uint8_t{0});
        flags_ = initialFlags_;
        resetCounts();
    }

    void Lattice::resetFlags()
    {
        flags_ = initialFlags_;
    }

    bool Lattice::evaluateNode(LatticeNode n)
    {
        setStatePosition(stateA_, position(n));
        ++validityChecks_;
        const bool free = si_->isValid(stateA_);
        flags_[n] = static_cast<std::uint8_t>((flags_[n] & kGoalLink) | (free ? kFree : kBlocked));
        return free;
    }

    bool Lattice::motionValid(const Vec2 &a, const Vec2 &b)
    {
        setStatePosition(stateA_, a);
        setStatePosition(stateB_, b);
        ++motionChecks_;
        return si_->checkMotion(stateA_, stateB_);
    }

    void Lattice::joinIfValid(const Vec2 &p, int i, int j, std::vector<LatticeLink> &out)
    {
        if (i < 0 || j < 0 || i >= width_ || j >= height_)
            return;
        const LatticeNode n = id(i, j);
        for (const LatticeLink &l : out)
            if (l.node == n)
                return;
        if (!nodeFree(n))
            return;
        const Vec2 q = position(n);
        if (q == p)
            out.push_back({n, 0.0});
        else if (motionValid(p, q))
            out.push_back({n, distance(p, q)});
    }

    bool Lattice::connect(const Vec2 &p, const ob::PlannerTerminationCondition &ptc,
                          std::vector<LatticeLink> &out)
    {
        out.clear();
        const double u = latticeX(p.x), v = latticeY(p.y);
        if (kind_ == LatticeKind::GridCells)
        {
            // Cell i covers [i, i + 1] in cell units; a point on a border belongs to both closed squares.
            const double cu = (p.x - base_.x) / spacing_, cv = (p.y - base_.y) / spacing_;
            const int i0 = static_cast<int>(std::floor(cu)), j0 = static_cast<int>(std::floor(cv));
            const int i1 = cu == i0 ? i0 - 1 : i0, j1 = cv == j0 ? j0 - 1 : j0;
            for (const int i : {i0, i1})
                for (const int j : {j0, j1})
                    joinIfValid(p, i, j, out);
        }
        else
        {
            const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
            for (const int i : {i0, i0 + 1})
                for (const int j : {j0, j0 + 1})
                    joinIfValid(p, i, j, out);
        }
        if (!out.empty())
            return true;
        // No neighbouring node can be joined: search rings of nodes around the nearest one.
        const int ci = std::min(std::max(static_cast<int>(std::lround(u)), 0), width_ - 1);
        const int cj = std::min(std::max(static_cast<int>(std::lround(v)), 0), height_ - 1);
        const int maxRing = std::max(width_, height_);
        for (int r = 1; r <= maxRing && out.empty(); ++r)
        {
            if (ptc())
                return false;
            for (int i = ci - r; i <= ci + r; ++i)
            {
                joinIfValid(p, i, cj - r, out);
                joinIfValid(p, i, cj + r, out);
            }
            for (int j = cj - r + 1; j <= cj + r - 1; ++j)
            {
                joinIfValid(p, ci - r, j, out);
                joinIfValid(p, ci + r, j, out);
            }
        }
        return true;
    }

    // ---------------------------------------------------------------------------------------------------
    // LatticePlanner

    LatticePlanner::LatticePlanner(const ob::SpaceInformationPtr &si, const std::string &name)
        : PlannerBase(si, name, false)
    {
        specs_.approximateSolutions = true;
        specs_.optimizingPaths = true;
        specs_.canReportIntermediateSolutions = true;
        specs_.multithreaded = false;
        specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;

        declareRanged<double>(params(), this, kResolution, &LatticePlanner::setResolution,
                              &LatticePlanner::getResolution);
        declareChoice(
            params(), this, "lattice", &LatticePlanner::setLattice, &LatticePlanner::getLattice,
            "auto,sampled",
            "auto: the grid's cells on grid worlds, else a sampled lattice; sampled: always sampled");
        declareMaxIterations("node expansions per solve() call; 0 = until the search ends");

        declareProgress(false);
        addPlannerProgressProperty("motion checks INTEGER",
                                   [this] { return std::to_string(motionCheckCount()); });
    }

    LatticePlanner::~LatticePlanner() = default;

    void LatticePlanner::setResolution(double r)
    {
        storeCheckedResetting(kResolution, resolution_, r, [this] { clear(); });
    }

    void LatticePlanner::setLattice(const std::string &lattice)
    {
        if (lattice != "auto" && lattice != "sampled")
            throw std::invalid_argument("parameter 'lattice' must be one of {auto, sampled}; got '" +
                                        lattice + "'");
        if (lattice != latticeName_)
            clear();
        latticeName_ = lattice;
    }

    void LatticePlanner::clear()
    {
        PlannerBase::clear();
        problemReady_ = linksReady_ = finished_ = found_ = false;
        solution_.clear();
        goalLinks_.clear();
        expansions_ = 0;
        lattice_.resetCounts();
        bestApproxH_ = std::numeric_limits<double>::infinity();
        motionCheckCount_ = 0;
    }

    void LatticePlanner::buildLattice()
    {
        const auto *space = si_->getStateSpace()->as<ob::RealVectorStateSpace>();
        const ob::RealVectorBounds &b = space->getBounds();
        const double w = b.high[0] - b.low[0], h = b.high[1] - b.low[1];
        const auto *checker =
            dynamic_cast<const WorldValidityChecker *>(si_->getStateValidityChecker().get());
        const auto *gridModel =
            checker != nullptr ? dynamic_cast<const GridCollisionModel *>(checker->model().get()) : nullptr;
        if (latticeName_ == "auto" && gridModel != nullptr && gridModel->robotRadius() == 0.0)
        {
            lattice_.buildFromGrid(si_, gridModel->grid());
            OMPL_INFORM("%s: %d x %d grid cells (MovingAI moves)", getName().c_str(), lattice_.width(),
                        lattice_.height());
            return;
        }
        if (resolution_ == 0.0 && gridModel != nullptr)
        {
            // One node per cell centre; validity and motions through the validator (e.g. a disc robot).
            const OccupancyGrid &grid = gridModel->grid();
            const double cs = grid.cellSize();
            lattice_.buildSampled(si_, grid.cellCenter(0, 0), cs, grid.width(), grid.height());
        }
        else
        {
            const double s = resolution_ > 0.0 ? resolution_ : std::max(w, h) / 100.0;
            const double nx = std::max(1.0, std::floor(w / s + 1e-9));
            const double ny = std::max(1.0, std::floor(h / s + 1e-9));
            // Centred in the bounds, so that no node sits on the border when the extent is a multiple of s.
            const Vec2 origin(b.low[0] + 0.5 * (w - (nx - 1.0) * s), b.low[1] + 0.5 * (h - (ny - 1.0) * s));
            lattice_.buildSampled(si_, origin, s, nx, ny);
        }
        OMPL_INFORM("%s: %d x %d lattice, spacing %g", getName().c_str(), lattice_.width(), lattice_.height(),
                    lattice_.spacing());
    }

    void LatticePlanner::setup()
    {
        ob::Planner::setup();
        const auto *space = dynamic_cast<const ob::RealVectorStateSpace *>(si_->getStateSpace().get());
        if (space == nullptr || space->getDimension() != 2)
        {
            refuseSetup("needs a 2D RealVectorStateSpace, got '" + si_->getStateSpace()->getName() +
                        "' of dimension " + std::to_string(si_->getStateSpace()->getDimension()));
        }
    }

    bool LatticePlanner::prepareProblem(const ob::PlannerTerminationCondition &ptc, ob::PlannerStatus &status)
    {
        if (!problemReady_)
        {
            const auto *space = dynamic_cast<const ob::RealVectorStateSpace *>(si_->getStateSpace().get());
            if (space == nullptr || space->getDimension() != 2)
            {
                OMPL_ERROR("%s: needs a 2D RealVectorStateSpace", getName().c_str());
                status = ob::PlannerStatus::ABORT;
                return false;
            }
            const ob::State *start = nullptr, *goal = nullptr;
            if (!startAndGoal(start, goal))
            {
                status = inputFailure();
                return false;
            }
            startPos_ = statePosition(start);
            goalPos_ = statePosition(goal);
            try
            {
                buildLattice();
            }
            catch (const std::invalid_argument &e)
            {
                OMPL_ERROR("%s: %s", getName().c_str(), e.what());
                status = ob::PlannerStatus::ABORT;
                return false;
            }
            const std::size_t n = lattice_.size();
            startNode_ = static_cast<LatticeNode>(n);
            goalNode_ = static_cast<LatticeNode>(n + 1);
            g_.resize(n + 2);
            parent_.resize(n + 2);
            open_.reset(n + 2);
            lattice_.resetFlags();
            goalU_ = lattice_.latticeX(goalPos_.x);
            goalV_ = lattice_.latticeY(goalPos_.y);
            bestApprox_ = startNode_;
            bestApproxH_ = std::numeric_limits<double>::infinity();
            problemReady_ = true;
            linksReady_ = false;
        }
        if (linksReady_)
            return true;

        g_[startNode_] = 0.0;
        parent_[startNode_] = kNoParent;
        open_.close(startNode_);
        if (startPos_ == goalPos_)
        {
            g_[goalNode_] = 0.0;
            parent_[goalNode_] = startNode_;
            open_.push(goalNode_, 0.0, 0.0);
            linksReady_ = true;
            return true;
        }
        std::vector<LatticeLink> startLinks;
        if (!lattice_.connect(startPos_, ptc, startLinks) || !lattice_.connect(goalPos_, ptc, goalLinks_))
        {
            publishCounts();
            status = ob::PlannerStatus::TIMEOUT;
            return false;
        }
        const double sp = lattice_.spacing();
        goalSlack_ = 0.0;
        for (const LatticeLink &l : goalLinks_)
        {
            lattice_.flags()[l.node] |= Lattice::kGoalLink;
            const double a = std::fabs(lattice_.column(l.node) - goalU_);
            const double b = std::fabs(lattice_.row(l.node) - goalV_);
            const double octile = sp * (std::max(a, b) + (std::sqrt(2.0) - 1.0) * std::min(a, b));
            goalSlack_ = std::max(goalSlack_, octile - l.cost);
        }
        for (const LatticeLink &l : startLinks)
            if (open_.unseen(l.node) || l.cost < g_[l.node])
            {
                g_[l.node] = l.cost;
                parent_[l.node] = startNode_;
                open_.push(l.node, l.cost + heuristic(l.node), l.cost);
            }
        if (startLinks.empty())
            OMPL_WARN("%s: the start cannot be joined to any lattice node", getName().c_str());
        if (goalLinks_.empty())
            OMPL_WARN("%s: the goal cannot be joined to any lattice node", getName().c_str());
        linksReady_ = true;
        return true;
    }

    double LatticePlanner::goalLinkCost(LatticeNode n) const
    {
        for (const LatticeLink &l : goalLinks_)
            if (l.node == n)
                return l.cost;
        return std::numeric_limits<double>::infinity();
    }

    std::vector<LatticeNode> LatticePlanner::nodeChain(LatticeNode last) const
    {
        std::vector<LatticeNode> chain;
        for (LatticeNode n = last; n != kNoParent; n = parent_[n])
            chain.push_back(n);
        std::reverse(chain.begin(), chain.end());
        return chain;
    }

    std::vector<Vec2> LatticePlanner::chainPoints(const std::vector<LatticeNode> &chain) const
    {
        std::vector<Vec2> points;
        points.reserve(chain.size());
        const auto isLattice = [this](LatticeNode n) { return n != startNode_ && n != goalNode_; };
        for (std::size_t k = 0; k < chain.size(); ++k)
        {
            if (k > 0 && k + 1 < chain.size() && isLattice(chain[k - 1]) && isLattice(chain[k]) &&
                isLattice(chain[k + 1]))
            {
                // Drop a lattice node between two lattice steps in the same direction (exact integers).
                const long di1 = lattice_.column(chain[k]) - lattice_.column(chain[k - 1]);
                const long dj1 = lattice_.row(chain[k]) - lattice_.row(chain[k - 1]);
                const long di2 = lattice_.column(chain[k + 1]) - lattice_.column(chain[k]);
                const long dj2 = lattice_.row(chain[k + 1]) - lattice_.row(chain[k]);
                if (di1 * dj2 == dj1 * di2 && di1 * di2 + dj1 * dj2 > 0)
                    continue;
            }
            const Vec2 p = nodePosition(chain[k]);
            if (points.empty() || points.back() != p || k + 1 == chain.size())
                points.push_back(p);
        }
        // A start or goal that coincides with its node leaves a zero-length segment: drop it (keep >= 2
        // points).
        if (points.size() > 2 && points[points.size() - 1] == points[points.size() - 2])
            points.erase(points.end() - 2);
        return points;
    }

    double LatticePlanner::objectiveCost(const std::vector<Vec2> &points, ob::Cost &cost)
    {
        const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
        double length = 0.0;
        for (std::size_t i = 1; i < points.size(); ++i)
            length += distance(points[i - 1], points[i]);
        if (!opt)
        {
            cost = ob::Cost(length);
            return length;
        }
        cost = opt->identityCost();
        ob::State *a = scratchState(0), *b = scratchState(1);
        for (std::size_t i = 1; i < points.size(); ++i)
        {
            setStatePosition(a, points[i - 1]);
            setStatePosition(b, points[i]);
            cost = opt->combineCosts(cost, opt->motionCost(a, b));
        }
        return length;
    }

    void LatticePlanner::reportPath(const std::vector<Vec2> &points, bool exact, double difference)
    {
        auto path = std::make_shared<og::PathGeometric>(si_);
        ob::State *s = si_->allocState();
        for (const Vec2 &p : points)
        {
            setStatePosition(s, p);
            path->append(s);
        }
        si_->freeState(s);
        ob::PlannerSolution solution(path);
        solution.setPlannerName(getName());
        if (exact)
        {
            const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
            if (opt)
                solution.setOptimized(opt, solutionCost_, opt->isSatisfied(solutionCost_));
        }
        else
            solution.setApproximate(std::max(difference, 1e-12));
        pdef_->addSolutionPath(solution);
    }

    ob::PlannerStatus LatticePlanner::solve(const ob::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        if (ptc())
            return ob::PlannerStatus::TIMEOUT;
        ob::PlannerStatus status = ob::PlannerStatus::TIMEOUT;
        if (!prepareProblem(ptc, status))
            return status;

        if (!finished_)
        {
            const SearchResult r = search(ptc, getMaxIterations());
            publishCounts();
            if (r == SearchResult::Found)
            {
                finished_ = found_ = true;
                solution_ = chainPoints(nodeChain(goalNode_));
                // An exact solution must pass the motion validator segment by segment.
                solutionExact_ = true;
                for (std::size_t i = 1; i < solution_.size(); ++i)
                    if (!lattice_.motionValid(solution_[i - 1], solution_[i]))
                    {
                        OMPL_WARN("%s: segment %zu of the lattice path fails the motion validator; reporting "
                                  "the valid prefix as approximate",
                                  getName().c_str(), i);
                        solution_.resize(i);
                        solutionExact_ = false;
                        solutionDifference_ = distance(solution_.back(), goalPos_);
                        break;
                    }
                publishCounts();
                if (solutionExact_)
                {
                    objectiveCost(solution_, solutionCost_);
                    bestCostValue_ = solutionCost_.value();
                    reportImprovementOf(
                        solution_.size(),
                        [this](ob::State *st, std::size_t i) { setStatePosition(st, solution_[i]); },
                        solutionCost_);
                }
            }
            else if (r == SearchResult::Exhausted)
            {
                finished_ = true;
                OMPL_INFORM("%s: no path on the lattice", getName().c_str());
            }
        }

        if (found_)
        {
            reportPath(solution_, solutionExact_, solutionDifference_);
            status =
                solutionExact_ ? ob::PlannerStatus::EXACT_SOLUTION : ob::PlannerStatus::APPROXIMATE_SOLUTION;
        }
        else
        {
            std::vector<Vec2> partial = chainPoints(nodeChain(bestApprox_));
            reportPath(partial, false, distance(partial.back(), goalPos_));
            status = ob::PlannerStatus::APPROXIMATE_SOLUTION;
        }
        OMPL_INFORM("%s: %lu expansions, %lu motion checks, best cost %s", getName().c_str(),
                    iterationCount(), motionCheckCount(), ompl::toString(bestCost()).c_str());
        return status;
    }

    void LatticePlanner::getPlannerData(ob::PlannerData &data) const
    {
        pathToPlannerData(
            data, solution_.size(),
            [this](ob::State *s, std::size_t i) { setStatePosition(s, solution_[i]); }, true);
    }
} // namespace mhplan
