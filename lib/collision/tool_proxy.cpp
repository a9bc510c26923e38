// SPDX-License-Identifier: Apache-2.0
#include "collision/tool_proxy.h"

#include <cmath>
#include <Eigen/LU>

#include "collision/shaft_contact.h"

namespace enteron::collision {

namespace {

// How far the continuous collision lets the proxy into a sphere it meets: a contact that has
// just begun, so that Newton's next step sees its stiffness (a fraction of the reach).
constexpr double kFirstTouchDepth = 1e-6;
// Longest Newton step while the proxy touches the bowel (a fraction of the reach): the
// contacts' linearisation holds for short steps around a curved surface.
constexpr double kLongestContactStep = 0.25;
// The line search along a Newton step (backtracking, Armijo's rule on |residual|): a step
// of length alpha is taken once it shrinks the residual by at least kSufficientDecrease
// alpha of it. The Newton step goes downhill on |residual|^2 wherever the Jacobian is
// the derivative, so halving finds such a step unless the balance has a kink there (a
// contact's onset, a sphere's centre on the shaft's axis) or Newton heads for a balance
// deep inside the bowel that the contacts' negative stiffness makes (pressed far in from a
// cold start). After the budget's max_halvings the proxy relaxes instead: a step along the
// net force on it, residual / (the stiffness holding it), the way a massless body let go
// would move.
constexpr double kSufficientDecrease = 1e-4;

// The fraction of `step` the shaft at p can go before it first reaches a sphere it does
// not touch yet, just inside it (continuous collision). A sphere it touches is already in
// the balance, however shallow: a step stopped at its first touch leaves it within
// rounding of the stop radius, where first_touch would stop every later step too.
double free_fraction(const ProxyProblem& problem, const std::pmr::vector<ProxyCandidate>& candidates, const Vec3& p,
                     const Vec3& step) {
    const Shaft shaft(p, p + problem.shaft, problem.reach, problem.blade);
    // Within the step (t <= 1) the shaft comes no closer to a centre than the centre's
    // distance to the box around it less the step's length: a centre outside the box
    // widened by the step (and a hundredth of the reach, for rounding) cannot be met, and
    // first_touch is not asked about it.
    const Shaft swept(p, p + problem.shaft, 1.01 * problem.reach + step.norm(), problem.blade);
    double first = 1.0;
    for (const ProxyCandidate& candidate : candidates) {
        if (!swept.in_box(candidate.center)) continue;
        ShaftPoint at;
        double distance2;
        Vec3 d;
        const double reach = problem.reach - candidate.thinner;
        if (shaft.touches(candidate.center, &at, &d, &distance2) && distance2 < reach * reach) continue;
        const double t = shaft.first_touch(candidate.center, step, reach - kFirstTouchDepth * problem.reach);
        if (t > 0.0) first = std::min(first, t);
    }
    return first;
}

// Solves J x = r for a 3 x 3 J that may be (nearly) singular: a direction nothing holds
// (a saturated coupling across a frictionless contact) gets a tiny stiffness instead.
template <int Columns>
Eigen::Matrix<double, 3, Columns> solve3(const Mat3& jacobian, const Eigen::Matrix<double, 3, Columns>& r) {
    const double scale = jacobian.cwiseAbs().maxCoeff();
    Mat3 j = jacobian;
    if (!(std::fabs(j.determinant()) > 1e-12 * scale * scale * scale)) j += (1e-6 * scale + 1e-12) * Mat3::Identity();
    return j.partialPivLu().solve(r);
}

}  // namespace

ToolProxy::ToolProxy(std::pmr::memory_resource* memory) : contacts_(memory) {}

void ToolProxy::reserve(std::size_t spheres) { contacts_.reserve(spheres); }

Vec3 ToolProxy::balance(const ProxyProblem& problem, const std::pmr::vector<ProxyCandidate>& candidates,
                        const Vec3& p, ProxyResult& result, Mat3& jacobian) {
    const double rate = problem.dt > 0.0 ? 1.0 / problem.dt : 0.0;  // d(v_p)/dp
    const Vec3 vp = problem.dt > 0.0 ? Vec3((p - problem.start) * rate) : problem.start_velocity;
    const Shaft shaft(p, p + problem.shaft, problem.reach, problem.blade);
    contacts_.clear();
    Vec3 given = Vec3::Zero();  // to the bowel
    Mat3 given_rate = Mat3::Zero();  // d(given)/dp
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        const ProxyCandidate& candidate = candidates[k];
        ShaftContact touch;
        if (!shaft_contact(shaft, candidate.center, &touch)) continue;
        touch.depth -= candidate.thinner;  // the shaft reaches as far as the largest sphere
        if (!(touch.depth > 0.0)) continue;
        ProxyContact contact;
        contact.candidate = k;
        contact.depth = touch.depth;
        contact.s = touch.at.s;
        contact.w = touch.at.w;
        contact.normal = touch.normal;
        Vec3 relative = candidate.velocity - (vp + touch.at.s * problem.shaft_velocity);
        if (touch.at.w != 0.0) relative -= touch.at.w * problem.side_velocity;
        contact.force = contact_force(problem.contact, contact.depth, contact.normal, relative);
        contact.jacobian = shaft_contact_jacobian(problem.contact, touch, contact.force, relative);
        given += contact.force.force;
        // v_p moves with (p - p0) / dt.
        given_rate += shaft_contact_rate(contact.jacobian, touch, shaft, problem.shaft_velocity, rate, problem.side_velocity);
        contacts_.push_back(contact);
    }
    result.grasp = GraspSpring{};
    if (problem.grasp.holding) {
        const ProxyGrasp& g = problem.grasp;
        result.grasp = grasp_spring(g.law, g.rest, p, vp, g.point, g.velocity);
        if (result.grasp.taut) given_rate += grasp_tip_rate(result.grasp, g.law, rate);
        given += result.grasp.force;
    }
    // The coupling and its bound.
    const Vec3 raw = problem.coupling_stiffness * (problem.target - p) + problem.coupling_damping * (problem.target_velocity - vp);
    const double magnitude = raw.norm();
    Mat3 bound = Mat3::Identity();  // d(F_c)/d(raw)
    result.saturated = magnitude > problem.max_force;
    result.coupling_force = raw;
    if (result.saturated) {
        const Vec3 u = raw / magnitude;
        result.coupling_force = problem.max_force * u;
        bound = (problem.max_force / magnitude) * (Mat3::Identity() - u * u.transpose());
    }
    result.position = p;
    result.velocity = vp;
    result.evaluations += 1;
    bound_ = bound;
    raw_ = raw;
    jacobian = (problem.coupling_stiffness + problem.coupling_damping * rate) * bound + given_rate;
    const Vec3 residual = result.coupling_force - given;
    result.residual = residual.norm();
    return residual;
}

