#include "collision/tools_force.h"

#include <algorithm>
#include <cmath>

#include "mechanics/system_matrix.h"

namespace enteron::collision {

using mechanics::add_axial_block;
using mechanics::add_point_force;

namespace {

// Normalised linear interpolation of unit quaternions (w x y z) along the shorter arc.
Vec4 nlerp(const Vec4& a, const Vec4& b, double t) {
    const double sign = a.dot(b) < 0.0 ? -1.0 : 1.0;
    const Vec4 q = (1.0 - t) * a + (t * sign) * b;
    // Opposite quaternions are the same rotation, so the sum never vanishes after the sign flip.
    return q / q.norm();
}

// The back end of the shaft of a tool at `pose`.
Vec3 tail_of(const ToolPose& pose, double length) {
    return pose.position + length * quaternion_z_axis(pose.orientation);
}

// The grasp: a tension-only spring-damper of rest length `rest` (the tool's radius plus
// the bowel's: the held point sits on the tool's surface, where the contact neither pushes
// nor pulls) from the held axis point p to the tip. Slack, it does nothing, so a grasp
// starts and ends without a jolt. Its stiffness, for the implicit step, is
// H = a n n^T + b I along the unit direction n from p to the tip.
struct GraspSpring {
    bool taut = false;
    Vec3 force = Vec3::Zero();  // on the bowel
    Vec3 direction = Vec3::UnitZ();
    double axial_stiffness = 0.0;      // a
    double isotropic_stiffness = 0.0;  // b
    Vec3 stiffness_times_velocity = Vec3::Zero();  // H v of the held point
};

GraspSpring grasp_spring(const ToolSettings& settings, double rest, const Vec3& tip, const Vec3& tip_v, const Vec3& p,
                         const Vec3& v) {
    GraspSpring spring;
    const Vec3 gap = tip - p;
    const double length = gap.norm();
    if (!(length > rest)) return spring;
    spring.taut = true;
    const double k = settings.grasp_stiffness;
    const Vec3& n = spring.direction = gap / length;
    spring.axial_stiffness = k * rest / length;
    spring.isotropic_stiffness = k * (1.0 - rest / length);
    spring.force = k * (length - rest) * n + settings.grasp_damping * (tip_v - v);
    spring.stiffness_times_velocity = spring.axial_stiffness * v.dot(n) * n + spring.isotropic_stiffness * v;
    return spring;
}

// A tool's shaft at one instant, as the segment tip + s axis (s in [0, 1]) that sphere
// centres are measured against: most spheres are far, so the test is on squared
// distances and the square root waits for a contact.
struct Shaft {
    Vec3 tip;
    Vec3 axis;
    double inverse_axis2;  // 0 for a zero-length shaft (the tip alone)
    double reach;          // the tool's radius plus the bowel's
    // A box around the shaft, reach wide (and a hair more, for rounding): a centre outside
    // it cannot touch, and most of the bowel's spheres are far from the tool.
    Vec3 low, high;

    Shaft(const Vec3& tip_in, const Vec3& tail, double reach_in)
        : tip(tip_in), axis(tail - tip_in), reach(reach_in) {
        const double axis2 = axis.squaredNorm();
        inverse_axis2 = axis2 > 0.0 ? 1.0 / axis2 : 0.0;
        const double margin = reach * (1.0 + 1e-9);
        low = tip.cwiseMin(tail).array() - margin;
        high = tip.cwiseMax(tail).array() + margin;
    }

