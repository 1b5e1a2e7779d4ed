// SPDX-License-Identifier: BSD-3-Clause
#include "src/io/QueryList.h"

#include "src/io/WorldIO.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/parser.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <unordered_set>

namespace mhplan
{
    namespace
    {
        std::atomic<std::size_t> splits{0};

        /** Thrown by the event handler to stop at the first thing the quick reading does not take. */
        struct NotPlain
        {
        };

        /** A number as yaml-cpp's conversion reads it, for the forms where that is strtod's reading:
            [-]digits[.digits][(e|E)[+|-]digits], finite, neither overflowing nor underflowing. Any other
            form (".5", "+1", "1_000", ".inf", hexadecimal, ...) is left to yaml-cpp. */
        bool plainNumber(const std::string &s, double &v)
        {
            std::size_t i = 0;
            const std::size_t n = s.size();
            const auto digits = [&]
            {
                const std::size_t from = i;
                while (i < n && s[i] >= '0' && s[i] <= '9')
                    ++i;
                return i > from;
            };
            if (i < n && s[i] == '-')
                ++i;
            if (!digits())
                return false;
            if (i < n && s[i] == '.')
            {
                ++i;
                digits();
            }
            if (i < n && (s[i] == 'e' || s[i] == 'E'))
            {
                ++i;
                if (i < n && (s[i] == '+' || s[i] == '-'))
                    ++i;
                if (!digits())
                    return false;
            }
            if (i != n)
                return false;
            errno = 0;
            char *end = nullptr;
            v = std::strtod(s.c_str(), &end);
            return errno == 0 && end == s.c_str() + n && std::isfinite(v);
        }

        /** An untagged scalar: plain ('?') or quoted ('!'), which the world reader takes as text or number.
         */
        bool untagged(const std::string &tag)
        {
            return tag == "?" || tag == "!";
        }

        class QueryEvents : public YAML::EventHandler
        {
          public:
            explicit QueryEvents(const std::string &text) : text_(text) {}

