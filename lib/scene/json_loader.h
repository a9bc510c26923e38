// SPDX-License-Identifier: Apache-2.0
// The JSON v1 scene description (docs/scene-json.md) read into a SceneConfig.
#pragma once

#include <cstddef>
#include <string>

#include "scene/scene_config.h"

namespace enteron::scene {

// Parses, type-checks and validates a JSON v1 scene description: length bytes of UTF-8 at
// text, which need not be NUL-terminated. A key that is absent takes its default (one set,
// scene_config.h); an effect's key that is absent leaves the effect off. Returns the
// validated, normalised config (validate.h).
// Throws Error with
//   ErrorCode::parse: not well-formed JSON, "JSON parse error at byte N (line L, column C):
//     ..." with N counted from 1;
//   ErrorCode::invalid_scene: unknown or repeated key, wrong type, value out of range; the
//     message names the path, "intestine.radius must be > 0, got -1";
//   ErrorCode::invalid_argument: text is null while length is not 0.
// A mesh obstacle's "file" is read here, relative to `base_directory` (the scene file's
// directory; empty: the current directory).
SceneConfig load_scene_json(const char* text, std::size_t length, const std::string& base_directory = "");

}  // namespace enteron::scene
