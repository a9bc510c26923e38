#include "collision/tools_force.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "collision/shaft_contact.h"
#include "collision/tool_shaft.h"
#include "mechanics/bordered_system.h"
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

Mat3 outer(const Vec3& n) { return n * n.transpose(); }

// The grasp: a tension-only spring-damper of rest length `rest` from the held axis point p
// to the tip (ToolsForce::grasp_rest: from where the held point was when grasped, closing
// to the tool's radius plus the bowel's, where the held point sits on the tool's surface
// and the contact neither pushes nor pulls). Slack, it does nothing, so a grasp starts
// and ends without a jolt. Its stiffness, for the implicit step, is
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

// The box around where a proxy may go in one solve: its shaft where it was and where the
// device is, grown by twice the reach (it may slide half round a tube on its way).
struct SweptBox {
    Vec3 low, high;
    SweptBox(const Vec3& from, const Vec3& to, const Vec3& shaft, double reach) {
        low = from.cwiseMin(to).cwiseMin(from + shaft).cwiseMin(to + shaft).array() - 2.0 * reach;
        high = from.cwiseMax(to).cwiseMax(from + shaft).cwiseMax(to + shaft).array() + 2.0 * reach;
    }
    bool contains(const Vec3& p) const { return !((p.array() < low.array()) || (p.array() > high.array())).any(); }
};

}  // namespace

ToolsForce::ToolsForce(CollisionSpheres& spheres, const ContactParameters& contact, const mechanics::State& initial,
                       ToolChannels& channels, std::pmr::memory_resource* memory)
    : spheres_(spheres),
      channels_(channels),
      contact_(contact),
      tools_(memory),
      contacts_(memory),
      candidates_(memory),
      proxy_(memory),
      log_(ContactKind::tool, kLoggedContactsPerSphere * spheres.size(), memory) {
    candidates_.reserve(spheres_.size());
    proxy_.reserve(spheres_.size());
    spheres_.update(initial.q.data());
}

std::size_t ToolsForce::add_tool(const ToolConfig& tool) {
    Tool t;
    t.settings = tool.settings;
    t.contact = contact_;
    if (t.settings.friction >= 0.0) t.contact.friction = t.settings.friction;
    if (t.settings.mode == ToolMode::proxy)
        t.contact.stiffness = proxy_contact_stiffness(contact_.stiffness, t.settings.max_force, spheres_.radius());
    t.current = tool.pose;
    t.target = tool.pose;
    t.proxy = t.step_proxy = tool.pose.position;
    t.grasp_rest = t.settings.radius + spheres_.radius();
    // Nothing changes if an allocation fails: every reservation comes first. Each tool may
    // touch every sphere and hold one point.
    tools_.reserve(tools_.size() + 1);
    contacts_.reserve((tools_.size() + 1) * (spheres_.size() + 1));
    channels_.add();
    tools_.push_back(t);
    return tools_.size() - 1;
}

void ToolsForce::remove_tool(std::size_t index) {
    Tool& tool = tools_[index];
    tool.removed = true;
    tool.grasping = false;
    tool.contact_count = tool.sphere_contacts = tool.contacts = 0;
    tool.wrench = ToolWrench{};
    tool.stiffness = tool.accepted_stiffness = Mat3::Zero();
    ToolOutput& output = channels_.outputs()[index];
    output = ToolOutput{};
    output.removed = true;
    channels_.mailbox(index)->retire();
}


std::size_t ToolsForce::border_bodies() const {
    std::size_t bodies = 0;
    for (const Tool& tool : tools_) bodies += !tool.removed && tool.settings.mode == ToolMode::proxy;
    return bodies;
}