    // For a centre p: s of the closest shaft point, d = p minus that point, and |d|^2;
    // true if the sphere reaches into the tool (false, the rest unset, when p is outside
    // the box).
    bool touches(const Vec3& p, double* s, Vec3* d, double* distance2) const {
        if (((p.array() < low.array()) || (p.array() > high.array())).any()) return false;
        const Vec3 rel = p - tip;
        *s = std::clamp(rel.dot(axis) * inverse_axis2, 0.0, 1.0);
        *d = rel - *s * axis;
        *distance2 = d->squaredNorm();
        return *distance2 < reach * reach;
    }
};

}  // namespace

ToolsForce::ToolsForce(CollisionSpheres& spheres, const ContactParameters& contact, const mechanics::State& initial,
                       ToolChannels& channels, std::pmr::memory_resource* memory)
    : spheres_(spheres),
      channels_(channels),
      contact_(contact),
      tools_(memory),
      hits_(memory) {
    hits_.reserve(spheres_.size());  // one contact per sphere and tool at most: no allocation in steps
    spheres_.update(initial.q.data());
}

std::size_t ToolsForce::add_tool(const ToolConfig& tool) {
    Tool t;
    t.settings = tool.settings;
    t.current = tool.pose;
    t.target = tool.pose;
    tools_.reserve(tools_.size() + 1);  // nothing changes if an allocation fails
    channels_.add();
    tools_.push_back(t);
    return tools_.size() - 1;
}

double ToolsForce::fraction_of_step(double t) const {
    if (!(step_dt_ > 0.0)) return 0.0;
    return std::clamp((t - step_start_) / step_dt_, 0.0, 1.0);
}

ToolsForce::Segment ToolsForce::segment_at(const Tool& tool, double t) const {
    const double alpha = fraction_of_step(t);
    ToolPose pose;
    pose.position = (1.0 - alpha) * tool.current.position + alpha * tool.target.position;
    const Eigen::Map<const Vec4> from(tool.current.orientation.data()), to(tool.target.orientation.data());
    Eigen::Map<Vec4>(pose.orientation.data()) = nlerp(from, to, alpha);
    Segment segment;
    segment.tip = pose.position;
    segment.tail = tail_of(pose, tool.settings.length);
    segment.tip_velocity = segment.tail_velocity = Vec3::Zero();
    if (step_dt_ > 0.0) {
        segment.tip_velocity = (tool.target.position - tool.current.position) / step_dt_;
        segment.tail_velocity =
            (tail_of(tool.target, tool.settings.length) - tail_of(tool.current, tool.settings.length)) / step_dt_;
    }
    return segment;
}

void ToolsForce::evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) {
    spheres_.update(state.q.data());
    last_ = {};
    const double r = spheres_.radius();
    // The implicit step solves for the end of the substep: meet the tool where it is then.
    const double t = state.time + (lin != nullptr ? lin->h : 0.0);
    for (Tool& tool : tools_) {
        const Segment segment = segment_at(tool, t);
        const Shaft shaft(segment.tip, segment.tail, tool.settings.radius + r);
        hits_.clear();
        tool.attempt_contacts = 0;
        Vec3 total = Vec3::Zero();    // on the bowel
        double total_magnitude = 0.0;  // sum of the magnitudes of its parts
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            const Sphere& sphere = spheres_[i];
            double s, dist2;
            Vec3 d;
            if (!shaft.touches(sphere.center, &s, &d, &dist2)) continue;
            const double dist = std::sqrt(dist2);
            Hit hit;
            hit.sphere = i;
            hit.depth = shaft.reach - dist;
            // A centre on the tool's axis: push it up, any direction will do.
            hit.normal = dist > 1e-12 ? Vec3(d / dist) : Vec3::UnitZ();
            const Vec3 v = spline::evaluate(state.v.data(), sphere.weights);
            const Vec3 tool_v = (1.0 - s) * segment.tip_velocity + s * segment.tail_velocity;
            hit.force = contact_force(contact_, hit.depth, hit.normal, v - tool_v);
            hit.point = segment.tip + s * shaft.axis + tool.settings.radius * hit.normal;
            total += hit.force.force;
            total_magnitude += hit.force.force.norm();
            hits_.push_back(hit);
            tool.attempt_contacts += 1;
            last_.count += 1;
            last_.max_penetration = std::max(last_.max_penetration, hit.depth);
        }

        Vec3 grasp = Vec3::Zero();  // on the bowel
        GraspSpring spring;
        const bool holding = tool.grasping && !tool.slipped;
        if (holding) {
            const Vec3 p = spline::evaluate(state.q.data(), tool.grasp_point);
            const Vec3 grasp_v = spline::evaluate(state.v.data(), tool.grasp_point);
            spring = grasp_spring(tool.settings, tool.settings.radius + r, segment.tip, segment.tip_velocity, p, grasp_v);
            grasp = spring.force;
            if (grasp.norm() > tool.settings.max_force) {
                tool.slipped = true;  // released when the step is accepted
                grasp = Vec3::Zero();
            }
            total += grasp;
            total_magnitude += grasp.norm();
        }

        // Action = reaction within the bound: every force of this tool shares one scale, set
        // by the sum of their magnitudes (which bounds the net force and, unlike the net
        // force, does not jump when contacts on opposite sides start to cancel).
        const double scale =
            total_magnitude > tool.settings.max_force ? tool.settings.max_force / total_magnitude : 1.0;
        ToolWrench wrench;
        wrench.force = -scale * total;
        for (const Hit& hit : hits_) {
            const Sphere& sphere = spheres_[hit.sphere];
            const Vec3 f = scale * hit.force.force;
            add_point_force(sphere.weights, f, force);
            wrench.torque += (hit.point - segment.tip).cross(-f);
            if (lin == nullptr) continue;
            const ContactForce& cf = hit.force;
            // Scaled with the force.
            const ContactLinearization l = contact_linearization(cf, lin->h);
            add_axial_block(*lin->system, sphere.weights, hit.normal, l.axial, l.transverse, scale);
            const Vec3 v = spline::evaluate(state.v.data(), sphere.weights);
            add_point_force(sphere.weights, scale * cf.stiffness * v.dot(hit.normal) * hit.normal,
                            lin->stiffness_times_velocity);
        }
        if (holding && !tool.slipped) {
            add_point_force(tool.grasp_point, scale * grasp, force);
            if (lin != nullptr && spring.taut) {
                const double h = lin->h;
                // h C + h^2 H with C = c I and H = a n n^T + b I (grasp_spring).
                add_axial_block(*lin->system, tool.grasp_point, spring.direction, h * h * spring.axial_stiffness,
                                h * tool.settings.grasp_damping + h * h * spring.isotropic_stiffness, scale);
                add_point_force(tool.grasp_point, scale * spring.stiffness_times_velocity, lin->stiffness_times_velocity);
            }
        }
        tool.attempt_wrench = wrench;
    }
}

