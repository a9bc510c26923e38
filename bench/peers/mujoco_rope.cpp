// SPDX-License-Identifier: Apache-2.0
#include "mujoco_rope.h"

#include "step_timing.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <sstream>

namespace enteron::peers {

namespace {

constexpr double kPi = 3.14159265358979323846;

// MuJoCo prints its warnings and writes them to MUJOCO_LOG.TXT by default; a benchmark
// must not litter, and the counters in mjData.warning already tell us what happened.
void quiet_warning(const char*) {}

struct Vec3 {
    double x, y, z;
};
Vec3 sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

// The smallest rotation (quaternion w x y z) taking unit vector a to unit vector b.
void rotation_between(const Vec3& a, const Vec3& b, mjtNum quat[4]) {
    const Vec3 axis = cross(a, b);
    const double s = norm(axis);
    const double c = dot(a, b);
    if (s < 1e-12) {
        if (c > 0.0) {
            quat[0] = 1.0;
            quat[1] = quat[2] = quat[3] = 0.0;
            return;
        }
        // Opposite directions: half a turn about any axis perpendicular to a.
        Vec3 other = std::fabs(a.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        Vec3 perpendicular = cross(a, other);
        const double n = norm(perpendicular);
        const mjtNum unit[3] = {perpendicular.x / n, perpendicular.y / n, perpendicular.z / n};
        mju_axisAngle2Quat(quat, unit, kPi);
        return;
    }
    const mjtNum unit[3] = {axis.x / s, axis.y / s, axis.z / s};
    mju_axisAngle2Quat(quat, unit, std::atan2(s, c));
}

bool all_finite(const mjtNum* values, int count) {
    for (int i = 0; i < count; ++i)
        if (!std::isfinite(values[i])) return false;
    return true;
}

// The drag of a rope that asks for it: the model's numeric kDragNumeric holds c (N s/m^2)
// and the segment length l. Every body is a segment of the rope (the walls are world
// geoms). On a rigid segment, -c v per metre integrates to the force -c l v at its centre
// and the torque -c l^3 / 12 omega across its axis. The generalised force is accumulated
// from the leaves to the root in MuJoCo's com-based frame, as mj_rne does, so that it costs
// O(N) (one mj_applyFT per body would cost O(N nv)).
constexpr const char* kDragNumeric = "enteron_drag";

void add_rope_drag(const mjModel* m, mjData* d) {
    const int id = mj_name2id(m, mjOBJ_NUMERIC, kDragNumeric);
    if (id < 0 || m->numeric_size[id] != 2) return;
    const mjtNum c = m->numeric_data[m->numeric_adr[id]];
    const mjtNum l = m->numeric_data[m->numeric_adr[id] + 1];
    mjMARKSTACK;
    mjtNum* body_force = mj_stackAlloc(d, 6 * m->nbody);  // [torque about the com frame's origin; force]
    mju_zero(body_force, 6 * m->nbody);
    for (int b = 1; b < m->nbody; ++b) {
        const mjtNum* origin = d->subtree_com + 3 * m->body_rootid[b];
        const mjtNum* centre = d->xipos + 3 * b;
        const mjtNum* w = d->cvel + 6 * b;       // angular velocity
        mjtNum arm[3], v[3], spin[3];
        mju_sub3(arm, centre, origin);
        mju_cross(spin, w, arm);
        mju_add3(v, d->cvel + 6 * b + 3, spin);  // the velocity of the segment's centre
        const mjtNum axis[3] = {d->xmat[9 * b], d->xmat[9 * b + 3], d->xmat[9 * b + 6]};
        mjtNum across[3];
        mju_addScl3(across, w, axis, -mju_dot3(w, axis));
        mjtNum* f = body_force + 6 * b;
        mju_scl3(f + 3, v, -c * l);
        mju_scl3(f, across, -c * l * l * l / 12.0);
        mjtNum moment[3];
        mju_cross(moment, arm, f + 3);
        mju_addTo3(f, moment);
    }
    for (int b = m->nbody - 1; b > 0; --b)
        if (m->body_parentid[b] > 0) mju_addTo(body_force + 6 * m->body_parentid[b], body_force + 6 * b, 6);
    for (int j = 0; j < m->nv; ++j)
        d->qfrc_passive[j] += mju_dot(d->cdof + 6 * j, body_force + 6 * m->dof_bodyid[j], 6);
    mjFREESTACK;
}

}  // namespace

const char* mujoco_integrator_name(MujocoIntegrator integrator) {
    switch (integrator) {
        case MujocoIntegrator::euler: return "Euler";
        case MujocoIntegrator::rk4: return "RK4";
        case MujocoIntegrator::implicit: return "implicit";
    }
    return "Euler";
}

MujocoRopeDesc mujoco_rope_desc_from(const ent_scene_desc& scene) {
    MujocoRopeDesc desc;
    desc.length_m = scene.length_m;
    desc.radius_m = scene.radius_m;
    desc.points = scene.control_points;
    desc.linear_density_kg_per_m = scene.linear_density_kg_per_m;
    const bool bend = (scene.effects & ENT_EFFECT_BIT(ENT_EFFECT_BEND)) != 0;
    desc.bend_stiffness_N_m2 = bend ? scene.bend_stiffness_N_m2 : 0.0;
    desc.timestep_s = scene.timestep_s;
    const bool gravity = (scene.effects & ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY)) != 0;
    for (int c = 0; c < 3; ++c) desc.gravity_m_per_s2[c] = gravity ? scene.gravity_m_per_s2[c] : 0.0;
    desc.friction = scene.contact_friction;
    desc.self_collision = (scene.effects & ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION)) != 0;
    desc.pin_first = (scene.effects & ENT_EFFECT_BIT(ENT_EFFECT_PINNED)) != 0 &&
                     (scene.pinned_ends == ENT_PIN_FIRST || scene.pinned_ends == ENT_PIN_BOTH);
    if (scene.shape == ENT_SHAPE_LINE)
        desc.initial_points_xyz_m =
            line_points(scene.control_points, scene.length_m, scene.shape_center_m, scene.shape_direction);
    else if (scene.shape == ENT_SHAPE_POINTS && scene.shape_points_xyz_m != nullptr)
        desc.initial_points_xyz_m.assign(scene.shape_points_xyz_m,
                                         scene.shape_points_xyz_m + 3 * static_cast<std::size_t>(scene.control_points));
    return desc;
}

