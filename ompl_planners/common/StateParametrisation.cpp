// SPDX-License-Identifier: BSD-3-Clause
/* StateParametrisation: the leaves of a state space and their coordinates (docs/spaces.md). */
#include "ompl_planners/common/StateParametrisation.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/base/spaces/SO3StateSpace.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr double kPi = 3.14159265358979323846;

        /** \brief Hamilton product a b of quaternions stored (x, y, z, w). */
        void multiply(const double *a, const double *b, double *out)
        {
            out[0] = a[3] * b[0] + b[3] * a[0] + a[1] * b[2] - a[2] * b[1];
            out[1] = a[3] * b[1] + b[3] * a[1] + a[2] * b[0] - a[0] * b[2];
            out[2] = a[3] * b[2] + b[3] * a[2] + a[0] * b[1] - a[1] * b[0];
            out[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
        }

        /** \brief The rotation vector of q relative to \e ref: log(conj(ref) q), norm in [0, pi]. */
        void logRelative(const double *ref, const double *q, double *v)
        {
            const double conj[4] = {-ref[0], -ref[1], -ref[2], ref[3]};
            double d[4];
            multiply(conj, q, d);
            if (d[3] < 0.0)
                for (double &c : d)
                    c = -c;
            const double s = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            // theta = 2 atan2(s, w); theta / s -> 2 / w as s -> 0 (relative error s^2 / 3 below 1e-8).
            const double scale = s > 1e-8 ? 2.0 * std::atan2(s, d[3]) / s : 2.0 / d[3];
            for (int c = 0; c < 3; ++c)
                v[c] = d[c] * scale;
        }

        /** \brief ref exp(v), normalised, into q (x, y, z, w). */
        void expRelative(const double *ref, const double *v, double *q)
        {
            const double theta = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            const double k = theta > 1e-8 ? std::sin(0.5 * theta) / theta : 0.5 - theta * theta / 48.0;
            const double d[4] = {k * v[0], k * v[1], k * v[2], std::cos(0.5 * theta)};
            multiply(ref, d, q);
            const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            for (int c = 0; c < 4; ++c)
                q[c] /= n;
        }

        /** \brief \e a wrapped to [-pi, pi) as SO2StateSpace::enforceBounds does. */
        double wrapAngle(double a)
        {
            double w = std::remainder(a, 2.0 * kPi);
            if (w >= kPi)
                w -= 2.0 * kPi;
            return w;
        }
    } // namespace

    std::string StateParametrisation::supportedSpaces()
    {
        return "RealVectorStateSpace (finite bounds), SO2StateSpace, SO3StateSpace and compound spaces of "
               "them (SE2StateSpace, DubinsStateSpace, ReedsSheppStateSpace, SE3StateSpace)";
    }

    std::unique_ptr<StateParametrisation> StateParametrisation::create(const ob::StateSpacePtr &space,
                                                                       std::string &why)
    {
        std::unique_ptr<StateParametrisation> p(new StateParametrisation);
        std::vector<unsigned int> path;
        if (!p->addLeaves(space, path, why))
            return nullptr;
        if (p->dim_ == 0)
        {
            why = "the state space '" + space->getName() + "' has no coordinates";
            return nullptr;
        }
        p->realVector_ = dynamic_cast<const ob::RealVectorStateSpace *>(space.get()) != nullptr;
        p->lower_.assign(p->dim_, 0.0);
        p->upper_.assign(p->dim_, 0.0);
        p->setReference(nullptr);
        return p;
    }

    bool StateParametrisation::addLeaves(const ob::StateSpacePtr &space, std::vector<unsigned int> &path,
                                         std::string &why)
    {
        Leaf leaf;
        leaf.path = path;
        leaf.offset = dim_;
        if (const auto *rv = dynamic_cast<const ob::RealVectorStateSpace *>(space.get()))
        {
            const ob::RealVectorBounds &b = rv->getBounds();
            leaf.kind = Kind::RealVector;
            leaf.count = rv->getDimension();
            for (unsigned int j = 0; j < leaf.count; ++j)
                if (!std::isfinite(b.low[j]) || !std::isfinite(b.high[j]) || b.low[j] > b.high[j])
                {
                    std::ostringstream msg;
                    msg.precision(12);
                    msg << "needs finite bounds low <= high on every coordinate of the RealVectorStateSpace '"
                        << space->getName() << "' (waypoints are drawn uniformly in them); coordinate " << j
                        << " has [" << b.low[j] << ", " << b.high[j] << "]";
                    why = msg.str();
                    return false;
                }
            leaf.low = b.low;
            leaf.high = b.high;
        }
        else if (dynamic_cast<const ob::SO2StateSpace *>(space.get()) != nullptr)
        {
            leaf.kind = Kind::SO2;
            leaf.count = 1;
            rotations_ = true;
        }
        else if (dynamic_cast<const ob::SO3StateSpace *>(space.get()) != nullptr)
        {
            leaf.kind = Kind::SO3;
            leaf.count = 3;
            rotations_ = true;
        }
        else if (space->isCompound())
        {
            const auto *compound = space->as<ob::CompoundStateSpace>();
            for (unsigned int i = 0; i < compound->getSubspaceCount(); ++i)
            {
                path.push_back(i);
                const bool ok = addLeaves(compound->getSubspace(i), path, why);
                path.pop_back();
                if (!ok)
                    return false;
            }
            return true;
        }
        else
        {
            why = "has no parametrisation for the state space '" + space->getName() + "'" +
                  (path.empty() ? "" : " (a component of a compound space)") +
                  "; supported: " + supportedSpaces();
            return false;
        }
        dim_ += leaf.count;
        rotationCoordinate_.insert(rotationCoordinate_.end(), leaf.count,
                                   leaf.kind == Kind::RealVector ? 0 : 1);
        leaves_.push_back(std::move(leaf));
        return true;
    }

    const ob::State *StateParametrisation::leafState(const ob::State *root, const Leaf &leaf)
    {
        const ob::State *s = root;
        for (const unsigned int i : leaf.path)
            s = s->as<ob::CompoundState>()->components[i];
        return s;
    }

    ob::State *StateParametrisation::leafState(ob::State *root, const Leaf &leaf)
    {
        ob::State *s = root;
        for (const unsigned int i : leaf.path)
            s = s->as<ob::CompoundState>()->components[i];
        return s;
    }

    void StateParametrisation::setReference(const ob::State *reference)
    {
        for (Leaf &leaf : leaves_)
        {
            double *lo = lower_.data() + leaf.offset, *hi = upper_.data() + leaf.offset;
            switch (leaf.kind)
            {
            case Kind::RealVector:
                std::copy(leaf.low.begin(), leaf.low.end(), lo);
                std::copy(leaf.high.begin(), leaf.high.end(), hi);
                break;
            case Kind::SO2:
                leaf.ref[0] =
                    reference ? leafState(reference, leaf)->as<ob::SO2StateSpace::StateType>()->value : 0.0;
                lo[0] = leaf.ref[0] - kPi;
                hi[0] = leaf.ref[0] + kPi;
                break;
            case Kind::SO3:
                if (reference != nullptr)
                {
                    const auto *q = leafState(reference, leaf)->as<ob::SO3StateSpace::StateType>();
                    leaf.ref[0] = q->x;
                    leaf.ref[1] = q->y;
                    leaf.ref[2] = q->z;
                    leaf.ref[3] = q->w;
                }
                else
                {
                    leaf.ref[0] = leaf.ref[1] = leaf.ref[2] = 0.0;
                    leaf.ref[3] = 1.0;
                }
                std::fill(lo, lo + 3, -kPi);
                std::fill(hi, hi + 3, kPi);
                break;
            }
        }
    }

    void StateParametrisation::toVector(const ob::State *state, double *x) const
    {
        for (const Leaf &leaf : leaves_)
        {
            const ob::State *s = leafState(state, leaf);
            double *v = x + leaf.offset;
            switch (leaf.kind)
            {
            case Kind::RealVector:
            {
                const double *values = s->as<ob::RealVectorStateSpace::StateType>()->values;
                std::copy(values, values + leaf.count, v);
                break;
            }
            case Kind::SO2:
                v[0] = leaf.ref[0] + wrapAngle(s->as<ob::SO2StateSpace::StateType>()->value - leaf.ref[0]);
                break;
            case Kind::SO3:
            {
                const auto *r = s->as<ob::SO3StateSpace::StateType>();
                const double q[4] = {r->x, r->y, r->z, r->w};
                logRelative(leaf.ref, q, v);
                break;
            }
            }
        }
    }

    void StateParametrisation::fromVector(const double *x, ob::State *state) const
    {
        for (const Leaf &leaf : leaves_)
        {
            ob::State *s = leafState(state, leaf);
            const double *v = x + leaf.offset;
            switch (leaf.kind)
            {
            case Kind::RealVector:
                std::copy(v, v + leaf.count, s->as<ob::RealVectorStateSpace::StateType>()->values);
                break;
            case Kind::SO2:
                s->as<ob::SO2StateSpace::StateType>()->value = wrapAngle(v[0]);
                break;
            case Kind::SO3:
            {
                double q[4];
                expRelative(leaf.ref, v, q);
                auto *r = s->as<ob::SO3StateSpace::StateType>();
                r->x = q[0];
                r->y = q[1];
                r->z = q[2];
                r->w = q[3];
                break;
            }
            }
        }
    }

    void StateParametrisation::enforce(double *x) const
    {
        for (const Leaf &leaf : leaves_)
        {
            double *v = x + leaf.offset;
            switch (leaf.kind)
            {
            case Kind::RealVector:
                for (unsigned int j = 0; j < leaf.count; ++j)
                    v[j] = std::min(std::max(v[j], leaf.low[j]), leaf.high[j]);
                break;
            case Kind::SO2:
                v[0] = leaf.ref[0] + std::remainder(v[0] - leaf.ref[0], 2.0 * kPi);
                break;
            case Kind::SO3:
            {
                const double theta = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                if (theta > kPi)
                {
                    // The same rotation with an angle in [-pi, pi] about the same axis.
                    const double s = std::remainder(theta, 2.0 * kPi) / theta;
                    for (int c = 0; c < 3; ++c)
                        v[c] *= s;
                }
                break;
            }
            }
        }
    }

    void StateParametrisation::sample(ompl::RNG &rng, double *x) const
    {
        for (const Leaf &leaf : leaves_)
        {
            double *v = x + leaf.offset;
            switch (leaf.kind)
            {
            case Kind::RealVector:
                for (unsigned int j = 0; j < leaf.count; ++j)
                    v[j] = rng.uniformReal(leaf.low[j], leaf.high[j]);
                break;
            case Kind::SO2:
                v[0] = rng.uniformReal(leaf.ref[0] - kPi, leaf.ref[0] + kPi);
                break;
            case Kind::SO3:
            {
                double q[4];
                rng.quaternion(q);
                logRelative(leaf.ref, q, v);
                break;
            }
            }
        }
    }
} // namespace mhplan
