// SPDX-License-Identifier: Apache-2.0
// A tool's proxy (a god-object, Zilles and Salisbury 1995): the massless capsule the bowel
// meets, joined to the commanded tip (the device) by a virtual coupling (Colgate et al.
// 1995), a spring k_c and a damper b_c whose force is bounded by max_force:
//
//   F_c = bound(k_c (x - p) + b_c (v_x - v_p)),   bound(f) = f min(1, max_force / |f|)
//
// with x, v_x the commanded tip and its velocity and p, v_p the proxy's. The proxy's
// contacts with the bowel's collision spheres follow the scene's penalty law with a stiffer
// spring (so that max_force on one sphere presses the proxy at most R / 10 in) and the
// tool's friction, at the proxy's velocity v_p = (p - p0) / dt over the time dt since it
// was at p0. Being massless, it rests where the coupling and its contacts balance:
//
//   F_c(p) = sum_i g_i(p) + g_grasp(p)        (g: the forces the proxy gives the bowel)
//
// solve() finds that p with the bowel held where it is: Newton's method from p0, each step
// no longer than a quarter of the reach and stopped where it would first touch another
// sphere (continuous collision: the proxy never passes through the bowel, however far the
// device went). The device feels -F_c, which is what the bowel receives.
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "collision/contact_model.h"
#include "collision/tool_grasp.h"
#include "collision/tool_shaft.h"

namespace enteron::collision {

// A collision sphere near the proxy: its index, centre and velocity (m, m/s).
struct ProxyCandidate {
    std::size_t sphere;
    Vec3 center;
    Vec3 velocity;
    // How much less far it reaches than ProxyProblem::reach assumes (a radius profile's
    // thinner part: the largest radius minus its own), m; 0 without a profile.
    double thinner = 0.0;
};

// The grasp, when it holds: the spring of tool_grasp.h from the held axis point to the
// proxy's tip.
struct ProxyGrasp {
    bool holding = false;
    Vec3 point = Vec3::Zero();     // m
    Vec3 velocity = Vec3::Zero();  // m/s
    double rest = 0.0;             // m
    GraspLaw law;
};

// The solve's budgets, which bound its work (docs/performance.md, "The worst case"): Newton
// iterations, and halvings of each iteration's line search. An iteration evaluates the
// balance at most max_halvings + 2 times (its step, each halving, the relaxation after the
// last), a solve at most 1 + max_iterations (max_halvings + 2) times: 769 with the defaults.
// Out of iterations, the proxy rests where the last one left it (ProxyResult::balanced
// false): on the bowel, never through it, since every move stops at the first sphere it
// meets, with the coupling force within max_force, as always; the implicit step then
// balances it with the bowel (its border body), the explicit ones scale its contacts'
// forces to the bound.
struct ProxyBudget {
    int max_iterations = 64;  // enough for a cold start far inside the bowel (test_tool_proxy.cpp)
    int max_halvings = 10;
    int most_evaluations() const { return 1 + max_iterations * (max_halvings + 2); }
};

struct ProxyProblem {
    Vec3 shaft = Vec3::Zero();           // tail - tip at this instant, m (the commanded orientation)
    Vec3 shaft_velocity = Vec3::Zero();  // its rate of change, m/s (a turning tool)
    Blade blade;                         // a retractor's blade at the tip (tool_shaft.h): its side turns with the tool
    Vec3 side_velocity = Vec3::Zero();   // the blade's side's rate of change, m/s
    double reach = 0.0;                  // the tool's radius plus R, m
    ContactParameters contact;           // the proxy's contact law
    double coupling_stiffness = 0.0;     // k_c, N/m
    double coupling_damping = 0.0;       // b_c, N s/m
    double max_force = 0.0;              // N
    Vec3 start = Vec3::Zero();           // p0, the proxy's tip dt ago, m
    Vec3 start_velocity = Vec3::Zero();  // the proxy's velocity when dt is 0, m/s
    Vec3 target = Vec3::Zero();          // x, m
    Vec3 target_velocity = Vec3::Zero(); // v_x, m/s
    double dt = 0.0;                     // s; 0: v_p is held at start_velocity
    ProxyGrasp grasp;
    ProxyBudget budget;
};

// A contact of the proxy with a sphere at the proxy's rest position.
struct ProxyContact {
    std::size_t candidate;  // index in the candidates
    double depth;           // m
    double s;               // shaft parameter of the closest point, in [0, 1]
    double w;               // across the blade, in [-1, 1]; 0 on the shaft
    Vec3 normal;            // out of the proxy, towards the sphere's centre
    ContactForce force;     // on the bowel
    ContactJacobian jacobian;
};

struct ProxyResult {
    Vec3 position = Vec3::Zero();        // p, the proxy's tip, m
    Vec3 velocity = Vec3::Zero();        // v_p, m/s
    Vec3 coupling_force = Vec3::Zero();  // F_c on the proxy (towards the device), N, bounded
    bool saturated = false;              // |k_c (x - p) + b_c (v_x - v_p)| > max_force
    GraspSpring grasp;                   // the grasp's spring at p (its force on the bowel)
    Mat3 device_stiffness = Mat3::Zero();  // d(-F_c)/dx with v_x held, N/m
    int iterations = 0;
    int evaluations = 0;    // of the balance: the start's, each iteration's step, halvings and relaxation
    double residual = 0.0;  // |F_c - sum of the forces given to the bowel|, N
    bool balanced = false;  // residual within kTolerance max_force (else the budget ran out)
};

class ToolProxy {
public:
    // Newton stops when the forces balance to this fraction of max_force.
    static constexpr double kTolerance = 1e-10;

    explicit ToolProxy(std::pmr::memory_resource* memory);
    // Room for contacts with `spheres` spheres. Allocates.
    void reserve(std::size_t spheres);

    // Where the proxy rests (see above); its contacts at that position in contacts().
    // Allocates nothing.
    ProxyResult solve(const ProxyProblem& problem, const std::pmr::vector<ProxyCandidate>& candidates);
    const std::pmr::vector<ProxyContact>& contacts() const { return contacts_; }

private:
    // The contacts, forces and residual at p; returns the residual F_c - sum g and fills
    // `jacobian` with -d(residual)/dp.
    Vec3 balance(const ProxyProblem& problem, const std::pmr::vector<ProxyCandidate>& candidates, const Vec3& p,
                 ProxyResult& result, Mat3& jacobian);

    std::pmr::vector<ProxyContact> contacts_;
    Mat3 bound_ = Mat3::Identity();  // d(F_c)/d(unbounded coupling force) at the last balance
    Vec3 raw_ = Vec3::Zero();        // the unbounded coupling force at the last balance, N
};

// The proxy's contact stiffness per sphere: max_force on one sphere presses the proxy
// R / 10 into the tube, and never softer than the scene's contacts.
inline double proxy_contact_stiffness(double scene_stiffness, double max_force, double bowel_radius) {
    return std::max(scene_stiffness, max_force / (0.1 * bowel_radius));
}

}  // namespace enteron::collision