double ToolsForce::potential_energy(const mechanics::State& state) const {
    spheres_.update(state.q.data());
    const double r = spheres_.radius();
    double energy = 0.0;
    for (const Tool& tool : tools_) {
        const Segment segment = segment_at(tool, state.time);
        const Shaft shaft(segment.tip, segment.tail, tool.settings.radius + r);
        double stored = 0.0, total_magnitude = 0.0;
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            double s, dist2;
            Vec3 d;
            if (!shaft.touches(spheres_[i].center, &s, &d, &dist2)) continue;
            const double depth = shaft.reach - std::sqrt(dist2);
            if (!(depth > 0.0)) continue;
            stored += 0.5 * contact_.stiffness * depth * depth;
            total_magnitude += contact_.stiffness * depth;
        }
        // The spring energy as far as the bound lets the contacts push (evaluate's scale).
        energy += total_magnitude > tool.settings.max_force ? stored * tool.settings.max_force / total_magnitude
                                                            : stored;
        // A grasp that slipped in this step holds no spring at its end: the guard must not
        // count the energy of the spring it let go of, however far the jump stretched it.
        if (tool.grasping && !tool.slipped) {
            const Vec3 p = spline::evaluate(state.q.data(), tool.grasp_point);
            const double stretch = std::max(0.0, (segment.tip - p).norm() - (tool.settings.radius + r));
            energy += 0.5 * tool.settings.grasp_stiffness * stretch * stretch;
        }
    }
    return energy;
}

void ToolsForce::grasp(Tool& tool, const mechanics::State& state) {
    spheres_.update(state.q.data());
    const double reach = tool.settings.radius + spheres_.radius() + tool.settings.grasp_margin;
    double best = reach * reach;
    bool found = false;
    for (std::size_t i = 0; i < spheres_.size(); ++i) {
        const double d2 = (spheres_[i].center - tool.current.position).squaredNorm();
        if (d2 <= best) {
            best = d2;
            tool.grasp_point = spheres_[i].weights;
            found = true;
        }
    }
    if (found) tool.grasping = true;
}

void ToolsForce::add_stiffness_bound(numerics::ScalarBandMatrix& bound) const {
    double grasp = 0.0;
    for (const Tool& tool : tools_) grasp += tool.settings.grasp_stiffness;
    spheres_.add_weight_products(contact_.stiffness * double(tools_.size()) + grasp, bound);
}

void ToolsForce::add_damping_bound(numerics::ScalarBandMatrix& bound) const {
    double grasp = 0.0;
    for (const Tool& tool : tools_) grasp += tool.settings.grasp_damping;
    const double friction = friction_damping_bound(contact_, spheres_.radius());
    spheres_.add_weight_products((contact_.damping + friction) * double(tools_.size()) + grasp, bound);
}

void ToolsForce::add_contacts(mechanics::ContactSummary& summary) const {
    summary.count += last_.count;
    summary.max_penetration = std::max(summary.max_penetration, last_.max_penetration);
}

double ToolsForce::external_work_bound() const {
    if (!(step_dt_ > 0.0)) return 0.0;
    double work = 0.0;
    for (const Tool& tool : tools_) {
        const double tip_move = (tool.target.position - tool.current.position).norm();
        const double tail_move =
            (tail_of(tool.target, tool.settings.length) - tail_of(tool.current, tool.settings.length)).norm();
        // Every point of the shaft moves at most as far as its ends (twice that for the
        // arc of a turn and the contact damping's share).
        work += 2.0 * tool.settings.max_force * std::max(tip_move, tail_move);
    }
    return work;
}

bool ToolsForce::begin_step(const mechanics::State& state, double dt) {
    bool grasp_changed = false;
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        Tool& tool = tools_[i];
        ToolMailbox& mailbox = *channels_.mailbox(i);
        mailbox.take_pose(tool.target);
        switch (mailbox.take_grasp()) {
            case ToolMailbox::Grasp::none: break;
            case ToolMailbox::Grasp::grasp: grasp(tool, state); grasp_changed = true; break;
            case ToolMailbox::Grasp::release: tool.grasping = false; grasp_changed = true; break;
        }
    }
    step_start_ = state.time;
    step_dt_ = dt;
    return grasp_changed;
}

void ToolsForce::begin_attempt() {
    for (Tool& tool : tools_) tool.slipped = false;
}

void ToolsForce::end_step(bool accepted) {
    std::pmr::vector<ToolOutput>& outputs = channels_.outputs();
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        Tool& tool = tools_[i];
        if (accepted) {
            if (tool.slipped) tool.grasping = false;
            tool.wrench = tool.attempt_wrench;
            tool.contacts = tool.attempt_contacts;
            tool.current = tool.target;
        }
        tool.slipped = false;
        outputs[i] = ToolOutput{tool.wrench, tool.grasping, tool.contacts};
    }
    step_dt_ = 0.0;
}

}  // namespace enteron::collision
