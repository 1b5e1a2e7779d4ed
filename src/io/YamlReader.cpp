// SPDX-License-Identifier: BSD-3-Clause
#include "src/io/YamlReader.h"

#include "src/base/World.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace mhplan
{
    namespace
    {
        /** \brief The 1-based line of the innermost '{' or '[' (\e open) still unclosed at byte \e end of
            \e text (brackets in quotes and comments ignored); -1 when there is none. */
        int unclosedFlowLine(const std::string &text, int end, char open)
        {
            std::vector<std::pair<char, int>> stack; // bracket, line
            int line = 1;
            char quote = 0;
            bool comment = false;
            const std::size_t stop = end < 0 ? text.size() : std::min(text.size(), std::size_t(end));
            for (std::size_t i = 0; i < stop; ++i)
            {
                const char c = text[i];
                if (c == '\n')
                {
                    ++line;
                    comment = false;
                    continue;
                }
                if (comment)
                    continue;
                if (quote != 0)
                {
                    if (c == quote)
                        quote = 0;
                    continue;
                }
                const char before = i == 0 ? '\n' : text[i - 1];
                if ((c == '"' || c == '\'') && std::strchr(" \t\n,[{:", before) != nullptr)
                    quote = c; // a quoted scalar starts (an apostrophe inside a word does not)
                else if (c == '#' && (i == 0 || std::isspace(static_cast<unsigned char>(text[i - 1]))))
                    comment = true;
                else if (c == '{' || c == '[')
                    stack.emplace_back(c, line);
                else if ((c == '}' || c == ']') && !stack.empty())
                    stack.pop_back();
            }
            for (auto it = stack.rbegin(); it != stack.rend(); ++it)
                if (it->first == open)
                    return it->second;
            return -1;
        }

        /** \brief Counts the documents a yaml-cpp parser reports, and where the second one starts. */
        class DocumentCounter : public YAML::EventHandler
        {
          public:
            void OnDocumentStart(const YAML::Mark &mark) override
            {
                if (++documents == 2)
                    second = mark;
            }
            void OnDocumentEnd() override {}
            void OnNull(const YAML::Mark &, YAML::anchor_t) override {}
            void OnAlias(const YAML::Mark &, YAML::anchor_t) override {}
            void OnScalar(const YAML::Mark &, const std::string &, YAML::anchor_t,
                          const std::string &) override
            {
            }
            void OnSequenceStart(const YAML::Mark &, const std::string &, YAML::anchor_t,
                                 YAML::EmitterStyle::value) override
            {
            }
            void OnSequenceEnd() override {}
            void OnMapStart(const YAML::Mark &, const std::string &, YAML::anchor_t,
                            YAML::EmitterStyle::value) override
            {
            }
            void OnMapEnd() override {}
            int documents{0};
            YAML::Mark second{YAML::Mark::null_mark()};
        };

        /** \brief True when \e text holds a second YAML document; \e line is its line (1-based, 0 unknown).
            Another document needs a marker line ("---" or "...") after the first character; without one the
            text is a single document and is not parsed twice. Otherwise at most two documents are parsed:
            yaml-cpp 0.7's LoadAll never ends on some malformed inputs (",\xf2SM" yields documents forever,
            growing memory; found by the world_yaml fuzz target). */
        bool secondDocument(const std::string &text, int &line)
        {
            if (text.find("\n---") == std::string::npos && text.find("\n...") == std::string::npos)
                return false;
            std::istringstream in(text);
            YAML::Parser parser(in);
            DocumentCounter counter;
            if (!parser.HandleNextDocument(counter) || !parser.HandleNextDocument(counter))
                return false;
            line = counter.second.line >= 0 ? counter.second.line + 1 : 0;
            return true;
        }
    } // namespace

    YAML::Node loadYamlMapping(const std::string &text, const std::string &fileName, const std::string &what,
                               const std::string &help)
    {
        if (text.size() > kMaxYamlBytes)
            throw InputError(fileName + ": the " + what + " is " + std::to_string(text.size()) +
                             " bytes; YAML input files are limited to " + std::to_string(kMaxYamlBytes) +
                             " bytes (4 MiB; large grids belong in .map or .pgm files)");
        YAML::Node root;
        try
        {
            root = YAML::Load(text);
            // A second document ("---") would otherwise be ignored silently.
            int line = 0;
            if (secondDocument(text, line))
            {
                std::ostringstream msg;
                msg << fileName;
                if (line > 0)
                    msg << ":" << line;
                msg << ": a " << what << " holds one YAML document; a second one (after '---') is not read";
                throw InputError(msg.str());
            }
        }
        catch (const YAML::ParserException &e)
        {
            std::ostringstream msg;
            // An unclosed '{' or '[' is noticed only at the next token, often on a later line: name the
            // line where it was opened.
            const bool mapFlow = e.msg.find("end of map flow") != std::string::npos;
            const bool seqFlow = e.msg.find("end of sequence flow") != std::string::npos;
            const int opened =
                mapFlow || seqFlow ? unclosedFlowLine(text, e.mark.pos, mapFlow ? '{' : '[') : -1;
            if (opened > 0)
                msg << fileName << ":" << opened << ": malformed YAML: '" << (mapFlow ? '{' : '[')
                    << "' opened on this line is not closed by '" << (mapFlow ? '}' : ']')
                    << "' (the parser stopped at line " << e.mark.line + 1 << ", column " << e.mark.column + 1
                    << ": " << e.msg << ")";
            else
                msg << fileName << ":" << e.mark.line + 1 << ":" << e.mark.column + 1
                    << ": malformed YAML: " << e.msg;
            throw InputError(msg.str());
        }
        if (!root.IsMap())
            throw InputError(fileName + ":1: a " + what + " must be a YAML mapping (see " + help + ")");
        return root;
    }

    std::string YamlReader::name(const YAML::Node &n, const std::string &field) const
    {
        const std::string s = text(n, field);
        for (char c : s)
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            {
                char code[8];
                std::snprintf(code, sizeof code, "0x%02x", static_cast<unsigned char>(c));
                fail(n, field,
                     std::string("a name must not contain control characters (found ") + code + ")");
            }
        return s;
    }

    void YamlReader::fail(const YAML::Node &node, const std::string &field, const std::string &what) const
    {
        std::ostringstream msg;
        msg << file_;
        if (node.IsDefined() && node.Mark().line >= 0)
            msg << ":" << node.Mark().line + 1;
        msg << ": field '" << field << "': " << what;
        throw InputError(msg.str());
    }

    std::string YamlReader::key(const YAML::Node &keyNode, const std::string &field) const
    {
        if (!keyNode.IsScalar())
            fail(keyNode, field, "a key must be a plain name, not a list or a mapping");
        return keyNode.Scalar();
    }

    void YamlReader::uniqueKeys(const YAML::Node &map, const std::string &field) const
    {
        if (!map.IsMap())
            fail(map, field, "expected a mapping");
        std::map<std::string, int> seen; // key -> its 1-based line
        for (const auto &kv : map)
        {
            const std::string k = key(kv.first, field.empty() ? std::string("(key)") : field + ".(key)");
            const auto previous = seen.emplace(k, kv.first.Mark().line + 1);
            if (!previous.second)
                fail(kv.first, field.empty() ? k : field + "." + k,
                     "duplicate key '" + k + "' (first given on line " +
                         std::to_string(previous.first->second) + ")");
        }
    }

    void YamlReader::allowKeys(const YAML::Node &map, const std::string &field,
                               const std::set<std::string> &keys) const
    {
        uniqueKeys(map, field);
        for (const auto &kv : map)
        {
            const std::string k = kv.first.Scalar();
            if (keys.count(k) != 0)
                continue;
            std::string accepted;
            for (const auto &a : keys)
                accepted += (accepted.empty() ? "" : ", ") + a;
            fail(kv.first, field.empty() ? k : field + "." + k,
                 "unknown key '" + k + "'; accepted: " + accepted);
        }
    }

    YAML::Node YamlReader::require(const YAML::Node &map, const std::string &key,
                                   const std::string &field) const
    {
        const YAML::Node n = map[key];
        if (!n.IsDefined() || n.IsNull())
            fail(map, field.empty() ? key : field + "." + key, "missing");
        return n;
    }

    namespace
    {
        const std::string kYamlInt = "tag:yaml.org,2002:int";
        const std::string kYamlFloat = "tag:yaml.org,2002:float";

        /** An explicit tag ("!!int 0.7", "!custom") other than the untagged ones ('?' plain, '!' quoted). */
        bool explicitTag(const YAML::Node &n)
        {
            return n.Tag() != "?" && n.Tag() != "!" && !n.Tag().empty();
        }
    } // namespace

    double YamlReader::number(const YAML::Node &n, const std::string &field) const
    {
        if (!n.IsScalar())
            fail(n, field, "expected a number");
        // An explicit tag must agree with the value: "!!int 0.7" is not silently 0.7.
        if (explicitTag(n) && n.Tag() != kYamlInt && n.Tag() != kYamlFloat)
            fail(n, field, "expected a number, got a value tagged '" + n.Tag() + "'");
        double v = 0.0;
        try
        {
            v = n.as<double>();
        }
        catch (const YAML::Exception &)
        {
            fail(n, field, "expected a number, got '" + n.Scalar() + "'");
        }
        if (!std::isfinite(v))
            fail(n, field, "must be finite");
        if (n.Tag() == kYamlInt && v != std::floor(v))
            fail(n, field, "tagged !!int but '" + n.Scalar() + "' is not an integer");
        return v;
    }

    double YamlReader::number(const YAML::Node &n, const std::string &field, double lo, double hi) const
    {
        const double v = number(n, field);
        if (v < lo || v > hi)
        {
            std::ostringstream range;
            range << "must be in [" << lo << ", " << hi << "] (got " << n.Scalar() << ")";
            fail(n, field, range.str());
        }
        return v;
    }

    long long YamlReader::integer(const YAML::Node &n, const std::string &field, long long lo,
                                  long long hi) const
    {
        const double v = number(n, field, static_cast<double>(lo), static_cast<double>(hi));
        if (v != std::floor(v))
            fail(n, field, "expected an integer (got " + n.Scalar() + ")");
        return static_cast<long long>(v);
    }

    std::string YamlReader::text(const YAML::Node &n, const std::string &field) const
    {
        if (!n.IsScalar())
            fail(n, field, "expected a string");
        if (explicitTag(n) && n.Tag() != "tag:yaml.org,2002:str")
            fail(n, field, "expected a string, got a value tagged '" + n.Tag() + "'");
        return n.Scalar();
    }

    std::string YamlReader::nonEmptyText(const YAML::Node &n, const std::string &field) const
    {
        if (!n.IsScalar() || n.Scalar().empty())
            fail(n, field, "expected a non-empty string");
        return n.Scalar();
    }

    bool YamlReader::boolean(const YAML::Node &n, const std::string &field) const
    {
        try
        {
            return n.as<bool>();
        }
        catch (const YAML::Exception &)
        {
            fail(n, field, "expected true or false");
        }
    }

    Vec2 YamlReader::point(const YAML::Node &n, const std::string &field) const
    {
        if (!n.IsSequence() || n.size() != 2)
            fail(n, field, "expected a point [x, y]");
        // The coordinate limit of world files (kMaxCoordinate in WorldIO.h).
        return {number(n[0], field + "[0]", -1e9, 1e9), number(n[1], field + "[1]", -1e9, 1e9)};
    }
} // namespace mhplan
