// SPDX-License-Identifier: Apache-2.0
// The one exception type of the library. The C API turns it into a status and a message.
#pragma once

#include <stdexcept>
#include <string>

namespace enteron {

// Mirrors ENT_ERROR_* of enteron.h (checked by static_assert in lib/capi).
enum class ErrorCode : int {
    invalid_argument = 1,
    version = 2,
    parse = 3,
    invalid_scene = 4,
    unstable = 5,
    out_of_memory = 6,
    not_found = 7,
    buffer_too_small = 8,
    internal = 9,
    busy = 10,
};

class Error : public std::runtime_error {
public:
    Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
    ErrorCode code() const noexcept { return code_; }

private:
    ErrorCode code_;
};

}  // namespace enteron