            void OnDocumentStart(const YAML::Mark &) override
            {
                if (++documents_ > 1)
                    throw NotPlain{}; // the reader refuses a second document
            }
            void OnDocumentEnd() override {}
            void OnNull(const YAML::Mark &mark, YAML::anchor_t anchor) override
            {
                if (anchor != YAML::NullAnchor || inQueries_)
                    throw NotPlain{};
                leaf(mark, nullptr);
            }
            void OnAlias(const YAML::Mark &, YAML::anchor_t) override { throw NotPlain{}; }
            void OnScalar(const YAML::Mark &mark, const std::string &tag, YAML::anchor_t anchor,
                          const std::string &value) override
            {
                if (anchor != YAML::NullAnchor)
                    throw NotPlain{};
                if (inQueries_)
                {
                    queryScalar(tag, value);
                    return;
                }
                leaf(mark, &value);
            }
            void OnSequenceStart(const YAML::Mark &mark, const std::string &tag, YAML::anchor_t anchor,
                                 YAML::EmitterStyle::value) override
            {
                if (anchor != YAML::NullAnchor)
                    throw NotPlain{};
                if (inQueries_)
                {
                    // Only a pose [x, y] or [x, y, yaw] opens a sequence inside the list.
                    if (depth_ != 3 || expectKey_ || (value_ != Value::Start && value_ != Value::Goal) ||
                        tag != "?")
                        throw NotPlain{};
                    count_ = 0;
                    ++depth_;
                    return;
                }
                if (depth_ == 0)
                    throw NotPlain{}; // a world file is a mapping
                if (depth_ == 1 && !rootKey_ && queriesNext_)
                {
                    // The list itself: it starts at this mark, after its key, indented further.
                    if (tag != "?" || mark.column <= keyColumn_)
                        throw NotPlain{};
                    queriesNext_ = false;
                    inQueries_ = true;
                    valueStart_ = static_cast<std::size_t>(mark.pos);
                    ++depth_;
                    return;
                }
                open(mark);
            }
            void OnSequenceEnd() override
            {
                if (inQueries_)
                {
                    if (depth_ == 4)
                    {
                        if (count_ < 2)
                            throw NotPlain{};
                        Query &q = current_;
                        if (value_ == Value::Start)
                        {
                            q.start = {pose_[0], pose_[1]};
                            q.startYaw = count_ == 3 ? pose_[2] : 0.0;
                        }
                        else
                        {
                            q.goal = {pose_[0], pose_[1]};
                            q.goalYaw = count_ == 3 ? pose_[2] : 0.0;
                        }
                        split_.headings = split_.headings || count_ == 3;
                        expectKey_ = true;
                        --depth_;
                        return;
                    }
                    // depth 2: the end of the list
                    inQueries_ = false;
                    listEnded_ = true;
                    --depth_;
                    rootKey_ = true;
                    return;
                }
                close();
            }
            void OnMapStart(const YAML::Mark &mark, const std::string &, YAML::anchor_t anchor,
                            YAML::EmitterStyle::value style) override
            {
                if (anchor != YAML::NullAnchor)
                    throw NotPlain{};
                if (inQueries_)
                {
                    if (depth_ != 2)
                        throw NotPlain{};
                    current_ = Query();
                    seen_ = 0;
                    expectKey_ = true;
                    ++depth_;
                    return;
                }
                if (depth_ == 0)
                {
                    // The root: a block mapping, so that the list's replacement keeps every other node.
                    if (style != YAML::EmitterStyle::Block)
                        throw NotPlain{};
                    depth_ = 1;
                    rootKey_ = true;
                    return;
                }
                open(mark);
            }
            void OnMapEnd() override
            {
                if (inQueries_)
                {
                    // The end of one query (depth 3): the reader's names and checks.
                    if (!expectKey_ || (seen_ & (kStart | kGoal)) != (kStart | kGoal))
                        throw NotPlain{};
                    const std::size_t i = split_.queries.size();
                    if (!(seen_ & kName))
                        current_.name = i == 0 ? std::string("default") : "q" + std::to_string(i);
                    if (!names_.insert(current_.name).second)
                        throw NotPlain{};
                    split_.queries.push_back(std::move(current_));
                    --depth_;
                    return;
                }
                close();
            }

            /** The result, once the whole text has been parsed. */
            std::optional<SplitQueries> finish()
            {
                if (!listEnded_)
                    return std::nullopt; // no list (nothing to gain), or not one the quick reading takes
                std::size_t end = text_.size();
                if (nextKey_ >= 0)
                {
                    // The next top-level key starts a line, at the list key's column.
                    end = static_cast<std::size_t>(nextKey_);
                    if (nextKeyColumn_ != keyColumn_ || end < static_cast<std::size_t>(keyColumn_) + 1)
                        return std::nullopt;
                    for (std::size_t i = end - keyColumn_; i < end; ++i)
                        if (text_[i] != ' ')
                            return std::nullopt;
                    if (text_[end - keyColumn_ - 1] != '\n')
                        return std::nullopt;
                }
                std::string &rest = split_.rest;
                rest.reserve(valueStart_ + 64 + (text_.size() - end));
                rest.append(text_, 0, valueStart_);
                rest += "[]";
                for (std::size_t i = valueStart_; i < end; ++i)
                    if (text_[i] == '\n')
                        rest += '\n';
                if (nextKey_ >= 0)
                    rest.append(static_cast<std::size_t>(keyColumn_), ' ');
                rest.append(text_, end, std::string::npos);
                return std::move(split_);
            }

          private:
            enum class Value
            {
                None,
                Name,
                Start,
                Goal
            };
            static constexpr unsigned kName = 1, kStart = 2, kGoal = 4;

