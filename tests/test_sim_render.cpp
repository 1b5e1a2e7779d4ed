// SPDX-License-Identifier: BSD-3-Clause
/* Drawing simulation runs (src/draw/SimRender.h): the GIF encoder (giflib, GifWriter.h) checked by an
   independent GIF and LZW decoder written here, the rasteriser and SVG on a small run, and `mhplan sim` end
   to end. */
#include "CliSupport.h"
#include "src/sim/ScenarioIO.h"
#include "src/draw/SimRender.h"
#include "src/sim/Simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <stdexcept>

using namespace mhplan;
using mhplan::test::contains;

namespace
{
    using Palette = std::vector<std::array<std::uint8_t, 3>>;
    using Frame = std::vector<std::uint8_t>;

    // ------------------------------------------------------------------------------------------------
    // A GIF decoder written from the GIF89a specification, independent of the encoder's code.

    /** Decode a GIF LZW code stream into palette indices; counts the clear codes it meets. */
    std::vector<std::uint8_t> lzwDecode(const std::vector<std::uint8_t> &data, int minCodeSize,
                                        int *clears = nullptr, int *maxWidth = nullptr)
    {
        const int clear = 1 << minCodeSize, eoi = clear + 1;
        std::vector<int> prefix(4096, -1);
        std::vector<std::uint8_t> suffix(4096, 0), first(4096, 0);
        for (int c = 0; c < clear; ++c)
        {
            suffix[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(c);
            first[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(c);
        }
        auto expand = [&](int code, std::vector<std::uint8_t> &out)
        {
            std::vector<std::uint8_t> rev;
            for (int c = code; c >= 0; c = prefix[static_cast<std::size_t>(c)])
                rev.push_back(suffix[static_cast<std::size_t>(c)]);
            out.insert(out.end(), rev.rbegin(), rev.rend());
        };
        std::vector<std::uint8_t> out;
        int size = minCodeSize + 1, next = eoi + 1, prev = -1;
        std::size_t bitPos = 0;
        if (clears)
            *clears = 0;
        if (maxWidth)
            *maxWidth = size;
        for (;;)
        {
            if (bitPos + static_cast<std::size_t>(size) > data.size() * 8)
                throw std::runtime_error("lzwDecode: code stream ends without EOI");
            int code = 0;
            for (int b = 0; b < size; ++b, ++bitPos)
                code |= ((data[bitPos / 8] >> (bitPos % 8)) & 1) << b;
            if (code == clear)
            {
                size = minCodeSize + 1;
                next = eoi + 1;
                prev = -1;
                if (clears)
                    ++*clears;
                continue;
            }
            if (code == eoi)
                break;
            if (prev < 0)
            {
                if (code >= clear)
                    throw std::runtime_error("lzwDecode: first code after clear is not a literal");
                out.push_back(static_cast<std::uint8_t>(code));
                prev = code;
                continue;
            }
            if (code > next)
                throw std::runtime_error("lzwDecode: code " + std::to_string(code) + " beyond next " +
                                         std::to_string(next));
            const std::uint8_t head =
                code < next ? first[static_cast<std::size_t>(code)] : first[static_cast<std::size_t>(prev)];
            if (next < 4096)
            {
                prefix[static_cast<std::size_t>(next)] = prev;
                suffix[static_cast<std::size_t>(next)] = head;
                first[static_cast<std::size_t>(next)] = first[static_cast<std::size_t>(prev)];
                ++next;
                if (next == (1 << size) && size < 12)
                    ++size;
            }
            expand(code, out);
            prev = code;
            if (maxWidth)
                *maxWidth = std::max(*maxWidth, size);
        }
        return out;
    }

    struct DecodedGif
    {
        int width{0}, height{0};
        Palette palette;
        bool hasLoop{false};
        int loopCount{-1};
        std::vector<int> delays;
        std::vector<int> transparent; // per frame, -1 = none
        std::vector<Frame> frames;    // composited canvases
        int clears{0};
        std::vector<int> minCodeSizes;                // per frame
        std::vector<std::vector<std::uint8_t>> codes; // per frame: the LZW code stream (sub-blocks joined)
    };

    DecodedGif decodeGif(const std::vector<std::uint8_t> &g)
    {
        DecodedGif d;
        std::size_t p = 0;
        auto need = [&](std::size_t n)
        {
            if (p + n > g.size())
                throw std::runtime_error("decodeGif: truncated at byte " + std::to_string(p));
        };
        auto u8 = [&]()
        {
            need(1);
            return static_cast<int>(g[p++]);
        };
        auto u16 = [&]()
        {
            const int lo = u8();
            return lo | (u8() << 8);
        };
        need(6);
        if (std::string(g.begin(), g.begin() + 6) != "GIF89a")
            throw std::runtime_error("decodeGif: not GIF89a");
        p = 6;
        d.width = u16();
        d.height = u16();
        const int packed = u8();
        u8(); // background
        u8(); // aspect
        if (!(packed & 0x80))
            throw std::runtime_error("decodeGif: no global colour table");
        const int entries = 1 << ((packed & 7) + 1);
        for (int k = 0; k < entries; ++k)
        {
            std::array<std::uint8_t, 3> c{};
            for (auto &v : c)
                v = static_cast<std::uint8_t>(u8());
            d.palette.push_back(c);
        }
        Frame canvas(static_cast<std::size_t>(d.width) * static_cast<std::size_t>(d.height), 0);
        int pendingDelay = 0, pendingTransparent = -1;
        auto subBlocks = [&]()
        {
            std::vector<std::uint8_t> data;
            for (int len = u8(); len != 0; len = u8())
            {
                need(static_cast<std::size_t>(len));
                data.insert(data.end(), g.begin() + static_cast<long>(p),
                            g.begin() + static_cast<long>(p) + len);
                p += static_cast<std::size_t>(len);
            }
            return data;
        };
        for (;;)
        {
            const int b = u8();
            if (b == 0x3B)
                break;
            if (b == 0x21)
            {
                const int label = u8();
                std::vector<std::uint8_t> data = subBlocks();
                if (label == 0xF9)
                {
                    if (data.size() != 4)
                        throw std::runtime_error("decodeGif: bad graphic control extension");
                    pendingDelay = data[1] | (data[2] << 8);
                    pendingTransparent = (data[0] & 1) ? data[3] : -1;
                    if (((data[0] >> 2) & 7) > 1)
                        throw std::runtime_error("decodeGif: unexpected disposal method");
                }
                else if (label == 0xFF && data.size() == 14 &&
                         std::string(data.begin(), data.begin() + 11) == "NETSCAPE2.0" && data[11] == 1)
                {
                    // The application identifier (an 11-byte sub-block) and the data sub-block {1, lo, hi},
                    // joined by subBlocks().
                    d.hasLoop = true;
                    d.loopCount = data[12] | (data[13] << 8);
                }
                continue;
            }
            if (b != 0x2C)
                throw std::runtime_error("decodeGif: unexpected block " + std::to_string(b));
            const int x0 = u16(), y0 = u16(), w = u16(), h = u16();
            const int flags = u8();
            if (flags & 0x80)
                throw std::runtime_error("decodeGif: local colour table not expected");
            if (x0 + w > d.width || y0 + h > d.height)
                throw std::runtime_error("decodeGif: frame outside the logical screen");
            const int minCodeSize = u8();
            int clears = 0;
            d.minCodeSizes.push_back(minCodeSize);
            d.codes.push_back(subBlocks());
            const std::vector<std::uint8_t> idx = lzwDecode(d.codes.back(), minCodeSize, &clears);
            d.clears += clears;
            if (idx.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h))
                throw std::runtime_error("decodeGif: frame has " + std::to_string(idx.size()) +
                                         " pixels, expected " + std::to_string(w * h));
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    if (idx[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                            static_cast<std::size_t>(x)] != pendingTransparent)
                        canvas[static_cast<std::size_t>(y0 + y) * static_cast<std::size_t>(d.width) +
                               static_cast<std::size_t>(x0 + x)] =
                            idx[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                                static_cast<std::size_t>(x)];
            d.frames.push_back(canvas);
            d.delays.push_back(pendingDelay);
            d.transparent.push_back(pendingTransparent);
            pendingTransparent = -1;
        }
        return d;
    }

    Palette greyPalette(std::size_t n);

    /** The LZW code stream the encoder writes for one frame of w x h \e indices over \e colours colours (the
        first frame of a GIF, stored whole), and its minimum code size. */
    std::vector<std::uint8_t> lzwStreamOf(const std::vector<std::uint8_t> &indices, int w, int h,
                                          std::size_t colours, int &minCodeSize)
    {
        const DecodedGif d = decodeGif(encodeGif(w, h, greyPalette(colours), {indices}, 5));
        if (d.codes.size() != 1)
            throw std::runtime_error("lzwStreamOf: expected one frame");
        minCodeSize = d.minCodeSizes[0];
        return d.codes[0];
    }

    Palette greyPalette(std::size_t n)
    {
        Palette p;
        for (std::size_t k = 0; k < n; ++k)
        {
            const auto v = static_cast<std::uint8_t>(k * 255 / std::max<std::size_t>(1, n - 1));
            p.push_back({v, static_cast<std::uint8_t>(255 - v), static_cast<std::uint8_t>(k % 7)});
        }
        return p;
    }

    // ------------------------------------------------------------------------------------------------
    // A small run to draw.

    /** Heads straight for the goal at full speed. */
    class StraightController : public Controller
    {
      public:
        std::string name() const override { return "straight"; }
        void reset(const Simulation &, ompl::RNG &) override {}
        void taskStarted(const Simulation &, std::size_t) override {}
        Command command(const Simulation &sim, std::size_t i) override
        {
            const Vec2 d = sim.state(i).goal - sim.state(i).position;
            const double n = norm(d);
            return {n > 0 ? d / n * sim.spec(i).maxSpeed : Vec2()};
        }
    };

    Scenario smallScenario()
    {
        return parseScenarioYaml(R"(
name: render_small
bounds: {xmin: 0, xmax: 8, ymin: 0, ymax: 4}
obstacles:
  - circle: {center: [4, 3.2], radius: 0.5}
  - polygon: {points: [[3.5, 0.2], [4.5, 0.2], [4, 0.9]]}
moving_obstacles:
  - {name: m1, radius: 0.3, motion: {circle: {center: [6, 3], radius: 0.5, angular_speed: 1.0, phase: 0}}}
robot_defaults: {radius: 0.15, max_speed: 1.0, max_turn_rate: 6.0}
robots:
  - {name: a, start: [0.5, 2], heading: 0, goal: [7.5, 2]}
  - {name: b, start: [7.5, 1.2], heading: 180, goal: [0.5, 1.2], join_time: 1}
simulation: {dt: 0.05, time_limit: 30}
)",
                                 "render_small.yaml");
    }

