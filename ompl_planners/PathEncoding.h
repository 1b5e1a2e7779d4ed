/* mhplan: the continuous waypoint encoding of ALGORITHMS.md section 1.1, shared by every population planner.
 */
#ifndef MHPLAN_PATH_ENCODING_H
#define MHPLAN_PATH_ENCODING_H

#include "Geometry.h"

#include <string>
#include <vector>

namespace mhplan
{
    /** \brief How a waypoint vector becomes a path (ALGORITHMS.md 1.1). */
    enum class PathDecoding
    {
        Polyline, ///< start, the m waypoints, goal joined by straight segments
        Spline    ///< [LRSMA] 4.4: not-a-knot cubic spline of x(t), y(t), t = 0..m+1, sampled at n points
    };

    /** \brief Parse "polyline" or "spline"; throws std::invalid_argument naming the parameter otherwise. */
    PathDecoding parsePathDecoding(const std::string &name);
    /** \brief "polyline" or "spline". */
    std::string toString(PathDecoding decoding);

    /** \brief Decodes a candidate x = (x1, y1, ..., xm, ym) into a path and into the interpolation points
        that the [LRSMA] collision term (ALGORITHMS.md 1.2) is measured on.

        - Spline: the path is the polyline through the n spline samples; the samples are the same points.
        - Polyline: the path is start, waypoints, goal; the samples are n points of the same piecewise-linear
          curve at the same evenly spaced parameters t as the spline's (so a segment crossing an obstacle is
          penalised, not only waypoints inside one). This sampling of polylines is mhplan's choice (open).

        Not-a-knot end conditions as MATLAB's spline(): with m + 2 = 2 points a line, 3 points a parabola,
        4 points the single cubic through them. All buffers are allocated by configure(); decode() does not
        allocate. Not thread-safe (one decoder per planner). */
    class WaypointDecoder
    {
      public:
        /** \brief Set the query and the encoding; allocates the buffers. \e samples >= 2. */
        void configure(const Vec2 &start, const Vec2 &goal, unsigned int waypoints, PathDecoding decoding,
                       unsigned int samples);

        /** \brief Decode \e x (2m values); the results stay valid until the next call. */
        void decode(const double *x);

        /** \brief The decoded path (first point start, last point goal). */
        const std::vector<Vec2> &path() const { return path_; }
        /** \brief The interpolation points of the last decode. */
        const std::vector<Vec2> &samples() const
        {
            return decoding_ == PathDecoding::Spline ? path_ : samples_;
        }

        /** \brief Number of waypoints m. */
        unsigned int waypoints() const { return waypoints_; }
        /** \brief Dimension 2m of a candidate. */
        unsigned int dimension() const { return 2 * waypoints_; }
        PathDecoding decoding() const { return decoding_; }
        const Vec2 &start() const { return start_; }
        const Vec2 &goal() const { return goal_; }

      private:
        /** \brief Second derivatives of the not-a-knot spline through knots_[i].{x|y}, unit spacing. */
        void splineMoments(bool yCoordinate, std::vector<double> &moments);

        Vec2 start_;
        Vec2 goal_;
        unsigned int waypoints_{0};
        PathDecoding decoding_{PathDecoding::Polyline};
        unsigned int sampleCount_{2};
        std::vector<Vec2> knots_;
        std::vector<Vec2> path_;
        std::vector<Vec2> samples_;
        std::vector<double> mx_, my_, rhs_, cprime_;
    };
} // namespace mhplan

#endif
