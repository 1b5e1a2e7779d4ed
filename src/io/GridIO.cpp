// SPDX-License-Identifier: BSD-3-Clause
#include "src/io/GridIO.h"

#include "src/io/InputFile.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace mhplan
{
    namespace
    {
        std::string where(const std::string &fileName, int line)
        {
            return fileName + ":" + std::to_string(line) + ": ";
        }

        void checkCellSize(double cellSize)
        {
            if (!(cellSize > 0.0) || !std::isfinite(cellSize))
            {
                std::ostringstream msg;
                msg << "cellSize must be finite and > 0 (got " << cellSize << ")";
                throw std::invalid_argument(msg.str());
            }
        }

        /** \brief Reads lines, strips one trailing '\r' and counts them (1-based). */
        class LineReader
        {
          public:
            explicit LineReader(std::istream &in) : in_(in) {}
            bool next(std::string &line)
            {
                if (!std::getline(in_, line))
                    return false;
                ++line_;
                if (!line.empty() && line.back() == '\r')
                    line.pop_back();
                return true;
            }
            int line() const { return line_; }

          private:
            std::istream &in_;
            int line_{0};
        };

        std::string trimmed(const std::string &s)
        {
            std::size_t b = 0;
            std::size_t e = s.size();
            while (b < e && std::isspace(static_cast<unsigned char>(s[b])))
                ++b;
            while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1])))
                --e;
            return s.substr(b, e - b);
        }

        /** \brief Parse "key value" where value is a positive integer; returns the value. */
        int headerSize(const std::string &line, const std::string &key, const std::string &fileName,
                       int lineNo)
        {
            std::istringstream ss(line);
            std::string k;
            long long v = 0;
            std::string rest;
            if (!(ss >> k) || k != key || !(ss >> v) || (ss >> rest))
                throw InputError(where(fileName, lineNo) + "expected '" + key + " <N>', got '" +
                                 printableText(line) + "'");
            if (v <= 0 || v > std::numeric_limits<int>::max() / 2)
                throw InputError(where(fileName, lineNo) + key + " must be a positive integer, got " +
                                 std::to_string(v));
            return static_cast<int>(v);
        }

        /** \brief A grid may hold at most kMaxGridCells cells (see GridIO.h). */
        void checkGridCells(long long width, long long height, const std::string &fileName, int lineNo)
        {
            // Division, not multiplication: the dimensions may be any values the reader accepted.
            if (width > 0 && height > 0 && width > kMaxGridCells / height)
                throw InputError(where(fileName, lineNo) + "grid too large: " + std::to_string(width) +
                                 " x " + std::to_string(height) + " cells (at most " +
                                 std::to_string(kMaxGridCells) + " cells)");
        }

        /** \brief 0 free, 1 blocked, -1 unknown. */
        int movingAICell(char c)
        {
            switch (c)
            {
            case '.':
            case 'G':
            case 'S':
                return 0;
            case '@':
            case 'O':
            case 'T':
            case 'W':
                return 1;
            default:
                return -1;
            }
        }

        std::string printable(char c)
        {
            if (std::isprint(static_cast<unsigned char>(c)))
                return std::string("'") + c + "'";
            std::ostringstream s;
            s << "byte 0x" << std::hex << static_cast<int>(static_cast<unsigned char>(c));
            return s.str();
        }
    } // namespace

    std::string printableText(const std::string &s)
    {
        std::string out;
        for (std::size_t i = 0; i < s.size() && i < 60; ++i)
        {
            const unsigned char c = static_cast<unsigned char>(s[i]);
            if (c >= 0x20 && c < 0x7f)
                out += static_cast<char>(c);
            else
            {
                static const char *hex = "0123456789abcdef";
                out += "\\x";
                out += hex[c >> 4];
                out += hex[c & 15];
            }
        }
        if (s.size() > 60)
            out += "...";
        return out;
    }

    OccupancyGrid parseMovingAIMap(std::istream &in, const std::string &fileName, double cellSize)
    {
        checkCellSize(cellSize);
        LineReader reader(in);
        std::string line;

        if (!reader.next(line))
            throw InputError(where(fileName, 1) + "empty file, expected 'type octile'");
        {
            std::istringstream ss(line);
            std::string k, v, rest;
            if (!(ss >> k >> v) || k != "type" || (ss >> rest))
                throw InputError(where(fileName, reader.line()) + "expected 'type octile', got '" +
                                 printableText(line) + "'");
            if (v != "octile")
                throw InputError(where(fileName, reader.line()) + "unsupported map type '" +
                                 printableText(v) + "' (only 'octile')");
        }

        int height = 0;
        int width = 0;
        // "height H" and "width W", in either order.
        for (int k = 0; k < 2; ++k)
        {
            if (!reader.next(line))
                throw InputError(
                    where(fileName, std::max(1, reader.line())) +
                    "unexpected end of file in the header, expected 'height <H>' and 'width <W>'");
            const std::string key = trimmed(line).rfind("width", 0) == 0 ? "width" : "height";
            int &target = key == "width" ? width : height;
            if (target != 0)
                throw InputError(where(fileName, reader.line()) + "duplicate '" + key + "' line");
            target = headerSize(line, key, fileName, reader.line());
        }

        if (!reader.next(line))
            throw InputError(where(fileName, reader.line()) + "unexpected end of file, expected 'map'");
        if (trimmed(line) != "map")
            throw InputError(where(fileName, reader.line()) + "expected 'map', got '" + printableText(line) +
                             "'");

        checkGridCells(width, height, fileName, reader.line());
        // The rows are read before the grid exists: memory grows with the input, never with what the
        // header declares.
        std::vector<std::uint8_t> cells;
        for (int row = 0; row < height; ++row)
        {
            if (!reader.next(line))
                throw InputError(where(fileName, reader.line()) + "missing map rows: expected " +
                                 std::to_string(height) + ", found " + std::to_string(row));
            if (static_cast<long long>(line.size()) != width)
                throw InputError(where(fileName, reader.line()) + "row " + std::to_string(row + 1) + " has " +
                                 std::to_string(line.size()) + " characters, expected width " +
                                 std::to_string(width));
            for (int col = 0; col < width; ++col)
            {
                const int v = movingAICell(line[static_cast<std::size_t>(col)]);
                if (v < 0)
                    throw InputError(where(fileName, reader.line()) + "column " + std::to_string(col + 1) +
                                     ": unknown map character " +
                                     printable(line[static_cast<std::size_t>(col)]) +
                                     " (free: . G S; blocked: @ O T W)");
                cells.push_back(static_cast<std::uint8_t>(v));
            }
        }
        OccupancyGrid grid(width, height, cellSize);
        for (int row = 0; row < height; ++row)
        {
            const int iy = grid.rowToIy(row);
            for (int col = 0; col < width; ++col)
                grid.setBlocked(col, iy, cells[static_cast<std::size_t>(row) * width + col] != 0);
        }
        while (reader.next(line))
        {
            if (!trimmed(line).empty())
                throw InputError(where(fileName, reader.line()) + "unexpected content after the " +
                                 std::to_string(height) + " map rows");
        }
        return grid;
    }

    OccupancyGrid loadMovingAIMap(const std::string &path, double cellSize)
    {
        requireRegularFile(path, "MovingAI map file");
        std::ifstream in(path, std::ios::binary);
        if (!in)
            throw InputError(path + ": cannot open MovingAI map file");
        return parseMovingAIMap(in, path, cellSize);
    }

    std::string movingAIMapText(const OccupancyGrid &grid)
    {
        std::string out = "type octile\nheight " + std::to_string(grid.height()) + "\nwidth " +
                          std::to_string(grid.width()) + "\nmap\n";
        out.reserve(out.size() + static_cast<std::size_t>(grid.height()) * (grid.width() + 1));
        for (int row = 0; row < grid.height(); ++row)
        {
            const int iy = grid.rowToIy(row);
            for (int ix = 0; ix < grid.width(); ++ix)
                out += grid.blocked(ix, iy) ? '@' : '.';
            out += '\n';
        }
        return out;
    }

    namespace
    {
        /** \brief Tokenizer of a PGM header: whitespace-separated tokens, '#' comments to end of line. */
        class PgmReader
        {
          public:
            PgmReader(std::istream &in, const std::string &fileName) : in_(in), fileName_(fileName) {}

            /** \brief Next non-negative integer token; \e what names it in errors. */
            long long integer(const std::string &what)
            {
                skipSpaceAndComments();
                const int startLine = line_;
                tokenLine_ = line_;
                std::string tok;
                int c;
                while ((c = in_.peek()) != EOF && !std::isspace(c) && c != '#')
                {
                    tok += static_cast<char>(c);
                    in_.get();
                }
                if (tok.empty())
                    throw InputError(where(fileName_, startLine) + "unexpected end of file, expected " +
                                     what);
                long long v = 0;
                for (char ch : tok)
                {
                    if (!std::isdigit(static_cast<unsigned char>(ch)) || v > 1000000000LL)
                        throw InputError(where(fileName_, startLine) + "expected " + what +
                                         " (a non-negative integer), got '" + printableText(tok) + "'");
                    v = v * 10 + (ch - '0');
                }
                return v;
            }

            std::string magic()
            {
                char m[2] = {0, 0};
                in_.read(m, 2);
                if (in_.gcount() != 2 || m[0] != 'P' || (m[1] != '2' && m[1] != '5'))
                    throw InputError(where(fileName_, 1) + "not a PGM file: expected magic 'P2' or 'P5'");
                return std::string(m, 2);
            }

            /** \brief After maxval: exactly one whitespace character precedes the binary raster. */
            void singleWhitespace()
            {
                const int c = in_.get();
                if (c == EOF || !std::isspace(c))
                    throw InputError(where(fileName_, line_) +
                                     "expected one whitespace character after maxval");
                if (c == '\n')
                    ++line_;
            }

            std::istream &stream() { return in_; }
            int line() const { return line_; }
            /** \brief Line of the last token read by integer(). */
            int tokenLine() const { return tokenLine_; }

          private:
            void skipSpaceAndComments()
            {
                int c;
                while ((c = in_.peek()) != EOF)
                {
                    if (c == '#')
                    {
                        while ((c = in_.get()) != EOF && c != '\n')
                        {
                        }
                        if (c == '\n')
                            ++line_;
                    }
                    else if (std::isspace(c))
                    {
                        in_.get();
                        if (c == '\n')
                            ++line_;
                    }
                    else
                        break;
                }
            }

            std::istream &in_;
            const std::string &fileName_;
            int line_{1};
            int tokenLine_{1};
        };
    } // namespace

    OccupancyGrid parsePgm(std::istream &in, const std::string &fileName, double cellSize, double threshold,
                           bool negate)
    {
        checkCellSize(cellSize);
        if (!(threshold >= 0.0 && threshold <= 1.0))
        {
            std::ostringstream msg;
            msg << "threshold must be in [0, 1] (got " << threshold << ")";
            throw std::invalid_argument(msg.str());
        }
        PgmReader reader(in, fileName);
        const std::string magic = reader.magic();
        const long long width = reader.integer("the image width");
        const int widthLine = reader.tokenLine();
        const long long height = reader.integer("the image height");
        if (width <= 0 || height <= 0)
            throw InputError(where(fileName, widthLine) + "PGM width and height must be positive, got " +
                             std::to_string(width) + " x " + std::to_string(height));
        checkGridCells(width, height, fileName, widthLine);
        const long long maxval = reader.integer("maxval");
        if (maxval <= 0 || maxval > 65535)
            throw InputError(where(fileName, reader.tokenLine()) + "PGM maxval must be in [1, 65535], got " +
                             std::to_string(maxval));

        const double cut = threshold * static_cast<double>(maxval);
        auto isBlocked = [&](long long v)
        { return negate ? static_cast<double>(v) > cut : static_cast<double>(v) < cut; };

        // The pixels are read before the grid exists: memory grows with the input, never with what the
        // header declares.
        const std::size_t n = static_cast<std::size_t>(width * height);
        std::vector<std::uint8_t> cells;
        if (magic == "P2")
        {
            for (std::size_t k = 0; k < n; ++k)
            {
                const long long v =
                    reader.integer("pixel " + std::to_string(k + 1) + " of " + std::to_string(n));
                if (v > maxval)
                    throw InputError(where(fileName, reader.tokenLine()) + "pixel " + std::to_string(k + 1) +
                                     " value " + std::to_string(v) + " exceeds maxval " +
                                     std::to_string(maxval));
                cells.push_back(isBlocked(v) ? 1 : 0);
            }
        }
        else
        {
            reader.singleWhitespace();
            const std::size_t bytesPer = maxval > 255 ? 2 : 1;
            const std::size_t expected = n * bytesPer;
            std::vector<unsigned char> chunk(std::min<std::size_t>(expected, 1 << 16));
            std::size_t got = 0;
            while (got < expected)
            {
                const std::size_t want = std::min(chunk.size(), expected - got);
                in.read(reinterpret_cast<char *>(chunk.data()), static_cast<std::streamsize>(want));
                const std::size_t read = static_cast<std::size_t>(in.gcount());
                if (read % bytesPer != 0 || read == 0)
                {
                    got += read;
                    break;
                }
                for (std::size_t b = 0; b < read; b += bytesPer)
                {
                    long long v = chunk[b];
                    if (bytesPer == 2)
                        v = (v << 8) | chunk[b + 1]; // 16-bit PGM is big-endian
                    const std::size_t k = (got + b) / bytesPer;
                    if (v > maxval)
                        throw InputError(fileName + ": P5 pixel " + std::to_string(k + 1) + " value " +
                                         std::to_string(v) + " exceeds maxval " + std::to_string(maxval) +
                                         " (byte offset " + std::to_string(got + b) + " of the raster)");
                    cells.push_back(isBlocked(v) ? 1 : 0);
                }
                got += read;
                if (read < want)
                    break;
            }
            if (got != expected)
                throw InputError(where(fileName, reader.line()) + "truncated P5 raster: expected " +
                                 std::to_string(expected) + " bytes, found " + std::to_string(got));
        }
        OccupancyGrid grid(static_cast<int>(width), static_cast<int>(height), cellSize);
        for (std::size_t k = 0; k < n; ++k)
        {
            const int col = static_cast<int>(k % static_cast<std::size_t>(width));
            const int row = static_cast<int>(k / static_cast<std::size_t>(width));
            grid.setBlocked(col, grid.rowToIy(row), cells[k] != 0);
        }
        return grid;
    }

    OccupancyGrid loadPgm(const std::string &path, double cellSize, double threshold, bool negate)
    {
        requireRegularFile(path, "PGM file");
        std::ifstream in(path, std::ios::binary);
        if (!in)
            throw InputError(path + ": cannot open PGM file");
        return parsePgm(in, path, cellSize, threshold, negate);
    }

    World gridWorld(const std::string &name, std::shared_ptr<const OccupancyGrid> grid)
    {
        if (!grid)
            throw std::invalid_argument("gridWorld: grid must not be null");
        World w;
        w.name = name;
        w.bounds = grid->bounds();
        w.grid = std::move(grid);
        return w;
    }
} // namespace mhplan