ProxyResult ToolProxy::solve(const ProxyProblem& problem, const std::pmr::vector<ProxyCandidate>& candidates) {
    ProxyResult result;
    Mat3 jacobian;
    Vec3 p = problem.start;
    Vec3 residual = balance(problem, candidates, p, result, jacobian);
    const double tolerance = kTolerance * problem.max_force;
    const double rate = problem.dt > 0.0 ? 1.0 / problem.dt : 0.0;  // d(v_p)/dp
    int iteration = 0;
    for (; iteration < problem.budget.max_iterations && !(result.residual <= tolerance); ++iteration) {
        const bool touching = !contacts_.empty();
        // Touching nothing, the proxy rests where the unbounded coupling force is zero, a
        // linear equation: one step, whatever the bound (whose Jacobian is singular along
        // a saturated force).
        const double coupling_rate = problem.coupling_stiffness + problem.coupling_damping * rate;
        Vec3 step = touching || result.grasp.taut ? solve3<1>(jacobian, residual) : Vec3(raw_ / coupling_rate);
        if (!step.allFinite()) break;
        const double longest = kLongestContactStep * problem.reach;
        // The proxy let go: it moves along the net force on it, residual / (the stiffness
        // holding it), no farther than a Newton step may.
        const auto relaxation = [&] {
            const double holding = coupling_rate + (problem.grasp.holding ? problem.grasp.law.stiffness : 0.0);
            const Vec3 relax = residual / holding;
            return relax.norm() > longest ? Vec3(relax * (longest / relax.norm())) : relax;
        };
        // Newton against the net force on the proxy heads for a balance deep inside the
        // bowel (the contacts' negative stiffness about a sphere's centre): relax instead.
        const bool uphill = touching && !(step.dot(residual) > 0.0);
        if (uphill) step = relaxation();
        if (touching && step.norm() > longest) step *= longest / step.norm();
        // Continuous collision: stop where the shaft first reaches a sphere it does not touch.
        const double first = free_fraction(problem, candidates, p, step);
        step *= first;
        // The line search along a Newton step (a step stopped at a first touch is taken as
        // it is: the sphere it meets joins the balance at the next iteration).
        const double before = result.residual;
        Vec3 trial = p + step;
        Vec3 trial_residual = balance(problem, candidates, trial, result, jacobian);
        const auto descended = [&](double alpha) {
            return result.residual <= (1.0 - kSufficientDecrease * alpha) * before;
        };
        if (!uphill && first == 1.0) {
            double alpha = 1.0;
            for (int halving = 0; halving < problem.budget.max_halvings && !descended(alpha); ++halving) {
                alpha *= 0.5;
                trial = p + alpha * step;
                trial_residual = balance(problem, candidates, trial, result, jacobian);
            }
            if (!descended(alpha)) {
                Vec3 relax = relaxation();
                relax *= free_fraction(problem, candidates, p, relax);
                trial = p + relax;
                trial_residual = balance(problem, candidates, trial, result, jacobian);
            }
        }
        p = trial;
        residual = trial_residual;
    }
    result.iterations = iteration;
    result.balanced = result.residual <= tolerance;
    // d(-F_c)/dx at rest: F_c moves with x directly (v_x held) and through p, which follows
    // dp/dx = J^-1 dF_c/dx so that the balance holds.
    const Mat3 direct = problem.coupling_stiffness * bound_;
    const Mat3 through = (problem.coupling_stiffness + problem.coupling_damping * rate) * bound_;
    // Touching nothing, the coupling force is zero wherever the device is.
    const bool free = contacts_.empty() && !result.grasp.taut;
    result.device_stiffness = free ? Mat3::Zero() : Mat3(-(direct - through * solve3<3>(jacobian, direct)));
    return result;
}

}  // namespace enteron::collision
