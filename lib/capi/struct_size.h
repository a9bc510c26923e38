// SPDX-License-Identifier: Apache-2.0
// The struct_size handshake of description structs. A struct_size is accepted only if it
// is the size of that struct in some released header: the current one, or an older,
// smaller one whose missing fields are then served with their defaults. Zero, garbage and
// sizes from a newer header are refused with ENT_ERROR_VERSION.
#pragma once

#include <cstdint>
#include <cstdio>
#include <initializer_list>

#include "base/error.h"

namespace enteron::capi {

inline void check_struct_size(uint32_t struct_size, std::initializer_list<std::size_t> released,
                              const char* type) {
    for (std::size_t size : released)
        if (struct_size == size) return;
    char message[192];
    std::snprintf(message, sizeof message,
                  "%s.struct_size is %u, which no release of this library (version %d.%d.%d) knows; "
                  "set it to sizeof the struct (the _default macros do it for you)",
                  type, struct_size, ENT_VERSION_MAJOR, ENT_VERSION_MINOR, ENT_VERSION_PATCH);
    throw Error(ErrorCode::version, message);
}

}  // namespace enteron::capi
