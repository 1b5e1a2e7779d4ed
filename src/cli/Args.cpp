// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/cli/Args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>
#include <sstream>

namespace mhplan::cli
{
    namespace
    {
        std::string accepted(const Args::Spec &spec)
        {
            std::set<std::string> all(spec.valued);
            all.insert(spec.repeatable.begin(), spec.repeatable.end());
            all.insert(spec.flags.begin(), spec.flags.end());
            std::string out;
            for (const auto &a : all)
                out += (out.empty() ? "--" : ", --") + a;
            return out.empty() ? "(no options)" : out;
        }
    } // namespace

    Args::Args(const std::string &command, const std::vector<std::string> &argv, const Spec &spec)
        : command_(command)
    {
        for (std::size_t i = 0; i < argv.size(); ++i)
        {
            const std::string &a = argv[i];
            if (a.size() < 3 || a.compare(0, 2, "--") != 0)
            {
                if (a.size() > 1 && a[0] == '-' && !(a[1] >= '0' && a[1] <= '9') && a[1] != '.')
                    throw InputError("mhplan " + command + ": unknown option '" + a +
                                     "'; accepted: " + accepted(spec));
                positional_.push_back(a);
                continue;
            }
            std::string name = a.substr(2);
            std::string value;
            bool inlineValue = false;
            const auto eq = name.find('=');
            if (eq != std::string::npos)
            {
                value = name.substr(eq + 1);
                name = name.substr(0, eq);
                inlineValue = true;
            }
            if (spec.flags.count(name))
            {
                if (inlineValue)
                    throw InputError("mhplan " + command + ": option --" + name + " takes no value");
                flags_.insert(name);
                continue;
            }
            const bool single = spec.valued.count(name) != 0;
            const bool multi = spec.repeatable.count(name) != 0;
            if (!single && !multi)
                throw InputError("mhplan " + command + ": unknown option '--" + name +
                                 "'; accepted: " + accepted(spec));
            if (!inlineValue)
            {
                if (i + 1 >= argv.size())
                    throw InputError("mhplan " + command + ": option --" + name + " needs a value");
                value = argv[++i];
            }
            if (single)
            {
                if (values_.count(name))
                    throw InputError("mhplan " + command + ": option --" + name + " given twice");
                values_[name] = value;
            }
            else
                repeated_[name].push_back(value);
        }
    }

    std::string Args::get(const std::string &name, const std::string &fallback) const
    {
        const auto it = values_.find(name);
        return it == values_.end() ? fallback : it->second;
    }

    const std::vector<std::string> &Args::all(const std::string &name) const
    {
        static const std::vector<std::string> empty;
        const auto it = repeated_.find(name);
        return it == repeated_.end() ? empty : it->second;
    }

    double Args::number(const std::string &name, double fallback) const
    {
        const auto it = values_.find(name);
        if (it == values_.end())
            return fallback;
        char *end = nullptr;
        errno = 0;
        const double v = std::strtod(it->second.c_str(), &end);
        if (it->second.empty() || errno != 0 || end != it->second.c_str() + it->second.size() ||
            !std::isfinite(v))
            throw InputError("mhplan " + command_ + ": option --" + name + " expects a finite number, got '" +
                             it->second + "'");
        return v;
    }

    double Args::timeLimit(double fallback) const
    {
        const double t = number("time", fallback);
        if (!(t >= kMinTimeLimit && t <= kMaxTimeLimit))
            throw InputError("mhplan " + command_ + ": --time must be in [0.001, 1000000] seconds (got " +
                             get("time") + ")");
        return t;
    }

    long long Args::integer(const std::string &name, long long fallback) const
    {
        const auto it = values_.find(name);
        if (it == values_.end())
            return fallback;
        char *end = nullptr;
        errno = 0;
        const long long v = std::strtoll(it->second.c_str(), &end, 10);
        if (it->second.empty() || errno != 0 || end != it->second.c_str() + it->second.size())
            throw InputError("mhplan " + command_ + ": option --" + name + " expects an integer, got '" +
                             it->second + "'");
        return v;
    }

