// SPDX-License-Identifier: Apache-2.0
// The seed's third remark as an experiment (France et al. 2002: "self-collisions could be
// detected more precisely by taking into account the information provided by the implicit
// surface"): the mechanics' self-contact with the depth and normal of each collision
// sphere taken from the other folds' implicit field (the tube of radius R around their
// axis, as the skins' contact surfaces measure it: lib/skinning/fold_contacts.h) instead
// of from the other folds' spheres. Nothing here touches the step: both models are
// evaluated on the same states, through the library's internals (enteron_core).
//
//  1. Penetration on the dense pile (the tight-fold pile of skin_piles.h, settled with the
//     spheres): for every collision sphere, the true depth of its fold into the others'
//     tubes (2 R less the distance from its centre to the nearest other fold's axis, the
//     spline sampled every R / 64) against each model's: contacts missed, depth error,
//     normal error.
//  2. Force continuity: two legs of a U-turn pressed 0.2 R into each other, one sliding
//     along the other over two sphere spacings in 200 steps: the normal force each model's
//     penalty law (the scene's stiffness) puts on one sphere in the middle of the sliding
//     leg, its ripple and largest step (what a fold feels sliding over another).
//  3. Cost: one evaluation of the self-contact forces on the pile, the scene's effect
//     (SelfContactForce, spheres and their near pairs) against the field's (the folds'
//     polyline index, then each sphere's other folds), medians of alternated runs.
//
//   build/bench/enteron_contact_field_bench [repetitions]
//
// Prints Markdown tables (docs/skinning.md, Self-contact from the implicit field).
#include <enteron/enteron.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory_resource>
#include <vector>

#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "collision/self_contact_force.h"
#include "collision/sphere_loads.h"
#include "mechanics/state.h"
#include "skin_piles.h"
#include "skinning/axis_samples.h"
#include "skinning/fold_contacts.h"
#include "spline/arc_length.h"
#include "spline/catmull_rom.h"

namespace {

using enteron::Vec3;
namespace collision = enteron::collision;
namespace skinning = enteron::skinning;

constexpr double kR = 0.0125;
constexpr double kPi = 3.14159265358979323846;
constexpr double kSphereSpacing = 0.5 * kR;  // the scene's default

double cpu_ms() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// A sphere's contact in one model: depth (m, <= 0: none) and the normal pushing it out.
struct SphereContact {
    double depth = 0.0;
    Vec3 normal = Vec3::Zero();
};

// The axis of some control points, with its arc-length table, its spheres and the folds'
// index (R / 4 samples, bowed), for both models.
struct Axis {
    explicit Axis(std::vector<double> points, double rest_length)
        : q(std::move(points)), state(std::pmr::new_delete_resource()),
          spheres(q.size() / 3, rest_length, kSphereSpacing, kR, std::pmr::new_delete_resource()) {
        table.build(q.data(), q.size() / 3);
        state.resize(q.size() / 3);
        state.q.assign(q.begin(), q.end());
        spheres.update(q.data());
        samples.build(table, q.data(), q.size() / 3, skinning::AxisSamples::intervals_for(table.total_length(), 0.25 * kR),
                      0.0, skinning::AxisSamples::Curvature::compute);
        folds.build(samples, kR, kR);
    }

    // The spheres' model: each sphere's deepest pair in the scene's self-contact effect.
    std::vector<SphereContact> by_spheres() {
        collision::SphereLoads loads(spheres, std::pmr::new_delete_resource());
        collision::SelfContactForce effect(spheres, collision::ContactParameters{}, state, std::pmr::new_delete_resource(),
                                           loads);
        std::vector<double> force(q.size(), 0.0);
        loads.clear();
        effect.evaluate(state, force.data(), nullptr);
        std::vector<SphereContact> out(spheres.size());
        for (const collision::ContactRecord& record : effect.contact_log()) {
            for (const auto& [sphere, sign] : {std::pair{record.sphere, 1.0}, std::pair{record.other, -1.0}}) {
                if (record.depth > out[sphere].depth) out[sphere] = {record.depth, sign * record.normal};
            }
        }
        return out;
    }

    // The field's model: each sphere against the other folds' tubes (normalised distance to
    // their axis, the mechanics' window entered smoothly).
    std::vector<SphereContact> by_field() const {
        std::vector<SphereContact> out(spheres.size());
        skinning::FoldContacts::Anchor anchors[8];
        for (std::size_t i = 0; i < spheres.size(); ++i) {
            const Vec3 c = spheres[i].center;
            const std::size_t count = folds.near(c, 0, spheres[i].arc_length, anchors, 8);
            for (std::size_t a = 0; a < count; ++a) {
                Vec3 gradient;
                const double level = folds.level(c, 0, spheres[i].arc_length, anchors[a], &gradient);
                const double depth = 2.0 * kR - level * kR;
                if (depth > out[i].depth) out[i] = {depth, enteron::normalized_or(gradient, Vec3::Zero())};
            }
        }
        return out;
    }

