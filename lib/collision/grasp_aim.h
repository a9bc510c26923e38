// SPDX-License-Identifier: Apache-2.0
// What a grasp takes (ent_tool_grasp): the collision sphere that lies between the tool's
// jaws along its aim. The jaws are the last `length` metres of the shaft from the tip,
// opening `opening` wide across the tool's local x axis: what they close on lies in the
// strip they sweep, the rectangle tip to tip + length a (a the shaft's unit axis) by
// -opening/2 to +opening/2 along x. A centre is a candidate within the reach (the tool's
// radius, the sphere's and the grasp margin) of that rectangle; candidates rank by how far
// they lie off the strip seen along the aim (their distance from the plane of the jaws,
// and beyond the opening across it; not how far ahead of the tip), ties going to the
// surface nearer to the tip. So a loop in the jaws' plane is taken before a nearer one beside
// them, and the loop under the jaws before one higher up a slope beside them: a surgeon
// aims by placing the jaws over a loop and turning them onto it. Without jaws (no length,
// no opening) the candidate whose surface is nearest the tip is taken (with one radius,
// the nearest centre: the first tools' rule).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "base/geometry.h"

namespace enteron::collision {

struct Jaws {
    Vec3 tip = Vec3::Zero();
    Vec3 axis = Vec3::UnitZ();     // unit, from the tip back along the shaft
    Vec3 across = Vec3::UnitX();   // unit, the direction the jaws open in (local x)
    double length = 0.0;           // m
    double half_opening = 0.0;     // m

    bool has_jaws() const { return length > 0.0 || half_opening > 0.0; }

    // |p - the point of the jaws' rectangle nearest p|^2.
    double distance2(const Vec3& p) const {
        const Vec3 rel = p - tip;
        const double along = std::clamp(rel.dot(axis), 0.0, length);
        const double side = std::clamp(rel.dot(across), -half_opening, half_opening);
        return (rel - along * axis - side * across).squaredNorm();
    }

    // |p off the jaws' strip, seen along the aim|^2: its part square to the axis, less the
    // part across within the opening.
    double off_aim2(const Vec3& p) const {
        const Vec3 rel = p - tip;
        const double side = std::clamp(rel.dot(across), -half_opening, half_opening);
        return (rel - rel.dot(axis) * axis - side * across).squaredNorm();
    }
};

// Picks among candidates offered one at a time: offer() each sphere's index, centre and
// radius; the pick is the one between the jaws along the aim, as above. Without jaws the
// one whose surface is nearest the tip (with equal radii, the nearest centre).
class GraspAim {
public:
    GraspAim(const Jaws& jaws, double tool_radius, double margin)
        : jaws_(jaws), tool_radius_(tool_radius), margin_(margin) {}

    void offer(std::size_t index, const Vec3& center, double radius) {
        const double reach = tool_radius_ + radius + margin_;
        const double jaws2 = jaws_.distance2(center);
        if (!(jaws2 <= reach * reach)) return;  // beyond the reach (or NaN: never picked)
        const double tip2 = (center - jaws_.tip).squaredNorm();
        const double gap = std::sqrt(tip2) - (tool_radius_ + radius);  // its surface from the tool's tip
        const double rank = jaws_.has_jaws() ? jaws_.off_aim2(center) : gap;
        if (rank > best_rank_ || (rank == best_rank_ && gap > best_gap_)) return;
        best_rank_ = rank;
        best_gap_ = gap;
        best_tip2_ = tip2;
        picked_ = index;
        found_ = true;
    }

    bool found() const { return found_; }
    std::size_t picked() const { return picked_; }
    // |centre - tip|^2 of the pick: where the grasp's spring starts.
    double picked_tip_distance2() const { return best_tip2_; }

private:
    Jaws jaws_;
    double tool_radius_, margin_;
    double best_rank_ = std::numeric_limits<double>::infinity();
    double best_gap_ = std::numeric_limits<double>::infinity();
    double best_tip2_ = 0.0;
    std::size_t picked_ = 0;
    bool found_ = false;
};

}  // namespace enteron::collision
