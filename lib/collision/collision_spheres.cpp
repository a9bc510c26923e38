// SPDX-License-Identifier: Apache-2.0
#include "collision/collision_spheres.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "base/hot_kernel.h"
#include "numerics/lanes.h"

namespace enteron::collision {

CollisionSpheres::CollisionSpheres(std::size_t control_points, double rest_length, double spacing,
                                   double radius, std::pmr::memory_resource* memory, spline::Ends ends,
                                   const spline::LengthProfile* radius_profile)
    : CollisionSpheres({SphereTube{0, control_points, rest_length, spacing, radius, ends, radius_profile}},
                       control_points, memory) {}

CollisionSpheres::CollisionSpheres(const std::vector<SphereTube>& tubes, std::size_t control_points,
                                   std::pmr::memory_resource* memory)
    : control_points_(control_points),
      radius_(0.0),
      tubes_(memory),
      sample_weights_(memory),
      sample_points_(memory),
      sample_arc_(memory),
      spheres_(memory),
      rest_fractions_(memory),
      placed_for_(3 * control_points, 0.0, memory),
      velocities_(memory),
      velocities_for_(3 * control_points, 0.0, memory) {
    for (const SphereTube& tube : tubes) add_tube(tube);
    sample_points_.assign(3 * sample_weights_.size(), 0.0);
    sample_arc_.assign(sample_weights_.size(), 0.0);
    velocities_.assign(3 * spheres_.size(), 0.0);
}

void CollisionSpheres::add_tube(const SphereTube& tube) {
    const double rest_length = tube.rest_length, spacing = tube.spacing, radius = tube.radius;
    const spline::LengthProfile* radius_profile = tube.radius_profile;
    TubeSpheres placed;
    placed.radius = radius;
    placed.profiled = radius_profile != nullptr;
    placed.sample_begin = sample_weights_.size();
    const std::size_t segments = tube.control_points - 1;
    for (std::size_t segment = 0; segment < segments; ++segment)
        for (std::size_t k = 0; k <= kSamplesPerSegment; ++k) {
            spline::SegmentWeights weights = spline::segment_weights(
                tube.control_points, segment, double(k) / kSamplesPerSegment, spline::Derivative::value, tube.ends);
            weights.first += tube.first;
            sample_weights_.push_back(weights);
        }
    placed.sample_end = sample_weights_.size();
    placed.sphere_begin = spheres_.size();
    const uint32_t index = static_cast<uint32_t>(tubes_.size());
    if (radius_profile == nullptr) {
        const std::size_t count = static_cast<std::size_t>(std::llround(rest_length / spacing)) + 1;
        placed.rest_spacing = rest_length / double(count - 1);
        spheres_.resize(spheres_.size() + std::max<std::size_t>(count, 2));
        for (std::size_t j = placed.sphere_begin; j < spheres_.size(); ++j) spheres_[j].radius = radius;
    } else {
        // Even steps of u(s) = R_max x integral of ds / R(s) (length_profile.h): a step of
        // `spacing` in u is spacing x R(s) / R_max in s.
        const double span = radius * radius_profile->reciprocal_integral(rest_length);
        const std::size_t count = std::max<std::size_t>(static_cast<std::size_t>(std::llround(span / spacing)) + 1, 2);
        placed.rest_spacing = span / double(count - 1);
        spheres_.resize(spheres_.size() + count);
        rest_fractions_.resize(spheres_.size());
        for (std::size_t j = 0; j < count; ++j) {
            const double s = j + 1 == count ? rest_length
                                            : radius_profile->where_reciprocal_integral_is(
                                                  placed.rest_spacing * double(j) / radius);
            rest_fractions_[placed.sphere_begin + j] = std::min(s / rest_length, 1.0);
            spheres_[placed.sphere_begin + j].radius = radius_profile->at(s);
        }
    }
    placed.sphere_end = spheres_.size();
    for (std::size_t j = placed.sphere_begin; j < placed.sphere_end; ++j) spheres_[j].tube = index;
    radius_ = std::max(radius_, radius);
    tubes_.push_back(placed);
}

ENTERON_HOT_KERNEL const double* CollisionSpheres::velocities(const double* v) {
    const std::size_t bytes = velocities_for_.size() * sizeof(double);
    if (velocities_placement_ == placement_ && std::memcmp(velocities_for_.data(), v, bytes) == 0)
        return velocities_.data();
    std::memcpy(velocities_for_.data(), v, bytes);
    velocities_placement_ = placement_;
    for (std::size_t i = 0; i < spheres_.size(); ++i) point_at(velocities_.data(), i) = spline::evaluate(v, spheres_[i].weights);
    return velocities_.data();
}

ENTERON_HOT_KERNEL void CollisionSpheres::update(const double* control_points) {
    // The same bits, the same placement (a byte compare: several effects ask per state).
    if (placed_ && std::memcmp(placed_for_.data(), control_points, placed_for_.size() * sizeof(double)) == 0) return;
    std::copy(control_points, control_points + placed_for_.size(), placed_for_.begin());
    placed_ = true;
    placement_ += 1;
    for (const TubeSpheres& tube : tubes_) place_tube(tube, control_points);
}

// One tube's spheres, for the control points of the whole state.
ENTERON_HOT_KERNEL void CollisionSpheres::place_tube(const TubeSpheres& tube, const double* control_points) {
    // The polyline: kSamplesPerSegment + 1 samples per segment (its two ends included), and
    // the arc length at each.
    constexpr std::size_t kPerSegment = kSamplesPerSegment + 1;
    const std::size_t segments = (tube.sample_end - tube.sample_begin) / kPerSegment;
    // Raw pointers (from the tube's first sample): the compiler need not reload the vectors'
    // storage after every store.
    const spline::SegmentWeights* weights = sample_weights_.data() + tube.sample_begin;
    double* points = sample_points_.data() + 3 * tube.sample_begin;
    double* arcs = sample_arc_.data() + tube.sample_begin;
    // The last sample stays in registers: reloading it from the stores that wrote it cost a
    // store-forwarding stall per segment.
    Vec3 last = spline::evaluate(control_points, weights[0]);
    double arc = 0.0;
    for (std::size_t segment = 0; segment < segments; ++segment) {
        const std::size_t first = segment * kPerSegment;
        // A segment starts where the one before ends (the spline interpolates its points).
        point_at(points, first) = last;
        arcs[first] = arc;  // the first sample repeats the last of the segment before
        for (std::size_t k = 1; k < kPerSegment; ++k) {
            const Vec3 next = spline::evaluate(control_points, weights[first + k]);
            arc += (next - last).norm();
            arcs[first + k] = arc;
            point_at(points, first + k) = last = next;
        }
    }
    // The spheres, evenly spread over the length: walk the polyline's intervals (never the
    // zero-length step from a segment's last sample to the next one's first).
    const double total = arc;
    const std::size_t count = tube.sphere_end - tube.sphere_begin;
    const double spacing = total / double(count - 1);
    Sphere* spheres = spheres_.data() + tube.sphere_begin;
    std::size_t segment = 0, k = 0;  // the interval from sample (segment, k) to (segment, k + 1)
    const double* fractions = tube.profiled ? rest_fractions_.data() + tube.sphere_begin : nullptr;
    for (std::size_t j = 0; j < count; ++j) {
        const double target = fractions != nullptr ? total * fractions[j] : spacing * double(j);
        for (;;) {
            const std::size_t next = segment * kPerSegment + k + 1;
            if (arcs[next] >= target) break;
            if (k + 1 < kSamplesPerSegment) {
                ++k;
            } else if (segment + 1 < segments) {
                ++segment, k = 0;
            } else {
                break;  // the far end (round-off)
            }
        }
        const std::size_t interval = segment * kPerSegment + k;
        const double a0 = arcs[interval], a1 = arcs[interval + 1];
        const double t = a1 > a0 ? std::clamp((target - a0) / (a1 - a0), 0.0, 1.0) : 0.0;
        const spline::SegmentWeights& w0 = weights[interval];
        const spline::SegmentWeights& w1 = weights[interval + 1];
        Sphere& sphere = spheres[j];
        sphere.weights.first = w0.first;
        // w = (1 - t) w0 + t w1, the four weights in lanes (numerics/lanes.h: the same bits).
        const numerics::Quad keep = {1.0 - t, 1.0 - t, 1.0 - t, 1.0 - t}, take = {t, t, t, t};
        numerics::Quad a, b;
        std::memcpy(&a, w0.w.data(), sizeof a);
        std::memcpy(&b, w1.w.data(), sizeof b);
        const numerics::Quad w = keep * a + take * b;
        std::memcpy(sphere.weights.w.data(), &w, sizeof w);
        sphere.center = (1.0 - t) * point_at(points, interval) + t * point_at(points, interval + 1);
        sphere.arc_length = target;
    }
}

void CollisionSpheres::add_weight_products(double scale, numerics::ScalarBandMatrix& bound) const {
    for (const Sphere& sphere : spheres_) {
        const spline::SegmentWeights& sw = sphere.weights;
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k <= j; ++k) bound.add(sw.first + j, sw.first + k, scale * sw.w[j] * sw.w[k]);
    }
}

}  // namespace enteron::collision
