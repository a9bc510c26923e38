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
#include "mechanics/dynamics.h"
#include "mechanics/integrator.h"
#include "mechanics/state.h"
#include "scene/scene_config.h"
#include "scene/snapshot.h"

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
    // Starts the environment effect with these obstacles.
    void add_environment(const std::vector<collision::Obstacle>& obstacles);
    // Bounds, substep limit and energies after the set of effects changed.
    void refinalize();
    // Fills a free snapshot slot from the current state and publishes it.
    void publish();

    std::pmr::memory_resource* memory_;
    Logger logger_;
    SolverConfig solver_;
    mechanics::AxisModel model_;
    mechanics::Dynamics dynamics_;
    Owned<mechanics::Integrator> integrator_;
    mechanics::State state_;
    mechanics::State backup_;  // the state before the current step, for rollbacks
    double explicit_substep_limit_;
    double rest_length_;
    double radius_;
    CollisionConfig collision_;
    std::size_t obstacles_ = 0;
    double total_mass_;
    mechanics::Dynamics::Energies energies_;  // of the current state
    SceneStats stats_;
    SnapshotPublisher publisher_;
};

}  // namespace enteron::scene
