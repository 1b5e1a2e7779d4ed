// SPDX-License-Identifier: BSD-3-Clause
// Content fingerprints, derived seeds and safe file stems of a campaign's experiments (benchmarks/README.md,
// "What a campaign guarantees").
#include "benchmarks/Campaign.h"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <string>

namespace mhplan::bench
{
    void Fingerprint::add(const std::string &text)
    {
        std::uint64_t h = h_;
        for (unsigned char ch : text)
        {
            h ^= ch;
            h *= 1099511628211ULL;
        }
        h_ = h;
    }

    std::string Fingerprint::hex() const
    {
        char buf[17];
        std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(h_));
        return buf;
    }

    std::string fingerprint(const std::string &text)
    {
        Fingerprint f;
        f.add(text);
        return f.hex();
    }

    std::uint32_t deriveSeed(std::uint32_t base, const std::string &label, std::uint64_t index)
    {
        std::uint64_t h = 1469598103934665603ULL;
        for (unsigned char ch : label)
        {
            h ^= ch;
            h *= 1099511628211ULL;
        }
        std::uint64_t z = h ^ (static_cast<std::uint64_t>(base) << 32) ^ (index * 0x9E3779B97F4A7C15ULL);
        // splitmix64 finaliser
        z += 0x9E3779B97F4A7C15ULL;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        z ^= z >> 31;
        return static_cast<std::uint32_t>(1 + z % 4294967295ULL);
    }

    std::string safeFileStem(const std::string &name)
    {
        std::string out;
        for (char ch : name)
            out += (std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_' || ch == '.')
                       ? ch
                       : '_';
        return out;
    }
} // namespace mhplan::bench
