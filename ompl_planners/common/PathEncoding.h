// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the continuous waypoint encoding of docs/algorithms.md 1.1, shared by every population planner.
 */
#ifndef MHPLAN_PATH_ENCODING_H
#define MHPLAN_PATH_ENCODING_H

#include "src/base/Geometry.h"

#include <cstddef>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief How a waypoint vector becomes a path (docs/algorithms.md 1.1). */
    enum class PathDecoding
    {
        Polyline, ///< start, the m waypoints, goal joined by straight segments
        Spline    ///< [LRSMA] 4.4: not-a-knot cubic spline of each coordinate against t = 0..m+1, n samples
    };

    /** \brief Parse "polyline" or "spline"; throws std::invalid_argument naming the parameter otherwise. */
    PathDecoding parsePathDecoding(const std::string &name);
    /** \brief "polyline" or "spline". */
    std::string toString(PathDecoding decoding);

    /** \brief Non-owning view of a polyline in R^k: \c count points of \c dim coordinates each, stored
        contiguously (point i is data[i * dim] .. data[i * dim + dim - 1]). */
    struct PointsView
    {
        /** \brief First coordinate of the first point. */
        const double *data{nullptr};
        /** \brief Number of points. */
        std::size_t count{0};
        /** \brief Coordinates per point (the state space's dimension k). */
        unsigned int dim{2};

        /** \brief Number of points. */
        std::size_t size() const { return count; }
        /** \brief Coordinates of point i. */
        const double *operator[](std::size_t i) const { return data + i * dim; }
    };

    /** \brief Decodes a candidate x = (waypoint 1, ..., waypoint m), each waypoint k coordinates (k = the
        state space's dimension; 2m values in the planar worlds), into a path and into the interpolation
        points that the [LRSMA] collision term (docs/algorithms.md 1.2) is measured on.

        - Spline: each coordinate is splined separately against t = 0, 1, ..., m + 1 (start at 0, goal at
          m + 1), as [LRSMA] does for x and y; the path is the polyline through the n spline samples; the
          samples are the same points. Works in any dimension k.
        - Polyline: the path is start, waypoints, goal; the samples are n points of the same piecewise-linear
          curve at the same evenly spaced parameters t as the spline's (so a segment crossing an obstacle is
          penalised, not only waypoints inside one). This sampling of polylines is mhplan's choice (open).

        Not-a-knot end conditions as MATLAB's spline(): with m + 2 = 2 points a line, 3 points a parabola,
        4 points the single cubic through them. All buffers are allocated by configure(); decode() does not
        allocate. Not thread-safe (one decoder per planner). */
    class WaypointDecoder
    {
      public:
        /** \brief Set the query (\e dim coordinates each) and the encoding; allocates the buffers.
            \e samples >= 2, \e dim >= 1. */
        void configure(const double *start, const double *goal, unsigned int dim, unsigned int waypoints,
                       PathDecoding decoding, unsigned int samples);
        /** \brief configure() for a planar query (k = 2). */
        void configure(const Vec2 &start, const Vec2 &goal, unsigned int waypoints, PathDecoding decoding,
                       unsigned int samples);

        /** \brief Decode \e x (dimension() values); the results stay valid until the next call. */
        void decode(const double *x);

        /** \brief The decoded path (first point start, last point goal), any dimension. */
        PointsView pathView() const { return {path_.data(), path_.size() / dim_, dim_}; }
        /** \brief The interpolation points of the last decode, any dimension. */
        PointsView samplesView() const
        {
            return decoding_ == PathDecoding::Spline
                       ? pathView()
                       : PointsView{samples_.data(), samples_.size() / dim_, dim_};
        }
        /** \brief The decoded path as planar points (k = 2 only; copies, so meant for tests and tools). */
        const std::vector<Vec2> &path() const;
        /** \brief The interpolation points as planar points (k = 2 only; copies). */
        const std::vector<Vec2> &samples() const;

        /** \brief Number of waypoints m. */
        unsigned int waypoints() const { return waypoints_; }
        /** \brief Dimension m k of a candidate. */
        unsigned int dimension() const { return dim_ * waypoints_; }
        /** \brief Coordinates per point k. */
        unsigned int spaceDimension() const { return dim_; }
        PathDecoding decoding() const { return decoding_; }
        /** \brief First two coordinates of the start. */
        Vec2 start() const { return {start_[0], dim_ > 1 ? start_[1] : 0.0}; }
        /** \brief First two coordinates of the goal. */
        Vec2 goal() const { return {goal_[0], dim_ > 1 ? goal_[1] : 0.0}; }

      private:
        /** \brief Second derivatives of the not-a-knot spline through coordinate \e c of the knots, unit
            spacing, written to M[0 .. knots - 1]. */
        void splineMoments(unsigned int c, double *M);
        double knot(std::size_t i, unsigned int c) const { return knots_[i * dim_ + c]; }

        unsigned int dim_{2};
        std::vector<double> start_{0.0, 0.0};
        std::vector<double> goal_{0.0, 0.0};
        unsigned int waypoints_{0};
        PathDecoding decoding_{PathDecoding::Polyline};
        unsigned int sampleCount_{2};
        /** \brief Flat point lists (dim_ values per point). */
        std::vector<double> knots_;
        std::vector<double> path_;
        std::vector<double> samples_;
        /** \brief Spline moments, knots values per coordinate. */
        std::vector<double> moments_;
        std::vector<double> rhs_, cprime_;
        mutable std::vector<Vec2> planarPath_, planarSamples_;
    };
} // namespace mhplan

#endif
