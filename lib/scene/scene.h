// SPDX-License-Identifier: Apache-2.0
// A simulated scene: the intestine axis and the effects its description names (assembly),
// the changes made to them between steps, the stepper that steps them
// (mechanics/stepper.h), and the snapshot it publishes for readers.
//
// step() has the strong guarantee: it either advances the state and publishes it, or
// throws enteron::Error with the state exactly as before (counters of the failed attempt
// aside: substeps, rollbacks and effect time record the work that was done).
//
// Threads: one thread at a time drives the scene (step, add_obstacle, add_tool, and the
// changes between steps: obstacle poses, friction and removal, gravity, pins, the
// mesentery's attachment); the C API enforces it. Any thread may post tool commands
// (tool_channels()) and read the published snapshots.
#pragma once

#include <array>
#include <memory_resource>
#include <optional>
#include <string>
#include <vector>

#include "base/logger.h"
#include "base/memory.h"
#include "base/state_io.h"
#include "collision/collision_spheres.h"
#include "collision/contact_log.h"
#include "collision/environment_force.h"
#include "collision/sphere_loads.h"
#include "collision/tool.h"
#include "collision/tool_channels.h"
#include "mechanics/dynamics.h"
#include "mechanics/rigid_frames.h"
#include "mechanics/stepper.h"
#include "scene/scene_config.h"
#include "scene/snapshot.h"
#include "scene/validate.h"

namespace enteron::collision {
class ToolsForce;
}  // namespace enteron::collision
namespace enteron::mechanics {
class GravityForce;
class MesenteryForce;
}  // namespace enteron::mechanics

namespace enteron::scene {

class Scene {
public:
    // The config must come from validate() (validate.h): checked, with its start points.
    // Allocates everything the scene needs from `memory`. The scene publishes into
    // `published`, which the caller owns (readers may outlive the scene): made with the
    // config's control point count and the same memory, and kept alive past the scene.
    // `names` name the config's fields in messages (a mesh obstacle's start is checked here,
    // once its field is built).
    Scene(const SceneConfig& config, SnapshotPublisher& published, std::pmr::memory_resource* memory, Logger logger,
          const FieldNames& names);

    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    // Advances by dt seconds (see ent_scene_step). Throws Error(invalid_argument) for a bad
    // dt, Error(unstable) when the guard cannot recover; its message names the check that
    // failed, by how much, and the effect and control point where it happened.
    void step(double dt);

    // Adds an obstacle to the environment (validated by the caller), starting the
    // environment effect with the first one; a mesh's field is built here and the bowel's
    // start checked against it (`name`, `names` for the message). Returns its index. Not
    // during a step.
    std::size_t add_obstacle(const collision::Obstacle& obstacle, const std::string& name, const FieldNames& names);
    // Obstacles added so far, removed ones included (the next index), and those present.
    std::size_t obstacle_indices() const { return obstacles_; }
    std::size_t obstacle_count() const;
    // The obstacle at index, or Error(not_found) naming it.
    const collision::Obstacle& obstacle(std::size_t index) const;
    // Between steps (anatomy.md): the pose an obstacle reaches at the end of the next step,
    // the velocities its contacts see during that step, its friction, its removal.
    void set_obstacle_pose(std::size_t index, const mechanics::RigidPose& pose);
    void set_obstacle_velocity(std::size_t index, const Vec3& linear, const Vec3& angular);
    void set_obstacle_friction(std::size_t index, double friction);
    void remove_obstacle(std::size_t index);
    // Where each obstacle rests now (removed ones too), for the snapshot.
    mechanics::RigidPose obstacle_pose(std::size_t index) const;

    // Between steps: gravity (starting the effect if the scene had none), m/s^2.
    void set_gravity(const Vec3& gravity);
    // Between steps: hold a control point where it is, in the world or on an obstacle's
    // frame (then it moves with it); let it go. unpin returns false if it was not pinned.
    // Both throw Error(invalid_argument) for a clamped end's end point (attach_clamped_ends).
    void pin_point(std::size_t point, std::optional<std::size_t> obstacle);
    bool unpin_point(std::size_t point);
    // Between steps: the mesentery's root follows an obstacle's frame (or stays in the world).
    void attach_mesentery(std::optional<std::size_t> obstacle);
    // Between steps: a clamped end (pin_first or pin_last; both with pin_both) follows an
    // obstacle's frame from where it is now, its end point and its tangent's direction (or
    // stays in the world where it is). Throws Error(not_found) if such an end is not clamped.
    void attach_clamped_ends(int32_t ends, std::optional<std::size_t> obstacle);

    // Adds a tool (validated: unit quaternion), starting the tools effect with the first
    // one; returns its index. Not during a step.
    std::size_t add_tool(const collision::ToolConfig& tool);
    // The tools' mailboxes: any thread posts poses, grasps and releases here; the next step
    // takes them (tool_channels.h).
    collision::ToolChannels& tool_channels() { return tool_channels_; }
    const collision::ToolChannels& tool_channels() const { return tool_channels_; }
    // Removes tool `index` (it exists and is not removed yet: tools_force.h) and publishes;
    // allocates nothing.
    void remove_tool(std::size_t index);

