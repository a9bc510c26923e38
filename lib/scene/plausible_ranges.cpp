// SPDX-License-Identifier: Apache-2.0
#include "scene/plausible_ranges.h"

#include <cmath>
#include <cstring>

#include "scene/checked_value.h"
#include "scene/points_length.h"
#include "scene/scene_table.h"

namespace enteron::scene {

namespace {

bool within(const PlausibleRange& range, double value) { return value >= range.low && value <= range.high; }

std::string with_unit(double value, const char* unit) {
    return format_number(value) + (unit[0] != '\0' ? std::string(" ") + unit : std::string());
}

void warn(const Logger& logger, const std::string& name, const PlausibleRange& range, double value) {
    const std::string unlikely = implausibility(range, value);
    if (!unlikely.empty()) logger.log(LogLevel::warning, "%s: %s", name.c_str(), unlikely.c_str());
}

// A mesh in millimetres (a CT export) is a thousand times too large: half its largest side
// is held to a box's half extents' range.
void warn_mesh_size(const collision::Obstacle& obstacle, const std::string& name, const Logger& logger) {
    const collision::TriangleMesh* mesh = obstacle.mesh ? obstacle.mesh.get() : nullptr;
    if (mesh == nullptr || mesh->vertex_count() == 0) return;
    Vec3 low = mesh->vertex(0), high = low;
    for (std::size_t v = 1; v < mesh->vertex_count(); ++v) {
        low = low.cwiseMin(mesh->vertex(v));
        high = high.cwiseMax(mesh->vertex(v));
    }
    const PlausibleRange& half_size = *obstacle_block().find("half_extents")->plausible;
    warn(logger, name + " (mesh) half of its largest side", half_size, 0.5 * (high - low).maxCoeff());
}

// Warns about each value of a part (and of the parts in it) outside its row's range.
class Warner {
public:
    Warner(const FieldNames& names, const Logger& logger, bool contacts)
        : names_(names), logger_(logger), contacts_(contacts) {}

    void walk(const Block& block, const void* part, const std::string& path, const std::string& prefix) const {
        for (const Field& f : block) {
            if (!block.applies(f, part) || (f.present != nullptr && !f.present(part))) continue;
            if (const Object* object = std::get_if<Object>(&f.value)) {
                // The contact law matters only to a scene that has contacts.
                if (object->block == contact_law_ && !contacts_) continue;
                if (const void* inner = object->find(part)) walk(*object->block, inner, join_path(path, f.key), prefix);
            } else if (const List* list = std::get_if<List>(&f.value)) {
                for (std::size_t i = 0; i < list->size(part); ++i) {
                    const std::string element = path + (path.empty() ? "" : ".") + f.key + "[" + std::to_string(i) + "]";
                    walk(*list->block, list->element(const_cast<void*>(part), i), element,
                         names_.element_prefix(f, prefix, i));
                }
            } else if (f.plausible != nullptr) {
                value(f, part, names_.of(f, path, prefix));
            }
        }
        if (block.check == Block::Check::obstacle) {
            const auto& obstacle = *static_cast<const collision::Obstacle*>(part);
            if (obstacle.kind == collision::ObstacleKind::mesh)
                warn_mesh_size(obstacle, names_.c_names ? prefix.substr(0, prefix.size() - 1) : path, logger_);
        }
    }

private:
    void value(const Field& f, const void* part, const std::string& name) const {
        if (const Number* number = std::get_if<Number>(&f.value)) {
            const double v = number->get(part);
            if (!(f.zero_is_off && v == 0.0)) warn(logger_, name, *f.plausible, v);
        } else if (const Point* point = std::get_if<Point>(&f.value)) {
            const Vec3 v = point->get(part);
            if (f.plausible_magnitude) {
                const double magnitude = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                if (!(f.zero_is_off && magnitude == 0.0)) warn(logger_, "|" + name + "|", *f.plausible, magnitude);
            } else {
                for (std::size_t k = 0; k < 3; ++k)
                    warn(logger_, name + "[" + std::to_string(k) + "]", *f.plausible, v[k]);
            }
        }
    }

    const FieldNames& names_;
    const Logger& logger_;
    bool contacts_;
    const Block* contact_law_ = std::get<Object>(find_path(scene_block(), "collision").field->value).block;
};

}  // namespace

std::string implausibility(const PlausibleRange& range, double value) {
    if (!std::isfinite(value) || within(range, value)) return {};
    std::string text = with_unit(value, range.unit) + " is far " + (value > range.high ? "above " : "below ") +
                       range.what + " (" + format_number(range.low) + " to " + with_unit(range.high, range.unit) + ")";
    for (const UnitSlip& slip : range.slips) {
        if (slip.unit != nullptr && within(range, value / slip.factor))
            return text + ": was it given in " + slip.unit + "?";
    }
    return text;
}

void warn_implausible(const SceneConfig& config, const FieldNames& names, const Logger& logger) {
    if (!logger.enabled()) return;
    const bool contacts = config.self_collision || !config.environment.empty() || !config.tools.empty();
    Warner(names, logger, contacts).walk(scene_block(), &config, "", "");
    warn_points_length(config, names, logger);
}

void warn_implausible(const collision::Obstacle& obstacle, const std::string& name, const Logger& logger) {
    if (!logger.enabled()) return;
    Warner(json_field_names(), logger, true).walk(obstacle_block(), &obstacle, name, name + ".");
}

void warn_implausible(const collision::ToolConfig& tool, const std::string& prefix, const FieldNames& names,
                      const Logger& logger) {
    if (!logger.enabled()) return;
    const std::string path = prefix.empty() ? prefix : prefix.substr(0, prefix.size() - 1);
    Warner(names, logger, true).walk(tool_block(), &tool, path, prefix);
}

}  // namespace enteron::scene
