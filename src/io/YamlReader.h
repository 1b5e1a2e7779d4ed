// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: reading YAML input files (worlds, campaigns) with errors that name the file, line and field. */
#ifndef MHPLAN_YAML_READER_H
#define MHPLAN_YAML_READER_H

#include "src/base/Geometry.h"

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <set>
#include <string>

namespace mhplan
{
    /** \brief The largest YAML input file (world, scenario, campaign): 4 MiB. yaml-cpp holds several KB per
        node, so a 50 MB world of circles would take gigabytes; larger worlds belong in grid files (.map,
        .pgm), which are read row by row. */
    constexpr std::size_t kMaxYamlBytes = std::size_t{4} << 20;

    /** \brief Parse one YAML document that must be a mapping (at most kMaxYamlBytes); InputError
       "FILE:LINE:COL: malformed YAML: ..." or "FILE:1: a WHAT must be a YAML mapping (see HELP)". */
    YAML::Node loadYamlMapping(const std::string &text, const std::string &fileName, const std::string &what,
                               const std::string &help);

    /** \brief Typed access to the nodes of one YAML document. Every problem throws InputError as
        "FILE:LINE: field 'a.b[2].c': what is wrong" (the line is 1-based, from the node's mark). */
    class YamlReader
    {
      public:
        explicit YamlReader(std::string file) : file_(std::move(file)) {}

        [[noreturn]] void fail(const YAML::Node &node, const std::string &field,
                               const std::string &what) const;
        /** \brief A mapping key, which must be a scalar (a list or mapping as a key is refused). */
        std::string key(const YAML::Node &keyNode, const std::string &field) const;
        /** \brief \e map must be a mapping of scalar keys, each given once (a repeated key is refused,
            naming both lines). */
        void uniqueKeys(const YAML::Node &map, const std::string &field) const;
        /** \brief \e map must be a mapping whose keys are all in \e keys (the message lists them), each
            given once (a repeated key is refused, naming both lines). */
        void allowKeys(const YAML::Node &map, const std::string &field,
                       const std::set<std::string> &keys) const;
        /** \brief map[key], which must be present and not null. */
        YAML::Node require(const YAML::Node &map, const std::string &key, const std::string &field) const;
        /** \brief A finite number. */
        double number(const YAML::Node &n, const std::string &field) const;
        /** \brief A finite number in [lo, hi]. */
        double number(const YAML::Node &n, const std::string &field, double lo, double hi) const;
        /** \brief An integer in [lo, hi]. */
        long long integer(const YAML::Node &n, const std::string &field, long long lo, long long hi) const;
        /** \brief A scalar as text (may be empty). */
        std::string text(const YAML::Node &n, const std::string &field) const;
        /** \brief A name (of a world, a query, a robot): a scalar without control characters (a newline or
            a tab in a name would break every line-oriented file it is written to: logs, side files). */
        std::string name(const YAML::Node &n, const std::string &field) const;
        /** \brief A non-empty scalar. */
        std::string nonEmptyText(const YAML::Node &n, const std::string &field) const;
        bool boolean(const YAML::Node &n, const std::string &field) const;
        /** \brief A point [x, y]. */
        Vec2 point(const YAML::Node &n, const std::string &field) const;

        const std::string &file() const { return file_; }

      private:
        std::string file_;
    };
} // namespace mhplan

#endif
