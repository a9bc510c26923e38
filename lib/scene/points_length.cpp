// SPDX-License-Identifier: Apache-2.0
#include "scene/points_length.h"

#include <cmath>
#include <string>

#include "scene/checked_value.h"
#include "spline/arc_length.h"

namespace enteron::scene {

namespace {

spline::ArcLengthTable spline_through_points(const SceneConfig& config) {
    const std::vector<double>& points = config.intestine.shape.points;
    spline::ArcLengthTable table;
    table.build(points.data(), points.size() / 3, spline_ends(config));
    return table;
}

const char* stretched_or_compressed(double strain) { return strain > 0.0 ? "stretched" : "compressed"; }

}  // namespace

double points_spline_length(const SceneConfig& config) { return spline_through_points(config).total_length(); }

void warn_points_length(const SceneConfig& config, const FieldNames& names, const Logger& logger) {
    if (!logger.enabled() || config.intestine.shape.kind != ShapeKind::points) return;
    const spline::ArcLengthTable table = spline_through_points(config);
    const double length = config.intestine.length;
    const std::string length_name = names.at("intestine.length"), points_name = names.at("intestine.shape.points");
    // The whole axis against its rest length.
    const double strain = table.total_length() / length - 1.0;
    if (std::fabs(strain) > kPointsLengthTolerance)
        logger.log(LogLevel::warning,
                   "%s (%s m) differs from the length of the spline through %s (%s m): the bowel starts %s by %s "
                   "%%. Give %s 0 (JSON: no length) to start it at rest: the spline's length is taken",
                   length_name.c_str(), format_number(length).c_str(), points_name.c_str(),
                   format_rounded(table.total_length()).c_str(), stretched_or_compressed(strain),
                   format_rounded(100.0 * std::fabs(strain)).c_str(), length_name.c_str());
    // Each segment against the one rest length of them all: points spaced unevenly.
    const std::size_t segments = config.intestine.control_points - 1;
    const double rest_segment = length / static_cast<double>(segments);
    double worst = strain;  // the segment strain farthest from the axis' own
    std::size_t where = 0;
    for (std::size_t i = 0; i < segments; ++i) {
        const double segment_strain = (table.length_at(double(i + 1)) - table.length_at(double(i))) / rest_segment - 1.0;
        if (std::fabs(segment_strain - strain) > std::fabs(worst - strain)) worst = segment_strain, where = i;
    }
    if (std::fabs(worst - strain) > kPointsSpacingTolerance)
        logger.log(LogLevel::warning,
                   "%s are spaced unevenly: the spline between points %zu and %zu is %s %% %s than the rest length of "
                   "a segment (%s / %zu segments), so the bowel starts %s there. Space the points evenly along "
                   "their path to start it at rest",
                   points_name.c_str(), where, where + 1, format_rounded(100.0 * std::fabs(worst)).c_str(),
                   worst > 0.0 ? "longer" : "shorter", length_name.c_str(), segments, stretched_or_compressed(worst));
}

}  // namespace enteron::scene