    std::size_t control_points() const { return model_.control_points; }
    // Tube radius R of the intestine, m (what skins reconstruct around the axis); with a
    // radius profile, its largest value.
    double radius() const { return radius_; }
    // The radius profile (spline/length_profile.h), empty when the radius is constant.
    const spline::LengthProfile& radius_profile() const { return profiles_.radius; }
    // The tube's radius at arc length s from the first end at rest, m.
    double radius_at(double s) const { return profiles_.radius.empty() ? radius_ : profiles_.radius.at(s); }
    // The smallest radius along the tube (radius() without a profile), m.
    double smallest_radius() const { return profiles_.radius.empty() ? radius_ : profiles_.radius.smallest(); }
    // The axis' length at rest, m.
    double rest_length() const { return rest_length_; }

    // Save and restore (docs/scoring-and-state.md; scene_state.cpp). save_state writes the state
    // into `buffer` if it fits in `capacity` bytes (a null buffer only measures) and returns
    // its size. restore_state checks the whole image first (format, fingerprint, every
    // section) and throws Error naming what is wrong with the scene untouched; then it
    // applies it and publishes the restored state. Not during a step.
    std::size_t save_state(void* buffer, std::size_t capacity) const;
    void restore_state(const void* data, std::size_t size);
    // What a saved state must have been saved from (scene_fingerprint.h): the description,
    // the obstacles and tools added since, and the effects in the order they run.
    uint64_t fingerprint() const;

private:
    // Collision sphere spacing at rest, m.
    double sphere_spacing() const;
    // The shared collision spheres, made on first use (a scene without contacts has none).
    collision::CollisionSpheres& collision_spheres();
    // The contact loads that the self-contact and the environment share (sphere_loads.h),
    // made on first use and registered with the dynamics, their time counted as the
    // `owner` of that first use.
    collision::SphereLoads& contact_loads(mechanics::EffectId owner);
    // Adds a prepared obstacle to the environment effect, making the effect (and its contact
    // log) with the first.
    void add_to_environment(const collision::Obstacle& prepared);
    // Error(not_found) for an index with no obstacle (never added, or removed).
    void require_obstacle(std::size_t index) const;
    // The environment effect, which holds obstacle `index`, or Error(not_found).
    collision::EnvironmentForce& environment_with(std::size_t index);
    const collision::EnvironmentForce& environment_with(std::size_t index) const;
    // A change between steps that changed the stored energy: the guard measures it again
    // and the change is published.
    void changed_between_steps();
    // pin_point and attach_mesentery without refinalize and publish (the constructor's).
    void pin_point_only(std::size_t point, std::optional<std::size_t> obstacle);
    void attach_mesentery_only(std::optional<std::size_t> obstacle);
    void attach_clamped_ends_only(int32_t ends, std::optional<std::size_t> obstacle);
    // Throws Error(invalid_argument) if `point` is a clamped end's end point: pinned or let
    // go alone, it would leave its clamp half attached.
    void refuse_clamped_end_point(std::size_t point, const char* change);
    // Adds a tool, creating the tools effect with the first; no refinalize.
    std::size_t add_tool_effect_only(const collision::ToolConfig& tool);
    // Bounds, substep limit and energies after the set of effects changed (Stepper::effects_changed).
    void refinalize();
    // Fills a free snapshot slot from the current state and publishes it.
    void publish();
    // The contact effects' last evaluations into a slot: tools, obstacles, then self-contacts.
    void publish_contacts(Snapshot& slot) const;

    std::pmr::memory_resource* memory_;
    Logger logger_;
    SolverConfig solver_;
    // The properties along the length (empty: constant); model_ and the spheres point here.
    struct Profiles {
        spline::LengthProfile radius, linear_density, stretch_stiffness, bend_stiffness;
    } profiles_;
    mechanics::AxisModel model_;
    // The collision spheres the contact effects share; made with the first of them (before
    // dynamics_, which holds those effects, so that it outlives them).
    Owned<collision::CollisionSpheres> spheres_;
    Owned<collision::SphereLoads> contact_loads_;  // made with the first of them, like spheres_
    collision::ToolChannels tool_channels_;        // the tools effect uses them: before dynamics_
    mechanics::RigidFrames frames_;                // obstacles' poses, followed by attachments: before dynamics_
    mechanics::Dynamics dynamics_;
    mechanics::Stepper stepper_;  // steps dynamics_ with frames_: after both
    // The effects the changes between steps reach, as assembly added them (owned by
    // dynamics_; null while the scene has none).
    collision::EnvironmentForce* environment_ = nullptr;
    collision::ToolsForce* tools_ = nullptr;
    mechanics::GravityForce* gravity_ = nullptr;
    mechanics::MesenteryForce* mesentery_ = nullptr;
    double rest_length_;
    double radius_;
    CollisionConfig collision_;
    std::size_t obstacles_ = 0;
    // How deep beyond an obstacle's surface the bowel may be and still start (validate.h): an
    // obstacle added later is checked against it.
    StartClearance start_clearance_;
    SceneStats stats_;
    SnapshotPublisher& published_;
    // The logs of the contact effects, by ContactKind (null: no such effect).
    std::array<const collision::ContactLog*, collision::kContactKinds> contact_logs_{};
    Fingerprint description_;  // of the description, the obstacles and the tools added since
};

}  // namespace enteron::scene
