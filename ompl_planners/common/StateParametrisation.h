// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: a state as a vector of reals and back (docs/spaces.md, "Planners on state spaces"): how the
   population planners' update rules, written for R^k, act on SE(2), Dubins, Reeds-Shepp, SE(3) and compound
   state spaces. */
#ifndef MHPLAN_STATE_PARAMETRISATION_H
#define MHPLAN_STATE_PARAMETRISATION_H

#include <ompl/base/StateSpace.h>
#include <ompl/util/RandomNumbers.h>

#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Maps a state of a supported state space to dimension() reals and back, with per-coordinate
        bounds for drawing and clamping (docs/spaces.md, "Planners on state spaces").

        Supported spaces, each a leaf or a compound of leaves (nested compounds too):
        - RealVectorStateSpace(k): k coordinates, the identity, the space's bounds (finite, low <= high);
        - SO2StateSpace: one angle, seen unwrapped relative to a reference angle a_ref (the start's):
          toVector() gives a_ref + wrap(a - a_ref) in [a_ref - pi, a_ref + pi); bounds [a_ref - pi,
          a_ref + pi]; enforce() wraps into that interval (the circle has no boundary to clamp to);
          fromVector() wraps to [-pi, pi) as SO2StateSpace does;
        - SO3StateSpace: a rotation vector v (3 coordinates) in the tangent space at a reference rotation
          q_ref (the start's): q = q_ref exp(v), |v| <= pi; bounds [-pi, pi] per coordinate; enforce() maps
          |v| > pi to the same rotation with |v| <= pi (v scaled by remainder(|v|, 2 pi) / |v|);
        - CompoundStateSpace (SE2StateSpace, DubinsStateSpace, ReedsSheppStateSpace, SE3StateSpace, user
          compounds) whose components are all supported: the components' coordinates concatenated in order.
        Anything else (DiscreteStateSpace, TimeStateSpace, ...) is unsupported: create() returns null and
        says why. Component weights do not enter the parametrisation (the space's distance() has them).

        Not thread-safe; toVector()/fromVector()/enforce()/sample() allocate nothing. */
    class StateParametrisation
    {
      public:
        /** \brief The parametrisation of \e space, or null when it is not supported (\e why then names the
            component and what is supported). */
        static std::unique_ptr<StateParametrisation> create(const ompl::base::StateSpacePtr &space,
                                                            std::string &why);

        /** \brief What create() accepts, for error messages. */
        static std::string supportedSpaces();

        /** \brief Reals per state. */
        unsigned int dimension() const { return dim_; }
        /** \brief Lower bound of coordinate j (0 <= j < dimension()), after setReference(). */
        double lower(unsigned int j) const { return lower_[j]; }
        /** \brief Upper bound of coordinate j. */
        double upper(unsigned int j) const { return upper_[j]; }
        /** \brief True when the space is a single RealVectorStateSpace (the identity). */
        bool isRealVector() const { return realVector_; }
        /** \brief True when the space has an SO(2) or SO(3) component. */
        bool hasRotations() const { return rotations_; }
        /** \brief True when coordinate j (0 <= j < dimension()) belongs to an SO(2) or SO(3) component. */
        bool isRotation(unsigned int j) const { return rotationCoordinate_[j] != 0; }

        /** \brief Take the SO(2) reference angles and SO(3) reference rotations from \e reference (the
            query's start) and set the bounds. */
        void setReference(const ompl::base::State *reference);

        /** \brief The coordinates of \e state (dimension() values) into \e x. */
        void toVector(const ompl::base::State *state, double *x) const;
        /** \brief The state of coordinates \e x (angles wrapped, rotations normalised). */
        void fromVector(const double *x, ompl::base::State *state) const;
        /** \brief Bring \e x into the bounds: clamp R^k coordinates, wrap SO(2) angles, fold SO(3) rotation
            vectors to norm <= pi (each the same state as far as the space is concerned, except clamping). */
        void enforce(double *x) const;
        /** \brief Draw coordinates with \e rng: uniform in the bounds per R^k or SO(2) coordinate (in that
            order), a uniform rotation (ompl::RNG::quaternion) for SO(3). */
        void sample(ompl::RNG &rng, double *x) const;

      private:
        enum class Kind
        {
            RealVector,
            SO2,
            SO3
        };
        /** \brief One leaf space: where its state is in the compound tree and its coordinates. */
        struct Leaf
        {
            Kind kind;
            /** \brief Component indices from the root state to the leaf's state. */
            std::vector<unsigned int> path;
            /** \brief First coordinate and count. */
            unsigned int offset;
            unsigned int count;
            /** \brief RealVector: the bounds. */
            std::vector<double> low, high;
            /** \brief SO(2): the reference angle; SO(3): the reference rotation (x, y, z, w). */
            double ref[4]{0.0, 0.0, 0.0, 1.0};
        };

        bool addLeaves(const ompl::base::StateSpacePtr &space, std::vector<unsigned int> &path,
                       std::string &why);
        static const ompl::base::State *leafState(const ompl::base::State *root, const Leaf &leaf);
        static ompl::base::State *leafState(ompl::base::State *root, const Leaf &leaf);

        std::vector<Leaf> leaves_;
        unsigned int dim_{0};
        bool realVector_{false};
        bool rotations_{false};
        std::vector<char> rotationCoordinate_;
        std::vector<double> lower_, upper_;
    };
} // namespace mhplan

#endif