double ToolsForce::grasp_rest(const Tool& tool, double t) const {
    const double surface = tool.settings.radius + spheres_.radius();
    const double elapsed = step_dt_ > 0.0 ? std::max(0.0, t - step_start_) : 0.0;
    return std::max(surface, tool.grasp_rest - kGraspClosingSpeed * elapsed);
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

void ToolsForce::apply(const Contact& contact, const Vec3& normal, double axial, double transverse, double scale,
                       const Vec3& stiffness_times_velocity, double* force, const mechanics::Linearization* lin) {
    add_point_force(contact.weights, contact.force, force);
    if (lin != nullptr) {
        add_axial_block(*lin->system, contact.weights, normal, axial, transverse, scale);
        add_point_force(contact.weights, stiffness_times_velocity, lin->stiffness_times_velocity);
    }
    contacts_.push_back(contact);
}

const ToolsForce::Contact& ToolsForce::apply_sphere(std::size_t sphere, double depth, const ContactForce& cf,
                                                     const Vec3& normal, double scale, const Vec3& position,
                                                     const Vec3& velocity,
                                                     const Vec3& arm, double* force,
                                                     const mechanics::Linearization* lin) {
    const Mat3 nn = outer(normal);
    Contact contact;
    contact.sphere = static_cast<uint32_t>(sphere);
    contact.depth = depth;
    contact.normal = normal;
    contact.weights = spheres_[sphere].weights;
    contact.force = scale * cf.force;
    contact.stiffness = (scale * cf.stiffness) * nn;
    contact.damping = scale * (cf.damping * nn + cf.friction_damping * (Mat3::Identity() - nn));
    contact.position = position;
    contact.velocity = velocity;
    contact.arm = arm;
    // The implicit system's block, scaled with the force.
    const ContactLinearization l = contact_linearization(cf, lin != nullptr ? lin->h : 0.0);
    apply(contact, normal, l.axial, l.transverse, scale, scale * cf.stiffness * velocity.dot(normal) * normal, force,
          lin);
    return contacts_.back();
}

void ToolsForce::evaluate(const mechanics::State& state, double* force, const mechanics::Linearization* lin) {
    spheres_.update(state.q.data());
    last_ = {};
    contacts_.clear();
    border_ = lin != nullptr ? lin->border : nullptr;
    // The implicit step solves for the end of the substep: meet the tool where it is then.
    const double t = state.time + (lin != nullptr ? lin->h : 0.0);
    for (Tool& tool : tools_) {
        tool.first_contact = contacts_.size();
        tool.contact_count = 0;
        tool.sphere_contacts = 0;
        tool.has_body = false;
        if (tool.removed) continue;
        if (tool.settings.mode == ToolMode::proxy)
            evaluate_proxy(tool, state, t, force, lin);
        else
            evaluate_direct(tool, state, t, force, lin);
        tool.contact_count = contacts_.size() - tool.first_contact;
        last_.count += tool.sphere_contacts;
    }
}

void ToolsForce::evaluate_direct(Tool& tool, const mechanics::State& state, double t, double* force,
                                 const mechanics::Linearization* lin) {
    const double r = spheres_.radius();
    const Segment segment = segment_at(tool, t);
    const Shaft shaft(segment.tip, segment.tail, tool.settings.radius + r);
    tool.evaluated_proxy = segment.tip;
    tool.evaluated_proxy_velocity = segment.tip_velocity;
    tool.evaluated_time = t;
    // The contacts, first unscaled: the bound scales them all by one factor, set by the sum
    // of their magnitudes (which bounds the net force and, unlike the net force, does not
    // jump when contacts on opposite sides start to cancel).
    hits_.clear();
    Vec3 total = Vec3::Zero();     // on the bowel
    double total_magnitude = 0.0;  // sum of the magnitudes of its parts
    // Their change as the tool moves rigidly by dx, velocities held (shaft_contact_rate): for the stiffness.
    Mat3 total_rate = Mat3::Zero();
    Eigen::RowVector3d magnitude_rate = Eigen::RowVector3d::Zero();
    for (std::size_t i = 0; i < spheres_.size(); ++i) {
        const Sphere& sphere = spheres_[i];
        ShaftContact touch;
        if (!shaft_contact(shaft, sphere.center, &touch)) continue;
        const double s = touch.s;
        Hit hit;
        hit.sphere = i;
        hit.depth = touch.depth;
        hit.normal = touch.normal;
        hit.velocity = spline::evaluate(state.v.data(), sphere.weights);
        const Vec3 relative = hit.velocity - ((1.0 - s) * segment.tip_velocity + s * segment.tail_velocity);
        hit.force = contact_force(tool.contact, hit.depth, hit.normal, relative);
        hit.arm = s * shaft.axis + tool.settings.radius * hit.normal;
        total += hit.force.force;
        const double magnitude = hit.force.force.norm();
        total_magnitude += magnitude;
        const Mat3 rate = shaft_contact_rate(shaft_contact_jacobian(tool.contact, touch, hit.force, relative), touch,
                                             shaft, segment.tail_velocity - segment.tip_velocity, 0.0);
        total_rate += rate;
        if (magnitude > 0.0) magnitude_rate += (hit.force.force / magnitude).transpose() * rate;
        hits_.push_back(hit);
        last_.max_penetration = std::max(last_.max_penetration, hit.depth);
    }
    tool.sphere_contacts = static_cast<uint32_t>(hits_.size());

    Vec3 grasp = Vec3::Zero();  // on the bowel
    GraspSpring spring;
    Vec3 grasp_v = Vec3::Zero();
    const bool holding = tool.grasping && !tool.slipped;
    if (holding) {
        const Vec3 p = spline::evaluate(state.q.data(), tool.grasp_point);
        grasp_v = spline::evaluate(state.v.data(), tool.grasp_point);
        spring = grasp_spring(tool.settings, grasp_rest(tool, t), segment.tip, segment.tip_velocity, p, grasp_v);
        grasp = spring.force;
        if (grasp.norm() > tool.settings.max_force) {
            tool.slipped = true;  // released when the step is accepted
            grasp = Vec3::Zero();
        }
        total += grasp;
        const double magnitude = grasp.norm();
        total_magnitude += magnitude;
        if (spring.taut && !tool.slipped) {
            const Mat3 h = spring.axial_stiffness * outer(spring.direction) + spring.isotropic_stiffness * Mat3::Identity();
            total_rate += h;
            if (magnitude > 0.0) magnitude_rate += (grasp / magnitude).transpose() * h;
        }
    }

    // Action = reaction within the bound: every force of this tool shares one scale.
    const double max_force = tool.settings.max_force;
    const bool bounded = total_magnitude > max_force;
    const double scale = bounded ? max_force / total_magnitude : 1.0;
    // The force on the tool is -scale total, the scale changing with the magnitudes.
    tool.stiffness = bounded ? Mat3(-scale * (total_rate - total * magnitude_rate / total_magnitude)) : Mat3(-total_rate);

    for (const Hit& hit : hits_)
        apply_sphere(hit.sphere, hit.depth, hit.force, hit.normal, scale, spheres_[hit.sphere].center,
                     hit.velocity, hit.arm, force, lin);
    // A slack grasp spring pulls nothing.
    if (holding && !tool.slipped && spring.taut) {
        Contact contact;
        contact.weights = tool.grasp_point;
        contact.force = scale * grasp;
        contact.stiffness =
            scale * (spring.axial_stiffness * outer(spring.direction) + spring.isotropic_stiffness * Mat3::Identity());
        contact.damping = (scale * tool.settings.grasp_damping) * Mat3::Identity();
        contact.position = spline::evaluate(state.q.data(), tool.grasp_point);
        contact.velocity = grasp_v;
        contact.arm = Vec3::Zero();
        const double h = lin != nullptr ? lin->h : 0.0;
        // h C + h^2 H with C = c I and H = a n n^T + b I (grasp_spring).
        apply(contact, spring.direction, h * h * spring.axial_stiffness,
              h * tool.settings.grasp_damping + h * h * spring.isotropic_stiffness, scale,
              scale * spring.stiffness_times_velocity, force, lin);
    }
}

void ToolsForce::evaluate_proxy(Tool& tool, const mechanics::State& state, double t, double* force,
                                const mechanics::Linearization* lin) {
    const double r = spheres_.radius();
    const Segment segment = segment_at(tool, t);
    ProxyProblem problem;
    problem.shaft = segment.tail - segment.tip;
    problem.shaft_velocity = segment.tail_velocity - segment.tip_velocity;
    problem.reach = tool.settings.radius + r;
    problem.contact = tool.contact;
    problem.coupling_stiffness = tool.settings.coupling_stiffness;
    problem.coupling_damping = tool.settings.coupling_damping;
    problem.max_force = tool.settings.max_force;
    problem.start = tool.proxy;
    problem.start_velocity = tool.proxy_velocity;
    problem.target = segment.tip;
    problem.target_velocity = segment.tip_velocity;
    problem.dt = std::max(0.0, t - tool.proxy_time);
    // The spheres the proxy may meet on its way from where it was to the device.
    candidates_.clear();
    const SweptBox box(tool.proxy, segment.tip, problem.shaft, problem.reach);
    for (std::size_t i = 0; i < spheres_.size(); ++i) {
        const Sphere& sphere = spheres_[i];
        if (!box.contains(sphere.center)) continue;
        candidates_.push_back({i, sphere.center, spline::evaluate(state.v.data(), sphere.weights)});
    }
    const bool holding = tool.grasping && !tool.slipped;
    if (holding) {
        problem.grasp.holding = true;
        problem.grasp.point = spline::evaluate(state.q.data(), tool.grasp_point);
        problem.grasp.velocity = spline::evaluate(state.v.data(), tool.grasp_point);
        problem.grasp.rest = grasp_rest(tool, t);
        problem.grasp.stiffness = tool.settings.grasp_stiffness;
        problem.grasp.damping = tool.settings.grasp_damping;
    }
    ProxyResult result = proxy_.solve(problem, candidates_);
    // Holding would take more than max_force: the grasp slips (released when the step is
    // accepted) and the proxy rests without it.
    if (holding && result.grasp_taut && result.saturated) {
        tool.slipped = true;
        problem.grasp.holding = false;
        result = proxy_.solve(problem, candidates_);
    }
    tool.evaluated_proxy = result.position;
    tool.evaluated_proxy_velocity = result.velocity;
    tool.evaluated_time = t;
    tool.stiffness = result.device_stiffness;

    // What the proxy gives the bowel: its contacts' forces, which balance the coupling force.
    // Explicit methods take them as they are (scaled to the bound should the balance be a
    // rounding off); the implicit step lets the proxy move with the bowel (its border body).
    Vec3 total = result.grasp_force;
    for (const ProxyContact& c : proxy_.contacts()) total += c.force.force;
    const double magnitude = total.norm();
    const double scale = lin == nullptr && magnitude > tool.settings.max_force ? tool.settings.max_force / magnitude : 1.0;
    const double h = lin != nullptr ? lin->h : 0.0;
    Mat3 block = Mat3::Zero();      // h sum E_i of the border body
    Vec3 predicted = Vec3::Zero();  // sum of the forces less h K v: the g-hats of the border
    for (const ProxyContact& c : proxy_.contacts()) {
        const ProxyCandidate& candidate = candidates_[c.candidate];
        const Contact& contact = apply_sphere(candidate.sphere, c.depth, c.force, c.normal, scale, candidate.center, candidate.velocity,
                                              c.s * problem.shaft + tool.settings.radius * c.normal, force, lin);
        const ContactLinearization l = contact_linearization(c.force, h);
        block += l.axial * outer(c.normal) + l.transverse * Mat3::Identity();
        predicted += contact.force - h * (contact.stiffness * contact.velocity);
        last_.max_penetration = std::max(last_.max_penetration, c.depth);
    }
    tool.sphere_contacts = static_cast<uint32_t>(proxy_.contacts().size());
    if (problem.grasp.holding && result.grasp_taut) {
        const Vec3 gap = result.position - problem.grasp.point;
        const double length = gap.norm();
        const Vec3 n = gap / length;
        const double a = tool.settings.grasp_stiffness * problem.grasp.rest / length;
        const double b = tool.settings.grasp_stiffness * (1.0 - problem.grasp.rest / length);
        Contact contact;
        contact.weights = tool.grasp_point;
        contact.force = scale * result.grasp_force;
        contact.stiffness = scale * (a * outer(n) + b * Mat3::Identity());
        contact.damping = (scale * tool.settings.grasp_damping) * Mat3::Identity();
        contact.position = problem.grasp.point;
        contact.velocity = problem.grasp.velocity;
        contact.arm = Vec3::Zero();
        const double axial = h * h * a, transverse = h * tool.settings.grasp_damping + h * h * b;
        apply(contact, n, axial, transverse, scale, contact.stiffness * contact.velocity, force, lin);
        block += axial * outer(n) + transverse * Mat3::Identity();
        predicted += contact.force - h * (contact.stiffness * contact.velocity);
    }
    if (lin != nullptr && lin->border != nullptr) {
        // The proxy's balance at the end of the substep (bordered_system.h, docs/haptics.md):
        // h sum E_i e - B^T dv = h (F_c - sum g-hat_i), B = h sum W_i^T E_i.
        tool.body = lin->border->add_body(block, h * (result.coupling_force - predicted));
        tool.has_body = true;
        for (std::size_t k = tool.first_contact; k < contacts_.size(); ++k) {
            const Contact& contact = contacts_[k];
            lin->border->add_coupling(tool.body, contact.weights, h * (h * contact.stiffness + contact.damping));
        }
    }
}

Vec3 ToolsForce::last_force(std::size_t index) const {
    const Tool& tool = tools_[index];
    Vec3 total = Vec3::Zero();
    for (std::size_t k = tool.first_contact; k < tool.first_contact + tool.contact_count; ++k)
        total += contacts_[k].force;
    return -total;
}

void ToolsForce::evaluation_used(double duration, const mechanics::State* after) {
    log_.clear();
    for (std::size_t index = 0; index < tools_.size(); ++index) {
        Tool& tool = tools_[index];
        if (tool.removed) continue;
        // The proxy's motion over the substep, as the implicit step solved it with the bowel.
        const Vec3 proxy_move =
            after != nullptr && tool.has_body ? Vec3(duration * border_->solution(tool.body)) : Vec3::Zero();
        Vec3 received = Vec3::Zero(), torque = Vec3::Zero(), touched = Vec3::Zero();
        // The tip the arms start from, where this evaluation leaves it.
        const Vec3 tip = tool.evaluated_proxy + proxy_move;
        for (std::size_t k = tool.first_contact; k < tool.first_contact + tool.contact_count; ++k) {
            const Contact& contact = contacts_[k];
            Vec3 force = contact.force;
            if (after != nullptr) {
                // The linearised force at the end of the substep: F - H (dq - dp) - C (dv - dp / h).
                const Vec3 v = spline::evaluate(after->v.data(), contact.weights);
                const Vec3 moved = spline::evaluate(after->q.data(), contact.weights) - contact.position - proxy_move;
                const Vec3 sped = v - contact.velocity - proxy_move / duration;
                force -= contact.stiffness * moved + contact.damping * sped;
            }
            received += force;
            torque += contact.arm.cross(-force);
            if (contact.sphere == Contact::kGrasp) continue;
            touched += force;
            log_.add(contact.sphere, static_cast<uint32_t>(index), contact.depth, tip + contact.arm, contact.normal,
                     force);
        }
        tool.attempt_contact_impulse -= duration * touched;
        tool.attempt_contact_impulse_magnitude += duration * touched.norm();
        tool.impulse += duration * received;
        tool.angular_impulse += duration * torque;
        tool.duration += duration;
        tool.used_stiffness = tool.stiffness;
        tool.used_contacts = tool.sphere_contacts;
        // The proxy is where this evaluation put it (and moved with the bowel since).
        const Vec3 before = tool.proxy;
        tool.proxy = tool.evaluated_proxy + proxy_move;
        tool.proxy_velocity = tool.evaluated_proxy_velocity + (duration > 0.0 ? Vec3(proxy_move / duration) : Vec3::Zero());
        tool.proxy_time = tool.evaluated_time;
        tool.proxy_travel += (tool.proxy - before).norm();
    }
}

double ToolsForce::potential_energy(const mechanics::State& state) const {
    spheres_.update(state.q.data());
    const double r = spheres_.radius();
    double energy = 0.0;
    for (const Tool& tool : tools_) {
        if (tool.removed) continue;
        // The capsule the bowel meets: the proxy where it rests now (with the commanded
        // orientation), or the commanded pose itself.
        const Segment segment = segment_at(tool, state.time);
        const bool proxy = tool.settings.mode == ToolMode::proxy;
        const Vec3 tip = proxy ? tool.proxy : segment.tip;
        const Shaft shaft(tip, tip + (segment.tail - segment.tip), tool.settings.radius + r);
        double stored = 0.0, total_magnitude = 0.0;
        for (std::size_t i = 0; i < spheres_.size(); ++i) {
            double s, dist2;
            Vec3 d;
            if (!shaft.touches(spheres_[i].center, &s, &d, &dist2)) continue;
            const double depth = shaft.reach - std::sqrt(dist2);
            if (!(depth > 0.0)) continue;
            stored += 0.5 * tool.contact.stiffness * depth * depth;
            total_magnitude += tool.contact.stiffness * depth;
        }
        // The spring energy as far as the bound lets the contacts push (evaluate's scale); the
        // proxy's contacts never push harder than max_force in all.
        energy += !proxy && total_magnitude > tool.settings.max_force
                      ? stored * tool.settings.max_force / total_magnitude
                      : stored;
        // A grasp that slipped in this step holds no spring at its end: the guard must not
        // count the energy of the spring it let go of, however far the jump stretched it.
        if (tool.grasping && !tool.slipped) {
            const Vec3 p = spline::evaluate(state.q.data(), tool.grasp_point);
            const double stretch = std::max(0.0, (tip - p).norm() - grasp_rest(tool, state.time));
            energy += 0.5 * tool.settings.grasp_stiffness * stretch * stretch;
        }
    }
    return energy;
}

void ToolsForce::grasp(Tool& tool, const mechanics::State& state) {
    spheres_.update(state.q.data());
    const double reach = tool.settings.radius + spheres_.radius() + tool.settings.grasp_margin;
    // Where the tool rests: the proxy's tip (the commanded tip in direct mode).
    const Vec3 tip = tool.settings.mode == ToolMode::proxy ? tool.proxy : tool.current.position;
    double best = reach * reach;
    bool found = false;
    for (std::size_t i = 0; i < spheres_.size(); ++i) {
        const double d2 = (spheres_[i].center - tip).squaredNorm();
        if (d2 <= best) {
            best = d2;
            tool.grasp_point = spheres_[i].weights;
            tool.grasp_sphere = static_cast<uint32_t>(i);
            found = true;
        }
    }
    if (found) {
        tool.grasping = true;
        // The spring starts slack wherever the held point is (no jolt), then closes.
        tool.grasp_rest = std::max(tool.settings.radius + spheres_.radius(), std::sqrt(best));
    }
}

void ToolsForce::add_stiffness_bound(numerics::ScalarBandMatrix& bound) const {
    double stiffness = 0.0;
    for (const Tool& tool : tools_)
        if (!tool.removed) stiffness += tool.contact.stiffness + tool.settings.grasp_stiffness;
    spheres_.add_weight_products(stiffness, bound);
}

void ToolsForce::add_damping_bound(numerics::ScalarBandMatrix& bound) const {
    double damping = 0.0;
    for (const Tool& tool : tools_)
        if (!tool.removed)
            damping += tool.contact.damping + friction_damping_bound(tool.contact, spheres_.radius()) +
                       tool.settings.grasp_damping;
    spheres_.add_weight_products(damping, bound);
}

void ToolsForce::add_contacts(mechanics::ContactSummary& summary) const {
    summary.count += last_.count;
    summary.max_penetration = std::max(summary.max_penetration, last_.max_penetration);
}

double ToolsForce::external_work_bound() const {
    if (!(step_dt_ > 0.0)) return 0.0;
    double work = 0.0;
    for (const Tool& tool : tools_) {
        if (tool.removed) continue;
        const double tip_move = (tool.target.position - tool.current.position).norm();
        const double tail_move =
            (tail_of(tool.target, tool.settings.length) - tail_of(tool.current, tool.settings.length)).norm();
        // Every point of the shaft moves at most as far as its ends (twice that for the
        // arc of a turn and the contact damping's share). A proxy goes its own way: the
        // length of its tip's path, and how far the turn of the shaft moved its back end.
        const double turn = (tail_of(tool.target, tool.settings.length) - tool.target.position -
                             (tail_of(tool.current, tool.settings.length) - tool.current.position))
                                .norm();
        const double move = tool.settings.mode == ToolMode::proxy ? tool.proxy_travel + turn
                                                                   : std::max(tip_move, tail_move);
        work += 2.0 * tool.settings.max_force * move;
    }
    return work;
}

bool ToolsForce::take_commands(const mechanics::State& state, double dt) {
    bool grasp_changed = false;
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        Tool& tool = tools_[i];
        if (tool.removed) continue;
        ToolMailbox& mailbox = *channels_.mailbox(i);
        mailbox.take_pose(tool.target);
        switch (mailbox.take_grasp()) {
            case ToolMailbox::Grasp::none: break;
            case ToolMailbox::Grasp::grasp: grasp(tool, state); grasp_changed = true; break;
            case ToolMailbox::Grasp::release: tool.grasping = false; grasp_changed = true; break;
        }
        tool.step_proxy = tool.proxy;
        tool.step_proxy_velocity = tool.proxy_velocity;
        tool.step_proxy_time = tool.proxy_time;
    }
    step_start_ = state.time;
    step_dt_ = dt;
    return grasp_changed;
}

