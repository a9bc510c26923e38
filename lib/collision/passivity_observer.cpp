// SPDX-License-Identifier: Apache-2.0
#include "collision/passivity_observer.h"

#include <cmath>

namespace enteron::collision {

ToolWrench PassivityObserver::observe(const ToolWrench& wrench, const Vec3& displacement, const Vec3& rotation,
                                      double max_force, bool limit) {
    ToolWrench rendered = wrench;
    const double work = -(wrench.force.dot(displacement) + wrench.torque.dot(rotation));
    const double deficit = -(balance() + work);
    if (limit && deficit > 0.0) {
        double left = deficit;  // energy the damper must take out, J
        const double distance = displacement.norm();
        if (distance > 0.0) {
            // The largest lambda that keeps |F - lambda u| <= max_force.
            const Vec3 u = displacement / distance;
            const double along = wrench.force.dot(u);
            const double room = along * along - wrench.force.squaredNorm() + max_force * max_force;
            const double most = along + std::sqrt(std::max(0.0, room));
            const double lambda = std::min(left / distance, std::max(0.0, most));
            rendered.force -= lambda * u;
            left -= lambda * distance;
        }
        const double turn = rotation.norm();
        if (left > 0.0 && turn > 0.0) rendered.torque -= (left / turn) * (rotation / turn);
    }
    const double rendered_work = -(rendered.force.dot(displacement) + rendered.torque.dot(rotation));
    if (rendered_work > 0.0)
        stats_.energy_in += rendered_work;
    else
        stats_.energy_out -= rendered_work;
    stats_.limiter_energy += rendered_work - work;
    stats_.largest_force_change = std::max(stats_.largest_force_change, (rendered.force - last_force_).norm());
    last_force_ = rendered.force;
    return rendered;
}

Vec3 rotation_between(const std::array<double, 4>& from, const std::array<double, 4>& to) {
    const Eigen::Quaterniond a(from[0], from[1], from[2], from[3]), b(to[0], to[1], to[2], to[3]);
    Eigen::Quaterniond delta = b * a.conjugate();
    if (delta.w() < 0.0) delta.coeffs() = -delta.coeffs();  // the shorter arc
    const double half_sine = delta.vec().norm();
    if (!(half_sine > 0.0)) return Vec3::Zero();
    const double angle = 2.0 * std::atan2(half_sine, delta.w());
    return (angle / half_sine) * delta.vec();
}

void PassivityObserver::save_state(StateWriter& out) const {
    out.f64(stats_.largest_force_change);
    out.f64(stats_.energy_in);
    out.f64(stats_.energy_out);
    out.f64(stats_.limiter_energy);
    out.f64s(last_force_.data(), 3);
}

void PassivityObserver::restore_state(StateReader& in, PassivityObserver& into) {
    into.stats_.largest_force_change = in.f64("largest force change");
    into.stats_.energy_in = in.f64("passivity energy in");
    into.stats_.energy_out = in.f64("passivity energy out");
    into.stats_.limiter_energy = in.f64("passivity limiter energy");
    in.f64s("last rendered force", 3, into.last_force_.data());
}

}  // namespace enteron::collision
