#include "collision/tools_force.h"

#include <algorithm>
#include <cmath>

#include "mechanics/system_matrix.h"

namespace enteron::collision {

using mechanics::add_axial_block;
using mechanics::add_point_force;

namespace {

double norm3(const double v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

void cross(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

// Normalised linear interpolation of unit quaternions along the shorter arc.
std::array<double, 4> nlerp(const std::array<double, 4>& a, const std::array<double, 4>& b, double t) {
    double dot = 0.0;
    for (int c = 0; c < 4; ++c) dot += a[c] * b[c];
    const double sign = dot < 0.0 ? -1.0 : 1.0;
    std::array<double, 4> q{};
    double norm2 = 0.0;
    for (int c = 0; c < 4; ++c) {
        q[c] = (1.0 - t) * a[c] + t * sign * b[c];
        norm2 += q[c] * q[c];
    }
    // Opposite quaternions are the same rotation, so the sum never vanishes after the sign flip.
    const double norm = std::sqrt(norm2);
    for (double& c : q) c /= norm;
    return q;
}

void tail_of(const ToolPose& pose, double length, double tail[3]) {
    const std::array<double, 3> z = quaternion_z_axis(pose.orientation);
    for (int c = 0; c < 3; ++c) tail[c] = pose.position[c] + length * z[c];
}

// The grasp: a tension-only spring-damper of rest length `rest` (the tool's radius plus
// the bowel's: the held point sits on the tool's surface, where the contact neither pushes
// nor pulls) from the held axis point p to the tip. Slack, it does nothing, so a grasp
// starts and ends without a jolt. Its stiffness, for the implicit step, is
// H = a n n^T + b I along the unit direction n from p to the tip.
struct GraspSpring {
    bool taut = false;
    double force[3] = {0.0, 0.0, 0.0};  // on the bowel
    double direction[3] = {0.0, 0.0, 1.0};
    double axial_stiffness = 0.0;      // a
    double isotropic_stiffness = 0.0;  // b
    double stiffness_times_velocity[3] = {0.0, 0.0, 0.0};  // H v of the held point
};

GraspSpring grasp_spring(const ToolSettings& settings, double rest, const double tip[3], const double tip_v[3],
                         const double p[3], const double v[3]) {
    GraspSpring spring;
    const double gap[3] = {tip[0] - p[0], tip[1] - p[1], tip[2] - p[2]};
    const double length = norm3(gap);
    if (!(length > rest)) return spring;
    spring.taut = true;
    const double k = settings.grasp_stiffness;
    for (int c = 0; c < 3; ++c) spring.direction[c] = gap[c] / length;
    spring.axial_stiffness = k * rest / length;
    spring.isotropic_stiffness = k * (1.0 - rest / length);
    const double* n = spring.direction;
    const double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    for (int c = 0; c < 3; ++c) {
        spring.force[c] = k * (length - rest) * n[c] + settings.grasp_damping * (tip_v[c] - v[c]);
        spring.stiffness_times_velocity[c] = spring.axial_stiffness * vn * n[c] + spring.isotropic_stiffness * v[c];
    }
    return spring;
}

// A tool's shaft at one instant, as the segment tip + s axis (s in [0, 1]) that sphere
// centres are measured against: most spheres are far, so the test is on squared
// distances and the square root waits for a contact.
struct Shaft {
    double tip[3];
    double axis[3];
    double inverse_axis2;  // 0 for a zero-length shaft (the tip alone)
    double reach;          // the tool's radius plus the bowel's
    // A box around the shaft, reach wide (and a hair more, for rounding): a centre outside
    // it cannot touch, and most of the bowel's spheres are far from the tool.
    double low[3], high[3];

    Shaft(const double tip_in[3], const double tail[3], double reach_in) : reach(reach_in) {
        double axis2 = 0.0;
        const double margin = reach * (1.0 + 1e-9);
        for (int c = 0; c < 3; ++c) {
            tip[c] = tip_in[c];
            axis[c] = tail[c] - tip[c];
            axis2 += axis[c] * axis[c];
            low[c] = std::min(tip[c], tail[c]) - margin;
            high[c] = std::max(tip[c], tail[c]) + margin;
        }
        inverse_axis2 = axis2 > 0.0 ? 1.0 / axis2 : 0.0;
    }

    // For a centre p: s of the closest shaft point, d = p minus that point, and |d|^2;
    // true if the sphere reaches into the tool (false, the rest unset, when p is outside
    // the box).
    bool touches(const double p[3], double* s, double d[3], double* distance2) const {
        if ((p[0] < low[0]) | (p[0] > high[0]) | (p[1] < low[1]) | (p[1] > high[1]) | (p[2] < low[2]) |
            (p[2] > high[2]))
            return false;
        double rel[3], along = 0.0;
        for (int c = 0; c < 3; ++c) rel[c] = p[c] - tip[c], along += rel[c] * axis[c];
        *s = std::clamp(along * inverse_axis2, 0.0, 1.0);
        for (int c = 0; c < 3; ++c) d[c] = rel[c] - *s * axis[c];
        *distance2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
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

void ToolsForce::segment_at(const Tool& tool, double t, double tip[3], double tail[3], double tip_v[3],
                            double tail_v[3]) const {
    const double alpha = fraction_of_step(t);
    ToolPose pose;
    for (int c = 0; c < 3; ++c) pose.position[c] = (1.0 - alpha) * tool.current.position[c] + alpha * tool.target.position[c];
    pose.orientation = nlerp(tool.current.orientation, tool.target.orientation, alpha);
    for (int c = 0; c < 3; ++c) tip[c] = pose.position[c];
    tail_of(pose, tool.settings.length, tail);
    if (step_dt_ > 0.0) {
        double tail0[3], tail1[3];
        tail_of(tool.current, tool.settings.length, tail0);
        tail_of(tool.target, tool.settings.length, tail1);
        for (int c = 0; c < 3; ++c) {
            tip_v[c] = (tool.target.position[c] - tool.current.position[c]) / step_dt_;
            tail_v[c] = (tail1[c] - tail0[c]) / step_dt_;
        }
    } else {
        for (int c = 0; c < 3; ++c) tip_v[c] = tail_v[c] = 0.0;
    }
}

void ToolsForce::evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) {
    spheres_.update(state.q.data());
    last_ = {};
    const double r = spheres_.radius();
    // The implicit step solves for the end of the substep: meet the tool where it is then.
    const double t = state.time + (lin != nullptr ? lin->h : 0.0);
    for (Tool& tool : tools_) {
        double tip[3], tail[3], tip_v[3], tail_v[3];
        segment_at(tool, t, tip, tail, tip_v, tail_v);
        const Shaft shaft(tip, tail, tool.settings.radius + r);
        const double* axis = shaft.axis;
        const double reach = shaft.reach;
        hits_.clear();
        tool.attempt_contacts = 0;
        double total[3] = {0.0, 0.0, 0.0};  // on the bowel
        double total_magnitude = 0.0;       // sum of the magnitudes of its parts
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            const Sphere& sphere = spheres_[i];
            double s, d[3], dist2;
            if (!shaft.touches(sphere.center, &s, d, &dist2)) continue;
            const double dist = std::sqrt(dist2);
            Hit hit;
            hit.sphere = i;
            hit.depth = reach - dist;
            if (dist > 1e-12) {
                for (int c = 0; c < 3; ++c) hit.normal[c] = d[c] / dist;
            } else {  // a centre on the tool's axis: push it up, any direction will do
                hit.normal[0] = 0.0, hit.normal[1] = 0.0, hit.normal[2] = 1.0;
            }
            double v[3];
            spline::evaluate(state.v.data(), sphere.weights, v);
            double v_rel[3];
            for (int c = 0; c < 3; ++c) v_rel[c] = v[c] - ((1.0 - s) * tip_v[c] + s * tail_v[c]);
            hit.force = contact_force(contact_, hit.depth, hit.normal, v_rel);
            for (int c = 0; c < 3; ++c) {
                hit.point[c] = tip[c] + s * axis[c] + tool.settings.radius * hit.normal[c];
                total[c] += hit.force.force[c];
            }
            total_magnitude += norm3(hit.force.force);
            hits_.push_back(hit);
            tool.attempt_contacts += 1;
            last_.count += 1;
            last_.max_penetration = std::max(last_.max_penetration, hit.depth);
        }

        double grasp[3] = {0.0, 0.0, 0.0};  // on the bowel
        GraspSpring spring;
        const bool holding = tool.grasping && !tool.slipped;
        if (holding) {
            double p[3], grasp_v[3];
            spline::evaluate(state.q.data(), tool.grasp_point, p);
            spline::evaluate(state.v.data(), tool.grasp_point, grasp_v);
            spring = grasp_spring(tool.settings, tool.settings.radius + r, tip, tip_v, p, grasp_v);
            for (int c = 0; c < 3; ++c) grasp[c] = spring.force[c];
            if (norm3(grasp) > tool.settings.max_force) {
                tool.slipped = true;  // released when the step is accepted
                grasp[0] = grasp[1] = grasp[2] = 0.0;
            }
            for (int c = 0; c < 3; ++c) total[c] += grasp[c];
            total_magnitude += norm3(grasp);
        }

        // Action = reaction within the bound: every force of this tool shares one scale, set
        // by the sum of their magnitudes (which bounds the net force and, unlike the net
        // force, does not jump when contacts on opposite sides start to cancel).
        const double scale =
            total_magnitude > tool.settings.max_force ? tool.settings.max_force / total_magnitude : 1.0;
        ToolWrench wrench;
        for (int c = 0; c < 3; ++c) wrench.force[c] = -scale * total[c];
        for (const Hit& hit : hits_) {
            const Sphere& sphere = spheres_[hit.sphere];
            double f[3], on_tool[3], arm[3], moment[3];
            for (int c = 0; c < 3; ++c) {
                f[c] = scale * hit.force.force[c];
                on_tool[c] = -f[c];
                arm[c] = hit.point[c] - tip[c];
            }
            add_point_force(sphere.weights, f, force);
            cross(arm, on_tool, moment);
            for (int c = 0; c < 3; ++c) wrench.torque[c] += moment[c];
            if (lin == nullptr) continue;
            const double h = lin->h;
            const ContactForce& cf = hit.force;
            // Scaled with the force.
            const ContactLinearization l = contact_linearization(cf, h);
            add_axial_block(*lin->system, sphere.weights, hit.normal, l.axial, l.transverse, scale);
            double v[3];
            spline::evaluate(state.v.data(), sphere.weights, v);
            const double vn = v[0] * hit.normal[0] + v[1] * hit.normal[1] + v[2] * hit.normal[2];
            const double hv[3] = {scale * cf.stiffness * vn * hit.normal[0], scale * cf.stiffness * vn * hit.normal[1],
                                  scale * cf.stiffness * vn * hit.normal[2]};
            add_point_force(sphere.weights, hv, lin->stiffness_times_velocity);
        }
        if (holding && !tool.slipped) {
            double f[3];
            for (int c = 0; c < 3; ++c) f[c] = scale * grasp[c];
            add_point_force(tool.grasp_point, f, force);
            if (lin != nullptr && spring.taut) {
                const double h = lin->h;
                // h C + h^2 H with C = c I and H = a n n^T + b I (grasp_spring).
                add_axial_block(*lin->system, tool.grasp_point, spring.direction, h * h * spring.axial_stiffness,
                                h * tool.settings.grasp_damping + h * h * spring.isotropic_stiffness, scale);
                double hv[3];
                for (int c = 0; c < 3; ++c) hv[c] = scale * spring.stiffness_times_velocity[c];
                add_point_force(tool.grasp_point, hv, lin->stiffness_times_velocity);
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
        double tip[3], tail[3], tip_v[3], tail_v[3];
        segment_at(tool, state.time, tip, tail, tip_v, tail_v);
        const Shaft shaft(tip, tail, tool.settings.radius + r);
        double stored = 0.0, total_magnitude = 0.0;
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            double s, d[3], dist2;
            if (!shaft.touches(spheres_[i].center, &s, d, &dist2)) continue;
            const double depth = shaft.reach - std::sqrt(dist2);
            if (!(depth > 0.0)) continue;
            stored += 0.5 * contact_.stiffness * depth * depth;
            total_magnitude += contact_.stiffness * depth;
        }
        // The spring energy as far as the bound lets the contacts push (evaluate's scale).
        energy += total_magnitude > tool.settings.max_force ? stored * tool.settings.max_force / total_magnitude
                                                            : stored;
        if (tool.grasping) {
            double p[3];
            spline::evaluate(state.q.data(), tool.grasp_point, p);
            const double gap[3] = {tip[0] - p[0], tip[1] - p[1], tip[2] - p[2]};
            const double stretch = std::max(0.0, norm3(gap) - (tool.settings.radius + r));
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
        double d2 = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double d = spheres_[i].center[c] - tool.current.position[c];
            d2 += d * d;
        }
        if (d2 <= best) {
            best = d2;
            tool.grasp_point = spheres_[i].weights;
            found = true;
        }
    }
    if (found) tool.grasping = true;
}

void ToolsForce::add_stiffness_bound(spline::ScalarBandMatrix& bound) const {
    double grasp = 0.0;
    for (const Tool& tool : tools_) grasp += tool.settings.grasp_stiffness;
    spheres_.add_weight_products(contact_.stiffness * double(tools_.size()) + grasp, bound);
}

void ToolsForce::add_damping_bound(spline::ScalarBandMatrix& bound) const {
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
        double tail0[3], tail1[3], tip_move[3], tail_move[3];
        tail_of(tool.current, tool.settings.length, tail0);
        tail_of(tool.target, tool.settings.length, tail1);
        for (int c = 0; c < 3; ++c) {
            tip_move[c] = tool.target.position[c] - tool.current.position[c];
            tail_move[c] = tail1[c] - tail0[c];
        }
        // Every point of the shaft moves at most as far as its ends (twice that for the
        // arc of a turn and the contact damping's share).
        work += 2.0 * tool.settings.max_force * std::max(norm3(tip_move), norm3(tail_move));
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
