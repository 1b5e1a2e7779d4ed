// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: pictures of OMPL.app problems (docs/omplapp.md, "Pictures"): `mhplan plan PROBLEM.cfg --svg FILE`
   draws the problem from above (the environment's triangles projected onto the x-y plane) with the path and
   the robot's footprint at poses along it; `mhplan worlds PROBLEM.cfg --json` exports the meshes as the
   planner uses them (the robot centred), which the report draws (analysis/mhplan_analysis/meshes.py). */
#include "src/cli/Args.h"
#include "src/cli/Commands.h"
#include "src/cli/Json.h"
#include "src/cli/CfgDraw.h"

#include "src/draw/Svg.h"

#include <ompl/base/ScopedState.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan::cli
{
    namespace
    {
        /** The triangles of \e mesh placed by \e pose and projected onto the x-y plane, as SVG path data in
            the drawing's coordinates \e at. */
        template <typename At>
        std::string projected(const TriangleMesh &mesh, const Eigen::Isometry3d &pose, const At &at)
        {
            std::ostringstream d;
            d.precision(6);
            for (const auto &t : mesh.triangles)
            {
                for (int k = 0; k < 3; ++k)
                {
                    const Eigen::Vector3d v = pose * mesh.vertices[t[k]];
                    const auto [x, y] = at(v);
                    d << (k == 0 ? "M" : "L") << x << " " << y << " ";
                }
                d << "Z ";
            }
            return d.str();
        }

        /** The rotation angle between two placements (radians). */
        double turned(const Eigen::Isometry3d &a, const Eigen::Isometry3d &b)
        {
            return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
        }
    } // namespace

    std::vector<Eigen::Isometry3d> footprintPlacements(const MeshRigidModel &model,
                                                       const ob::SpaceInformationPtr &si,
                                                       const og::PathGeometric &path)
    {
        const double step = std::max(model.reach() / 4.0, 1e-3);
        const std::size_t count = path.getStateCount();
        std::vector<Eigen::Isometry3d> poses;
        ob::ScopedState<> s(si->getStateSpace());
        for (std::size_t i = 0; i + 1 < count; ++i)
        {
            const ob::State *a = path.getState(i), *b = path.getState(i + 1);
            const double n = std::max(
                1.0, std::min(1e4, std::ceil(meshMotionBound(model, *si->getStateSpace(), a, b) / step)));
            for (double k = 0; k < n; ++k)
            {
                si->getStateSpace()->interpolate(a, b, k / n, s.get());
                poses.push_back(model.placement(s.get()));
            }
        }
        if (count > 0)
            poses.push_back(model.placement(path.getState(count - 1)));
        double travel = 0.0;
        for (std::size_t i = 1; i < poses.size(); ++i)
            travel += (poses[i].translation() - poses[i - 1].translation()).norm();
        // As `plan --svg` on 2D worlds (docs/cli.md): every max(1.5 reach, travel / 60) metres and wherever
        // the robot turned by 30 degrees since the last one drawn.
        const double spacing = std::max(1.5 * model.reach(), travel / 60.0);
        std::vector<Eigen::Isometry3d> out;
        double since = 0.0;
        for (std::size_t i = 0; i < poses.size(); ++i)
        {
            if (i > 0)
                since += (poses[i].translation() - poses[i - 1].translation()).norm();
            if (out.empty() || since >= spacing || turned(out.back(), poses[i]) >= M_PI / 6.0 ||
                i + 1 == poses.size())
            {
                out.push_back(poses[i]);
                since = 0.0;
            }
        }
        return out;
    }

    std::string cfgProblemSvg(const LoadedCfgProblem &p, const ob::SpaceInformationPtr &si,
                              const og::PathGeometric *path)
    {
        const MeshRigidModel &model = *p.spec.model;
        const Eigen::AlignedBox3d &v = p.spec.volume;
        const double width = v.max().x() - v.min().x(), height = v.max().y() - v.min().y();
        const double scale = 800.0 / std::max(width, height), margin = 20.0;
        const auto at = [&](const Eigen::Vector3d &q)
        {
            return std::pair<double, double>{margin + (q.x() - v.min().x()) * scale,
                                             margin + (v.max().y() - q.y()) * scale};
        };
        std::ostringstream svg;
        svg.precision(6);
        svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width * scale + 2 * margin
            << "\" height=\"" << height * scale + 2 * margin << "\">\n<title>" << svgEscape(p.cfg.name)
            << " (" << p.cfg.spaceLabel() << (p.cfg.se3 ? ", seen from above)" : ", from above)")
            << "</title>\n"
            << "<rect x=\"" << margin << "\" y=\"" << margin << "\" width=\"" << width * scale
            << "\" height=\"" << height * scale << "\" fill=\"white\" stroke=\"black\"/>\n";
        svg << "<path class=\"environment\" fill=\"#9a9a9a\" fill-opacity=\"0.6\" stroke=\"#444444\" "
               "stroke-width=\"0.3\" d=\""
            << projected(model.environmentMesh(), Eigen::Isometry3d::Identity(), at) << "\"/>\n";
        const auto footprint = [&](const Eigen::Isometry3d &pose, const std::string &color,
                                   const std::string &cls, double opacity)
        {
            svg << "<path class=\"" << cls << "\" fill=\"" << color << "\" fill-opacity=\"" << opacity
                << "\" stroke=\"" << color << "\" stroke-width=\"0.5\" d=\""
                << projected(model.robotMesh(), pose, at) << "\"/>\n";
        };
        const auto placed = [&](const RigidPose &r)
        {
            Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
            t.translation() = r.position;
            t.linear() = r.orientation.toRotationMatrix();
            return t;
        };
        if (path != nullptr)
        {
            for (const auto &pose : footprintPlacements(model, si, *path))
                footprint(pose, "#d62728", "footprint", 0.12);
            og::PathGeometric driven(*path); // a car's curve, sampled every eighth of the turning radius
            if (!p.cfg.car.empty())
                driven.interpolate(static_cast<unsigned>(
                    std::min(1e5, std::ceil(8.0 * path->length() / p.cfg.turningRadius) + 1.0)));
            svg << "<polyline class=\"path\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\" points=\"";
            for (std::size_t i = 0; i < driven.getStateCount(); ++i)
            {
                const auto [x, y] = at(model.placement(driven.getState(i)).translation());
                svg << x << "," << y << " ";
            }
            svg << "\"/>\n";
        }
        footprint(placed(p.spec.start), "#2ca02c", "start", 0.35);
        footprint(placed(p.spec.goal), "#1f77b4", "goal", 0.35);
        svg << "</svg>\n";
        return svg.str();
    }

    namespace
    {
        void writeMesh(JsonWriter &json, const TriangleMesh &mesh)
        {
            json.beginObject().key("vertices").beginArray();
            for (const auto &v : mesh.vertices)
                json.beginArray().value(v.x()).value(v.y()).value(v.z()).endArray();
            json.endArray().key("triangles").beginArray();
            for (const auto &t : mesh.triangles)
                json.beginArray().value(t[0]).value(t[1]).value(t[2]).endArray();
            json.endArray().endObject();
        }

        void writePose(JsonWriter &json, const RigidPose &r)
        {
            const Eigen::Vector3d &x = r.position;
            const Eigen::Quaterniond &q = r.orientation;
            json.beginObject().key("position").beginArray().value(x.x()).value(x.y()).value(x.z()).endArray();
            json.key("orientation")
                .beginArray()
                .value(q.w())
                .value(q.x())
                .value(q.y())
                .value(q.z())
                .endArray();
            json.endObject();
        }
    } // namespace

    int cmdWorldsCfg(const Argv &argv)
    {
        const Args args("worlds", argv, {{}, {}, {"json"}});
        std::vector<LoadedCfgProblem> problems;
        for (const auto &f : args.positional())
            problems.push_back(loadCfgProblem(f)); // refuses a bad file before anything is printed
        if (!args.has("json"))
        {
            for (const auto &p : problems)
                std::cout << p.cfg.name << "\t" << p.cfg.spaceName() << "\t"
                          << (p.cfg.world3d
                                  ? std::to_string(p.spec.model->obstacles().size()) + " obstacles, "
                                  : "")
                          << p.spec.model->environmentTriangles()
                          << (p.cfg.world3d ? " mesh triangles\t" : " environment triangles\t")
                          << p.spec.model->robotTriangles() << " robot triangles\treach "
                          << p.spec.model->reach() << "\t" << p.cfg.file << "\n";
            return 0;
        }
        JsonWriter out(std::cout);
        out.beginObject().field("command", "worlds").key("problems").beginArray();
        for (const auto &p : problems)
        {
            const Eigen::AlignedBox3d &v = p.spec.volume;
            out.beginObject().field("name", p.cfg.name).field("file", p.cfg.file);
            out.field("space", p.cfg.spaceName());
            out.field("robot_reach", p.spec.model->reach());
            if (!p.cfg.car.empty())
                out.field("turning_radius", p.cfg.turningRadius);
            out.key("volume").beginObject();
            out.key("min").beginArray().value(v.min().x()).value(v.min().y()).value(v.min().z()).endArray();
            out.key("max").beginArray().value(v.max().x()).value(v.max().y()).value(v.max().z()).endArray();
            out.endObject();
            out.key("start");
            writePose(out, p.spec.start);
            out.key("goal");
            writePose(out, p.spec.goal);
            out.key("environment");
            writeMesh(out, p.spec.model->environmentMesh());
            out.key("robot"); // centred: a state's position places its origin
            writeMesh(out, p.spec.model->robotMesh());
            out.endObject();
        }
        out.endArray().endObject().finish();
        return 0;
    }
} // namespace mhplan::cli