    struct SmallRun
    {
        Scenario scenario;
        SimulationResult result;
    };

    const SmallRun &smallRun()
    {
        static const SmallRun run = []
        {
            SmallRun r;
            r.scenario = smallScenario();
            Simulation sim(r.scenario, std::make_shared<StraightController>(), 7);
            r.result = sim.run();
            return r;
        }();
        return run;
    }

    /** Tags balance (a tiny XML well-formedness check: comments, declarations, self-closing tags, quoted
        attribute values). Returns "" when balanced, else what is wrong. */
    std::string xmlBalance(const std::string &s)
    {
        std::vector<std::string> stack;
        std::size_t p = 0;
        while ((p = s.find('<', p)) != std::string::npos)
        {
            if (s.compare(p, 4, "<!--") == 0)
            {
                p = s.find("-->", p);
                if (p == std::string::npos)
                    return "unterminated comment";
                continue;
            }
            // Find the end of the tag outside quotes.
            std::size_t e = p + 1;
            char quote = 0;
            for (; e < s.size(); ++e)
            {
                if (quote)
                {
                    if (s[e] == quote)
                        quote = 0;
                }
                else if (s[e] == '"' || s[e] == '\'')
                    quote = s[e];
                else if (s[e] == '<')
                    return "'<' inside a tag at " + std::to_string(e);
                else if (s[e] == '>')
                    break;
            }
            if (e >= s.size())
                return "unterminated tag at " + std::to_string(p);
            const std::string tag = s.substr(p + 1, e - p - 1);
            p = e + 1;
            if (tag.empty() || tag[0] == '?' || tag[0] == '!')
                continue;
            if (tag[0] == '/')
            {
                const std::string name = tag.substr(1);
                if (stack.empty() || stack.back() != name)
                    return "closing </" + name + "> does not match <" + (stack.empty() ? "" : stack.back()) +
                           ">";
                stack.pop_back();
                continue;
            }
            if (tag.back() == '/')
                continue;
            stack.push_back(tag.substr(0, tag.find_first_of(" \t\n")));
        }
        return stack.empty() ? "" : "unclosed <" + stack.back() + ">";
    }

