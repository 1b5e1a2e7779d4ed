// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the one parameter convention of mhplan's planners. A numeric parameter's range is written once, as
   a ParamRange, and used both by the OMPL declaration (its range suggestion) and by the setter's check;
   switches are bool ("0,1"; the registry also accepts true/false); choices are words ("a,b,c"). */
#ifndef MHPLAN_BASE_PARAMETERS_H
#define MHPLAN_BASE_PARAMETERS_H

#include <ompl/base/GenericParam.h>

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

namespace mhplan
{
    /** \brief A numeric parameter: its name and its accepted closed interval [lo, hi], with the step OMPL's
        range suggestion advertises ("lo:step:hi"), and one line saying what it does (`mhplan planners`). */
    struct ParamRange
    {
        const char *name;
        double lo;
        double step;
        double hi;
        const char *description{""};
    };

    /** \brief What a parameter does, carried by the parameter itself (OMPL's GenericParam has no such
        field): the parameters declared through declareRanged, declareSwitch and declareChoice have one. */
    class ParameterDescription
    {
      public:
        explicit ParameterDescription(std::string text) : text_(std::move(text)) {}
        virtual ~ParameterDescription() = default;
        const std::string &description() const { return text_; }

      private:
        std::string text_;
    };

    /** \brief An OMPL parameter with a description. */
    template <typename T>
    class DescribedParam : public ompl::base::SpecificParam<T>, public ParameterDescription
    {
      public:
        DescribedParam(const std::string &name, typename ompl::base::SpecificParam<T>::SetterFn setter,
                       typename ompl::base::SpecificParam<T>::GetterFn getter, std::string description)
            : ompl::base::SpecificParam<T>(name, std::move(setter), std::move(getter)),
              ParameterDescription(std::move(description))
        {
        }
    };

    /** \brief The description of \e param ("" when it has none, e.g. OMPL's own planners' parameters). */
    std::string parameterDescription(const ompl::base::GenericParam &param);

    /** \brief The OMPL range suggestion "lo:step:hi" of \e range. */
    std::string rangeSuggestion(const ParamRange &range);

    /** \brief Throws std::invalid_argument "parameter 'name' must be in [lo, hi]; got value" unless
        lo <= value <= hi. */
    void checkParameterRange(const char *param, double value, double lo, double hi);

    /** \brief The setter's check of a ParamRange (checkParameterRange with its name and bounds). */
    inline void checkParameter(const ParamRange &range, double value)
    {
        checkParameterRange(range.name, value, range.lo, range.hi);
    }

    /** \brief The check-and-store of a ranged setter, written once: checkParameter(range, value), then
        field = value (a refused value leaves the field as it was). */
    template <typename T, typename V> void storeChecked(const ParamRange &range, T &field, V value)
    {
        checkParameter(range, static_cast<double>(value));
        field = value;
    }

    /** \brief storeChecked() for a parameter whose change resets its owner: after the check, \e reset is
        called (before the store) when the value differs from the field's. */
    template <typename T, typename V, typename Reset>
    void storeCheckedResetting(const ParamRange &range, T &field, V value, Reset reset)
    {
        checkParameter(range, static_cast<double>(value));
        if (value != field)
            reset();
        field = value;
    }

    /** \brief A decimal string that reads back as exactly \e value (15 significant digits, 17 when needed)
       (OMPL prints double parameters with six significant digits, which does not round-trip). */
    std::string formatParameter(double value);

    /** \brief \e text as a number for \e range; throws std::invalid_argument naming the parameter and its
        range when \e text is not a number (the range itself is the setter's check). */
    double parseParameter(const ParamRange &range, const std::string &text);

