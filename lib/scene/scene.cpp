// SPDX-License-Identifier: Apache-2.0
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/error.h"
#include "collision/self_contact_force.h"
#include "collision/tools_force.h"
#include "mechanics/bend_force.h"
#include "mechanics/damping_force.h"
#include "mechanics/gravity_force.h"
#include "mechanics/mesentery_force.h"
#include "mechanics/pinned_points.h"
#include "mechanics/stretch_force.h"
#include "scene/pin_spans.h"
#include "scene/scene_fingerprint.h"

namespace enteron::scene {

namespace {

using namespace enteron::mechanics;

int32_t clamped_ends(const SceneConfig& config) { return config.pinned ? config.pinned->clamped : pin_none; }

// A profile given, or null (the constant).
const spline::LengthProfile* given(const spline::LengthProfile& profile) {
    return profile.empty() ? nullptr : &profile;
}

template <class Profiles>
AxisModel make_model(const SceneConfig& config, const Profiles& profiles) {
    const IntestineConfig& intestine = config.intestine;
    AxisModel model;
    model.control_points = intestine.control_points;
    model.rest_segment_length = intestine.length / static_cast<double>(intestine.control_points - 1);
    model.linear_density = intestine.linear_density;
    model.ends = spline_ends(config);
    model.linear_density_profile = given(profiles.linear_density);
    model.stretch_stiffness_profile = given(profiles.stretch_stiffness);
    model.bend_stiffness_profile = given(profiles.bend_stiffness);
    return model;
}

// The point pins, a clamped end's end point among them.
std::vector<uint32_t> pinned_indices(const PinnedConfig& pinned, std::size_t count, double length) {
    std::vector<uint32_t> points = pinned.points;
    const int32_t ends = pinned.ends | pinned.clamped;
    if (ends & pin_first) points.push_back(0);
    if (ends & pin_last) points.push_back(static_cast<uint32_t>(count - 1));
    for (const PinSpan& span : pinned.spans) {
        if (span.obstacle) continue;  // pinned on its obstacle once the environment is made
        const ControlPointRange range = control_points_in(span, count, length);
        for (uint32_t i = range.first; i <= range.last; ++i) points.push_back(i);
    }
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    return points;
}

// The contact damper fades in over this fraction of the radius of penetration, so that
// every contact force starts from zero (contact_model.h).
constexpr double kContactDampingDepth = 0.1;

// Tells what a mesh obstacle's connectivity means for its contacts.
void warn_mesh_topology(const collision::Obstacle& obstacle, const std::string& name, const Logger& logger) {
    if (obstacle.kind != collision::ObstacleKind::mesh || !logger.enabled()) return;
    const collision::MeshDistanceField& field = *obstacle.field;
    const collision::MeshTopologyReport& r = field.report();
    if (!r.closed())
        logger.log(LogLevel::warning,
                   "%s (mesh): not a closed, consistently oriented surface (%zu open edges, %zu edges of three or "
                   "more triangles, %zu edges whose triangles disagree on orientation): it has no inside, so its "
                   "contact is one-sided, pushing the bowel to the side its triangles' normals face "
                   "(counter-clockwise winding)",
                   name.c_str(), r.open_edges, r.nonmanifold_edges, r.flipped_edges);
    else if (r.signed_volume < 0.0)
        logger.log(LogLevel::info, "%s (mesh): its normals face inward, so the bowel is kept inside it (a cavity)",
                   name.c_str());
    if (r.degenerate_triangles > 0)
        logger.log(LogLevel::warning, "%s (mesh): %zu triangles of zero area are ignored", name.c_str(),
                   r.degenerate_triangles);
    logger.log(LogLevel::info, "%s (mesh): %zu triangles, distance field of %zu voxels of %g m (%.1f MB)",
               name.c_str(), field.mesh().triangle_count(), field.voxel_count(), field.settings().voxel_size,
               1e-6 * double(field.memory_bytes()));
}

StepperSettings stepper_settings(const SceneConfig& config, const AxisModel& model) {
    const SolverConfig& solver = config.solver;
    const IntestineConfig& intestine = config.intestine;
    const double mass = model.linear_density_profile != nullptr
                            ? model.linear_density_profile->integral(intestine.length)
                            : intestine.linear_density * intestine.length;
    return {solver.integrator, solver.timestep, solver.max_substeps, solver.max_subdivisions, solver.max_speed, mass};
}

}  // namespace

Scene::Scene(const SceneConfig& config, SnapshotPublisher& published, std::pmr::memory_resource* memory,
             Logger logger, const FieldNames& names)
    : memory_(memory),
      logger_(logger),
      solver_(config.solver),
      profiles_{spline::LengthProfile(config.intestine.radius_profile, memory),
                spline::LengthProfile(config.intestine.linear_density_profile, memory),
                spline::LengthProfile(config.intestine.stretch_stiffness_profile, memory),
                spline::LengthProfile(config.intestine.bend_stiffness_profile, memory)},
      model_(make_model(config, profiles_)),
      tool_channels_(memory),
      frames_(memory),
      dynamics_(model_, memory),
      stepper_(dynamics_, frames_, stepper_settings(config, model_), logger, memory),
      rest_length_(config.intestine.length),
      radius_(config.intestine.radius),
      collision_(config.collision),
      start_clearance_(scene::start_clearance(config, memory)),
      published_(published) {
    const IntestineConfig& intestine = config.intestine;
    const std::size_t n = model_.control_points;
    if (config.start_points.size() != 3 * n || published_.control_points() != n)
        throw Error(ErrorCode::internal, "a scene made from a config that validate() did not return");
    mechanics::State& state = stepper_.state();
    std::copy(config.start_points.begin(), config.start_points.end(), state.q.begin());
    collision_.contact.damping_depth = kContactDampingDepth * radius_;
    stats_.rest_length = rest_length_;
    add_to_fingerprint(description_, config);

    // A zero stiffness asks for nothing: the effect is not built and costs nothing.
    if (intestine.stretch_stiffness != 0.0)
        dynamics_.add_effect(make_owned<StretchForce>(memory, model_, intestine.stretch_stiffness, memory));
    if (intestine.bend_stiffness != 0.0)
        dynamics_.add_effect(make_owned<BendForce>(memory, model_, intestine.bend_stiffness, memory));
    if (config.damping) {
        const DampingCoefficients coefficients{config.damping->drag, config.damping->stretch,
                                               config.damping->bend};
        dynamics_.add_effect(make_owned<DampingForce>(memory, model_, coefficients, memory));
    }
    if (config.gravity) gravity_ = &dynamics_.add_effect(make_owned<GravityForce>(memory, model_, *config.gravity, memory));
    if (config.mesentery) {
        const MesenteryConfig& m = *config.mesentery;
        MesenteryParameters parameters;
        parameters.root_start = m.root_start;
        parameters.root_end = m.root_end;
        parameters.attachments = m.attachments;
        parameters.stiffness = m.stiffness;
        parameters.rest_length = m.rest_length;
        parameters.root_points = m.root_points;
        parameters.root_mapping = m.root_mapping;
        parameters.bowel_length = intestine.length;
        mesentery_ = &dynamics_.add_effect(make_owned<MesenteryForce>(memory, model_, parameters, state, memory));
    }
    if (config.pinned)
        dynamics_.add_pins(make_owned<PinnedPoints>(memory, pinned_indices(*config.pinned, n, intestine.length), frames_,
                                                    config.solver.max_speed, memory));
    if (const int32_t clamped = clamped_ends(config))
        dynamics_.add_clamps(make_owned<ClampedEnds>(memory, (clamped & pin_first) != 0, (clamped & pin_last) != 0,
                                                     state.q.data(), n));
    // The self-contact's time takes the shared contact loads', even though the environment
    // is made first.
    if (config.self_collision) contact_loads(EffectId::self_collision);
    for (std::size_t i = 0; i < config.environment.size(); ++i) {
        collision::Obstacle obstacle = config.environment[i];
        const std::string name = names.obstacle(i);
        collision::EnvironmentForce::prepare(obstacle, radius_, memory_, smallest_radius());
        // A mesh's start can only be checked once its field is built.
        if (obstacle.kind == collision::ObstacleKind::mesh)
            validate_obstacle(obstacle, name, names, state.q.data(), n, &start_clearance_);
        warn_mesh_topology(obstacle, name, logger_);
        add_to_environment(obstacle);
        ++obstacles_;
    }
    if (config.pinned)
        for (const PinAttachment& pin : config.pinned->attached) pin_point_only(pin.point, pin.obstacle);
    if (config.pinned)
        for (const PinSpan& span : config.pinned->spans) {
            if (!span.obstacle) continue;
            const ControlPointRange range = control_points_in(span, n, intestine.length);
            for (uint32_t i = range.first; i <= range.last; ++i) pin_point_only(i, span.obstacle);
        }
    if (config.mesentery && config.mesentery->obstacle) attach_mesentery_only(config.mesentery->obstacle);
    if (config.pinned)
        for (const auto& [end, obstacle] : {std::pair{pin_first, config.pinned->clamped_obstacle[0]},
                                            std::pair{pin_last, config.pinned->clamped_obstacle[1]}})
            if (obstacle) attach_clamped_ends_only(end, obstacle);
    for (const collision::ToolConfig& tool : config.tools) add_tool_effect_only(tool);
    if (config.self_collision) {
        const collision::SelfContactForce& self = dynamics_.add_effect(make_owned<collision::SelfContactForce>(
            memory, collision_spheres(), collision_.contact, state, memory, contact_loads(EffectId::self_collision)));
        contact_logs_[static_cast<std::size_t>(collision::ContactKind::self)] = &self.contact_log();
    }

    published_.reserve_tools(tool_channels_.size());
    published_.reserve_obstacles(obstacles_);
    refinalize();
    publish();
}

void Scene::refinalize() {
    stepper_.effects_changed();
    if (logger_.enabled())
        logger_.log(LogLevel::info, "scene: %zu control points, substep limit %g s", model_.control_points,
                    stepper_.longest_substep());
}

std::size_t Scene::add_obstacle(const collision::Obstacle& obstacle, const std::string& name,
                                const FieldNames& names) {
    collision::Obstacle prepared = obstacle;
    collision::EnvironmentForce::prepare(prepared, radius_, memory_, smallest_radius());
    published_.reserve_obstacles(obstacles_ + 1);
    validate_obstacle(prepared, name, names, stepper_.state().q.data(), model_.control_points, &start_clearance_);
    add_to_environment(prepared);
    add_to_fingerprint(description_, obstacle);
    warn_mesh_topology(prepared, name, logger_);
    const std::size_t index = obstacles_++;
    refinalize();
    publish();
    return index;
}

void Scene::add_to_environment(const collision::Obstacle& prepared) {
    if (environment_ != nullptr) {
        environment_->add_obstacle(prepared);
        return;
    }
    // The first obstacle: the effect is added to the dynamics only once it holds it, so that
    // nothing changes if that throws.
    auto effect = make_owned<collision::EnvironmentForce>(memory_, collision_spheres(), collision_.contact, frames_,
                                                          stepper_.state(), memory_,
                                                          contact_loads(EffectId::environment));
    effect->add_obstacle(prepared);
    environment_ = &dynamics_.add_effect(std::move(effect));
    contact_logs_[static_cast<std::size_t>(collision::ContactKind::obstacle)] = &environment_->contact_log();
}

void Scene::require_obstacle(std::size_t index) const {
    if (environment_ == nullptr || environment_->obstacle(index) == nullptr)
        throw Error(ErrorCode::not_found, "obstacle " + std::to_string(index) + " does not exist (" +
                                              (index < obstacles_ ? std::string("it was removed")
                                                                  : "the scene has had " + std::to_string(obstacles_) +
                                                                        " obstacles") +
                                              ")");
}

collision::EnvironmentForce& Scene::environment_with(std::size_t index) {
    require_obstacle(index);
    return *environment_;
}

const collision::EnvironmentForce& Scene::environment_with(std::size_t index) const {
    require_obstacle(index);
    return *environment_;
}

std::size_t Scene::obstacle_count() const { return environment_ != nullptr ? environment_->live_count() : 0; }

const collision::Obstacle& Scene::obstacle(std::size_t index) const { return *environment_with(index).obstacle(index); }

void Scene::set_obstacle_pose(std::size_t index, const mechanics::RigidPose& pose) {
    frames_.set_target(environment_with(index).frame_of(index), pose);
}

void Scene::set_obstacle_velocity(std::size_t index, const Vec3& linear, const Vec3& angular) {
    frames_.set_velocity(environment_with(index).frame_of(index), linear, angular);
}

void Scene::set_obstacle_friction(std::size_t index, double friction) {
    environment_with(index).set_friction(index, friction);
    refinalize();  // the explicit substep's bound follows the largest friction
    publish();
}

void Scene::remove_obstacle(std::size_t index) {
    environment_with(index).remove_obstacle(index);
    changed_between_steps();
}

mechanics::RigidPose Scene::obstacle_pose(std::size_t index) const {
    return frames_.pose(environment_->frame_of(index));
}

void Scene::set_gravity(const Vec3& gravity) {
    if (gravity_ == nullptr) {
        gravity_ = &dynamics_.add_effect(make_owned<GravityForce>(memory_, model_, gravity, memory_));
        changed_between_steps();
        return;
    }
    // Gravity bounds no stiffness: only the guard's energy reference moves (no allocation,
    // so a table may tilt a little before every step).
    gravity_->set_gravity(gravity);
    stepper_.energy_changed();
    publish();
}

void Scene::pin_point_only(std::size_t point, std::optional<std::size_t> obstacle) {
    const std::size_t frame = obstacle ? environment_with(*obstacle).frame_of(*obstacle) : PinnedPoints::kWorld;
    if (dynamics_.pins() == nullptr)
        dynamics_.add_pins(make_owned<PinnedPoints>(memory_, std::vector<uint32_t>{}, frames_, solver_.max_speed, memory_));
    dynamics_.pins()->pin(static_cast<uint32_t>(point), frame, stepper_.state());
    stepper_.state_set_from_outside();  // the pin stopped the point
}

void Scene::refuse_clamped_end_point(std::size_t point, const char* change) {
    const ClampedEnds* clamps = dynamics_.clamps();
    const ClampedEnd end = clamps != nullptr ? clamped_end_point(point, model_.control_points, clamps->clamped(true),
                                                                 clamps->clamped(false))
                                             : ClampedEnd::none;
    if (end != ClampedEnd::none)
        throw Error(ErrorCode::invalid_argument,
                    "control point " + std::to_string(point) + " is the scene's " +
                        (end == ClampedEnd::first ? "first" : "last") + " clamped end (clamped_ends): " + change +
                        " it alone would leave the clamp half attached; attach the clamped end instead");
}

void Scene::pin_point(std::size_t point, std::optional<std::size_t> obstacle) {
    refuse_clamped_end_point(point, "pinning");
    pin_point_only(point, obstacle);
    changed_between_steps();
}

bool Scene::unpin_point(std::size_t point) {
    refuse_clamped_end_point(point, "unpinning");
    PinnedPoints* pins = dynamics_.pins();
    if (pins == nullptr || !pins->unpin(static_cast<uint32_t>(point))) return false;
    changed_between_steps();
    return true;
}

void Scene::attach_mesentery_only(std::optional<std::size_t> obstacle) {
    if (mesentery_ == nullptr) throw Error(ErrorCode::not_found, "the scene has no mesentery to attach");
    const std::size_t frame = obstacle ? environment_with(*obstacle).frame_of(*obstacle) : MesenteryForce::kNoFrame;
    mesentery_->attach(&frames_, frame, stepper_.state().time);
}

void Scene::attach_mesentery(std::optional<std::size_t> obstacle) {
    attach_mesentery_only(obstacle);
    changed_between_steps();
}

void Scene::attach_clamped_ends_only(int32_t ends, std::optional<std::size_t> obstacle) {
    ClampedEnds* clamps = dynamics_.clamps();
    for (const bool first : {true, false})
        if ((ends & (first ? pin_first : pin_last)) != 0 && (clamps == nullptr || !clamps->clamped(first)))
            throw Error(ErrorCode::not_found, std::string("the scene's ") + (first ? "first" : "last") +
                                                  " end is not clamped (clamped_ends)");
    const std::size_t frame = obstacle ? environment_with(*obstacle).frame_of(*obstacle) : ClampedEnds::kWorld;
    // All or nothing: a clamped end's point is always pinned, so with room for both
    // attachments reserved first, neither end's change below can fail.
    if (PinnedPoints* pins = dynamics_.pins()) pins->reserve_attachments(2);
    for (const bool first : {true, false}) {
        if ((ends & (first ? pin_first : pin_last)) == 0) continue;
        // The end point rides on the frame like a pin; the clamp turns its direction with it.
        pin_point_only(first ? 0 : model_.control_points - 1, obstacle);
        clamps->attach(first, frames_, frame, stepper_.state().time);
    }
}

void Scene::attach_clamped_ends(int32_t ends, std::optional<std::size_t> obstacle) {
    attach_clamped_ends_only(ends, obstacle);
    changed_between_steps();
}

void Scene::changed_between_steps() {
    refinalize();
    publish();
}

std::size_t Scene::add_tool_effect_only(const collision::ToolConfig& tool) {
    if (tools_ == nullptr) {
        tools_ = &dynamics_.add_effect(make_owned<collision::ToolsForce>(
            memory_, collision_spheres(), collision_.contact, stepper_.state(), tool_channels_, memory_));
        contact_logs_[static_cast<std::size_t>(collision::ContactKind::tool)] = &tools_->contact_log();
    }
    return tools_->add_tool(tool);
}

std::size_t Scene::add_tool(const collision::ToolConfig& tool) {
    published_.reserve_tools(tool_channels_.size() + 1);
    const std::size_t index = add_tool_effect_only(tool);
    add_to_fingerprint(description_, tool);
    refinalize();
    publish();
    return index;
}

void Scene::remove_tool(std::size_t index) {
    tools_->remove_tool(index);
    publish();
}

collision::CollisionSpheres& Scene::collision_spheres() {
    if (!spheres_) {
        auto spheres = make_owned<collision::CollisionSpheres>(memory_, model_.control_points, rest_length_,
                                                               sphere_spacing(), radius_, memory_, model_.ends,
                                                               given(profiles_.radius));
        // Room for the contacts each snapshot lists, before anything refers to the spheres.
        published_.reserve_contacts(collision::kLoggedContactsPerSphere * spheres->size());
        spheres_ = std::move(spheres);
    }
    return *spheres_;
}

double Scene::sphere_spacing() const {
    return resting_sphere_spacing(collision_, radius_);
}

collision::SphereLoads& Scene::contact_loads(EffectId owner) {
    if (!contact_loads_) {
        contact_loads_ = make_owned<collision::SphereLoads>(memory_, collision_spheres(), memory_);
        dynamics_.add_shared_loads(contact_loads_.get(), owner);
    }
    return *contact_loads_;
}

void Scene::step(double dt) {
    const bool accepted = stepper_.step(dt);
    publish();  // a failed step: the same state, with the counters of its attempts
    if (!accepted) throw Error(ErrorCode::unstable, stepper_.failure());
}

void Scene::publish() {
    Snapshot* slot = published_.begin_write();
    if (slot == nullptr) {
        logger_.log(LogLevel::warning, "every snapshot slot is being read; publication skipped");
        return;
    }
    const mechanics::State& state = stepper_.state();
    const mechanics::StabilityGuard& guard = stepper_.guard();
    std::copy(state.q.begin(), state.q.end(), slot->control_points.begin());
    stats_.time = state.time;
    const mechanics::StepCounters& counters = stepper_.counters();
    stats_.steps = counters.steps;
    stats_.substeps = counters.substeps;
    stats_.last_step_ns = counters.last_step_ns;
    stats_.last_step_attempts = counters.last_step_attempts;
    stats_.last_step_substeps = counters.last_step_substeps;
    stats_.max_step_ns = counters.max_step_ns;
    stats_.late_steps = counters.late_steps;
    stats_.subdivided_steps = counters.subdivided_steps;
    stats_.work = dynamics_.work();
    stats_.rollbacks = guard.rollbacks();
    const ContactSummary contacts = dynamics_.contacts();
    stats_.contacts = contacts.count;
    stats_.max_penetration = contacts.max_penetration;
    stats_.kinetic_energy = guard.reference().kinetic;
    stats_.potential_energy = guard.reference().potential;
    slot->stats = stats_;
    for (std::size_t e = 0; e < kEffectCount; ++e) {
        const EffectId id = static_cast<EffectId>(e);
        const EffectCounters& counters = dynamics_.counters(id);
        slot->effects[e] = EffectStats{dynamics_.has_effect(id), counters.calls, counters.total_time_ns};
    }
    const std::pmr::vector<collision::ToolOutput>& tools = tool_channels_.outputs();
    slot->tools.assign(tools.begin(), tools.end());  // reserved when the tools were added
    slot->obstacles.resize(obstacles_);              // reserved when the obstacles were added
    for (std::size_t i = 0; i < obstacles_; ++i)
        slot->obstacles[i] =
            ObstacleOutput{environment_->obstacle(i) != nullptr, frames_.pose(environment_->frame_of(i))};
    publish_contacts(*slot);
    published_.publish(slot);
}

void Scene::publish_contacts(Snapshot& slot) const {
    using collision::ContactKind;
    ContactTotals& totals = slot.contact_totals;
    totals = ContactTotals{};
    totals.spheres = spheres_ ? static_cast<uint32_t>(spheres_->size()) : 0;
    slot.contacts.clear();
    double largest_squared = 0.0;
    // The tools' first (what a trainer scores), the self-contacts' last: the first dropped
    // when the list is full (reserved with the spheres: no allocation here).
    for (const ContactKind kind : {ContactKind::tool, ContactKind::obstacle, ContactKind::self}) {
        const std::size_t k = static_cast<std::size_t>(kind);
        const collision::ContactLog* log = contact_logs_[k];
        if (log == nullptr) continue;
        const std::size_t listed = std::min(log->size(), slot.contacts.capacity() - slot.contacts.size());
        slot.contacts.insert(slot.contacts.end(), log->begin(), log->begin() + listed);
        totals.found[k] = log->found();
        totals.listed[k] = static_cast<uint32_t>(listed);
        if (log->largest_force_squared() > largest_squared) {
            largest_squared = log->largest_force_squared();
            totals.largest_force_sphere = log->largest_force_sphere();
        }
    }
    totals.largest_force = std::sqrt(largest_squared);
}

}  // namespace enteron::scene
