// SPDX-License-Identifier: Apache-2.0
// A text mesh file (OBJ, ASCII PLY, OFF, ASCII STL) read a line at a time, a word at a time,
// counting lines so that a refusal names the line. Numbers are read with std::from_chars:
// correctly rounded, as strtod and an iostream read them, without a locale.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "scene/mesh_soup.h"

namespace enteron::scene {

class MeshText {
public:
    // `text` from its `first_line`; a word starting with `comment` (OBJ and OFF: '#') ends
    // its line, 0 for none.
    MeshText(std::string_view text, std::size_t first_line = 1, char comment = 0)
        : text_(text), next_line_number_(first_line), comment_(comment) {}

    // Moves to the next line; false when there is none.
    bool next_line() {
        if (next_ >= text_.size()) return false;
        const std::size_t end = text_.find('\n', next_);
        line_ = text_.substr(next_, end == std::string_view::npos ? std::string_view::npos : end - next_);
        at_ = 0;
        next_ = end == std::string_view::npos ? text_.size() : end + 1;
        line_number_ = next_line_number_++;
        return true;
    }
    std::size_t line() const { return line_number_; }
    MeshPlace place() const { return MeshPlace::line(line_number_); }
    // Where the text after the current line starts (a binary PLY's body).
    std::size_t consumed() const { return next_; }

    // The next word of the line, empty at its end (or at a comment).
    std::string_view word() {
        while (at_ < line_.size() && is_space(line_[at_])) ++at_;
        if (at_ == line_.size() || (comment_ != 0 && line_[at_] == comment_)) {
            at_ = line_.size();
            return {};
        }
        const std::size_t start = at_;
        while (at_ < line_.size() && !is_space(line_[at_])) ++at_;
        return line_.substr(start, at_ - start);
    }
    // True when only spaces (or a comment) are left on the line.
    bool at_end() {
        const std::size_t before = at_;
        const bool end = word().empty();
        at_ = end ? at_ : before;
        return end;
    }

    // The next word as a finite number of type T (double, or float as a PLY file declares
    // it), `what` naming it in a refusal.
    template <class T = double>
    T number(const char* what) {
        const std::string_view w = word();
        if (w.empty()) refuse(std::string("expected ") + what + ", found the end of the line");
        T value;
        if (!parse(w, value) || !std::isfinite(value))
            refuse(std::string("expected ") + what + ", a finite number, found " + shown(w));
        return value;
    }
    // The next word as a whole number in [least, most].
    int64_t integer(const char* what, int64_t least, int64_t most) {
        const std::string_view w = word();
        if (w.empty()) refuse(std::string("expected ") + what + ", found the end of the line");
        int64_t value;
        if (!parse(w, value))
            refuse(std::string("expected ") + what + ", a whole number, found " + shown(w));
        if (value < least || value > most)
            refuse(std::string(what) + " is " + std::to_string(value) + ", not in [" + std::to_string(least) + ", " +
                   std::to_string(most) + "]");
        return value;
    }

    [[noreturn]] void refuse(const std::string& why) const { refuse_mesh(place(), why); }

    // A whole word as a number (a leading '+' allowed, as strtod allows it).
    template <class T>
    static bool parse(std::string_view w, T& value) {
        if (w.size() > 1 && w[0] == '+' && w[1] != '-') w.remove_prefix(1);
        const auto [end, error] = std::from_chars(w.data(), w.data() + w.size(), value);
        return error == std::errc() && end == w.data() + w.size();
    }

    // A word of the file quoted for a message: at most 40 characters, bytes that are not
    // printable as \xNN (a binary file read as text).
    static std::string shown(std::string_view w) {
        static const char kHex[] = "0123456789abcdef";
        std::string out = "\"";
        for (std::size_t i = 0; i < w.size() && i < 40; ++i) {
            const auto c = static_cast<unsigned char>(w[i]);
            if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
                out += static_cast<char>(c);
            } else {
                out += "\\x";
                out += kHex[c >> 4];
                out += kHex[c & 15];
            }
        }
        return out + (w.size() > 40 ? "...\"" : "\"");
    }

private:
    static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

    std::string_view text_;
    std::string_view line_;
    std::size_t next_ = 0;  // where the next line starts
    std::size_t at_ = 0;    // in line_
    std::size_t line_number_ = 0;
    std::size_t next_line_number_;
    char comment_;
};

}  // namespace enteron::scene