    // The true depth: against the spline itself beyond pi R along it (R / 64 samples).
    std::vector<SphereContact> truth() const {
        const double length = table.total_length();
        const auto n = std::size_t(std::ceil(length / (kR / 64.0))) + 1;
        std::vector<Vec3> points(n);
        std::vector<double> arcs(n);
        for (std::size_t j = 0; j < n; ++j) {
            arcs[j] = length * double(j) / double(n - 1);
            points[j] = enteron::spline::evaluate(
                q.data(), enteron::spline::weights_at(q.size() / 3, table.parameter_at(arcs[j]), enteron::spline::Derivative::value));
        }
        std::vector<SphereContact> out(spheres.size());
        for (std::size_t i = 0; i < spheres.size(); ++i) {
            const Vec3 c = spheres[i].center;
            double best = 4.0 * kR;
            Vec3 nearest = Vec3::Zero();
            for (std::size_t j = 0; j < n; ++j) {
                if (std::fabs(arcs[j] - spheres[i].arc_length) <= kPi * kR) continue;
                const double d = (points[j] - c).norm();
                if (d < best) best = d, nearest = points[j];
            }
            if (best < 2.0 * kR) out[i] = {2.0 * kR - best, enteron::normalized_or(c - nearest, Vec3::Zero())};
        }
        return out;
    }

    std::vector<double> q;
    enteron::spline::ArcLengthTable table;
    enteron::mechanics::State state;
    collision::CollisionSpheres spheres;
    skinning::AxisSamples samples;
    skinning::FoldContacts folds;
};

void compare(const char* model, const std::vector<SphereContact>& truth, const std::vector<SphereContact>& seen) {
    std::size_t contacts = 0, missed = 0;
    double sum2 = 0.0, under = 0.0, over = 0.0, angle2 = 0.0, angle_max = 0.0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (!(truth[i].depth > 0.0)) continue;
        ++contacts;
        if (!(seen[i].depth > 0.0)) {
            ++missed;
            under = std::max(under, truth[i].depth);
            sum2 += truth[i].depth * truth[i].depth;
            continue;
        }
        const double error = seen[i].depth - truth[i].depth;
        sum2 += error * error;
        under = std::max(under, -error);
        over = std::max(over, error);
        const double angle = std::acos(std::clamp(seen[i].normal.dot(truth[i].normal), -1.0, 1.0));
        angle2 += angle * angle;
        angle_max = std::max(angle_max, angle);
    }
    const std::size_t seen_count = contacts - missed;
    std::printf("| %s | %zu | %zu (%.1f %%) | %.2f | %.2f | %.2f | %.1f | %.1f |\n", model, contacts, missed,
                contacts ? 100.0 * double(missed) / double(contacts) : 0.0, 100.0 * std::sqrt(sum2 / double(std::max<std::size_t>(1, contacts))) / kR,
                100.0 * under / kR, 100.0 * over / kR, 180.0 / kPi * std::sqrt(angle2 / double(std::max<std::size_t>(1, seen_count))),
                180.0 / kPi * angle_max);
}

// The normal force (N) on the sphere of the sliding leg nearest to arc length `arc`: the
// scene's penalty stiffness on its depth, along its normal, towards the other leg.
double sphere_force(const std::vector<SphereContact>& contacts, const collision::CollisionSpheres& spheres, double arc) {
    const collision::ContactParameters law;
    std::size_t nearest = 0;
    for (std::size_t i = 0; i < spheres.size(); ++i)
        if (std::fabs(spheres[i].arc_length - arc) < std::fabs(spheres[nearest].arc_length - arc)) nearest = i;
    return contacts[nearest].depth > 0.0 ? law.stiffness * contacts[nearest].depth * std::fabs(contacts[nearest].normal.y()) : 0.0;
}

// Two legs along -x, 1.8 R apart, joined by a half circle; the second leg's points slid by
// `slide` along -x beyond its first 2 cm (the turn stays).
std::vector<double> sliding_u_turn(double slide) {
    std::vector<double> q;
    const double leg = 0.2, step = kR, r = 0.9 * kR;
    for (double x = -leg; x < 0.0; x += step) q.insert(q.end(), {x, -r, 0.0});
    for (int i = 0; i < 4; ++i) {
        const double a = -0.5 * kPi + kPi * i / 4.0;
        q.insert(q.end(), {r * std::cos(a), r * std::sin(a), 0.0});
    }
    for (double x = 0.0; x >= -leg; x -= step) {
        const double w = std::clamp(-x / 0.02, 0.0, 1.0);
        q.insert(q.end(), {x - slide * w * w * (3.0 - 2.0 * w), r, 0.0});
    }
    return q;
}

}  // namespace

