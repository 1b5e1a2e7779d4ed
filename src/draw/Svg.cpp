// SPDX-License-Identifier: BSD-3-Clause
#include "src/draw/Svg.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace mhplan
{
    namespace
    {
        std::string escape(const std::string &s)
        {
            std::string out;
            for (char c : s)
            {
                switch (c)
                {
                case '<':
                    out += "&lt;";
                    break;
                case '>':
                    out += "&gt;";
                    break;
                case '&':
                    out += "&amp;";
                    break;
                case '"':
                    out += "&quot;";
                    break;
                default:
                    out += c;
                }
            }
            return out;
        }
    } // namespace

    std::string worldSvg(const World &world, const Query *query, const std::vector<SvgPath> &paths,
                         double pixelsPerMetre, const std::vector<SvgFootprint> &footprints)
    {
        const Box &b = world.bounds;
        if (pixelsPerMetre <= 0.0)
            pixelsPerMetre = 800.0 / std::max(b.width(), b.height());
        const double margin = 20.0;
        const double legend = paths.empty() ? 0.0 : 18.0 * static_cast<double>(paths.size()) + 10.0;
        const double w = b.width() * pixelsPerMetre + 2 * margin;
        const double h = b.height() * pixelsPerMetre + 2 * margin + legend;
        auto X = [&](double x) { return margin + (x - b.xmin) * pixelsPerMetre; };
        auto Y = [&](double y) { return margin + (b.ymax - y) * pixelsPerMetre; };

        std::ostringstream s;
        s << std::fixed << std::setprecision(2);
        s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
          << "\" viewBox=\"0 0 " << w << " " << h << "\">\n";
        s << "<title>" << escape(world.name) << "</title>\n";
        s << "<rect x=\"0\" y=\"0\" width=\"" << w << "\" height=\"" << h << "\" fill=\"white\"/>\n";
        s << worldSvgShapes(world, pixelsPerMetre, margin);
        for (const SvgFootprint &f : footprints)
        {
            s << "<polygon class=\"footprint\" fill=\"" << escape(f.color)
              << "\" fill-opacity=\"0.15\" stroke=\"" << escape(f.color)
              << "\" stroke-width=\"1.2\" points=\"";
            for (const auto &v : f.vertices)
                s << X(v.x) << "," << Y(v.y) << " ";
            s << "\"><title>" << escape(f.title) << "</title></polygon>\n";
        }
        for (std::size_t i = 0; i < paths.size(); ++i)
        {
            const SvgPath &p = paths[i];
            s << "<polyline fill=\"none\" stroke=\"" << escape(p.color)
              << "\" stroke-width=\"2\" stroke-linejoin=\"round\" points=\"";
            for (const auto &v : p.points)
                s << X(v.x) << "," << Y(v.y) << " ";
            s << "\"/>\n";
            if (world.robotRadius > 0.0)
                for (const auto &v : p.points)
                    s << "<circle cx=\"" << X(v.x) << "\" cy=\"" << Y(v.y) << "\" r=\""
                      << world.robotRadius * pixelsPerMetre << "\" fill=\"none\" stroke=\"" << escape(p.color)
                      << "\" stroke-opacity=\"0.3\"/>\n";
            const double ly = b.height() * pixelsPerMetre + 2 * margin + 14.0 + 18.0 * static_cast<double>(i);
            s << "<line x1=\"" << margin << "\" y1=\"" << ly - 4 << "\" x2=\"" << margin + 24 << "\" y2=\""
              << ly - 4 << "\" stroke=\"" << escape(p.color) << "\" stroke-width=\"3\"/>\n";
            s << "<text x=\"" << margin + 30 << "\" y=\"" << ly
              << "\" font-family=\"sans-serif\" font-size=\"13\">" << escape(p.label) << "</text>\n";
        }
        if (query != nullptr)
        {
            s << "<circle cx=\"" << X(query->start.x) << "\" cy=\"" << Y(query->start.y)
              << "\" r=\"6\" fill=\"#2ca02c\"><title>start</title></circle>\n";
            s << "<circle cx=\"" << X(query->goal.x) << "\" cy=\"" << Y(query->goal.y)
              << "\" r=\"6\" fill=\"#1f77b4\"><title>goal</title></circle>\n";
        }
        s << "</svg>\n";
        return s.str();
    }

    std::string worldSvgShapes(const World &world, double pixelsPerMetre, double margin)
    {
        const Box &b = world.bounds;
        auto X = [&](double x) { return margin + (x - b.xmin) * pixelsPerMetre; };
        auto Y = [&](double y) { return margin + (b.ymax - y) * pixelsPerMetre; };
        std::ostringstream s;
        s << std::fixed << std::setprecision(2);
        s << "<rect x=\"" << X(b.xmin) << "\" y=\"" << Y(b.ymax) << "\" width=\""
          << b.width() * pixelsPerMetre << "\" height=\"" << b.height() * pixelsPerMetre
          << "\" fill=\"#fafafa\" stroke=\"black\"/>\n";
        if (world.isGrid())
        {
            const OccupancyGrid &g = *world.grid;
            const double cs = g.cellSize() * pixelsPerMetre;
            s << "<g fill=\"#444\">\n";
            for (int iy = 0; iy < g.height(); ++iy)
            {
                // Merge runs of blocked cells in a row into one rectangle to keep big maps small.
                int ix = 0;
                while (ix < g.width())
                {
                    if (!g.blocked(ix, iy))
                    {
                        ++ix;
                        continue;
                    }
                    int end = ix;
                    while (end < g.width() && g.blocked(end, iy))
                        ++end;
                    const Box cb = g.cellBox(ix, iy);
                    s << "<rect x=\"" << X(cb.xmin) << "\" y=\"" << Y(cb.ymax) << "\" width=\""
                      << cs * (end - ix) << "\" height=\"" << cs << "\"/>\n";
                    ix = end;
                }
            }
            s << "</g>\n";
        }
        s << "<g fill=\"#888\" stroke=\"#333\" stroke-width=\"1\">\n";
        for (const auto &c : world.circles)
            s << "<circle cx=\"" << X(c.center.x) << "\" cy=\"" << Y(c.center.y) << "\" r=\""
              << c.radius * pixelsPerMetre << "\"/>\n";
        for (const auto &p : world.polygons)
        {
            s << "<polygon points=\"";
            for (const auto &v : p.vertices)
                s << X(v.x) << "," << Y(v.y) << " ";
            s << "\"/>\n";
        }
        s << "</g>\n";
        return s.str();
    }

    std::string svgEscape(const std::string &text)
    {
        return escape(text);
    }

    void writeTextFile(const std::string &path, const std::string &text)
    {
        std::ofstream out(path);
        if (!out)
            throw InputError(path + ": cannot open for writing");
        out << text;
        if (!out)
            throw InputError(path + ": write failed");
    }
} // namespace mhplan