void ToolsForce::begin_attempt() {
    for (Tool& tool : tools_) {
        tool.slipped = false;
        tool.proxy = tool.step_proxy;
        tool.proxy_velocity = tool.step_proxy_velocity;
        tool.proxy_time = tool.step_proxy_time;
        tool.proxy_travel = 0.0;
        tool.impulse = tool.angular_impulse = tool.attempt_contact_impulse = Vec3::Zero();
        tool.duration = tool.attempt_contact_impulse_magnitude = 0.0;
    }
}

void ToolsForce::end_step(bool accepted) {
    std::pmr::vector<ToolOutput>& outputs = channels_.outputs();
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        Tool& tool = tools_[i];
        if (tool.removed) continue;
        if (accepted) {
            if (tool.slipped) tool.grasping = false;
            // Minus what the bowel received over the step, then the port's passivity.
            ToolWrench received;
            if (tool.duration > 0.0) {
                received.force = -tool.impulse / tool.duration;
                received.torque = tool.angular_impulse / tool.duration;
            }
            // A device's safety: never more than max_force. Only where the proxy is not solved
            // with the bowel (clamped ends, bdf2's second-order substeps) can minus what the
            // bowel received exceed it (docs/haptics.md "The wrench"). Clipped before the
            // observer, so that its balance counts the work of the force rendered.
            const double magnitude = received.force.norm();
            if (magnitude > tool.settings.max_force) received.force *= tool.settings.max_force / magnitude;
            const Vec3 displacement = tool.target.position - tool.current.position;
            const Vec3 rotation = rotation_between(tool.current.orientation, tool.target.orientation);
            tool.wrench = tool.observer.observe(received, displacement, rotation, tool.settings.max_force,
                                                tool.settings.passivity_limiter);
            tool.accepted_stiffness = tool.used_stiffness;
            tool.contacts = tool.used_contacts;
            tool.current = tool.target;
            tool.grasp_rest = grasp_rest(tool, step_start_ + step_dt_);
            tool.contact_impulse += tool.attempt_contact_impulse;
            tool.contact_impulse_magnitude += tool.attempt_contact_impulse_magnitude;
        } else {
            tool.proxy = tool.step_proxy;
            tool.proxy_velocity = tool.step_proxy_velocity;
            tool.proxy_time = tool.step_proxy_time;
        }
        tool.slipped = false;
        write_output(tool, outputs[i]);
    }
    step_dt_ = 0.0;
}