std::vector<double> line_points(uint32_t points, double length_m, const double start_m[3],
                                const double direction[3]) {
    const double n = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
    std::vector<double> xyz(3 * static_cast<std::size_t>(points));
    for (uint32_t i = 0; i < points; ++i) {
        const double s = points > 1 ? length_m * i / (points - 1) : 0.0;
        for (int c = 0; c < 3; ++c) xyz[3 * i + c] = start_m[c] + (n > 0.0 ? s * direction[c] / n : 0.0);
    }
    return xyz;
}

struct MujocoRope::Model {
    mjModel* model = nullptr;
    mjData* data = nullptr;
    ~Model() {
        if (data) mj_deleteData(data);
        if (model) mj_deleteModel(model);
    }
};

namespace {

// The MJCF of the chain, MuJoCo's own composite rope: bodies rB0 ... rB(N-2), each a
// capsule of half-length l/2 centred on its origin along its local +x; every body after
// the first turns about the far end of its parent by two hinges (local y, then z), a
// universal joint (the rope has no twist, like our axis). The root body rB0 is ours:
// free, or pinned at its first end by a ball joint. (A hand-written chain of nested
// bodies would exceed the XML parser's nesting limit of about 100 elements.)
std::string rope_xml(const MujocoRopeDesc& desc) {
    const uint32_t bodies = desc.points - 1;
    const double l = desc.length_m / bodies;
    const double r = desc.radius_m;
    const double mass = desc.linear_density_kg_per_m * l;
    const double joint_stiffness = desc.bend_stiffness_N_m2 / l;

    // Pairs closer along the axis than the neighbour window pi R never collide (as on
    // our side); the gap between capsules i and j > i is (j - i - 1) l.
    const double window = kPi * r;
    uint32_t excluded_span = 1;  // parent-child pairs: MuJoCo's filterparent drops them
    while (excluded_span < bodies && excluded_span * l < window) ++excluded_span;

    std::ostringstream x;
    x.precision(17);
    x << "<mujoco model=\"enteron_peer_rope\">\n"
      << "  <compiler angle=\"radian\"/>\n"
      << "  <option timestep=\"" << desc.timestep_s << "\" integrator=\""
      << mujoco_integrator_name(desc.integrator) << "\" gravity=\"" << desc.gravity_m_per_s2[0] << ' '
      << desc.gravity_m_per_s2[1] << ' ' << desc.gravity_m_per_s2[2] << "\">\n"
      // The composite rope holds each stretch joint near zero by a soft equality constraint
      // on top of its spring: off, so that the spring EA / l alone sets the stretch (and the
      // constraint solver has nothing to do). The model has no other equality.
      << "    <flag equality=\"disable\"/>\n"
      << "  </option>\n"
      << "  <size nconmax=\"" << desc.max_contacts << "\" njmax=\"" << desc.max_constraint_rows << "\"/>\n"
      << "  <worldbody>\n";
    if (desc.box) {
        // The inside of the box: six planes facing inward (a plane pushes along its +z).
        const double* c = desc.box_center_m;
        const double* h = desc.box_half_extents_m;
        for (int axis = 0; axis < 3; ++axis) {
            for (int side = -1; side <= 1; side += 2) {
                double pos[3] = {c[0], c[1], c[2]};
                pos[axis] += side * h[axis];
                double normal[3] = {0.0, 0.0, 0.0};
                normal[axis] = -side;
                x << "    <geom type=\"plane\" size=\"0 0 1\" contype=\"0\" conaffinity=\"1\" friction=\""
                  << desc.friction << " 0.005 0.0001\" pos=\"" << pos[0] << ' ' << pos[1] << ' ' << pos[2]
                  << "\" zaxis=\"" << normal[0] << ' ' << normal[1] << ' ' << normal[2] << "\"/>\n";
            }
        }
    }
    const double* p0 = desc.initial_points_xyz_m.data();
    if (desc.pin_first)
        x << "    <body name=\"rB0\" pos=\"" << p0[0] + 0.5 * l << ' ' << p0[1] << ' ' << p0[2] << "\">\n"
          << "      <joint name=\"pin\" type=\"ball\" pos=\"" << -0.5 * l << " 0 0\"/>\n";
    else
        x << "    <body name=\"rB0\">\n"
          << "      <freejoint name=\"free\"/>\n";
    // Self-collision off: the capsules still touch the walls (contype 1 meets the planes'
    // conaffinity 1) but not each other (conaffinity 0).
    x << "      <composite type=\"rope\" count=\"" << bodies << " 1 1\" spacing=\"" << l << "\" prefix=\"r\">\n"
      << "        <joint kind=\"main\" stiffness=\"" << joint_stiffness << "\" damping=\""
      << desc.joint_damping_N_m_s << "\"/>\n";
    if (desc.stretch_stiffness_N > 0.0)
        x << "        <joint kind=\"stretch\" stiffness=\"" << desc.stretch_stiffness_N / l << "\" damping=\""
          << desc.stretch_damping_N_s / l << "\"/>\n";
    x << "        <geom type=\"capsule\" size=\"" << r << ' ' << 0.5 * l << "\" mass=\"" << mass
      << "\" friction=\"" << desc.friction << " 0.005 0.0001\" contype=\"1\" conaffinity=\""
      << (desc.self_collision ? 1 : 0) << "\"/>\n"
      << "      </composite>\n"
      << "    </body>\n"
      << "  </worldbody>\n";
    if (desc.self_collision && excluded_span > 1) {
        x << "  <contact>\n";
        for (uint32_t i = 0; i < bodies; ++i)
            for (uint32_t j = i + 2; j < bodies && j - i <= excluded_span; ++j)
                x << "    <exclude body1=\"rB" << i << "\" body2=\"rB" << j << "\"/>\n";
        x << "  </contact>\n";
    }
    if (desc.drag_N_s_per_m2 > 0.0)
        x << "  <custom>\n    <numeric name=\"" << kDragNumeric << "\" data=\"" << desc.drag_N_s_per_m2 << ' ' << l
          << "\"/>\n  </custom>\n";
    x << "</mujoco>\n";
    return x.str();
}

}  // namespace

