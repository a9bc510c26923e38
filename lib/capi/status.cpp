// SPDX-License-Identifier: Apache-2.0
// Version, status strings, the per-thread last error, effect names.
#include <cstring>

#include "capi/call_guard.h"
#include "mechanics/effect_id.h"

namespace {
thread_local char last_error[1024] = "";
}

namespace enteron::capi {
void set_last_error(const char* message) {
    std::strncpy(last_error, message, sizeof last_error - 1);
    last_error[sizeof last_error - 1] = '\0';
}
}  // namespace enteron::capi

extern "C" {

ENT_API uint32_t ent_version(void) { return ENT_VERSION; }

ENT_API const char* ent_status_string(ent_status status) {
    switch (status) {
        case ENT_OK: return "ok";
        case ENT_ERROR_INVALID_ARGUMENT: return "invalid argument";
        case ENT_ERROR_VERSION: return "version mismatch";
        case ENT_ERROR_PARSE: return "JSON parse error";
        case ENT_ERROR_INVALID_SCENE: return "invalid scene description";
        case ENT_ERROR_UNSTABLE: return "unstable step";
        case ENT_ERROR_OUT_OF_MEMORY: return "out of memory";
        case ENT_ERROR_NOT_FOUND: return "not found";
        case ENT_ERROR_BUFFER_TOO_SMALL: return "buffer too small";
        case ENT_ERROR_INTERNAL: return "internal error";
        case ENT_ERROR_BUSY: return "busy: another call that must not overlap is running on this scene or skin";
        default: return "unknown status";
    }
}

ENT_API const char* ent_last_error(void) { return last_error; }

ENT_API const char* ent_effect_name(int32_t effect) {
    if (effect < 0 || effect >= ENT_EFFECT_COUNT) return nullptr;
    return enteron::mechanics::effect_name(static_cast<enteron::mechanics::EffectId>(effect));
}

}  // extern "C"
