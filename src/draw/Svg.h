// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: SVG drawings of worlds and paths. */
#ifndef MHPLAN_SVG_H
#define MHPLAN_SVG_H

#include "src/base/World.h"

#include <string>
#include <vector>

namespace mhplan
{
    /** \brief A path to draw. */
    struct SvgPath
    {
        std::vector<Vec2> points;
        std::string label;
        std::string color{"#d62728"};
    };

    /** \brief A robot's outline placed in the world (world-frame vertices), drawn filled and translucent. */
    struct SvgFootprint
    {
        std::vector<Vec2> vertices;
        std::string color{"#d62728"};
        std::string title; ///< the element's tooltip ("start", "goal", "pose 3", ...)
    };

    /** \brief An SVG document of the world (bounds, obstacles, the query's start and goal) and paths, y up;
        \e footprints (a polygon robot's outline at poses along the path, docs/cli.md "plan") are drawn
        beneath the paths, as elements \c polygon of class \c footprint. */
    std::string worldSvg(const World &world, const Query *query, const std::vector<SvgPath> &paths,
                         double pixelsPerMetre = 0.0, const std::vector<SvgFootprint> &footprints = {});

    /** \brief The world's SVG elements (bounds, grid cells, obstacles) without a document around them, in
        worldSvg's coordinates: x' = margin + (x - xmin) * pixelsPerMetre, y' = margin + (ymax - y) *
        pixelsPerMetre. For drawings that add their own content (SimRender.h). */
    std::string worldSvgShapes(const World &world, double pixelsPerMetre, double margin);

    /** \brief Text escaped for SVG/XML content and attribute values. */
    std::string svgEscape(const std::string &text);

    /** \brief Write text to a file; throws InputError naming the file on failure. */
    void writeTextFile(const std::string &path, const std::string &text);
} // namespace mhplan

#endif
