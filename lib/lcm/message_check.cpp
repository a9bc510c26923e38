// SPDX-License-Identifier: Apache-2.0
#include "lcm/message_check.h"

#include <lcmtypes/enteron_journal_step_t.h>
#include <lcmtypes/enteron_journal_tool_t.h>
#include <lcmtypes/enteron_mesh_t.h>
#include <lcmtypes/enteron_scene_state_t.h>
#include <lcmtypes/enteron_server_status_t.h>
#include <lcmtypes/enteron_session_t.h>
#include <lcmtypes/enteron_tool_command_t.h>
#include <lcmtypes/enteron_tool_feedback_t.h>
#include <lcmtypes/enteron_tool_state_t.h>

#include <cinttypes>
#include <cstdarg>
#include <cstdio>
#include <mutex>

#include "enteron/enteron_lcm.h"

namespace enteron::lcm {

namespace {

// How the variable part of a type is laid out after its fixed fields.
enum class Tail { none, counts, string };

struct TypeLayout {
    const char* name = "";
    int64_t fingerprint = 0;
    int64_t fixed_size = 0;           // with every count 0 and the string "", fingerprint included
    Tail tail = Tail::none;
    int count_fields = 0;             // Tail::counts: int32 counts just before the arrays
    int64_t element_size[3] = {0, 0, 0};  // bytes per unit of each count
};

TypeLayout layouts[8];

void compute_layouts() {
    {
        enteron_tool_command_t m{};
        layouts[ENT_LCM_TOOL_COMMAND] = {"tool_command_t", __enteron_tool_command_t_get_hash(),
                                         enteron_tool_command_t_encoded_size(&m)};
    }
    {
        enteron_tool_feedback_t m{};
        layouts[ENT_LCM_TOOL_FEEDBACK] = {"tool_feedback_t", __enteron_tool_feedback_t_get_hash(),
                                          enteron_tool_feedback_t_encoded_size(&m)};
    }
    {
        enteron_scene_state_t m{};
        enteron_tool_state_t tool{};
        TypeLayout& layout = layouts[ENT_LCM_SCENE_STATE];
        layout = {"scene_state_t", __enteron_scene_state_t_get_hash(), enteron_scene_state_t_encoded_size(&m),
                  Tail::counts, 3};
        layout.element_size[0] = 3 * 4;  // control_points_m: float[3]
        layout.element_size[1] = 3 * 4;  // axis_m: float[3]
        layout.element_size[2] = __enteron_tool_state_t_encoded_array_size(&tool, 1);
    }
    {
        enteron_mesh_t m{};
        TypeLayout& layout = layouts[ENT_LCM_MESH];
        layout = {"mesh_t", __enteron_mesh_t_get_hash(), enteron_mesh_t_encoded_size(&m), Tail::counts, 2};
        layout.element_size[0] = 3 * 4 + 3 * 4 + 4;  // per vertex: position, normal, axis_u
        layout.element_size[1] = 3 * 4;              // per triangle: three int32 indices
    }
    {
        enteron_session_t m{};
        char empty[] = "";
        m.scene_json = empty;
        layouts[ENT_LCM_SESSION] = {"session_t", __enteron_session_t_get_hash(), enteron_session_t_encoded_size(&m),
                                    Tail::string};
    }
    {
        enteron_server_status_t m{};
        layouts[ENT_LCM_SERVER_STATUS] = {"server_status_t", __enteron_server_status_t_get_hash(),
                                          enteron_server_status_t_encoded_size(&m)};
    }
    {
        enteron_journal_tool_t m{};
        layouts[ENT_LCM_JOURNAL_TOOL] = {"journal_tool_t", __enteron_journal_tool_t_get_hash(),
                                         enteron_journal_tool_t_encoded_size(&m)};
    }
    {
        enteron_journal_step_t m{};
        layouts[ENT_LCM_JOURNAL_STEP] = {"journal_step_t", __enteron_journal_step_t_get_hash(),
                                         enteron_journal_step_t_encoded_size(&m)};
    }
    // The tool state is nested (no fingerprint of its own), so its hash is computed here too.
    (void)__enteron_tool_state_t_get_hash();
}

const TypeLayout& layout_of(int32_t type) {
    static std::once_flag once;
    std::call_once(once, compute_layouts);
    return layouts[type];
}

int64_t read_be(const unsigned char* p, int bytes) {
    uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | p[i];
    if (bytes == 4) return static_cast<int32_t>(static_cast<uint32_t>(value));
    return static_cast<int64_t>(value);
}

MessageFault fail(MessageFault fault, char* detail, std::size_t detail_size, const char* format, ...)
    __attribute__((format(printf, 4, 5)));
MessageFault fail(MessageFault fault, char* detail, std::size_t detail_size, const char* format, ...) {
    if (detail != nullptr && detail_size > 0) {
        va_list args;
        va_start(args, format);
        std::vsnprintf(detail, detail_size, format, args);
        va_end(args);
    }
    return fault;
}

}  // namespace

bool known_message_type(int32_t type) { return type >= ENT_LCM_TOOL_COMMAND && type <= ENT_LCM_JOURNAL_STEP; }

void prepare_message_types() { (void)layout_of(ENT_LCM_TOOL_COMMAND); }

std::size_t tool_command_size() { return static_cast<std::size_t>(layout_of(ENT_LCM_TOOL_COMMAND).fixed_size); }

MessageFault check_message(int32_t type, const void* bytes, std::size_t size, char* detail, std::size_t detail_size) {
    if (!known_message_type(type))
        return fail(MessageFault::fingerprint, detail, detail_size, "unknown message type %d", type);
    const TypeLayout& layout = layout_of(type);
    const auto* p = static_cast<const unsigned char*>(bytes);
    const int64_t length = static_cast<int64_t>(size);
    if (length < layout.fixed_size || (layout.tail == Tail::none && length != layout.fixed_size))
        return fail(MessageFault::size, detail, detail_size, "%zu bytes, not a %s (%s %" PRId64 " bytes)", size,
                    layout.name, layout.tail == Tail::none ? "exactly" : "at least", layout.fixed_size);
    const int64_t fingerprint = read_be(p, 8);
    if (fingerprint != layout.fingerprint)
        return fail(MessageFault::fingerprint, detail, detail_size,
                    "fingerprint 0x%016" PRIx64 " is not %s's 0x%016" PRIx64, static_cast<uint64_t>(fingerprint),
                    layout.name, static_cast<uint64_t>(layout.fingerprint));
    int64_t expected = layout.fixed_size;
    if (layout.tail == Tail::counts) {
        for (int i = 0; i < layout.count_fields; ++i) {
            const int64_t count = read_be(p + layout.fixed_size - 4 * (layout.count_fields - i), 4);
            if (count < 0)
                return fail(MessageFault::count, detail, detail_size, "%s with a negative count (%" PRId64 ")",
                            layout.name, count);
            expected += count * layout.element_size[i];  // at most 3 * 2^31 * a few hundred: no overflow
        }
    } else if (layout.tail == Tail::string) {
        // The string's int32 length (its bytes with the NUL) sits where "" put 1, then the bytes.
        const int64_t string_length = read_be(p + layout.fixed_size - 5, 4);
        if (string_length < 1)
            return fail(MessageFault::count, detail, detail_size, "%s with a string length of %" PRId64, layout.name,
                        string_length);
        expected += string_length - 1;
        if (expected == length && p[length - 1] != 0)
            return fail(MessageFault::count, detail, detail_size, "%s whose string does not end with a NUL",
                        layout.name);
    }
    if (expected != length)
        return fail(MessageFault::size, detail, detail_size, "%zu bytes, but this %s's counts call for %" PRId64,
                    size, layout.name, expected);
    return MessageFault::none;
}

}  // namespace enteron::lcm