int main(int argc, char** argv) {
    const int repetitions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 21;

    // 1. Penetration on the dense pile.
    ent_scene* scene = enteron::bench::settle_pile(enteron::bench::kTightFoldPile);
    if (scene == nullptr) {
        std::fprintf(stderr, "the tight-fold pile: %s\n", ent_last_error());
        return 1;
    }
    uint32_t count = 0;
    ent_scene_control_points(scene, 0, nullptr, &count);
    std::vector<double> points(3 * std::size_t(count));
    ent_scene_control_points(scene, count, points.data(), &count);
    ent_scene_destroy(scene);
    Axis pile(points, 6.0);
    const std::vector<SphereContact> truth = pile.truth();
    std::printf("## Penetration on the tight-fold pile (%zu spheres R / 2 apart)\n\n", pile.spheres.size());
    std::printf("| model | spheres in contact (true) | missed | depth error RMS %% R | deepest under %% R | deepest over %% R | normal error RMS deg | max deg |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
    compare("spheres (the scene's)", truth, pile.by_spheres());
    compare("implicit field", truth, pile.by_field());

    // 2. Force continuity on a sliding contact.
    std::printf("\n## Force on a sphere of a leg sliding along another, pressed 0.2 R (two sphere spacings in 200 steps)\n\n");
    std::printf("| model | mean N | ripple (max - min) / mean | largest step / mean |\n|---|---:|---:|---:|\n");
    std::vector<double> by_spheres, by_field;
    for (int step = 0; step <= 200; ++step) {
        std::vector<double> q = sliding_u_turn(2.0 * kSphereSpacing * step / 200.0);
        enteron::spline::ArcLengthTable table;
        table.build(q.data(), q.size() / 3);
        Axis sliding(q, table.total_length());  // at rest length: spheres R / 2 apart
        const double middle = sliding.table.total_length() - 0.1;  // the second leg's middle
        by_spheres.push_back(sphere_force(sliding.by_spheres(), sliding.spheres, middle));
        by_field.push_back(sphere_force(sliding.by_field(), sliding.spheres, middle));
    }
    for (const auto& [model, forces] : {std::pair{"spheres (the scene's)", &by_spheres}, {"implicit field", &by_field}}) {
        double mean = 0.0, low = 1e300, high = 0.0, jump = 0.0;
        for (std::size_t i = 0; i < forces->size(); ++i) {
            mean += (*forces)[i] / double(forces->size());
            low = std::min(low, (*forces)[i]);
            high = std::max(high, (*forces)[i]);
            if (i > 0) jump = std::max(jump, std::fabs((*forces)[i] - (*forces)[i - 1]));
        }
        std::printf("| %s | %.3f | %.4f | %.5f |\n", model, mean, (high - low) / mean, jump / mean);
    }

    // 3. Cost on the pile, alternated.
    collision::SphereLoads loads(pile.spheres, std::pmr::new_delete_resource());
    collision::SelfContactForce effect(pile.spheres, collision::ContactParameters{}, pile.state,
                                       std::pmr::new_delete_resource(), loads);
    std::vector<double> force(pile.q.size(), 0.0);
    std::vector<double> spheres_ms, field_ms;
    skinning::FoldContacts::Anchor anchors[8];
    double sink = 0.0;
    for (int r = 0; r < repetitions; ++r) {
        // A step's evaluation: the spheres placed anew (their near pairs kept, as from step to
        // step when little moves).
        pile.spheres.forget_placement();
        double start = cpu_ms();
        loads.clear();
        effect.evaluate(pile.state, force.data(), nullptr);
        spheres_ms.push_back(cpu_ms() - start);
        start = cpu_ms();
        pile.folds.build(pile.samples, kR, kR);
        for (std::size_t i = 0; i < pile.spheres.size(); ++i) {
            const Vec3 c = pile.spheres[i].center;
            const std::size_t n = pile.folds.near(c, 0, pile.spheres[i].arc_length, anchors, 8);
            for (std::size_t a = 0; a < n; ++a) {
                Vec3 gradient;
                sink += pile.folds.level(c, 0, pile.spheres[i].arc_length, anchors[a], &gradient);
            }
        }
        field_ms.push_back(cpu_ms() - start);
    }
    std::sort(spheres_ms.begin(), spheres_ms.end());
    std::sort(field_ms.begin(), field_ms.end());
    std::printf("\n## Cost of one evaluation on the pile (CPU ms, median of %d alternated; the spheres' with the forces'\n"
                "## assembly and its near pairs kept, the field's without either)\n\n| model | median ms |\n|---|---:|\n"
                "| spheres (the scene's) | %.3f |\n| implicit field | %.3f |\n",
                repetitions, spheres_ms[spheres_ms.size() / 2], field_ms[field_ms.size() / 2]);
    if (sink == 42.0) std::printf("\n");  // keep the field's work
    return 0;
}
