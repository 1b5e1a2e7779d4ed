// SPDX-License-Identifier: BSD-3-Clause
/* A population planner with its protected evaluation hooks opened for a test (the allocation tests of
   test_nd.cpp and test_spaces_planners.cpp). */
#ifndef MHPLAN_TESTS_EVALUATION_PROBE_H
#define MHPLAN_TESTS_EVALUATION_PROBE_H

namespace mhplan::test
{
    /** \brief Planner \e P (a PopulationPlanner) with evaluate(), randomPosition() and dimension() public. */
    template <typename P> class EvaluationProbe : public P
    {
      public:
        using P::P;
        double evaluateCandidate(const double *x) { return this->evaluate(x); }
        void randomCandidate(double *x) { this->randomPosition(x); }
        unsigned int candidateDimension() const { return this->dimension(); }
    };
} // namespace mhplan::test

#endif