    /** \brief Declare the numeric parameter \e range on \e params, of type \e T, with the callables \e set
        (taking a T) and \e get (returning one). A floating-point parameter is read and printed exactly
        (parseParameter, formatParameter), so that setParam followed by getParam gives the same string. */
    template <typename T, typename Set, typename Get>
    void declareRangedWith(ompl::base::ParamSet &params, const ParamRange &range, Set set, Get get)
    {
        if constexpr (std::is_floating_point_v<T>)
            params.add(std::make_shared<DescribedParam<std::string>>(
                range.name,
                [set, range](const std::string &text) { set(static_cast<T>(parseParameter(range, text))); },
                [get] { return formatParameter(static_cast<double>(get())); }, range.description));
        else
            params.add(std::make_shared<DescribedParam<T>>(
                range.name, [set](T v) { set(v); }, [get] { return static_cast<T>(get()); },
                range.description));
        params[range.name].setRangeSuggestion(rangeSuggestion(range));
    }

    /** \brief Declare the numeric parameter \e range on \e params, of type \e T, with the member setter and
        getter of \e owner (the setter checks the value with checkParameter(range, value)). */
    template <typename T, typename Owner, typename Setter, typename Getter>
    void declareRanged(ompl::base::ParamSet &params, Owner *owner, const ParamRange &range, Setter setter,
                       Getter getter)
    {
        declareRangedWith<T>(
            params, range, [owner, setter](T v) { (owner->*setter)(v); },
            [owner, getter] { return (owner->*getter)(); });
    }

    /** \brief Declare the numeric parameter \e range on \e params straight onto the field \e field (which
        must outlive \e params): setting it checks the value with checkParameter(range, value), stores it
        and then calls \e changed (when given). */
    template <typename T>
    void declareRangedField(ompl::base::ParamSet &params, const ParamRange &range, T &field,
                            std::function<void()> changed = {})
    {
        declareRangedWith<T>(
            params, range,
            [&field, range, changed](T v)
            {
                storeChecked(range, field, v);
                if (changed)
                    changed();
            },
            [&field] { return field; });
    }

    /** \brief Declare the bool switch \e name ("0,1") on \e params with the member setter and getter of
        \e owner. */
    template <typename Owner, typename Setter, typename Getter>
    void declareSwitch(ompl::base::ParamSet &params, Owner *owner, const std::string &name, Setter setter,
                       Getter getter, const std::string &description = "")
    {
        params.add(std::make_shared<DescribedParam<bool>>(
            name, [owner, setter](bool v) { (owner->*setter)(v); },
            [owner, getter] { return (owner->*getter)(); }, description));
        params[name].setRangeSuggestion("0,1");
    }

    /** \brief Declare the bool switch \e name ("0,1") on \e params straight onto the field \e field (which
        must outlive \e params); setting it stores the value and then calls \e changed (when given). */
    inline void declareSwitchField(ompl::base::ParamSet &params, const std::string &name, bool &field,
                                   const std::string &description, std::function<void()> changed = {})
    {
        params.add(std::make_shared<DescribedParam<bool>>(
            name,
            [&field, changed](bool v)
            {
                field = v;
                if (changed)
                    changed();
            },
            [&field] { return field; }, description));
        params[name].setRangeSuggestion("0,1");
    }

    /** \brief Declare the word-valued parameter \e name with the accepted words \e choices ("a,b,c"), with
        the callables \e set (taking a word; it refuses any other) and \e get (returning one). */
    template <typename Set, typename Get>
    void declareChoiceWith(ompl::base::ParamSet &params, const std::string &name, Set set, Get get,
                           const std::string &choices, const std::string &description = "")
    {
        params.add(std::make_shared<DescribedParam<std::string>>(
            name, [set](const std::string &v) { set(v); }, [get] { return std::string(get()); },
            description));
        params[name].setRangeSuggestion(choices);
    }

    /** \brief declareChoiceWith() with the member setter and getter of \e owner. */
    template <typename Owner, typename Setter, typename Getter>
    void declareChoice(ompl::base::ParamSet &params, Owner *owner, const std::string &name, Setter setter,
                       Getter getter, const std::string &choices, const std::string &description = "")
    {
        declareChoiceWith(
            params, name, [owner, setter](const std::string &v) { (owner->*setter)(v); },
            [owner, getter] { return (owner->*getter)(); }, choices, description);
    }
} // namespace mhplan

#endif
