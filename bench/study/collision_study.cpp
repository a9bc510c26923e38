// Collision accuracy: how deep the bowel sinks into the cavity walls and into itself in
// the dense pile, against the collision sphere spacing (R/4 to R) and the contact
// stiffness, with the cost of a 1 ms step.
//
// The pile (study_scenes.h) settles for kSettle, then for kMeasure the study takes a
// snapshot every 50 ms and measures the penetration geometrically on the axis sampled
// every R/8 (so a coarse sphere spacing cannot hide the overlap between its spheres);
// the library's own deepest contact (ent_stats.max_penetration_m, at sphere centres) is
// reported next to it. Cost: median wall time of the steps of the measuring window.
#include "collision_study.h"

#include "study_scenes.h"

#include <algorithm>
#include <cmath>

namespace study {

void run_collision_study(const Options& options) {
    const double r = kPileRadius;
    const std::vector<double> spacings = pile_sphere_spacings(options);
    const std::vector<double> stiffnesses = pile_contact_stiffnesses(options);
    const double settle_s = options.fast ? 1.0 : 2.0;
    const double measure_s = options.fast ? 0.5 : 1.0;
    const double step_s = 1e-3;
    const double sample_spacing = r / 8;
    const uint32_t samples = static_cast<uint32_t>(std::lround(6.0 / sample_spacing)) + 1;

    Csv csv(options.out_dir + "/collision_pile.csv",
            {"sphere_spacing_m", "sphere_spacing_radii", "contact_stiffness_N_per_m",
             "max_penetration_m", "rms_penetration_m", "max_penetration_radii", "rms_penetration_radii",
             "penetrating_fraction", "library_max_penetration_m", "contacts", "us_per_ms", "substeps_per_ms",
             "rollbacks", "status"});
    auto run = [&](const PileSettings& settings) {
        Penetration penetration;
        double library_max = 0.0, contacts = 0.0, us = std::nan(""), substeps = std::nan("");
        uint64_t rollbacks = 0;
        std::string status = "ok";
        const double start = now_s();
        try {
            ScenePtr scene = make_scene(pile_json(settings));
            const long settle_steps = std::lround(settle_s / step_s);
            const long measure_steps = std::lround(measure_s / step_s);
            const long snapshot_every = std::lround(0.05 / step_s);
            for (long k = 0; k < settle_steps; ++k) check(ent_scene_step(scene.get(), step_s), "ent_scene_step");
            const ent_stats before = scene_stats(scene.get());
            std::vector<double> times;
            long snapshots = 0;
            for (long k = 1; k <= measure_steps; ++k) {
                const double t0 = now_s();
                check(ent_scene_step(scene.get(), step_s), "ent_scene_step");
                times.push_back((now_s() - t0) * 1e6);
                if (k % snapshot_every == 0) {
                    penetration.add(measure_pile_penetration(sample_axis(scene.get(), samples), sample_spacing));
                    const ent_stats s = scene_stats(scene.get());
                    library_max = std::max(library_max, s.max_penetration_m);
                    contacts += s.contacts;
                    ++snapshots;
                }
            }
            const ent_stats after = scene_stats(scene.get());
            us = median(times);
            substeps = static_cast<double>(after.substeps - before.substeps) / static_cast<double>(measure_steps);
            rollbacks = after.rollbacks;
            contacts /= static_cast<double>(std::max(snapshots, 1L));
        } catch (const ApiError& error) {
            status = error.what();
            std::replace(status.begin(), status.end(), ',', ';');
        }
        const double spacing = settings.sphere_spacing_m;
        progress("collision pile spacing %.2f R, stiffness %6.0f N/m: max %.2f mm, rms %.2f mm, %7.1f us/ms, "
                 "%.1f s %s",
                 spacing / r, settings.contact_stiffness_N_per_m, 1e3 * penetration.max_m,
                 1e3 * penetration.rms_m(), us, now_s() - start, status.c_str());
        const double fraction = penetration.samples ? static_cast<double>(penetration.penetrating) /
                                                          static_cast<double>(penetration.samples)
                                                    : std::nan("");
        csv.row({num(spacing), num(spacing / r), num(settings.contact_stiffness_N_per_m),
                 num(penetration.max_m), num(penetration.rms_m()), num(penetration.max_m / r),
                 num(penetration.rms_m() / r), num(fraction), num(library_max), num(contacts), num(us),
                 num(substeps), num(rollbacks), status});
    };
    for (double spacing : spacings)
        for (double stiffness : stiffnesses) {
            PileSettings settings;
            settings.sphere_spacing_m = spacing;
            settings.contact_stiffness_N_per_m = stiffness;
            run(settings);
        }
    // Each integrator on the default pile: what its contacts cost. The explicit ones take
    // hundreds of substeps per 1 ms (the contact and self-contact stiffness bound their
    // stable substep), so only the first steps of the drop are timed, for all three alike.
    Csv integrators(options.out_dir + "/collision_pile_integrators.csv",
                    {"integrator", "steps", "us_per_ms", "substeps_per_ms", "status"});
    const int steps = options.fast ? 3 : 10;
    for (int32_t id : kIntegrators) {
        PileSettings settings;
        settings.integrator = integrator_name(id);
        std::vector<double> us;
        std::string status = "ok";
        double substeps = std::nan("");
        try {
            ScenePtr scene = make_scene(pile_json(settings));
            for (int k = 0; k < steps; ++k) {
                const double t0 = now_s();
                check(ent_scene_step(scene.get(), step_s), "ent_scene_step");
                us.push_back((now_s() - t0) * 1e6);
            }
            substeps = static_cast<double>(scene_stats(scene.get()).substeps) / steps;
        } catch (const ApiError& error) {
            status = error.what();
            std::replace(status.begin(), status.end(), ',', ';');
        }
        progress("collision pile %-16s first %d steps: %9.1f us/ms, %.0f substeps/ms %s", settings.integrator, steps,
                 median(us), substeps, status.c_str());
        integrators.row({settings.integrator, num(steps), num(median(us)), num(substeps), status});
    }
}

}  // namespace study
