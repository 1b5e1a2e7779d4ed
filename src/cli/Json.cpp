// SPDX-License-Identifier: BSD-3-Clause
#include "src/cli/Json.h"

#include "src/base/Parameters.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace mhplan::cli
{
    std::string JsonWriter::quote(const std::string &text)
    {
        std::string out = "\"";
        for (const char c : text)
        {
            switch (c)
            {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20)
                {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned int>(c));
                    out += buf;
                }
                else
                    out += c;
            }
        }
        return out + "\"";
    }

    void JsonWriter::newline()
    {
        out_ << "\n" << std::string(2 * stack_.size(), ' ');
    }

    void JsonWriter::beforeValue()
    {
        if (done_)
            throw std::logic_error("JsonWriter: a value after the end of the document");
        if (stack_.empty())
            return;
        Level &top = stack_.back();
        if (top.object)
        {
            if (!top.keyPending)
                throw std::logic_error("JsonWriter: a value in an object without a key");
            top.keyPending = false;
            return;
        }
        if (!top.empty)
            out_ << ",";
        top.empty = false;
        newline();
    }

    JsonWriter &JsonWriter::key(const std::string &name)
    {
        if (stack_.empty() || !stack_.back().object || stack_.back().keyPending)
            throw std::logic_error("JsonWriter: key '" + name + "' outside an object or after a key");
        Level &top = stack_.back();
        if (!top.empty)
            out_ << ",";
        top.empty = false;
        top.keyPending = true;
        newline();
        out_ << quote(name) << ": ";
        return *this;
    }

    JsonWriter &JsonWriter::beginObject()
    {
        beforeValue();
        out_ << "{";
        stack_.push_back({true});
        return *this;
    }

    JsonWriter &JsonWriter::beginArray()
    {
        beforeValue();
        out_ << "[";
        stack_.push_back({false});
        return *this;
    }

    JsonWriter &JsonWriter::endObject()
    {
        if (stack_.empty() || !stack_.back().object || stack_.back().keyPending)
            throw std::logic_error("JsonWriter: endObject without an open object (or after a key)");
        const bool empty = stack_.back().empty;
        stack_.pop_back();
        if (!empty)
            newline();
        out_ << "}";
        done_ = stack_.empty();
        return *this;
    }

    JsonWriter &JsonWriter::endArray()
    {
        if (stack_.empty() || stack_.back().object)
            throw std::logic_error("JsonWriter: endArray without an open array");
        const bool empty = stack_.back().empty;
        stack_.pop_back();
        if (!empty)
            newline();
        out_ << "]";
        done_ = stack_.empty();
        return *this;
    }

    JsonWriter &JsonWriter::value(const std::string &v)
    {
        beforeValue();
        out_ << quote(v);
        done_ = stack_.empty();
        return *this;
    }

    JsonWriter &JsonWriter::value(double v)
    {
        if (!std::isfinite(v))
            return null();
        beforeValue();
        out_ << formatParameter(v);
        done_ = stack_.empty();
        return *this;
    }

    JsonWriter &JsonWriter::integer(long long v)
    {
        beforeValue();
        out_ << v;
        done_ = stack_.empty();
        return *this;
    }

    JsonWriter &JsonWriter::value(bool v)
    {
        beforeValue();
        out_ << (v ? "true" : "false");
        done_ = stack_.empty();
        return *this;
    }

    JsonWriter &JsonWriter::null()
    {
        beforeValue();
        out_ << "null";
        done_ = stack_.empty();
        return *this;
    }

    JsonWriter &JsonWriter::point(const Vec2 &p)
    {
        beforeValue();
        // A point stays on one line: [x, y].
        out_ << "[";
        out_ << (std::isfinite(p.x) ? formatParameter(p.x) : "null") << ", "
             << (std::isfinite(p.y) ? formatParameter(p.y) : "null") << "]";
        done_ = stack_.empty();
        return *this;
    }

    JsonWriter &JsonWriter::points(const std::vector<Vec2> &pts)
    {
        beginArray();
        for (const Vec2 &p : pts)
            point(p);
        return endArray();
    }

    void JsonWriter::finish()
    {
        if (!done_ || !stack_.empty())
            throw std::logic_error("JsonWriter: the document is not complete");
        out_ << "\n";
    }

    void writeWorldSummary(JsonWriter &json, const World &world)
    {
        json.beginObject()
            .field("name", world.name)
            .field("file", world.file)
            .field("type", world.type())
            .field("obstacles", world.obstacleCount())
            .field("robot_radius", world.robotRadius);
        writeSpaceFields(json, world);
        json.endObject();
    }

    void writeSpaceFields(JsonWriter &json, const World &world)
    {
        if (!world.isRigid())
            return; // r2 worlds: the fields they always had, no more
        json.field("space", toString(world.space));
        json.key("turning_radius");
        world.turningRadius > 0.0 ? json.value(world.turningRadius) : json.null();
        json.key("robot_polygon");
        world.robotPolygon.empty() ? json.null() : json.points(world.robotPolygon);
        json.field("robot_reach", world.robotReach());
    }

    void writeQuery(JsonWriter &json, const Query &query, bool withYaw)
    {
        json.beginObject().field("name", query.name);
        json.key("start").point(query.start);
        json.key("goal").point(query.goal);
        if (withYaw)
            json.field("start_yaw", query.startYaw).field("goal_yaw", query.goalYaw);
        json.endObject();
    }

    void writeWorld(JsonWriter &json, const World &world, const std::string &file)
    {
        json.beginObject()
            .field("name", world.name)
            .field("file", file)
            .field("type", world.type())
            .field("description", world.description)
            .field("source", world.source)
            .field("assumptions", world.assumptions)
            .field("robot_radius", world.robotRadius)
            .field("obstacles", world.obstacleCount());
        writeSpaceFields(json, world);
        json.key("bounds")
            .beginObject()
            .field("xmin", world.bounds.xmin)
            .field("xmax", world.bounds.xmax)
            .field("ymin", world.bounds.ymin)
            .field("ymax", world.bounds.ymax)
            .endObject();
        json.key("circles").beginArray();
        for (const Circle &c : world.circles)
        {
            json.beginObject();
            json.key("center").point(c.center);
            json.field("radius", c.radius).endObject();
        }
        json.endArray();
        json.key("polygons").beginArray();
        for (const Polygon &p : world.polygons)
        {
            json.beginObject().field("kind", p.kind);
            json.key("vertices").points(p.vertices);
            json.endObject();
        }
        json.endArray();
        json.key("grid");
        if (world.isGrid())
        {
            const OccupancyGrid &g = *world.grid;
            json.beginObject()
                .field("width", g.width())
                .field("height", g.height())
                .field("cell_size", g.cellSize());
            json.key("origin").point(g.origin());
            json.field("blocked", g.blockedCount());
            json.key("rows").beginArray();
            std::string row(static_cast<std::size_t>(g.width()), '.');
            for (int iy = g.height() - 1; iy >= 0; --iy)
            {
                for (int ix = 0; ix < g.width(); ++ix)
                    row[static_cast<std::size_t>(ix)] = g.blocked(ix, iy) ? '@' : '.';
                json.value(row);
            }
            json.endArray().endObject();
        }
        else
            json.null();
        json.key("queries").beginArray();
        for (const Query &q : world.queries)
            writeQuery(json, q, world.isRigid());
        json.endArray().endObject();
    }
} // namespace mhplan::cli
