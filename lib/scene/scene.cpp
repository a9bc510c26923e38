#include "scene/scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "base/error.h"
#include "collision/environment_force.h"
#include "collision/self_contact_force.h"
#include "collision/tools_force.h"
#include "mechanics/bend_force.h"
#include "mechanics/damping_force.h"
#include "mechanics/gravity_force.h"
#include "mechanics/mesentery_force.h"
#include "mechanics/pinned_points.h"
#include "mechanics/stretch_force.h"
#include "scene/shape_builder.h"

namespace enteron::scene {

namespace {

using namespace enteron::mechanics;

// The guard's allowance for energy appearing in one step, as a fraction of the kinetic and
// deformation energy: an explicit method's energy wobbles by much less (stability suite:
// under 0.4 %), while an implicit step whose contacts appeared within it can gain tens of
// percent and, step after step, pile up joules from nothing (50 ms steps in a dense pile
// went from 0.6 J to 12.9 J with an allowance of 100 %; 1 % refuses legitimate steps out of
// a deep initial overlap). Below this floor (a bowel at rest) the
// allowance is the kinetic energy of the whole bowel at 0.1 m/s.
constexpr double kEnergyGrowthFactor = 0.1;
constexpr double kEnergyFloorSpeed = 0.1;  // m/s

AxisModel make_model(const IntestineConfig& intestine) {
    AxisModel model;
    model.control_points = intestine.control_points;
    model.rest_segment_length = intestine.length / static_cast<double>(intestine.control_points - 1);
    model.linear_density = intestine.linear_density;
    return model;
}

std::vector<uint32_t> pinned_indices(const PinnedConfig& pinned, std::size_t count) {
    std::vector<uint32_t> points = pinned.points;
    if (pinned.ends & pin_first) points.push_back(0);
    if (pinned.ends & pin_last) points.push_back(static_cast<uint32_t>(count - 1));
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    return points;
}

bool all_finite(const std::pmr::vector<double>& values) {
    for (double v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

double max_speed(const State& state) {
    double fastest = 0.0;
    for (std::size_t i = 0; i + 2 < state.v.size(); i += 3) {
        const double* v = &state.v[i];
        fastest = std::max(fastest, v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    return std::sqrt(fastest);
}

// The contact damper fades in over this fraction of the radius of penetration, so that
// every contact force starts from zero (contact_model.h).
constexpr double kContactDampingDepth = 0.1;

uint64_t elapsed_ns(std::chrono::steady_clock::time_point start) {
    return static_cast<uint64_t>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace

Scene::Scene(const SceneConfig& config, std::pmr::memory_resource* memory, Logger logger)
    : memory_(memory),
      logger_(logger),
      solver_(config.solver),
      model_(make_model(config.intestine)),
      dynamics_(model_, memory),
      state_(memory),
      backup_(memory),
      explicit_substep_limit_(0.0),
      rest_length_(config.intestine.length),
      radius_(config.intestine.radius),
      collision_(config.collision),
      total_mass_(config.intestine.linear_density * config.intestine.length),
      publisher_(3 * model_.control_points, memory) {
    const IntestineConfig& intestine = config.intestine;
    const std::size_t n = model_.control_points;
    state_.resize(n);
    backup_.resize(n);
    build_shape(intestine.shape, intestine.length, n, state_.q.data());
    collision_.contact.damping_depth = kContactDampingDepth * radius_;

    if (intestine.stretch_stiffness)
        dynamics_.add_effect(make_owned<StretchForce>(memory, model_, *intestine.stretch_stiffness, memory));
    if (intestine.bend_stiffness)
        dynamics_.add_effect(make_owned<BendForce>(memory, model_, *intestine.bend_stiffness, memory));
    if (config.damping) {
        const DampingCoefficients coefficients{config.damping->drag, config.damping->stretch,
                                               config.damping->bend};
        dynamics_.add_effect(make_owned<DampingForce>(memory, model_, coefficients, memory));
    }
    if (config.gravity) dynamics_.add_effect(make_owned<GravityForce>(memory, model_, *config.gravity, memory));
    if (config.mesentery) {
        const MesenteryConfig& m = *config.mesentery;
        const MesenteryParameters parameters{m.root_start, m.root_end, m.attachments, m.stiffness,
                                             m.rest_length};
        dynamics_.add_effect(make_owned<MesenteryForce>(memory, model_, parameters, state_, memory));
    }
    if (config.pinned)
        dynamics_.add_pins(make_owned<PinnedPoints>(memory, pinned_indices(*config.pinned, n), memory));
    // The self-contact's time takes the shared contact loads', even though the environment
    // is made first.
    if (config.self_collision) contact_loads(EffectId::self_collision);
    if (!config.environment.empty()) add_environment(config.environment);
    for (const collision::ToolConfig& tool : config.tools) add_tool_effect_only(tool);
    if (config.self_collision)
        dynamics_.add_effect(make_owned<collision::SelfContactForce>(memory, collision_spheres(), collision_.contact,
                                                                     state_, memory,
                                                                     contact_loads(EffectId::self_collision)));

    const auto kind = static_cast<mechanics::IntegratorKind>(static_cast<int32_t>(solver_.integrator));
    integrator_ = make_integrator(kind, 3 * n, memory);
    refinalize();
    publish();
}

void Scene::refinalize() {
    dynamics_.finalize();
    explicit_substep_limit_ = dynamics_.explicit_substep_limit(integrator_->stability_interval());
    energies_ = dynamics_.energies(state_);
    if (logger_.enabled())
        logger_.log(LogLevel::info, "scene: %zu control points, substep limit %g s", model_.control_points,
                    std::min(solver_.timestep, explicit_substep_limit_));
}

std::size_t Scene::add_obstacle(const collision::Obstacle& obstacle) {
    const std::size_t index = obstacles_;
    if (auto* environment = static_cast<collision::EnvironmentForce*>(dynamics_.find_effect(EffectId::environment))) {
        environment->add_obstacle(obstacle);
        ++obstacles_;
    } else {
        add_environment({obstacle});
    }
    refinalize();
    publish();
    return index;
}

std::size_t Scene::add_tool_effect_only(const collision::ToolConfig& tool) {
    if (tools_ == nullptr) {
        auto effect =
            make_owned<collision::ToolsForce>(memory_, collision_spheres(), collision_.contact, state_, memory_);
        tools_ = effect.get();
        dynamics_.add_effect(std::move(effect));
    }
    collision::ToolConfig normalized = tool;
    normalized.pose = collision::normalized_pose(tool.pose, "tool.", collision::kJsonToolFields, ErrorCode::internal);
    return tools_->add_tool(normalized);
}

std::size_t Scene::add_tool(const collision::ToolConfig& tool) {
    const std::size_t index = add_tool_effect_only(tool);
    refinalize();
    publish();
    return index;
}

std::size_t Scene::tool_count() const { return tools_ != nullptr ? tools_->size() : 0; }

void Scene::set_tool_pose(std::size_t tool, const collision::ToolPose& pose) { tools_->set_target(tool, pose); }

// A grasp or a release adds or removes the spring's energy between steps: the guard
// compares the next step with the energies as they are now.
bool Scene::grasp(std::size_t tool) {
    const bool held = tools_->grasp(tool, state_);
    energies_ = dynamics_.energies(state_);
    return held;
}

void Scene::release(std::size_t tool) {
    tools_->release(tool);
    energies_ = dynamics_.energies(state_);
}

bool Scene::grasping(std::size_t tool) const { return tools_->grasping(tool); }

void Scene::tool_wrench(std::size_t tool, double force[3], double torque[3]) const {
    const collision::ToolWrench& wrench = tools_->wrench(tool);
    for (int c = 0; c < 3; ++c) force[c] = wrench.force[c], torque[c] = wrench.torque[c];
}

collision::CollisionSpheres& Scene::collision_spheres() {
    if (!spheres_)
        spheres_ = make_owned<collision::CollisionSpheres>(memory_, model_.control_points, rest_length_,
                                                           sphere_spacing(), radius_, memory_);
    return *spheres_;
}

double Scene::sphere_spacing() const {
    return collision_.sphere_spacing > 0.0 ? collision_.sphere_spacing : 0.5 * radius_;
}

collision::SphereLoads& Scene::contact_loads(EffectId owner) {
    if (!contact_loads_) {
        contact_loads_ = make_owned<collision::SphereLoads>(memory_, collision_spheres(), memory_);
        dynamics_.add_shared_loads(contact_loads_.get(), owner);
    }
    return *contact_loads_;
}

void Scene::add_environment(const std::vector<collision::Obstacle>& obstacles) {
    dynamics_.add_effect(make_owned<collision::EnvironmentForce>(memory_, collision_spheres(), collision_.contact,
                                                                 obstacles, state_, memory_,
                                                                 contact_loads(EffectId::environment)));
    obstacles_ += obstacles.size();
}

void Scene::step(double dt) {
    const auto start = std::chrono::steady_clock::now();
    if (!std::isfinite(dt) || !(dt > 0.0)) {
        char message[128];
        std::snprintf(message, sizeof message, "dt_s must be finite and > 0, got %g", dt);
        throw Error(ErrorCode::invalid_argument, message);
    }
    const double longest = std::min(solver_.timestep, explicit_substep_limit_);
    const double needed = std::ceil(dt / longest * (1.0 - 1e-12));
    if (!(needed <= static_cast<double>(solver_.max_substeps))) {
        char message[256];
        std::snprintf(message, sizeof message,
                      "dt_s = %g needs %g substeps of at most %g s, more than max_substeps (%zu)", dt,
                      needed, longest, solver_.max_substeps);
        throw Error(ErrorCode::invalid_argument, message);
    }
    const std::size_t substeps = std::max<std::size_t>(1, static_cast<std::size_t>(needed));

    backup_.assign(state_);
    if (tools_ != nullptr) tools_->begin_step(state_.time, dt);
    for (std::size_t attempt = 0; attempt <= solver_.max_subdivisions; ++attempt) {
        if (tools_ != nullptr) tools_->begin_attempt();
        if (try_step(dt, substeps << attempt)) {
            if (tools_ != nullptr) tools_->end_step();
            stats_.steps += 1;
            stats_.last_step_ns = elapsed_ns(start);
            publish();
            return;
        }
        state_.assign(backup_);
        stats_.rollbacks += 1;
        logger_.log(LogLevel::warning, "step at t = %g s rejected by the guard; retrying with %zu substeps",
                    state_.time, substeps << (attempt + 1));
    }
    if (tools_ != nullptr) tools_->abort_step();
    stats_.last_step_ns = elapsed_ns(start);
    publish();  // the same state, with the counters of the failed attempts
    char message[256];
    std::snprintf(message, sizeof message,
                  "the step of %g s at t = %g s stayed unstable after %zu subdivisions; the state is "
                  "unchanged", dt, state_.time, solver_.max_subdivisions);
    throw Error(ErrorCode::unstable, message);
}

bool Scene::try_step(double dt, std::size_t substeps) {
    const double h = dt / static_cast<double>(substeps);
    const double start_time = state_.time;
    for (std::size_t i = 0; i < substeps; ++i) {
        stats_.substeps += 1;
        if (!integrator_->step(dynamics_, state_, h)) return false;
        if (!all_finite(state_.v) || !all_finite(state_.q)) return false;
    }
    state_.time = start_time + dt;  // no drift from summing substeps
    if (!(max_speed(state_) <= solver_.max_speed)) return false;

    const Dynamics::Energies after = dynamics_.energies(state_);
    const double floor = 0.5 * total_mass_ * kEnergyFloorSpeed * kEnergyFloorSpeed;
    const double allowance = std::max(floor, kEnergyGrowthFactor * (energies_.kinetic + energies_.deformation)) +
                             dynamics_.external_work_bound();
    // A state whose energy is not finite is an explosion, whatever the allowance.
    if (!std::isfinite(after.kinetic + after.potential)) return false;
    if (!(after.kinetic + after.potential <= energies_.kinetic + energies_.potential + allowance)) return false;
    energies_ = after;
    return true;
}

void Scene::publish() {
    Snapshot* slot = publisher_.begin_write();
    if (slot == nullptr) {
        logger_.log(LogLevel::warning, "every snapshot slot is being read; publication skipped");
        return;
    }
    std::copy(state_.q.begin(), state_.q.end(), slot->control_points.begin());
    stats_.time = state_.time;
    const ContactSummary contacts = dynamics_.contacts();
    stats_.contacts = contacts.count;
    stats_.max_penetration = contacts.max_penetration;
    stats_.kinetic_energy = energies_.kinetic;
    stats_.potential_energy = energies_.potential;
    slot->stats = stats_;
    for (std::size_t e = 0; e < kEffectCount; ++e) {
        const EffectId id = static_cast<EffectId>(e);
        const EffectCounters& counters = dynamics_.counters(id);
        slot->effects[e] = EffectStats{dynamics_.has_effect(id), counters.calls, counters.total_time_ns};
    }
    publisher_.publish(slot);
}

}  // namespace enteron::scene
