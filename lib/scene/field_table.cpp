// SPDX-License-Identifier: Apache-2.0
#include "scene/field_table.h"

#include <cstring>

namespace enteron::scene {

const Field* Block::find(const char* key) const {
    for (const Field& field : *this)
        if (std::strcmp(field.key, key) == 0) return &field;
    return nullptr;
}

bool Block::applies(const Field& field, const void* part) const {
    if (kind == nullptr || &field == kind) return true;
    const int32_t value = std::get<Choice>(kind->value).get(part);
    // A kind out of range is refused by its own row, which comes first.
    return value >= 0 && value < 32 && (field.kinds & (1u << static_cast<uint32_t>(value))) != 0;
}

}  // namespace enteron::scene
