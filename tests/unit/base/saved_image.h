// SPDX-License-Identifier: Apache-2.0
// Shared by the unit tests of what saves its state (base/state_io.h users): an image of
// exactly what `save` writes, measured first and then written, as the scene saves.
#pragma once

#include <cstdint>
#include <vector>

#include "base/state_io.h"

namespace state_test {

// `save(StateWriter&)` writes sections; the image holds them behind a header.
template <class Save>
std::vector<unsigned char> saved_image(Save save, uint64_t fingerprint = 0) {
    enteron::StateWriter measure(nullptr, 0, fingerprint);
    save(measure);
    std::vector<unsigned char> bytes(measure.finish());
    enteron::StateWriter out(bytes.data(), bytes.size(), fingerprint);
    save(out);
    out.finish();
    return bytes;
}

}  // namespace state_test
