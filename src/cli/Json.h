// SPDX-License-Identifier: BSD-3-Clause
/* mhplan CLI: a small streaming JSON writer for the --json output of the subcommands (field names:
   docs/cli.md). Numbers are written so that they read back exactly; a non-finite number is written as null.
 */
#ifndef MHPLAN_CLI_JSON_H
#define MHPLAN_CLI_JSON_H

#include "src/base/Geometry.h"
#include "src/base/World.h"

#include <ostream>
#include <string>
#include <vector>

namespace mhplan::cli
{
    /** \brief Writes one JSON document: objects, arrays, strings, numbers, booleans and null, indented by
        nesting. Misuse (a value where a key is expected, unbalanced ends) throws std::logic_error. */
    class JsonWriter
    {
      public:
        explicit JsonWriter(std::ostream &out) : out_(out) {}
        ~JsonWriter() = default;
        JsonWriter(const JsonWriter &) = delete;
        JsonWriter &operator=(const JsonWriter &) = delete;

        JsonWriter &beginObject();
        JsonWriter &endObject();
        JsonWriter &beginArray();
        JsonWriter &endArray();
        /** \brief The key of the next member (inside an object only). */
        JsonWriter &key(const std::string &name);

        JsonWriter &value(const std::string &v);
        JsonWriter &value(const char *v) { return value(std::string(v)); }
        JsonWriter &value(double v);
        JsonWriter &value(int v) { return integer(v); }
        JsonWriter &value(long v) { return integer(v); }
        JsonWriter &value(long long v) { return integer(v); }
        JsonWriter &value(unsigned int v) { return integer(static_cast<long long>(v)); }
        JsonWriter &value(unsigned long v) { return integer(static_cast<long long>(v)); }
        JsonWriter &value(unsigned long long v) { return integer(static_cast<long long>(v)); }
        JsonWriter &value(bool v);
        JsonWriter &null();
        /** \brief [x, y] */
        JsonWriter &point(const Vec2 &p);
        /** \brief [[x, y], ...] */
        JsonWriter &points(const std::vector<Vec2> &pts);

        /** \brief key(name).value(v) */
        template <typename T> JsonWriter &field(const std::string &name, const T &v)
        {
            key(name);
            return value(v);
        }

        /** \brief Ends the document with a newline; throws unless every object and array is closed. */
        void finish();

        /** \brief \e text as a JSON string literal (quotes included). */
        static std::string quote(const std::string &text);

      private:
        JsonWriter &integer(long long v);
        void beforeValue();
        void newline();

        struct Level
        {
            bool object;
            bool empty{true};
            bool keyPending{false};
        };
        std::ostream &out_;
        std::vector<Level> stack_;
        bool done_{false};
    };

    /** \brief The "world" member of plan and optimum: {name, file, type, obstacles, robot_radius}. */
    void writeWorldSummary(JsonWriter &json, const World &world);
    /** \brief A query: {name, start: [x, y], goal: [x, y]}, with \e withYaw also start_yaw and goal_yaw
        (radians; SE(2)-based worlds). */
    void writeQuery(JsonWriter &json, const Query &query, bool withYaw = false);
    /** \brief SE(2)-based worlds only (nothing for r2): space, turning_radius (null unless a car),
        robot_polygon (robot frame; null for a disc) and robot_reach. */
    void writeSpaceFields(JsonWriter &json, const World &world);
    /** \brief Everything `mhplan worlds --json` tells about one world, including its geometry (bounds,
        circles, polygons, grid cells as rows of '.' and '@', top row first) and queries. */
    void writeWorld(JsonWriter &json, const World &world, const std::string &file);
} // namespace mhplan::cli

#endif
