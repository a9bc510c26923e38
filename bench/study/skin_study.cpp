// SPDX-License-Identifier: Apache-2.0
// Skin accuracy: for each skinning method and resolution, how far the mesh is from the
// ideal tube of radius R around the axis (ent_skin_metrics: radius error RMS and max,
// unwanted blending, volume error, watertightness), against the wall time of one
// ent_skin_update (median), on the settled 6 m pile (study_scenes.h, default collision):
// skin.csv; and on the tight-fold pile of the skin benchmark (bench/skin_piles.h):
// skin_tight_fold.csv.
#include "skin_study.h"

#include "study_scenes.h"

#include "../skin_piles.h"

#include <cmath>
#include <cstring>

namespace study {

namespace {

struct Resolution {
    const char* name;
    uint32_t segments;        // tube, convolution: vertices around
    double ring_spacing;      // tube, convolution: in R
    double skeleton_spacing;  // point_skeleton, convolution: in R
    double voxel_size;        // point_skeleton: in R
};

constexpr Resolution kResolutions[] = {
    {"coarse", 8, 1.0, 0.5, 0.5},
    {"medium", 12, 0.75, 0.35, 0.4},
    {"default", 16, 0.5, 0.25, 1.0 / 3.0},
    {"fine", 24, 0.35, 0.18, 0.3},
    {"finest", 32, 0.25, 0.125, 0.25},
};

struct Method {
    const char* name;
    int32_t id;
};
constexpr Method kMethods[] = {
    {"tube", ENT_SKIN_TUBE}, {"point_skeleton", ENT_SKIN_POINT_SKELETON}, {"convolution", ENT_SKIN_CONVOLUTION}};

// One table: every method at every resolution on the settled scene, into `file`.
void skin_table(const Options& options, ent_scene* scene, const char* pile, const std::string& file) {
    const int timed_updates = options.fast ? 3 : 15;
    Csv csv(options.out_dir + "/" + file,
            {"method", "resolution", "segments", "ring_spacing_radii", "skeleton_spacing_radii", "voxel_size_radii",
             "triangles", "radius_error_rms", "radius_error_max", "free_radius_error_rms", "blended_vertices", "inverted_triangles",
             "volume_error", "watertight", "open_edges", "nonmanifold_edges", "normal_deviation_rms_rad", "ms_per_update"});
    for (const Method& method : kMethods)
        for (const Resolution& resolution : kResolutions) {
            if (options.fast && std::strcmp(resolution.name, "medium") == 0) continue;
            if (options.fast && std::strcmp(resolution.name, "fine") == 0) continue;
            ent_skin_desc desc;
            ent_skin_desc_default(&desc);
            desc.method = method.id;
            desc.segments = resolution.segments;
            desc.ring_spacing_radii = resolution.ring_spacing;
            desc.skeleton_spacing_radii = resolution.skeleton_spacing;
            desc.voxel_size_radii = resolution.voxel_size;
            ent_skin* raw = nullptr;
            check(ent_skin_create(scene, &desc, &raw), "ent_skin_create");
            SkinPtr skin(raw);
            // Two untimed updates: buffers and temporal coherence warm, as on a render thread.
            check(ent_skin_update(skin.get()), "ent_skin_update");
            check(ent_skin_update(skin.get()), "ent_skin_update");
            std::vector<double> ms;
            for (int i = 0; i < timed_updates; ++i) {
                const double t0 = now_s();
                check(ent_skin_update(skin.get()), "ent_skin_update");
                ms.push_back((now_s() - t0) * 1e3);
            }
            struct ent_skin_metrics m;
            std::memset(&m, 0, sizeof m);
            m.struct_size = sizeof m;
            check(ent_skin_metrics(skin.get(), &m), "ent_skin_metrics");
            const double ms_median = median(ms);
            progress("skin %s %-14s %-7s %7u triangles, radius RMS %.3f %% R, blended %u, %.2f ms", pile, method.name,
                     resolution.name, m.triangle_count, 100 * m.radius_error_rms, m.blended_vertices, ms_median);
            csv.row({method.name, resolution.name, num(resolution.segments), num(resolution.ring_spacing),
                     num(resolution.skeleton_spacing), num(resolution.voxel_size), num(m.triangle_count),
                     num(m.radius_error_rms), num(m.radius_error_max), num(m.free_radius_error_rms), num(m.blended_vertices),
                     num(m.inverted_triangles), num(m.volume_error), num(m.watertight), num(m.open_edges), num(m.nonmanifold_edges),
                     num(m.normal_deviation_rms_rad), num(ms_median)});
        }
}

}  // namespace

void run_skin_study(const Options& options) {
    const double settle_s = options.fast ? 1.0 : 2.0;
    ScenePtr scene = make_scene(pile_json(PileSettings{}));
    for (long k = 0; k < std::lround(settle_s / 1e-3); ++k) check(ent_scene_step(scene.get(), 1e-3), "ent_scene_step");
    skin_table(options, scene.get(), "pile", "skin.csv");
    // The tight-fold pile of the skin benchmark: more than half of the axis bends with a
    // radius under 4 R, U-turns down to 1.5 R (bench/skin_piles.h).
    ScenePtr tight(enteron::bench::settle_pile(enteron::bench::kTightFoldPile));
    check(tight ? ENT_OK : ENT_ERROR_INVALID_ARGUMENT, "settle_pile(tight_fold_pile)");
    skin_table(options, tight.get(), "tight_fold_pile", "skin_tight_fold.csv");
}

}  // namespace study
