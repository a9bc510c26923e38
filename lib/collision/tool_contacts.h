// SPDX-License-Identifier: Apache-2.0
// The contacts of one evaluation of the tools (tools_force.h), every tool's in one list: a
// collision sphere touching a tool, or a tool's grasp spring, each with the force the bowel
// receives, the blocks of its linearisation (H, C) and where it acts. Each is added to the
// bowel's generalised forces and, in an implicit evaluation, to the implicit system as it is
// made; the list stays for what comes after the solve: the proxy's border body
// (tool_proxy_contacts.h) and the account of what the bowel received (tool_outputs.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "collision/contact_model.h"
#include "collision/tool_grasp.h"
#include "mechanics/effect.h"
#include "spline/catmull_rom.h"

namespace enteron::collision {

struct ToolContact {
    static constexpr uint32_t kGrasp = ~uint32_t{0};
    uint32_t sphere = kGrasp;     // the collision sphere touched; kGrasp for the grasp's spring
    double depth = 0.0;           // m
    Vec3 normal = Vec3::UnitZ();  // from the tool to the sphere
    spline::SegmentWeights weights;
    Vec3 force;      // on the bowel, N
    Mat3 stiffness;  // H of the implicit system, N/m
    Mat3 damping;    // C of the implicit system, N s/m
    Vec3 position;   // of the bowel's point at the evaluation, m
    Vec3 velocity;   // of the bowel's point at the evaluation, m/s
    Vec3 arm;        // from the tool's tip to where the force acts on the tool, m
};

class ToolContacts {
public:
    explicit ToolContacts(std::pmr::memory_resource* memory) : contacts_(memory) {}
    // Room for `count` contacts. Allocates.
    void reserve(std::size_t count) { contacts_.reserve(count); }

    // Starts an evaluation whose forces go into `force` (3n values) and, with `lin`, into the
    // implicit system; forgets the last one's contacts.
    void begin(double* force, const mechanics::Linearization* lin);
    // The substep of the implicit evaluation, s (0 for an explicit one).
    double h() const { return lin_ != nullptr ? lin_->h : 0.0; }
    const mechanics::Linearization* linearization() const { return lin_; }

    // Collision sphere `sphere` (its weights, centre `position` and velocity) touching a
    // tool `depth` deep along `normal`, with the law's force `law` scaled by `scale`; `arm`
    // from the tool's tip to the contact point on its surface.
    const ToolContact& add_sphere(uint32_t sphere, const spline::SegmentWeights& weights, double depth,
                                  const ContactForce& law, const Vec3& normal, double scale, const Vec3& position,
                                  const Vec3& velocity, const Vec3& arm);
    // A taut grasp spring (tool_grasp.h) holding the axis point of `weights` (at `position`,
    // moving at `velocity`), its force scaled by `scale`.
    const ToolContact& add_grasp(const GraspSpring& spring, const GraspLaw& law, const spline::SegmentWeights& weights,
                                 double scale, const Vec3& position, const Vec3& velocity);

    std::size_t size() const { return contacts_.size(); }
    const ToolContact& operator[](std::size_t k) const { return contacts_[k]; }
    // The sphere contacts of the evaluation and the deepest of them (for ent_stats).
    const mechanics::ContactSummary& summary() const { return summary_; }

private:
    // Adds `contact` (its force, H and C already scaled) to the bowel's forces and, with an
    // implicit evaluation, its block scale (blocks.axial n n^T + blocks.transverse I) along
    // `normal` and its H v to the implicit system; then to the list.
    const ToolContact& add(const ToolContact& contact, const ContactLinearization& blocks, double scale,
                           const Vec3& stiffness_times_velocity);

    std::pmr::vector<ToolContact> contacts_;
    double* force_ = nullptr;
    const mechanics::Linearization* lin_ = nullptr;
    mechanics::ContactSummary summary_;
};

}  // namespace enteron::collision
