// SPDX-License-Identifier: Apache-2.0
// A MuJoCo rope as a peer of the Enteron bowel, for the benchmarks and the accuracy study:
// the same length, point count, radius, mass per length, bending stiffness, time step,
// gravity, self-collision rule and box cavity, built from the same ent_scene_desc.
//
// The rope is MuJoCo's composite rope: a chain of N - 1 rigid capsules (radius R, length
// l = L / (N - 1)), each turning about the end of the previous one by two hinges (a
// universal joint: bending, no twist, like our axis), so its N joint points (the first
// end, the N - 2 joints, the last end) play the part of our N control points. Each body
// carries the mass of its segment, mu l (inertia from the capsule's shape). Bending: a
// spring of stiffness EI / l on each hinge (the discrete form of the energy
// EI/2 integral of curvature^2 ds, straight at rest, like ours). Stretching: none by
// default, the segments are rigid (the collision benchmark's rope); with
// stretch_stiffness_N set (the accuracy study), MuJoCo's stretch joints, a slide along each
// segment of stiffness EA / l. Drag, when set, goes through MuJoCo's passive-force
// callback (mjcb_passive): MuJoCo has no drag per metre of a rope. Self-collision: every
// capsule pair except those closer along the axis than our neighbour window (pi R): parent
// and child (MuJoCo filters those itself) and next-but-one bodies (excluded explicitly).
// The box cavity is six inward-facing planes. Contacts use MuJoCo's own soft-constraint
// model with its default solver settings and our friction coefficient; there is no
// mesentery (MuJoCo has no matching element), and no drag or stretch damping unless set
// (the collision benchmark leaves them off), which the benchmark report says.
//
// MuJoCo 2.2.2 (Debian 12's libmujoco-dev) has neither the cable composite nor flexcomp
// (both came later), hence the rope. Built only when MuJoCo is found (ENTERON_BENCH_MUJOCO).
#pragma once

#include <enteron/enteron.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace enteron::peers {

// MuJoCo's integrators (mjtIntegrator), by name for reports.
enum class MujocoIntegrator { euler, rk4, implicit };
const char* mujoco_integrator_name(MujocoIntegrator integrator);

struct MujocoRopeDesc {
    double length_m = 6.0;
    double radius_m = 0.0125;
    uint32_t points = 240;                   // joint points N, so N - 1 capsules
    double linear_density_kg_per_m = 0.3;
    double bend_stiffness_N_m2 = 2.5e-3;     // EI; a joint spring EI / l
    double joint_damping_N_m_s = 0.0;        // per ball joint, N m s / rad
    // EA, N: 0 keeps the segments rigid; > 0 adds a stretch joint between neighbours (a
    // slide along the segment) of stiffness EA / l, the discrete form of EA/2 integral of
    // strain^2 ds. The capsules keep their length: a stretched rope shows gaps between
    // them, and its last segment (after the last joint) does not stretch.
    double stretch_stiffness_N = 0.0;
    double stretch_damping_N_s = 0.0;        // axial force per unit strain rate: damping c / l on each stretch joint
    // Drag, N s / m^2: a force -c v per metre of axis, as Enteron's drag. On each rigid
    // segment, -c l v at its centre and the torque -c l^3 / 12 omega across it.
    double drag_N_s_per_m2 = 0.0;
    double timestep_s = 1e-3;
    MujocoIntegrator integrator = MujocoIntegrator::euler;
    double gravity_m_per_s2[3] = {0.0, 0.0, -9.81};
    double friction = 0.3;                   // sliding friction coefficient of every contact
    bool self_collision = true;
    bool box = false;                        // the inside of an axis-aligned box
    double box_center_m[3] = {0.0, 0.0, 0.0};
    double box_half_extents_m[3] = {0.15, 0.15, 0.15};
    bool pin_first = false;                  // first end held in place (free to turn) vs. free
    // Sizes of MuJoCo's preallocated contact and constraint buffers (MJCF size nconmax,
    // njmax); a pyramidal friction cone of condim 3 takes 4 constraint rows per contact.
    // A full buffer drops contacts and is counted (buffer_overflows).
    // Their memory grows with rows^2, and so does creation time (not step time).
    int max_contacts = 200;
    int max_constraint_rows = 800;
    // Initial axis: `points` x 3 coordinates, m. The segment directions are taken from
    // consecutive points; every segment has length l, so the chain follows the polyline
    // from the first point. Starts at rest.
    std::vector<double> initial_points_xyz_m;
};

// The rope matching an Enteron scene description: length, radius, control points, linear
// density, bend stiffness, time step, gravity (zero when the effect is off), friction,
// self-collision (on when the scene's effect is on) and a pinned first end (when the
// scene pins it). Stretching, stretch damping and drag stay off (rigid segments, as the
// collision benchmark times them): set them for a closer match. The initial axis is the scene's for the shapes "line" (the swinging
// scene: pinned at one end, released from horizontal) and "points"; for the others it is
// left empty: give it the scene's control points (ent_scene_control_points).
MujocoRopeDesc mujoco_rope_desc_from(const ent_scene_desc& scene);

// `points` points evenly spaced on a straight line of length_m from start_m along
// direction (normalised here), x y z each.
std::vector<double> line_points(uint32_t points, double length_m, const double start_m[3],
                                const double direction[3]);

class MujocoRope {
public:
    // Builds the MJCF model, compiles it and places the chain on the initial axis. On
    // failure returns nullptr and puts MuJoCo's message into *error.
    static std::unique_ptr<MujocoRope> create(const MujocoRopeDesc& desc, std::string* error);
    ~MujocoRope();
    MujocoRope(const MujocoRope&) = delete;
    MujocoRope& operator=(const MujocoRope&) = delete;

    // One mj_step of the model's time step. Returns false once the state is not finite
    // (or MuJoCo found a bad qpos, qvel or qacc and reset the state: also a failure).
    bool step();
    // Steps until the simulated time reaches time_s (to within half a step).
    bool advance_to(double time_s);

    bool finite() const;           // every qpos and qvel finite, no MuJoCo instability warning
    double time_s() const;
    int contacts() const;          // active contacts after the last step
    int constraint_rows() const;   // constraint rows (nefc) of the last step
    // Steps whose contact or constraint buffer was full (contacts were dropped).
    int buffer_overflows() const;
    double max_penetration_m() const;  // deepest contact after the last step (0 if none)
    uint32_t points() const { return points_; }

    // The N joint points (first end, joints, last end), N x 3, m: the counterpart of our
    // control points.
    void joint_points(std::vector<double>& out_xyz_m) const;
    // count points evenly spaced in arc length along the joint polyline, like
    // ent_scene_axis on our side (count >= 2).
    void axis(uint32_t count, std::vector<double>& out_xyz_m) const;

    // The MJCF text the model was compiled from (for inspection).
    const std::string& xml() const { return xml_; }

private:
    MujocoRope() = default;
    struct Model;
    std::unique_ptr<Model> model_;
    std::string xml_;
    uint32_t points_ = 0;
    double segment_length_m_ = 0.0;
};

// Wall time of `steps` mj_step calls, each timed alone: median and p99 in microseconds,
// and whether the state stayed finite throughout (timing stops at the first failure).
struct StepTiming {
    double median_us = 0.0;
    double p99_us = 0.0;
    double max_us = 0.0;
    uint64_t steps = 0;
    bool finite = true;
};
StepTiming time_steps(MujocoRope& rope, uint64_t steps);

// "MuJoCo 2.2.2": the loaded library's version.
std::string mujoco_version();

}  // namespace enteron::peers