            /** A scalar or null outside the list. */
            void leaf(const YAML::Mark &mark, const std::string *value)
            {
                if (depth_ == 0)
                    throw NotPlain{}; // a world file is a mapping
                if (depth_ != 1)
                    return;
                if (!rootKey_)
                {
                    if (queriesNext_)
                        throw NotPlain{}; // 'queries:' with a scalar or null: the reader says what it expects
                    rootKey_ = true;
                    return;
                }
                if (value == nullptr)
                    throw NotPlain{}; // a null key
                rootKey_ = false;
                if (listEnded_ && nextKey_ < 0)
                {
                    nextKey_ = mark.pos;
                    nextKeyColumn_ = mark.column;
                }
                if (*value == "queries")
                {
                    if (seenQueries_)
                        throw NotPlain{}; // given twice: the reader names both lines
                    seenQueries_ = true;
                    queriesNext_ = true;
                    keyColumn_ = mark.column;
                }
            }

            /** A mapping or sequence outside the list. */
            void open(const YAML::Mark &mark)
            {
                if (depth_ == 1)
                {
                    if (rootKey_)
                        throw NotPlain{}; // a complex key
                    if (queriesNext_)
                        throw NotPlain{}; // 'queries:' with a mapping
                }
                (void)mark;
                ++depth_;
            }

            void close()
            {
                --depth_;
                if (depth_ == 1)
                    rootKey_ = true; // the value of a top-level key has ended
            }

            void queryScalar(const std::string &tag, const std::string &value)
            {
                if (!untagged(tag))
                    throw NotPlain{};
                if (depth_ == 3 && expectKey_)
                {
                    unsigned bit = 0;
                    if (value == "name")
                    {
                        bit = kName;
                        value_ = Value::Name;
                    }
                    else if (value == "start")
                    {
                        bit = kStart;
                        value_ = Value::Start;
                    }
                    else if (value == "goal")
                    {
                        bit = kGoal;
                        value_ = Value::Goal;
                    }
                    if (bit == 0 || (seen_ & bit))
                        throw NotPlain{}; // an unknown or repeated key
                    seen_ |= bit;
                    expectKey_ = false;
                    return;
                }
                if (depth_ == 3 && value_ == Value::Name)
                {
                    for (char c : value)
                        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
                            throw NotPlain{};
                    current_.name = value;
                    expectKey_ = true;
                    return;
                }
                if (depth_ != 4 || count_ == 3)
                    throw NotPlain{};
                double v = 0.0;
                if (!plainNumber(value, v))
                    throw NotPlain{};
                const double limit = count_ == 2 ? 1e3 : kMaxCoordinate; // the reader's limits (readPose)
                if (std::fabs(v) > limit)
                    throw NotPlain{};
                pose_[count_++] = v;
            }

            const std::string &text_;
            SplitQueries split_;
            std::unordered_set<std::string> names_;
            int documents_{0};
            int depth_{0};
            bool rootKey_{true}; // at depth 1: the next node is a key
            bool seenQueries_{false};
            bool queriesNext_{false}; // the next node at depth 1 is the list
            bool inQueries_{false};
            bool listEnded_{false};
            int keyColumn_{0};
            std::size_t valueStart_{0};
            int nextKey_{-1};
            int nextKeyColumn_{0};
            // the query being read
            Query current_;
            unsigned seen_{0};
            bool expectKey_{true};
            Value value_{Value::None};
            double pose_[3]{0.0, 0.0, 0.0};
            int count_{0};
        };
    } // namespace

    std::optional<SplitQueries> splitQueries(const std::string &text)
    {
        if (text.size() > kMaxYamlBytes)
            return std::nullopt;
        QueryEvents events(text);
        try
        {
            std::istringstream in(text);
            YAML::Parser parser(in);
            // One document; a second one is refused by the tree reader (loadYamlMapping). Never a loop over
            // the documents: yaml-cpp 0.7 reports documents forever on some malformed inputs
            // (tests/data/fuzz_regressions/README.md, loadall_endless).
            if (parser.HandleNextDocument(events) && parser.HandleNextDocument(events))
                return std::nullopt;
        }
        catch (const NotPlain &)
        {
            return std::nullopt;
        }
        catch (const YAML::Exception &)
        {
            return std::nullopt; // malformed: yaml-cpp's tree reader says where
        }
        std::optional<SplitQueries> split = events.finish();
        if (split)
            ++splits;
        return split;
    }

    std::size_t splitQueriesCount()
    {
        return splits.load();
    }
} // namespace mhplan
