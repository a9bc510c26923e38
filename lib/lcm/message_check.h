// SPDX-License-Identifier: Apache-2.0
// Checks that bytes from a network or a file are exactly one message of a given type
// before anything decodes them (ent_lcm_check_message). The decoders lcm-gen 1.3.1 writes
// trust the counts inside a message: a negative or huge count makes the C decoder
// allocate up to 2^64 bytes. Every type of bindings/lcm puts its counts (or its one
// string) last among its fixed fields and its arrays after them, in the same order, so the
// exact size of a message follows from a few numbers read at known offsets:
//   size = fixed size (counts 0, string "") + sum of count_i * element size_i
// (+ the string's length). The fingerprint is the first 8 bytes.
#pragma once

#include <cstddef>
#include <cstdint>

namespace enteron::lcm {

enum class MessageFault {
    none,
    size,         // not the size the type (and its counts) call for
    fingerprint,  // another type's fingerprint
    count,        // a negative count, or a string length below 1 or without its NUL
};

// ENT_LCM_* types; `detail` (may be null) receives a line naming what is wrong.
// An unknown type is reported as MessageFault::fingerprint with "unknown message type".
MessageFault check_message(int32_t type, const void* bytes, std::size_t size, char* detail, std::size_t detail_size);

// Whether `type` is one of ENT_LCM_*.
bool known_message_type(int32_t type);

// The encoded size of tool_command_t (fixed): what the receive thread expects.
std::size_t tool_command_size();

// Computes every type's fingerprint once, before any thread of the bridge runs (the C code
// lcm-gen writes caches it in a plain static).
void prepare_message_types();

}  // namespace enteron::lcm