    ValiditySetup setupFromArgs(const Args &args)
    {
        const std::string kind = args.get("setup", "exact");
        double resolution = std::nan("");
        if (args.has("resolution"))
        {
            if (kind != "app")
                throw InputError(
                    "mhplan " + args.command() +
                    ": --resolution belongs to --setup app (the exact set-up decides every point "
                    "of a motion)");
            resolution = args.number("resolution", kDefaultAppResolution);
        }
        try
        {
            return makeValiditySetup(kind, resolution);
        }
        catch (const InputError &e)
        {
            throw InputError("mhplan " + args.command() + ": --" +
                             (kind == "exact" || kind == "app" ? "resolution" : "setup") + ": " + e.what());
        }
    }

    Vec2 Args::point(const std::string &name) const
    {
        const std::vector<double> v = parseNumberList("--" + name, get(name));
        if (v.size() != 2)
            throw InputError("mhplan " + command_ + ": option --" + name + " expects X,Y, got '" + get(name) +
                             "'");
        return {v[0], v[1]};
    }

    namespace
    {
        bool writableDirectory(const std::filesystem::path &dir)
        {
            std::error_code ec;
            return std::filesystem::is_directory(dir, ec) && access(dir.c_str(), W_OK | X_OK) == 0;
        }
    } // namespace

    void checkOutputFile(const Args &args, const std::string &name)
    {
        if (!args.has(name))
            return;
        namespace fs = std::filesystem;
        const std::string path = args.get(name);
        const std::string what = "mhplan " + args.command() + ": --" + name + " '" + path + "': ";
        std::error_code ec;
        if (path.empty())
            throw InputError(what + "an empty file name");
        if (fs::is_directory(path, ec))
            throw InputError(what + "is a directory; give a file name");
        const fs::path parent =
            fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
        if (!fs::is_directory(parent, ec))
            throw InputError(what + "the directory '" + parent.string() + "' does not exist");
        if (!writableDirectory(parent))
            throw InputError(what + "the directory '" + parent.string() + "' is not writable");
        if (fs::exists(path, ec) && access(path.c_str(), W_OK) != 0)
            throw InputError(what + "the file exists and is not writable");
    }

    void checkOutputDirectory(const std::string &command, const std::string &name, const std::string &path)
    {
        namespace fs = std::filesystem;
        const std::string what = "mhplan " + command + ": --" + name + " '" + path + "': ";
        std::error_code ec;
        if (path.empty())
            throw InputError(what + "an empty directory name");
        fs::path p = fs::absolute(path, ec).lexically_normal();
        if (fs::exists(p, ec) && !fs::is_directory(p, ec))
            throw InputError(what + "exists and is not a directory");
        // The nearest existing ancestor must be a writable directory (the rest is created by the run).
        while (!p.empty() && !fs::exists(p, ec) && p != p.parent_path())
            p = p.parent_path();
        if (!fs::is_directory(p, ec))
            throw InputError(what + "'" + p.string() + "' is not a directory");
        if (!writableDirectory(p))
            throw InputError(what + "the directory '" + p.string() + "' is not writable");
    }

    std::vector<double> parseNumberList(const std::string &name, const std::string &text)
    {
        std::vector<double> out;
        std::stringstream ss(text);
        std::string item;
        while (std::getline(ss, item, ','))
        {
            char *end = nullptr;
            errno = 0;
            const double v = std::strtod(item.c_str(), &end);
            if (item.empty() || errno != 0 || end != item.c_str() + item.size() || !std::isfinite(v))
                throw InputError("option " + name + ": '" + item + "' is not a finite number (in '" + text +
                                 "')");
            out.push_back(v);
        }
        return out;
    }
} // namespace mhplan::cli