std::unique_ptr<MujocoRope> MujocoRope::create(const MujocoRopeDesc& desc, std::string* error) {
    const auto fail = [&](const std::string& message) -> std::unique_ptr<MujocoRope> {
        if (error) *error = message;
        return nullptr;
    };
    if (desc.points < 3) return fail("a MuJoCo rope needs at least 3 points");
    if (!(desc.length_m > 0.0 && desc.radius_m > 0.0 && desc.linear_density_kg_per_m > 0.0 &&
          desc.timestep_s > 0.0 && desc.bend_stiffness_N_m2 >= 0.0 && desc.stretch_stiffness_N >= 0.0 &&
          desc.stretch_damping_N_s >= 0.0 && desc.drag_N_s_per_m2 >= 0.0))
        return fail("length, radius, linear density and time step must be > 0; bend and stretch stiffness, "
                    "stretch damping and drag >= 0");
    if (desc.initial_points_xyz_m.size() != 3 * static_cast<std::size_t>(desc.points))
        return fail("initial_points_xyz_m must hold points x 3 coordinates");

    if (mj_version() != mjVERSION_HEADER)
        return fail("libmujoco version " + std::to_string(mj_version()) + " does not match its header (" +
                    std::to_string(mjVERSION_HEADER) + ")");
    mju_user_warning = quiet_warning;
    // One process-wide hook; it acts only on models that carry the drag numeric.
    if (desc.drag_N_s_per_m2 > 0.0) mjcb_passive = add_rope_drag;
    std::unique_ptr<MujocoRope> rope(new MujocoRope());
    rope->points_ = desc.points;
    rope->segment_length_m_ = desc.length_m / (desc.points - 1);
    rope->xml_ = rope_xml(desc);

    // Compile from memory through a virtual file system (mjVFS is large: on the heap).
    auto vfs = std::make_unique<mjVFS>();
    mj_defaultVFS(vfs.get());
    const char* file = "enteron_peer_rope.xml";
    if (mj_makeEmptyFileVFS(vfs.get(), file, static_cast<int>(rope->xml_.size())) != 0)
        return fail("mj_makeEmptyFileVFS failed");
    const int index = mj_findFileVFS(vfs.get(), file);
    std::memcpy(vfs->filedata[index], rope->xml_.data(), rope->xml_.size());
    char message[1024] = "";
    rope->model_ = std::make_unique<Model>();
    rope->model_->model = mj_loadXML(file, vfs.get(), message, sizeof message);
    mj_deleteVFS(vfs.get());
    if (!rope->model_->model) return fail(std::string("mj_loadXML: ") + message);
    rope->model_->data = mj_makeData(rope->model_->model);
    if (!rope->model_->data) return fail("mj_makeData failed");

    // Place the chain on the initial polyline. The root body turns +x to the first
    // segment's direction (the smallest rotation); every later body turns its parent's +x
    // to its own segment's direction by its two hinges: about y by a, then about the new
    // z by b, which sends +x to (cos a cos b, sin b, -sin a cos b) in the parent's frame.
    const mjModel* m = rope->model_->model;
    mjData* d = rope->model_->data;
    const auto point = [&](uint32_t i) {
        return Vec3{desc.initial_points_xyz_m[3 * i], desc.initial_points_xyz_m[3 * i + 1],
                    desc.initial_points_xyz_m[3 * i + 2]};
    };
    const double l = rope->segment_length_m_;
    mjtNum world[4] = {1.0, 0.0, 0.0, 0.0};  // orientation of the current body
    for (uint32_t i = 0; i + 1 < desc.points; ++i) {
        Vec3 direction = sub(point(i + 1), point(i));
        const double n = norm(direction);
        if (!(n > 0.0) || !std::isfinite(n)) return fail("initial points must be finite and distinct");
        direction = {direction.x / n, direction.y / n, direction.z / n};
        if (i == 0) {
            rotation_between(Vec3{1.0, 0.0, 0.0}, direction, world);
            const int address = m->jnt_qposadr[0];
            if (desc.pin_first) {
                std::copy(world, world + 4, d->qpos + address);
            } else {
                // The free root body's origin is the centre of its capsule.
                const Vec3 p = point(0);
                d->qpos[address + 0] = p.x + 0.5 * l * direction.x;
                d->qpos[address + 1] = p.y + 0.5 * l * direction.y;
                d->qpos[address + 2] = p.z + 0.5 * l * direction.z;
                std::copy(world, world + 4, d->qpos + address + 3);
            }
            continue;
        }
        // The direction in the parent's frame.
        mjtNum inverse[4], local[3];
        const mjtNum world_direction[3] = {direction.x, direction.y, direction.z};
        mju_negQuat(inverse, world);
        mju_rotVecQuat(local, world_direction, inverse);
        const double b = std::asin(std::clamp(local[1], -1.0, 1.0));
        const double a = std::atan2(-local[2], local[0]);
        const int hinge_y = m->body_jntadr[i + 1];  // body 0 is the world; a stretch joint follows the hinges
        d->qpos[m->jnt_qposadr[hinge_y]] = a;
        d->qpos[m->jnt_qposadr[hinge_y + 1]] = b;
        const mjtNum y_axis[3] = {0.0, 1.0, 0.0}, z_axis[3] = {0.0, 0.0, 1.0};
        mjtNum turn_y[4], turn_z[4], after_y[4];
        mju_axisAngle2Quat(turn_y, y_axis, a);
        mju_axisAngle2Quat(turn_z, z_axis, b);
        mju_mulQuat(after_y, world, turn_y);
        mju_mulQuat(world, after_y, turn_z);
    }
    mju_zero(d->qvel, m->nv);
    mj_forward(m, d);
    return rope;
}

