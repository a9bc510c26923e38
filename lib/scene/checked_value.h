// SPDX-License-Identifier: Apache-2.0
// One value under test, named for messages: the building block of every check of caller
// input (the scene description, the skin description). Each check throws Error(code) on
// failure and returns *this, so checks chain:
//   Checked<double>(r, "intestine.radius", code).above(0.0).below(length, "intestine.length");
// gives "intestine.radius must be > 0, got -1". A floating-point value must be finite.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>

#include "base/error.h"

namespace enteron::scene {

// Shortest text that reads back as the same double ("-1", not "-1.000000"). to_chars
// ignores the locale, which a host program may have changed.
inline std::string format_number(double value) {
    if (std::isnan(value)) return "nan";
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

// A measured quantity in a message, to three significant digits ("0.979", "512").
inline std::string format_rounded(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
std::string format_number(Integer value) {
    return std::to_string(value);
}

template <typename T>
class Checked {
public:
    Checked(T value, std::string name, ErrorCode code) : value_(value), name_(std::move(name)), code_(code) {
        if constexpr (std::is_floating_point_v<T>) {
            if (!std::isfinite(value_)) fail("must be finite");
        }
    }

    // bound_name, when given, says where the bound comes from: "< intestine.length (6)".
    const Checked& above(T bound, const std::string& bound_name = {}) const {
        return require(value_ > bound, ">", bound, bound_name);
    }
    const Checked& at_least(T bound, const std::string& bound_name = {}) const {
        return require(value_ >= bound, ">=", bound, bound_name);
    }
    const Checked& below(T bound, const std::string& bound_name = {}) const {
        return require(value_ < bound, "<", bound, bound_name);
    }
    const Checked& at_most(T bound, const std::string& bound_name = {}) const {
        return require(value_ <= bound, "<=", bound, bound_name);
    }

    [[noreturn]] void fail(const std::string& requirement) const {
        throw Error(code_, name_ + " " + requirement + ", got " + format_number(value_));
    }

private:
    const Checked& require(bool ok, const char* relation, T bound, const std::string& bound_name) const {
        if (!ok) {
            const std::string bound_text =
                bound_name.empty() ? format_number(bound) : bound_name + " (" + format_number(bound) + ")";
            fail(std::string("must be ") + relation + " " + bound_text);
        }
        return *this;
    }

    T value_;
    std::string name_;
    ErrorCode code_;
};

}  // namespace enteron::scene
