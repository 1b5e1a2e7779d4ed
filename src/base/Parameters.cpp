// SPDX-License-Identifier: BSD-3-Clause
#include "src/base/Parameters.h"

#include <cerrno>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace mhplan
{
    std::string rangeSuggestion(const ParamRange &range)
    {
        std::ostringstream out;
        out << std::setprecision(12) << range.lo << ':' << range.step << ':' << range.hi;
        return out.str();
    }

    std::string parameterDescription(const ompl::base::GenericParam &param)
    {
        const auto *described = dynamic_cast<const ParameterDescription *>(&param);
        return described ? described->description() : std::string();
    }

    std::string formatParameter(double value)
    {
        // 15 significant digits print every value that has them exactly (trailing zeros dropped, no exponent
        // below 1e15); the others need 17.
        for (const int precision : {15, 17})
        {
            std::ostringstream out;
            out << std::setprecision(precision) << value;
            if (precision == 17 || std::strtod(out.str().c_str(), nullptr) == value)
                return out.str();
        }
        return {};
    }

    double parseParameter(const ParamRange &range, const std::string &text)
    {
        char *end = nullptr;
        errno = 0;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || errno != 0 || end != text.c_str() + text.size())
        {
            std::ostringstream msg;
            msg << std::setprecision(12) << "parameter '" << range.name << "' must be a number in ["
                << range.lo << ", " << range.hi << "]; got '" << text << "'";
            throw std::invalid_argument(msg.str());
        }
        return value;
    }

    void checkParameterRange(const char *param, double value, double lo, double hi)
    {
        if (value >= lo && value <= hi)
            return;
        std::ostringstream msg;
        msg << std::setprecision(12) << "parameter '" << param << "' must be in [" << lo << ", " << hi
            << "]; got " << value;
        throw std::invalid_argument(msg.str());
    }
} // namespace mhplan