MujocoRope::~MujocoRope() = default;

bool MujocoRope::finite() const {
    const mjModel* m = model_->model;
    const mjData* d = model_->data;
    // MuJoCo resets the state itself when qacc goes bad and only counts a warning.
    const int bad = d->warning[mjWARN_BADQPOS].number + d->warning[mjWARN_BADQVEL].number +
                    d->warning[mjWARN_BADQACC].number;
    return bad == 0 && all_finite(d->qpos, m->nq) && all_finite(d->qvel, m->nv);
}

bool MujocoRope::step() {
    mj_step(model_->model, model_->data);
    return finite();
}

bool MujocoRope::advance_to(double time_s) {
    const double h = model_->model->opt.timestep;
    while (model_->data->time < time_s - 0.5 * h)
        if (!step()) return false;
    return true;
}

double MujocoRope::time_s() const { return model_->data->time; }

int MujocoRope::contacts() const { return model_->data->ncon; }

int MujocoRope::constraint_rows() const { return model_->data->nefc; }

int MujocoRope::buffer_overflows() const {
    return model_->data->warning[mjWARN_CONTACTFULL].number + model_->data->warning[mjWARN_CNSTRFULL].number;
}

double MujocoRope::max_penetration_m() const {
    double deepest = 0.0;
    for (int i = 0; i < model_->data->ncon; ++i) deepest = std::max(deepest, -model_->data->contact[i].dist);
    return deepest;
}

