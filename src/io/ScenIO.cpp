// SPDX-License-Identifier: BSD-3-Clause
#include "src/io/ScenIO.h"

#include "src/io/InputFile.h"

#include "src/io/GridIO.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace mhplan
{
    namespace
    {
        bool parseInt(const std::string &s, int &out)
        {
            if (s.empty())
                return false;
            char *end = nullptr;
            errno = 0;
            const long v = std::strtol(s.c_str(), &end, 10);
            if (errno != 0 || end != s.c_str() + s.size() || v < -2147483647L || v > 2147483647L)
                return false;
            out = static_cast<int>(v);
            return true;
        }

        bool parseReal(const std::string &s, double &out)
        {
            if (s.empty())
                return false;
            char *end = nullptr;
            errno = 0;
            out = std::strtod(s.c_str(), &end);
            return errno == 0 && end == s.c_str() + s.size() && std::isfinite(out);
        }
    } // namespace

    std::vector<ScenProblem> parseMovingAIScen(std::istream &in, const std::string &path,
                                               const OccupancyGrid &grid)
    {
        std::vector<ScenProblem> out;
        std::string text;
        int lineNo = 0;
        bool haveVersion = false;
        while (std::getline(in, text))
        {
            ++lineNo;
            if (!text.empty() && text.back() == '\r')
                text.pop_back();
            std::istringstream fields(text);
            std::vector<std::string> f;
            for (std::string w; fields >> w;)
                f.push_back(w);
            if (f.empty())
                continue;
            const std::string where = path + ":" + std::to_string(lineNo) + ": ";
            if (!haveVersion)
            {
                double version = 0.0;
                if (f.size() != 2 || f[0] != "version" || !parseReal(f[1], version))
                    throw InputError(where + "expected the header 'version 1', got '" + printableText(text) +
                                     "'");
                if (version < 1.0 || version >= 2.0)
                    throw InputError(where + "unsupported scenario version '" + printableText(f[1]) +
                                     "' (supported: version 1)");
                haveVersion = true;
                continue;
            }
            if (f.size() != 9)
                throw InputError(where +
                                 "expected 9 fields (bucket map width height start-x start-y goal-x " +
                                 "goal-y optimal-length), got " + std::to_string(f.size()));
            ScenProblem p;
            p.line = lineNo;
            int width = 0, height = 0;
            const char *names[] = {"bucket", "width", "height", "start-x", "start-y", "goal-x", "goal-y"};
            int *targets[] = {&p.bucket, &width, &height, &p.sx, &p.sy, &p.gx, &p.gy};
            const std::size_t columns[] = {0, 2, 3, 4, 5, 6, 7};
            for (std::size_t k = 0; k < 7; ++k)
                if (!parseInt(f[columns[k]], *targets[k]))
                    throw InputError(where + "field '" + names[k] + "': expected an integer, got '" +
                                     printableText(f[columns[k]]) + "'");
            if (!parseReal(f[8], p.optimal) || p.optimal < 0.0)
                throw InputError(where + "field 'optimal-length': expected a number >= 0, got '" +
                                 printableText(f[8]) + "'");
            if (width != grid.width() || height != grid.height())
                throw InputError(where + "map size " + std::to_string(width) + " x " +
                                 std::to_string(height) + " does not match the map (" +
                                 std::to_string(grid.width()) + " x " + std::to_string(grid.height()) + ")");
            const auto cellOk = [&](int x, int y, const char *what)
            {
                if (x < 0 || y < 0 || x >= width || y >= height)
                    throw InputError(where + what + " (" + std::to_string(x) + ", " + std::to_string(y) +
                                     ") is outside the map");
                if (grid.blocked(x, grid.rowToIy(y)))
                    throw InputError(where + what + " (" + std::to_string(x) + ", " + std::to_string(y) +
                                     ") is a blocked cell");
            };
            cellOk(p.sx, p.sy, "start");
            cellOk(p.gx, p.gy, "goal");
            out.push_back(p);
        }
        if (!haveVersion)
            throw InputError(path + ": empty scenario file (expected the header 'version 1')");
        if (out.empty())
            throw InputError(path + ": the scenario has no problems");
        return out;
    }

    std::vector<ScenProblem> selectScenProblems(const std::vector<ScenProblem> &problems,
                                                const ScenSelection &selection)
    {
        const unsigned int every = std::max(1u, selection.every);
        std::map<int, std::pair<unsigned int, unsigned int>> seen; // bucket -> (problems seen, taken)
        std::vector<ScenProblem> out;
        for (const ScenProblem &p : problems)
        {
            if (!selection.buckets.empty() && std::find(selection.buckets.begin(), selection.buckets.end(),
                                                        p.bucket) == selection.buckets.end())
                continue;
            auto &count = seen[p.bucket];
            const bool take = count.first++ % every == 0 &&
                              (selection.perBucket == 0 || count.second < selection.perBucket);
            if (take)
            {
                ++count.second;
                out.push_back(p);
            }
        }
        return out;
    }

    bool scenOptimumMatches(double scenOptimal, double cells)
    {
        return std::fabs(cells - scenOptimal) <= std::max(1e-4, 1e-5 * scenOptimal);
    }

    std::vector<ScenProblem> loadMovingAIScen(const std::string &path, const OccupancyGrid &grid)
    {
        requireRegularFile(path, "scenario file");
        std::ifstream in(path, std::ios::binary);
        if (!in)
            throw InputError(path + ": cannot open the scenario file");
        return parseMovingAIScen(in, path, grid);
    }
} // namespace mhplan
