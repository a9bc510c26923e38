// Every C entry point runs its body through guarded(): exceptions become a status and a
// message for ent_last_error(); nothing escapes into the caller's C code.
#pragma once

#include <cstdint>
#include <exception>
#include <new>

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

template <class Body>
ent_status guarded(Body&& body) noexcept {
    try {
        body();
        return ENT_OK;
    } catch (const Error& error) {
        set_last_error(error.what());
        return static_cast<ent_status>(error.code());
    } catch (const std::bad_alloc&) {
        set_last_error("out of memory");
        return ENT_ERROR_OUT_OF_MEMORY;
    } catch (const std::exception& error) {
        set_last_error(error.what());
        return ENT_ERROR_INTERNAL;
    } catch (...) {
        set_last_error("unknown internal error");
        return ENT_ERROR_INTERNAL;
    }
}

}  // namespace enteron::capi