    std::size_t countOf(const std::string &s, const std::string &needle)
    {
        std::size_t n = 0;
        for (std::size_t p = s.find(needle); p != std::string::npos; p = s.find(needle, p + 1))
            ++n;
        return n;
    }

    std::string readFile(const std::string &path)
    {
        std::ifstream in(path, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }

    std::string tempPath(const std::string &name)
    {
        return testing::TempDir() + "/mhplan_simrender_" + name;
    }
} // namespace

// ----------------------------------------------------------------------------------------------------------
// LZW and the GIF container

namespace
{
    // The code stream of the first frame, stored whole, with 2^m - 1 colours (plus the transparent index:
    // minimum code size m) or 256 (m = 8, no transparent index).
    std::size_t coloursForCodeSize(int minCodeSize)
    {
        return minCodeSize == 8 ? 256 : (std::size_t{1} << minCodeSize) - 1;
    }
} // namespace

TEST(GifLzw, RandomIndicesRoundTripAndHitTheTableLimit)
{
    std::mt19937 gen(12345);
    for (int minCodeSize : {2, 3, 5, 8})
    {
        const std::size_t colours = coloursForCodeSize(minCodeSize);
        std::uniform_int_distribution<int> pick(0, static_cast<int>(colours) - 1);
        for (const auto &shape : {std::pair<int, int>{1, 1}, {2, 1}, {300, 1}, {280, 250}})
        {
            const std::size_t n =
                static_cast<std::size_t>(shape.first) * static_cast<std::size_t>(shape.second);
            std::vector<std::uint8_t> idx(n);
            for (auto &v : idx)
                v = static_cast<std::uint8_t>(pick(gen));
            int clears = 0, maxWidth = 0, codeSize = 0;
            const auto codes = lzwStreamOf(idx, shape.first, shape.second, colours, codeSize);
            ASSERT_EQ(codeSize, minCodeSize) << colours << " colours";
            ASSERT_EQ(lzwDecode(codes, minCodeSize, &clears, &maxWidth), idx)
                << "min code size " << minCodeSize << ", " << n << " indices";
            if (n == 70000)
            {
                // 70000 random symbols need far more than 4096 codes: the table is reset, widths reach 12.
                EXPECT_GE(clears, 3) << minCodeSize;
                EXPECT_EQ(maxWidth, 12) << minCodeSize;
            }
        }
    }
}

TEST(GifLzw, LongUniformRunFillsTheTable)
{
    // A run of one symbol adds codes for runs of length 2, 3, ...: 4093 codes need about 8.4 million pixels.
    const std::vector<std::uint8_t> idx(9000000, 2);
    int clears = 0, maxWidth = 0, codeSize = 0;
    const auto codes = lzwStreamOf(idx, 3000, 3000, 3, codeSize);
    ASSERT_EQ(codeSize, 2);
    EXPECT_LT(codes.size(), 10000u);
    EXPECT_EQ(lzwDecode(codes, 2, &clears, &maxWidth), idx);
    EXPECT_EQ(clears, 2); // the leading clear and one reset
    EXPECT_EQ(maxWidth, 12);
}

TEST(GifLzw, PatternsAtEveryWidthBoundary)
{
    // Lengths around the points where the code width grows (the decoder lags one code behind the encoder).
    std::mt19937 gen(99);
    for (std::size_t n = 1; n < 2200; n += 7)
    {
        std::vector<std::uint8_t> idx(n);
        for (std::size_t k = 0; k < n; ++k)
            idx[k] = static_cast<std::uint8_t>((k * k / 3 + gen() % 2) % 3);
        int codeSize = 0;
        const auto codes = lzwStreamOf(idx, static_cast<int>(n), 1, 3, codeSize);
        ASSERT_EQ(codeSize, 2);
        ASSERT_EQ(lzwDecode(codes, 2), idx) << n;
    }
}

TEST(GifEncoder, ContainerFieldsAndFramesRoundTrip)
{
    std::mt19937 gen(4242);
    for (std::size_t colours :
         {std::size_t{2}, std::size_t{5}, std::size_t{64}, std::size_t{200}, std::size_t{256}})
    {
        const int w = 37, h = 23;
        const Palette palette = greyPalette(colours);
        std::uniform_int_distribution<int> pick(0, static_cast<int>(colours) - 1);
        std::vector<Frame> frames;
        Frame f(static_cast<std::size_t>(w * h));
        for (auto &v : f)
            v = static_cast<std::uint8_t>(pick(gen));
        frames.push_back(f);
        // A frame that changes a small block, one that is identical, one fully random.
        for (int y = 5; y < 9; ++y)
            for (int x = 10; x < 20; ++x)
                f[static_cast<std::size_t>(y * w + x)] = static_cast<std::uint8_t>(pick(gen));
        frames.push_back(f);
        frames.push_back(f);
        for (auto &v : f)
            v = static_cast<std::uint8_t>(pick(gen));
        frames.push_back(f);
        const std::vector<int> delays = {10, 20, 30, 250};
        const std::vector<std::uint8_t> gif = encodeGif(w, h, palette, frames, delays);

        ASSERT_GE(gif.size(), 13u);
        EXPECT_EQ(std::string(gif.begin(), gif.begin() + 6), "GIF89a");
        EXPECT_EQ(gif[6] | (gif[7] << 8), w);
        EXPECT_EQ(gif[8] | (gif[9] << 8), h);
        EXPECT_EQ(gif.back(), 0x3B);
        const DecodedGif d = decodeGif(gif);
        EXPECT_EQ(d.width, w);
        EXPECT_EQ(d.height, h);
        std::size_t table = 2;
        while (table < colours + (colours < 256 ? 1 : 0)) // one more index: transparent
            table *= 2;
        ASSERT_EQ(d.palette.size(), table) << colours;
        for (std::size_t k = 0; k < colours; ++k)
            EXPECT_EQ(d.palette[k], palette[k]);
        EXPECT_TRUE(d.hasLoop);
        EXPECT_EQ(d.loopCount, 0); // forever
        EXPECT_EQ(d.delays, delays);
        ASSERT_EQ(d.frames.size(), frames.size());
        for (std::size_t k = 0; k < frames.size(); ++k)
            EXPECT_EQ(d.frames[k], frames[k]) << colours << " colours, frame " << k;
        EXPECT_EQ(d.transparent[0], -1);
        EXPECT_EQ(d.transparent[1], colours < 256 ? static_cast<int>(colours) : -1);
    }
}

TEST(GifEncoder, LargeUniformFramesHitTheTableLimit)
{
    const int w = 3000, h = 3000;
    const Palette palette = greyPalette(4);
    std::vector<Frame> frames = {Frame(static_cast<std::size_t>(w) * h, 1),
                                 Frame(static_cast<std::size_t>(w) * h, 2)};
    const std::vector<std::uint8_t> gif = encodeGif(w, h, palette, frames, 5);
    EXPECT_LT(gif.size(), 40000u);
    const DecodedGif d = decodeGif(gif);
    ASSERT_EQ(d.frames.size(), 2u);
    EXPECT_EQ(d.frames[0], frames[0]);
    EXPECT_EQ(d.frames[1], frames[1]);
    EXPECT_GE(d.clears, 4); // two frames, each with a reset of the full table
    EXPECT_EQ(d.delays, (std::vector<int>{5, 5}));
}

TEST(GifEncoder, RefusesMisuseNamingTheParameter)
{
    const Palette p = greyPalette(4);
    auto message = [](const std::function<void()> &f)
    {
        try
        {
            f();
        }
        catch (const std::invalid_argument &e)
        {
            return std::string(e.what());
        }
        return std::string("no exception");
    };
    EXPECT_TRUE(contains(message([&] { encodeGif(0, 4, p, {Frame(0)}, 5); }), "width and height"));
    EXPECT_TRUE(contains(message([&] { encodeGif(2, 2, greyPalette(1), {Frame(4)}, 5); }), "palette"));
    EXPECT_TRUE(contains(message([&] { encodeGif(2, 2, p, {Frame(3)}, 5); }), "expected w * h = 4"));
    EXPECT_TRUE(contains(message([&] { encodeGif(2, 2, p, {Frame(4, 9)}, 5); }), "index 9"));
    EXPECT_TRUE(contains(message([&] { encodeGif(2, 2, p, {}, 5); }), "frames"));
    EXPECT_TRUE(contains(message(
                             [&] {
                                 encodeGif(2, 2, p, {Frame(4), Frame(4)}, std::vector<int>{1, 2, 3});
                             }),
                         "delaysCs"));
}

// ----------------------------------------------------------------------------------------------------------
// Drawing a run

TEST(SimRender, GifShowsWorldRobotsAndObstaclesFrameByFrame)
{
    const SmallRun &run = smallRun();
    ASSERT_EQ(run.result.done, 2u) << "the straight controller should finish this open world";
    GifOptions o;
    o.width = 400;
    o.maxFrames = 50;
    o.fps = 20;
    o.holdLast = 1.0;
    const DecodedGif d = decodeGif(simulationGif(run.scenario, run.result, o));
    EXPECT_EQ(d.width, 400);
    EXPECT_EQ(d.height, 196 + 8 + 16); // 8 x 4 m at 49 px/m (392 / 8), 4 px margins, 16 px time label
    ASSERT_EQ(d.frames.size(), 50u);
    EXPECT_EQ(d.delays.front(), 5);
    EXPECT_EQ(d.delays.back(), 105);
    EXPECT_TRUE(d.hasLoop);

    const double scale = (400 - 8.0) / 8.0;
    auto pixel = [&](const Frame &f, Vec2 p)
    {
        const int x = static_cast<int>(4 + p.x * scale), y = static_cast<int>(4 + (4 - p.y) * scale);
        return d.palette[f[static_cast<std::size_t>(y * d.width + x)]];
    };
    const std::array<std::uint8_t, 3> obstacle = {136, 136, 136}, world = {250, 250, 250};
    const std::array<std::uint8_t, 3> robotA = {0x1f, 0x77, 0xb4}, robotB = {0xff, 0x7f, 0x0e};
    const std::array<std::uint8_t, 3> moving = {230, 85, 13};
    for (const Frame &f : {d.frames.front(), d.frames.back()})
    {
        EXPECT_EQ(pixel(f, {4, 3.2}), obstacle);  // circle
        EXPECT_EQ(pixel(f, {4, 0.45}), obstacle); // triangle
        EXPECT_EQ(pixel(f, {1.5, 3.5}), world);
    }
    // First frame: robot a at its start; b has not joined yet.
    EXPECT_EQ(pixel(d.frames.front(), {0.5, 2}), robotA);
    EXPECT_EQ(pixel(d.frames.front(), {7.5, 1.2}), world);
    EXPECT_EQ(pixel(d.frames.front(), {6.5, 3}), moving); // circle motion at phase 0
    // Last frame: both robots at their goals, a's trail behind it in its light colour.
    const RobotResult &a = run.result.robots[0], &b = run.result.robots[1];
    EXPECT_EQ(pixel(d.frames.back(), a.positions.back()), robotA);
    EXPECT_EQ(pixel(d.frames.back(), b.positions.back()), robotB);
    const auto trail = pixel(d.frames.back(), {3.0, 2.0});
    EXPECT_NE(trail, world);
    EXPECT_NE(trail, robotA);
    const Vec2 mEnd = run.result.obstaclePositions[0].back();
    EXPECT_EQ(pixel(d.frames.back(), mEnd), moving);
}

TEST(SimRender, FramesSubsampleTheRecordedTimesEvenly)
{
    const SmallRun &run = smallRun();
    GifOptions o;
    o.width = 64;
    o.maxFrames = 100000;
    int w = 0, h = 0;
    Palette palette;
    const auto all = renderSimulationFrames(run.scenario, run.result, o, w, h, palette);
    EXPECT_EQ(all.size(), run.result.times.size());
    EXPECT_LE(palette.size(), 256u);
    o.maxFrames = 7;
    EXPECT_EQ(renderSimulationFrames(run.scenario, run.result, o, w, h, palette).size(), 7u);
    o.width = 8;
    EXPECT_THROW(renderSimulationFrames(run.scenario, run.result, o, w, h, palette), std::invalid_argument);
}

TEST(SimRender, SvgHasOnePathPerRobotAndIsWellFormed)
{
    const SmallRun &run = smallRun();
    for (bool animate : {false, true})
    {
        const std::string svg = simulationSvg(run.scenario, run.result, animate);
        EXPECT_EQ(xmlBalance(svg), "") << animate;
        EXPECT_EQ(countOf(svg, "<path "), run.result.robots.size());
        EXPECT_EQ(countOf(svg, "class=\"trajectory\""), run.result.robots.size());
        EXPECT_TRUE(contains(svg, "controller straight"));
        EXPECT_TRUE(contains(svg, "seed 7"));
        EXPECT_TRUE(contains(svg, "makespan "));
        EXPECT_TRUE(contains(svg, "flowtime "));
        EXPECT_TRUE(contains(svg, "collisions 0"));
        EXPECT_TRUE(contains(svg, robotColor(0)) && contains(svg, robotColor(1)));
        EXPECT_EQ(contains(svg, "<animate "), animate);
        // The late robot is hidden until it joins.
        EXPECT_EQ(contains(svg, "attributeName=\"visibility\""), animate);
    }
    EXPECT_NE(xmlBalance("<svg><g></svg>"), ""); // the checker itself
}

TEST(SimRender, CsvHasOneRowPerSampleOrderedByTime)
{
    const SmallRun &run = smallRun();
    const std::string csv = trajectoryCsv(run.result);
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "time,robot,x,y,heading");
    std::size_t rows = 0;
    double last = -1.0;
    while (std::getline(in, line))
    {
        ++rows;
        const double t = std::stod(line.substr(0, line.find(',')));
        EXPECT_GE(t, last);
        last = t;
    }
    EXPECT_EQ(rows, run.result.robots[0].times.size() + run.result.robots[1].times.size());
    EXPECT_TRUE(contains(csv, "\n0,a,0.5,2,0\n"));
}