void ToolsForce::write_output(const Tool& tool, ToolOutput& output) {
    output.wrench = tool.wrench;
    output.grasping = tool.grasping;
    output.contacts = tool.contacts;
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(output.stiffness.data()) = tool.accepted_stiffness;
    output.commanded = tool.current;
    output.proxy.position = tool.proxy;
    output.proxy.orientation = tool.current.orientation;
    output.stats = tool.observer.stats();
    output.grasp_sphere = tool.grasp_sphere;
    output.contact_impulse = tool.contact_impulse;
    output.contact_impulse_magnitude = tool.contact_impulse_magnitude;
}

namespace {

void save_pose(StateWriter& out, const ToolPose& pose) {
    out.f64s(pose.position.data(), 3);
    out.f64s(pose.orientation.data(), 4);
}

ToolPose restore_pose(StateReader& in, const char* what) {
    ToolPose pose;
    in.f64s(what, 3, pose.position.data());
    in.f64s(what, 4, pose.orientation.data());
    if (!(std::fabs(Eigen::Map<const Vec4>(pose.orientation.data()).norm() - 1.0) <= 1e-9))
        in.fail(std::string(what) + ": the orientation is not a unit quaternion");
    return pose;
}

void save_mat3(StateWriter& out, const Mat3& m) { out.f64s(m.data(), 9); }

}  // namespace

