// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: Particle Swarm Optimization as an OMPL planner ([LRSMA] Table 3's PSO). */
#ifndef MHPLAN_PARTICLE_SWARM_H
#define MHPLAN_PARTICLE_SWARM_H

#include "ompl_planners/population/SwarmPlanner.h"

namespace mhplan
{
    /** \brief Particle Swarm Optimization (PSO): Kennedy & Eberhart, "Particle swarm optimization", Proc.
        IEEE ICNN 1995, with the inertia weight w of Shi & Eberhart 1998, as [LRSMA] compares it (Table 3,
        settings of Table 2: c1 = c2 = 0.4, w = 1; docs/algorithms.md 10.1).

        Each iteration, for every particle i and coordinate j with fresh r1, r2 ~ U(0, 1):
        v_ij = w v_ij + c1 r1 (p_ij - x_ij) + c2 r2 (g_j - x_ij), limited to |v_ij| <= vmax_j, and
        x_ij = x_ij + v_ij, clamped to the bounds; then every particle is evaluated, its personal best p_i
        taken when strictly better, and the global best g is the best personal best.

        Choices where the papers leave room (docs/algorithms.md 10.1): velocities start at zero; vmax_j =
        \c velocity_limit (ub_j - lb_j), 0.2 by default (the 1995 paper bounds velocities by a Vmax without
        a value; with w = 1 nothing else damps them); a clamped coordinate keeps its velocity; p and g are
        updated after the whole evaluation round (synchronous). Framework: SwarmPlanner ([LRSMA]'s spline,
        fitness S, N = T = 30, m = 3). */
    class ParticleSwarm : public SwarmPlanner
    {
      public:
        explicit ParticleSwarm(const ompl::base::SpaceInformationPtr &si);

        /** \brief Inertia weight w (0..2). */
        void setInertia(double w);
        double getInertia() const { return w_; }
        /** \brief Cognitive coefficient c1 (0..4). */
        void setCognitive(double c1);
        double getCognitive() const { return c1_; }
        /** \brief Social coefficient c2 (0..4). */
        void setSocial(double c2);
        double getSocial() const { return c2_; }
        /** \brief vmax as a share of each coordinate's extent (0..1; 0 = no limit). */
        void setVelocityLimit(double share);
        double getVelocityLimit() const { return vmaxShare_; }

        /** \brief The velocity update of one coordinate (before the vmax limit): w v + c1 r1 (p - x) +
            c2 r2 (g - x). */
        static double velocity(double v, double x, double pbest, double gbest, double w, double c1, double c2,
                               double r1, double r2)
        {
            return w * v + c1 * r1 * (pbest - x) + c2 * r2 * (gbest - x);
        }

      protected:
        bool iterate(unsigned int t) override;
        void startSwarm() override;
        void evaluated() override;

      private:
        double w_{1.0}, c1_{0.4}, c2_{0.4}, vmaxShare_{0.2};
        std::vector<double> v_, nextV_, pbest_, pbestFit_;
        LeaderArchive global_;
    };
} // namespace mhplan

#endif