// ----------------------------------------------------------------------------------------------------------
// mhplan sim

TEST(SimCli, WritesGifSvgAndCsv)
{
    const std::string gif = tempPath("run.gif"), svg = tempPath("run.svg"), csv = tempPath("run.csv");
    std::remove(gif.c_str());
    const auto r =
        mhplan::test::runCli("sim mapf_2robots --controller dapf --seed 3 --gif " + gif + " --svg " + svg +
                             " --csv " + csv + " --gif-width 200 --max-frames 60");
    ASSERT_TRUE(r.code == 0 || r.code == 3) << r.out;
    for (const char *field : {"robots:", "flowtime:", "makespan:", "collisions:", "robot-steps/s",
                              "seed:       3", "min robot distance", "r1", "r2"})
        EXPECT_TRUE(contains(r.out, field)) << field << "\n" << r.out;
    EXPECT_EQ(r.code == 0, contains(r.out, "2 done")) << r.out;
    const std::string bytes = readFile(gif);
    ASSERT_GT(bytes.size(), 6u);
    EXPECT_EQ(bytes.substr(0, 6), "GIF89a");
    const DecodedGif d = decodeGif(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
    EXPECT_EQ(d.width, 200);
    EXPECT_EQ(d.frames.size(), 60u);
    const std::string s = readFile(svg);
    EXPECT_EQ(xmlBalance(s), "");
    EXPECT_EQ(countOf(s, "<path "), 2u);
    EXPECT_TRUE(contains(readFile(csv), "time,robot,x,y,heading\n0,r1,"));
}

TEST(SimCli, SameSeedSameTrajectories)
{
    const std::string a = tempPath("seed_a.csv"), b = tempPath("seed_b.csv");
    const auto ra =
        mhplan::test::runCli("sim bfo_case3_lines --controller bfo --seed 11 --time-limit 20 --csv " + a);
    const auto rb =
        mhplan::test::runCli("sim bfo_case3_lines --controller bfo --seed 11 --time-limit 20 --csv " + b);
    ASSERT_TRUE(ra.code == 0 || ra.code == 3) << ra.out;
    ASSERT_TRUE(rb.code == 0 || rb.code == 3) << rb.out;
    const std::string ca = readFile(a);
    EXPECT_GT(ca.size(), 100u);
    EXPECT_EQ(ca, readFile(b));
}

TEST(SimCli, UnfinishedRunExitsWithThree)
{
    const auto r = mhplan::test::runCli("sim mapf_2robots --controller dapf --seed 1 --time-limit 1");
    EXPECT_EQ(r.code, 3) << r.out;
    EXPECT_TRUE(contains(r.out, "2 unfinished")) << r.out;
    EXPECT_TRUE(contains(r.out, "(lower bound)")) << r.out;
}

TEST(SimCli, RefusesBadInputWithAClearMessage)
{
    struct Case
    {
        std::string args;
        std::vector<std::string> expect;
    };
    const std::vector<Case> cases = {
        {"sim mapf_2robots --controller nosuch", {"nosuch", "dapf", "aapf"}},
        {"sim mapf_2robots", {"--controller NAME is required", "dapf"}},
        {"sim no_such_scenario.yaml --controller dapf", {"no_such_scenario.yaml", "no such file"}},
        {"sim --controller dapf", {"expected exactly one SCENARIO"}},
        {"sim mapf_2robots --controller dapf --time-limit 0", {"--time-limit must be > 0"}},
        {"sim mapf_2robots --controller dapf --fps 0", {"--fps must be in (0, 100]"}},
        {"sim mapf_2robots --controller dapf --gif-width 3", {"--gif-width must be in [16, 4096]"}},
        {"sim mapf_2robots --controller dapf --seed 0", {"--seed must be in"}},
        {"sim mapf_2robots --controller dapf --set", {"needs a value"}},
        {"sim mapf_2robots --controller dapf --set nonsense", {"key=value"}},
        {"sim mapf_2robots --controller dapf --colour red", {"unknown option '--colour'", "--gif"}},
    };
    for (const auto &c : cases)
    {
        const auto r = mhplan::test::runCli(c.args);
        EXPECT_EQ(r.code, 1) << c.args << "\n" << r.out;
        for (const auto &e : c.expect)
            EXPECT_TRUE(contains(r.out, e)) << c.args << ": output lacks '" << e << "':\n" << r.out;
    }
}
