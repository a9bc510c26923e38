// A simulated scene: the intestine axis, the effects its description names, an integrator,
// the stability guard, and the published snapshot that readers use.
//
// step() has the strong guarantee: it either advances the state and publishes it, or
// throws enteron::Error with the state exactly as before (counters of the failed attempt
// aside: substeps, rollbacks and effect time record the work that was done).
#pragma once

#include <memory_resource>

#include "base/logger.h"
#include "base/memory.h"
#include "collision/collision_spheres.h"
#include "collision/sphere_loads.h"
#include "collision/tool.h"
#include "mechanics/dynamics.h"
#include "mechanics/integrator.h"
#include "mechanics/state.h"
#include "scene/scene_config.h"
#include "scene/snapshot.h"

namespace enteron::collision {
class ToolsForce;
}

namespace enteron::scene {

class Scene {
public:
    // The config must have been validated (validate.h). Allocates everything the scene
    // needs from `memory`.
    Scene(const SceneConfig& config, std::pmr::memory_resource* memory, Logger logger);

    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    // Advances by dt seconds (see ent_scene_step). Throws Error(invalid_argument) for a bad
    // dt, Error(unstable) when the guard cannot recover.
    void step(double dt);

    // Adds an obstacle to the environment (validated by the caller), starting the
    // environment effect with the first one. Returns its index. Not during a step.
    std::size_t add_obstacle(const collision::Obstacle& obstacle);
    std::size_t obstacle_count() const { return obstacles_; }

    // Tools (tools_force.h): add_tool starts the tools effect with the first one and
    // returns the tool's index. The tool calls take a valid index (the caller checks it
    // against tool_count) and a validated, normalised pose. Not during a step.
    std::size_t add_tool(const collision::ToolConfig& tool);
    std::size_t tool_count() const;
    void set_tool_pose(std::size_t tool, const collision::ToolPose& pose);
    bool grasp(std::size_t tool);
    void release(std::size_t tool);
    bool grasping(std::size_t tool) const;
    // Force (N) and torque about the tip (N m) on the tool in the last accepted step.
    void tool_wrench(std::size_t tool, double force[3], double torque[3]) const;

    // The latest published snapshot, pinned while the reader lives. Any thread.
    SnapshotPublisher::Reader read() const { return SnapshotPublisher::Reader(publisher_); }

    std::size_t control_points() const { return model_.control_points; }
    // Tube radius R of the intestine, m (what skins reconstruct around the axis).
    double radius() const { return radius_; }
    std::pmr::memory_resource* memory() const { return memory_; }
    const Logger& logger() const { return logger_; }

private:
    // One attempt at dt in `substeps` equal substeps; false if the guard rejects it.
    bool try_step(double dt, std::size_t substeps);
    // Collision sphere spacing at rest, m.
    double sphere_spacing() const;
    // The shared collision spheres, made on first use (a scene without contacts has none).
    collision::CollisionSpheres& collision_spheres();
    // The contact loads that the self-contact and the environment share (sphere_loads.h),
    // made on first use and registered with the dynamics, their time counted as the
    // `owner` of that first use.
    collision::SphereLoads& contact_loads(EffectId owner);
    // Starts the environment effect with these obstacles.
    void add_environment(const std::vector<collision::Obstacle>& obstacles);
    // Adds a tool, creating the tools effect with the first; no refinalize.
    std::size_t add_tool_effect_only(const collision::ToolConfig& tool);
    // Bounds, substep limit and energies after the set of effects changed.
    void refinalize();
    // Fills a free snapshot slot from the current state and publishes it.
    void publish();

    std::pmr::memory_resource* memory_;
    Logger logger_;
    SolverConfig solver_;
    mechanics::AxisModel model_;
    // The collision spheres the contact effects share; made with the first of them (before
    // dynamics_, which holds those effects, so that it outlives them).
    Owned<collision::CollisionSpheres> spheres_;
    Owned<collision::SphereLoads> contact_loads_;  // made with the first of them, like spheres_
    mechanics::Dynamics dynamics_;
    Owned<mechanics::Integrator> integrator_;
    mechanics::State state_;
    mechanics::State backup_;  // the state before the current step, for rollbacks
    double explicit_substep_limit_;
    double rest_length_;
    double radius_;
    CollisionConfig collision_;
    std::size_t obstacles_ = 0;
    collision::ToolsForce* tools_ = nullptr;  // owned by dynamics_; null until the first tool
    double total_mass_;
    mechanics::Dynamics::Energies energies_;  // of the current state
    SceneStats stats_;
    SnapshotPublisher publisher_;
};

}  // namespace enteron::scene
