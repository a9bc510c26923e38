// SPDX-License-Identifier: Apache-2.0
// The rest length of a "points" shape. The bowel starts at rest when its rest length is the
// length of the axis it starts as: the Catmull-Rom spline through the given points, with the
// scene's end treatment. That spline cuts the corners of the points' polyline, so a user
// cannot compute its length by hand: validate() takes it as the intestine's length when
// that is kLengthOfThePoints (JSON: no "length"; C: length_m 0). A length that is given and
// differs from it by more than kPointsLengthTolerance starts the bowel stretched or
// compressed by that much, and warn_points_length says so.
#pragma once

#include "base/logger.h"
#include "scene/scene_config.h"
#include "scene/validate.h"

namespace enteron::scene {

// The intestine's length of a points shape that takes its spline's.
constexpr double kLengthOfThePoints = 0.0;

// Relative difference between a given length and the spline's beyond which a warning is
// logged (docs/scene-json.md): 1 %, a strain the bowel sheds in its first steps.
constexpr double kPointsLengthTolerance = 0.01;

// Every segment has one rest length (the length over the segments), so points spaced
// unevenly start stretched where they are far apart and compressed where they are close. A
// segment whose strain departs from the whole axis' by more than this is warned about.
constexpr double kPointsSpacingTolerance = 0.1;

// The arc length (m) of the spline through the points of a points shape, whose count
// validate() has checked (control_points x 3 values).
double points_spline_length(const SceneConfig& config);

// Logs a warning (ENT_LOG_WARNING) when a points shape's length differs from its spline's by
// more than kPointsLengthTolerance, naming both with `names`, and one when its points are
// spaced so unevenly that a segment starts strained by kPointsSpacingTolerance more.
void warn_points_length(const SceneConfig& config, const FieldNames& names, const Logger& logger);

}  // namespace enteron::scene
