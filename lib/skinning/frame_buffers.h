// SPDX-License-Identifier: Apache-2.0
// Work buffers resized every frame to sizes that breathe: a few more axis samples when the
// bowel stretches, a few fewer when it relaxes, more rings when it bends, more voxel blocks
// when its folds spread. Their capacity is kept at least half as large again as the size
// (doubled to twice the size when the size passes two thirds of it), so that once a skin
// has seen its sizes it stops allocating unless one grows by a third above the largest it
// had (ent_skin_update promises to allocate only when the mesh grows beyond any size it had
// before; the mesh buffers themselves only ever grow).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace enteron::skinning {

template <typename T>
void reserve_with_headroom(std::vector<T>& buffer, std::size_t size) {
    if (3 * size > 2 * buffer.capacity()) buffer.reserve(2 * size);
}

template <typename T>
void resize_buffer(std::vector<T>& buffer, std::size_t size) {
    reserve_with_headroom(buffer, size);
    buffer.resize(size);
}

template <typename T>
void assign_buffer(std::vector<T>& buffer, std::size_t size, const T& value) {
    resize_buffer(buffer, size);
    std::fill(buffer.begin(), buffer.end(), value);
}

}  // namespace enteron::skinning
