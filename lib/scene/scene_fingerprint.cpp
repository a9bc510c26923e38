// SPDX-License-Identifier: Apache-2.0
#include "scene/scene_fingerprint.h"

#include <iterator>

#include "collision/triangle_mesh.h"

namespace enteron::scene {

namespace {

void add(Fingerprint& f, const Vec3& v) {
    for (int c = 0; c < 3; ++c) f.add(v[c]);
}

void add(Fingerprint& f, std::size_t value) { f.add(static_cast<uint64_t>(value)); }

// Numbers a newer description may give, only when given (tagged), so that a scene without
// them keeps its fingerprint (and the states saved from it).
void add_if_given(Fingerprint& f, std::size_t tag, const std::vector<double>& values) {
    if (values.empty()) return;
    add(f, tag);
    add(f, values.size());
    f.add_bytes(values.data(), values.size() * sizeof(double));
}

// An optional part: whether it is there, then its values.
template <class T, class AddValues>
void add_optional(Fingerprint& f, const std::optional<T>& part, AddValues add_values) {
    f.add(uint64_t{part.has_value()});
    if (part) add_values(*part);
}

}  // namespace

void add_to_fingerprint(Fingerprint& f, const SceneConfig& config) {
    const IntestineConfig& intestine = config.intestine;
    f.add(intestine.length);
    f.add(intestine.radius);
    add(f, intestine.control_points);
    f.add(intestine.linear_density);
    f.add(intestine.stretch_stiffness);
    f.add(intestine.bend_stiffness);
    // The profiles only when given, so that a scene without them keeps its fingerprint (and
    // the states saved from it).
    const std::vector<double>* profiles[] = {&intestine.radius_profile, &intestine.linear_density_profile,
                                             &intestine.stretch_stiffness_profile, &intestine.bend_stiffness_profile};
    for (std::size_t k = 0; k < std::size(profiles); ++k) add_if_given(f, k, *profiles[k]);
    // The start shape as its points: the mesentery's springs take their lengths there.
    add(f, config.start_points.size());
    f.add_bytes(config.start_points.data(), config.start_points.size() * sizeof(double));

    const SolverConfig& solver = config.solver;
    add(f, static_cast<std::size_t>(solver.integrator));
    f.add(solver.timestep);
    add(f, solver.max_substeps);
    add(f, solver.max_subdivisions);
    f.add(solver.max_speed);

    add_optional(f, config.gravity, [&](const Vec3& g) { add(f, g); });
    add_optional(f, config.damping, [&](const DampingConfig& d) {
        f.add(d.drag);
        f.add(d.stretch);
        f.add(d.bend);
    });
    add_optional(f, config.mesentery, [&](const MesenteryConfig& m) {
        add(f, m.root_start);
        add(f, m.root_end);
        add(f, m.attachments);
        f.add(m.stiffness);
        f.add(m.rest_length);
        add(f, m.obstacle ? *m.obstacle + 1 : 0);
        add_if_given(f, 10, m.root_points);
        add_if_given(f, 11, m.root_mapping);
    });
    add_optional(f, config.pinned, [&](const PinnedConfig& p) {
        add(f, static_cast<std::size_t>(p.ends));
        add(f, static_cast<std::size_t>(p.clamped));
        add(f, p.points.size());
        for (const uint32_t point : p.points) add(f, point);
        add(f, p.attached.size());
        for (const PinAttachment& a : p.attached) {
            add(f, a.point);
            add(f, a.obstacle);
        }
        std::vector<double> spans;
        for (const PinSpan& span : p.spans)
            spans.insert(spans.end(), {span.from, span.to, span.obstacle ? double(*span.obstacle) + 1.0 : 0.0});
        add_if_given(f, 12, spans);
    });

    const collision::ContactParameters& contact = config.collision.contact;
    f.add(config.collision.sphere_spacing);
    f.add(contact.stiffness);
    f.add(contact.damping);
    f.add(contact.friction);
    f.add(contact.slip_speed);
    f.add(uint64_t{config.self_collision});
    add(f, config.environment.size());
    for (const collision::Obstacle& obstacle : config.environment) add_to_fingerprint(f, obstacle);
    add(f, config.tools.size());
    for (const collision::ToolConfig& tool : config.tools) add_to_fingerprint(f, tool);
}

void add_to_fingerprint(Fingerprint& f, const collision::Obstacle& obstacle) {
    add(f, static_cast<std::size_t>(obstacle.kind));
    add(f, obstacle.center);
    add(f, obstacle.extent);
    f.add(obstacle.radius);
    // A mesh by its data (its pose and friction belong to the state: frames, environment).
    f.add(obstacle.voxel_size);
    if (obstacle.mesh) {
        add(f, obstacle.mesh->vertices.size());
        f.add_bytes(obstacle.mesh->vertices.data(), obstacle.mesh->vertices.size() * sizeof(double));
        add(f, obstacle.mesh->indices.size());
        f.add_bytes(obstacle.mesh->indices.data(), obstacle.mesh->indices.size() * sizeof(uint32_t));
    }
}

void add_to_fingerprint(Fingerprint& f, const collision::ToolConfig& tool) {
    const collision::ToolSettings& s = tool.settings;
    f.add(s.radius);
    f.add(s.length);
    f.add(s.max_force);
    f.add(s.grasp_margin);
    f.add(s.grasp_stiffness);
    f.add(s.grasp_damping);
    add(f, static_cast<std::size_t>(s.mode));
    f.add(s.coupling_stiffness);
    f.add(s.coupling_damping);
    f.add(s.friction);
    f.add(uint64_t{s.passivity_limiter});
    // The jaws and the blade only when a tool has them: a state saved before they existed
    // still restores.
    if (s.jaw_length != 0.0 || s.jaw_opening != 0.0 || s.blade_width != 0.0 || s.blade_length != 0.0) {
        f.add(s.jaw_length);
        f.add(s.jaw_opening);
        f.add(s.blade_width);
        f.add(s.blade_length);
    }
    // Not its start pose: where a tool is belongs to the state.
}

}  // namespace enteron::scene
