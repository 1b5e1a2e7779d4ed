// SPDX-License-Identifier: BSD-3-Clause
/* PopulationPlanner: its parameters (each range written once, in kRanges below) and their setters. */
#include "ompl_planners/common/PopulationPlanner.h"

#include "src/base/Parameters.h"

#include <functional>
#include <stdexcept>
#include <string>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kIterations{
            "iterations", 1, 1, 1000000,
            "T, length of the coefficient schedules (the papers' iteration budget); does not stop a run"};
        constexpr ParamRange kWaypoints{"waypoints", 1, 1, 100,
                                        "m, intermediate waypoints of a candidate path"};
        constexpr ParamRange kSplineSamples{"spline_samples", 2, 1, 100000,
                                            "points of the spline decoding's polyline"};
        constexpr ParamRange kLengthWeight{"length_weight", 0, 1, 1000000,
                                           "eta1 of [LRSMA]'s fitness: weight of the path length"};
        constexpr ParamRange kPenaltyWeight{"penalty_weight", 0, 1, 1000000000,
                                            "eta2 of [LRSMA]'s fitness: weight of the collision penalty"};
        constexpr ParamRange kDistanceWeight{"distance_weight", 0, 0.1, 1000000,
                                             "w_d of [GMS]'s fitness: weight of the path length"};
        constexpr ParamRange kSafetyWeight{
            "safety_weight", 0, 0.1, 1000000,
            "w_s of [GMS]'s fitness: weight of the safety term (clearance below safe_distance)"};
        constexpr ParamRange kSmoothnessWeight{"smoothness_weight", 0, 0.1, 1000000,
                                               "w_sm of [GMS]'s fitness: weight of the turning angles"};
        constexpr ParamRange kSafeDistance{
            "safe_distance", 0.000001, 0.1, 1000000,
            "d_safe of [GMS]: clearance below which the safety term grows (m)"};
        constexpr ParamRange kInfeasibleLengthWeight{
            "infeasible_length_weight", 0, 0.1, 1000000,
            "w_l of [GMS]: weight of the length inside obstacles of an infeasible path"};
        constexpr ParamRange kCrossingWeight{
            "crossing_weight", 0, 0.1, 1000000,
            "w_c of [GMS]: weight of the obstacle crossings of an infeasible path"};
        constexpr ParamRange kStagnationRestart{
            "stagnation_restart", 0, 1, 1000000,
            "restart the population after this many iterations without improvement (0 = off)"};
    } // namespace

    void PopulationPlanner::declareParameters()
    {
        const std::function<void()> changed = [this] { invalidate(); }; // a weight changes the fitness
        declareRanged<unsigned int>(params(), this, kIterations, &PopulationPlanner::setIterations,
                                    &PopulationPlanner::getIterations);
        declareRanged<unsigned int>(params(), this, kWaypoints, &PopulationPlanner::setWaypoints,
                                    &PopulationPlanner::getWaypoints);
        declareChoice(params(), this, "decoding", &PopulationPlanner::setDecoding,
                      &PopulationPlanner::getDecoding, "polyline,spline,auto",
                      "how a candidate becomes a path: straight segments between waypoints, a spline, or "
                      "auto (the spline in R^k, the space's interpolation on other spaces)");
        declareRanged<unsigned int>(params(), this, kSplineSamples, &PopulationPlanner::setSplineSamples,
                                    &PopulationPlanner::getSplineSamples);
        declareChoice(params(), this, "fitness", &PopulationPlanner::setFitness,
                      &PopulationPlanner::getFitness, "auto,lrsma,gms",
                      "fitness function: [LRSMA] S, [GMS] f1/f2, or auto ([GMS] on grid worlds)");
        declareRangedField(params(), kLengthWeight, weights_.lengthWeight, changed);
        declareRangedField(params(), kPenaltyWeight, weights_.penaltyWeight, changed);
        declareRangedField(params(), kDistanceWeight, weights_.distanceWeight, changed);
        declareRangedField(params(), kSafetyWeight, weights_.safetyWeight, changed);
        declareRangedField(params(), kSmoothnessWeight, weights_.smoothnessWeight, changed);
        declareRangedField(params(), kSafeDistance, weights_.safeDistance, changed);
        declareRangedField(params(), kInfeasibleLengthWeight, weights_.infeasibleLengthWeight, changed);
        declareRangedField(params(), kCrossingWeight, weights_.crossingWeight, changed);
        declareChoiceWith(
            params(), "infeasible_base",
            [this](const std::string &base)
            {
                if (base != "path" && base != "constant")
                    throw std::invalid_argument(
                        "parameter 'infeasible_base' must be 'path' or 'constant'; got '" + base + "'");
                weights_.infeasibleBaseIsPath = base == "path";
                invalidate();
            },
            [this] { return weights_.infeasibleBaseIsPath ? "path" : "constant"; }, "path,constant",
            "[GMS] f2's D for infeasible paths: the path's own f1 denominator, or a constant");
        declareRanged<unsigned int>(params(), this, kStagnationRestart,
                                    &PopulationPlanner::setStagnationRestart,
                                    &PopulationPlanner::getStagnationRestart);
        declareGmsParameters(params(), gms_, [this] { setup_ = false; }); // setup() checks the switches
    }

    void PopulationPlanner::setPopulationSize(unsigned int n)
    {
        checkParameter(SharedParameterRanges::populationSize, n);
        if (n != getPopulationSize())
            invalidate();
        PlannerBase::setPopulationSize(n);
    }

    void PopulationPlanner::setIterations(unsigned int t)
    {
        storeChecked(kIterations, iterations_, t);
    }

    void PopulationPlanner::setWaypoints(unsigned int m)
    {
        storeCheckedResetting(kWaypoints, waypoints_, m, [this] { invalidate(); });
    }

    void PopulationPlanner::setDecoding(const std::string &decoding)
    {
        const bool autoDecoding = decoding == "auto";
        const PathDecoding d = autoDecoding ? PathDecoding::Spline : parsePathDecoding(decoding);
        if (d != decoding_ || autoDecoding != decodingAuto_)
            invalidate();
        decoding_ = d;
        decodingAuto_ = autoDecoding;
    }

    void PopulationPlanner::setSplineSamples(unsigned int n)
    {
        storeCheckedResetting(kSplineSamples, splineSamples_, n, [this] { invalidate(); });
    }

    void PopulationPlanner::setFitness(const std::string &fitness)
    {
        if (fitness != "auto")
            parseFitnessKind(fitness); // validates
        if (fitness != fitnessName_)
            invalidate();
        fitnessName_ = fitness;
    }

    void PopulationPlanner::setSeed(unsigned long seed)
    {
        PlannerBase::setSeed(seed); // checks the range
        invalidate();
    }

    void PopulationPlanner::setStagnationRestart(unsigned int n)
    {
        storeChecked(kStagnationRestart, stagnationRestart_, n);
    }

    void PopulationPlanner::setGmsSettings(const GmsSettings &settings)
    {
        settings.check();
        gms_ = settings;
        setup_ = false;
    }

    void PopulationPlanner::checkGmsSwitches()
    {
        const std::string why = gms_.refusal(
            supportsGmsOperators(), realVector_ ? std::string() : si_->getStateSpace()->getName(), spaceDim_);
        if (!why.empty())
            refuseSetup(why);
    }

} // namespace mhplan