// Between steps a tool's state is its poses, grasp, proxy (where the last evaluation used
// left it), accepted outputs, passivity observer and impulses; the rest is rebuilt by the
// next step (the attempt's sums, the evaluation's contacts).
void ToolsForce::save_state(StateWriter& out) const {
    out.begin_section("tools", 3);
    out.u32(static_cast<uint32_t>(tools_.size()));
    for (const Tool& tool : tools_) {
        out.u8(tool.removed ? 1 : 0);
        save_pose(out, tool.current);
        save_pose(out, tool.target);
        out.u8(tool.grasping ? 1 : 0);
        out.u32(static_cast<uint32_t>(tool.grasp_point.first));
        out.f64s(tool.grasp_point.w.data(), 4);
        out.u32(tool.grasp_sphere);
        out.f64(tool.grasp_rest);
        out.f64s(tool.proxy.data(), 3);
        out.f64s(tool.proxy_velocity.data(), 3);
        out.f64(tool.proxy_time);
        save_mat3(out, tool.stiffness);
        out.f64s(tool.wrench.force.data(), 3);
        out.f64s(tool.wrench.torque.data(), 3);
        save_mat3(out, tool.accepted_stiffness);
        out.u32(tool.contacts);
        tool.observer.save_state(out);
        out.f64s(tool.contact_impulse.data(), 3);
        out.f64(tool.contact_impulse_magnitude);
    }
    out.u32(last_.count);
    out.f64(last_.max_penetration);
    log_.save_state(out);
    out.end_section();
}