void MujocoRope::joint_points(std::vector<double>& out) const {
    const mjData* d = model_->data;
    out.resize(3 * static_cast<std::size_t>(points_));
    const uint32_t bodies = points_ - 1;
    const double half = 0.5 * segment_length_m_;
    // Body b (1 ... bodies; 0 is the world) is a capsule centred on its origin along its
    // +x, the first column of its row-major frame xmat: its first end is joint point
    // b - 1, and the last body's far end is the last point.
    for (uint32_t b = 1; b <= bodies; ++b) {
        const mjtNum* frame = d->xmat + 9 * b;
        for (int c = 0; c < 3; ++c) out[3 * (b - 1) + c] = d->xpos[3 * b + c] - half * frame[3 * c];
    }
    const mjtNum* frame = d->xmat + 9 * bodies;
    for (int c = 0; c < 3; ++c) out[3 * bodies + c] = d->xpos[3 * bodies + c] + half * frame[3 * c];
}

void MujocoRope::axis(uint32_t count, std::vector<double>& out) const {
    std::vector<double> p;
    joint_points(p);
    const std::size_t n = points_;
    std::vector<double> arc(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) {
        const Vec3 a{p[3 * i - 3], p[3 * i - 2], p[3 * i - 1]};
        const Vec3 b{p[3 * i], p[3 * i + 1], p[3 * i + 2]};
        arc[i] = arc[i - 1] + norm(sub(b, a));
    }
    out.resize(3 * static_cast<std::size_t>(count));
    std::size_t segment = 0;
    for (uint32_t k = 0; k < count; ++k) {
        const double s = count > 1 ? arc[n - 1] * k / (count - 1) : 0.0;
        while (segment + 2 < n && arc[segment + 1] < s) ++segment;
        const double span = arc[segment + 1] - arc[segment];
        const double t = span > 0.0 ? std::clamp((s - arc[segment]) / span, 0.0, 1.0) : 0.0;
        for (int c = 0; c < 3; ++c)
            out[3 * k + c] = (1.0 - t) * p[3 * segment + c] + t * p[3 * (segment + 1) + c];
    }
}

StepTiming time_steps(MujocoRope& rope, uint64_t steps) {
    StepTiming timing;
    std::vector<double> samples;
    samples.reserve(steps);
    for (uint64_t i = 0; i < steps; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const bool ok = rope.step();
        const auto stop = std::chrono::steady_clock::now();
        samples.push_back(std::chrono::duration<double, std::micro>(stop - start).count());
        if (!ok) {
            timing.finite = false;
            break;
        }
    }
    timing.steps = samples.size();
    const bench::StepTimeSummary summary = bench::summarize(samples);
    timing.median_us = summary.median_us;
    timing.p99_us = summary.p99_us;
    timing.max_us = summary.max_us;
    return timing;
}

std::string mujoco_version() {
    const int v = mj_version();
    return "MuJoCo " + std::to_string(v / 100) + "." + std::to_string(v / 10 % 10) + "." + std::to_string(v % 10);
}

}  // namespace enteron::peers
