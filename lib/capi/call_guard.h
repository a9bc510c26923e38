// SPDX-License-Identifier: Apache-2.0
// Every C entry point runs its body through guarded(): exceptions become a status and a
// message for ent_last_error(); nothing escapes into the caller's C code.
#pragma once

#include <cstdint>
#include <exception>
#include <new>
#include <utility>

#include "base/error.h"
#include "enteron/enteron.h"

namespace enteron::capi {

// Stores the calling thread's last error message (truncated to a fixed buffer, so
// reporting an error never allocates).
void set_last_error(const char* message);

// Throws Error(invalid_argument) naming `name` when pointer is null.
inline void require(const void* pointer, const char* name) {
    if (pointer == nullptr) throw Error(ErrorCode::invalid_argument, std::string(name) + " must not be NULL");
}

// The guard with the store of the message given: libenteron_lcm keeps its own
// (ent_lcm_last_error), so that the two libraries' messages never mix.
template <void (*Report)(const char*), class Body>
ent_status guarded_with(Body&& body) noexcept {
    try {
        body();
        return ENT_OK;
    } catch (const Error& error) {
        Report(error.what());
        return static_cast<ent_status>(error.code());
    } catch (const std::bad_alloc&) {
        Report("out of memory");
        return ENT_ERROR_OUT_OF_MEMORY;
    } catch (const std::exception& error) {
        Report(error.what());
        return ENT_ERROR_INTERNAL;
    } catch (...) {
        Report("unknown internal error");
        return ENT_ERROR_INTERNAL;
    }
}

template <class Body>
ent_status guarded(Body&& body) noexcept {
    return guarded_with<set_last_error>(std::forward<Body>(body));
}

}  // namespace enteron::capi