void ToolsForce::restore_state(StateReader& in) {
    // Version 1 (before the proxy) cannot give a proxy's state: refused as too old.
    const uint32_t version = in.begin_section("tools", 3);
    if (version < 2) in.fail("saved before tools had proxies (version 1); save it again");
    if (in.u32("tools") != tools_.size()) in.fail("saved with another number of tools");
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        Tool& tool = tools_[i];
        Tool saved = tool;
        if (in.flag("tool removed") != tool.removed)
            in.fail("tool " + std::to_string(i) + (tool.removed ? " was removed from this scene but not from the saved one"
                                                                 : " was removed from the saved scene but not from this one"));
        saved.current = restore_pose(in, "tool pose");
        saved.target = restore_pose(in, "tool target pose");
        saved.grasping = in.flag("grasping");
        saved.grasp_point.first = in.index("first control point grasped", spheres_.control_points() - 3);
        in.f64s("grasp weights", 4, saved.grasp_point.w.data());
        saved.grasp_sphere = in.index("sphere grasped", spheres_.size());
        // Version 2 held the point on the tool's surface from the start.
        saved.grasp_rest = version >= 3 ? in.f64("grasp rest length") : tool.settings.radius + spheres_.radius();
        if (!(saved.grasp_rest >= tool.settings.radius + spheres_.radius()) || !std::isfinite(saved.grasp_rest))
            in.fail("grasp rest length shorter than the tool's radius plus the bowel's, or not finite");
        in.f64s("proxy position", 3, saved.proxy.data());
        in.f64s("proxy velocity", 3, saved.proxy_velocity.data());
        saved.proxy_time = in.f64("proxy time");
        in.f64s("tool stiffness", 9, saved.stiffness.data());
        in.f64s("tool force", 3, saved.wrench.force.data());
        in.f64s("tool torque", 3, saved.wrench.torque.data());
        in.f64s("published tool stiffness", 9, saved.accepted_stiffness.data());
        saved.contacts = in.count("tool contacts", spheres_.size());
        PassivityObserver::restore_state(in, saved.observer);
        in.f64s("contact impulse", 3, saved.contact_impulse.data());
        saved.contact_impulse_magnitude = in.f64("contact impulse magnitude");
        saved.step_proxy = saved.proxy;
        saved.step_proxy_velocity = saved.proxy_velocity;
        saved.step_proxy_time = saved.proxy_time;
        saved.slipped = false;
        if (!in.checking()) tool = saved;
    }
    const uint32_t contacts = in.count("contacts", spheres_.size() * (tools_.size() + 1));
    const double max_penetration = in.f64("deepest contact");
    log_.restore_state(in, spheres_.size(), tools_.size());
    in.end_section();
    if (in.checking()) return;
    last_ = {contacts, max_penetration};
    for (std::size_t i = 0; i < tools_.size(); ++i)
        if (!tools_[i].removed) write_output(tools_[i], channels_.outputs()[i]);
}

}  // namespace enteron::collision
