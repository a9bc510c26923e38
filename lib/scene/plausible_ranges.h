// SPDX-License-Identifier: Apache-2.0
// The ranges a human abdomen gives the settings of a scene. A value far outside its range
// is still valid (a scene may model something else), but it is most often a unit mistake:
// gravity in mm/s^2, a box in millimetres, a density a thousand times too large. The scene
// logs a warning for each such value through the log callback, naming the key as the
// caller wrote it and the likely mistake. docs/scene-json.md lists the ranges; the table
// (scene_table.cpp) gives each field its range.
#pragma once

#include <string>

#include "base/logger.h"
#include "collision/obstacle.h"
#include "collision/tool.h"
#include "scene/scene_config.h"
#include "scene/validate.h"

namespace enteron::scene {

// A value written in `unit` instead of the SI unit is `factor` times too large.
struct UnitSlip {
    double factor;
    const char* unit;
};

struct PlausibleRange {
    const char* what;  // "a human small bowel's radius"
    double low, high;  // in the SI unit
    const char* unit;  // "m"
    UnitSlip slips[2];
};

// "" when value lies within the range; else what is wrong with it, and the unit mistake
// that would explain it if one does: "12.5 m is far outside a human small bowel's radius
// (0.004 to 0.03 m): was it given in millimetres?".
std::string implausibility(const PlausibleRange& range, double value);

// Logs one warning (ENT_LOG_WARNING) for each value of a validated config, obstacle or
// tool that lies outside the plausible range its row in the scene's table gives it
// (scene_table.h), naming it with `names` ("gravity", "gravity_m_per_s2"). An obstacle is
// named by `name` ("environment[0]", "obstacle[2]"), a tool's fields by `prefix`
// ("tools[1].radius", "radius_m").
void warn_implausible(const SceneConfig& config, const FieldNames& names, const Logger& logger);
void warn_implausible(const collision::Obstacle& obstacle, const std::string& name, const Logger& logger);
void warn_implausible(const collision::ToolConfig& tool, const std::string& prefix, const FieldNames& names,
                      const Logger& logger);

}  // namespace enteron::scene
