// Cost and accuracy of each skinning method on the settled 6 m bowel of the demo (helix,
// stretch, bend, damping, gravity, mesentery; 2 s simulated first), at three resolutions.
// Through the C API only. Every benchmark iteration is one ent_skin_update of the same
// state (after two untimed updates, so temporal coherence and buffers are warm, as on a
// render thread following a slowly moving bowel). Counters: ms per update, updates per
// second, triangles, radius error RMS / max (fraction of R), unwanted-blending vertices,
// inverted triangles and watertightness, from ent_skin_metrics.
//
//   build/bench/enteron_skin_bench --benchmark_min_time=0.5
#include <enteron/enteron.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

namespace {

ent_scene* settled_bowel() {
    static ent_scene* scene = [] {
        ent_scene_desc desc;
        ent_scene_desc_default(&desc);
        desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                       ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) |
                       ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
        desc.length_m = 6.0;
        desc.radius_m = 0.0125;
        desc.control_points = 240;
        desc.shape = ENT_SHAPE_HELIX;
        desc.shape_center_m[2] = -0.15;
        desc.shape_helix_radius_m = 0.1;
        desc.shape_helix_pitch_m = 0.03;
        ent_scene* s = nullptr;
        if (ent_scene_create(&desc, &s) != ENT_OK) return static_cast<ent_scene*>(nullptr);
        for (int i = 0; i < 2000; ++i)
            if (ent_scene_step(s, 1e-3) != ENT_OK) break;
        return s;
    }();
    return scene;
}

struct Resolution {
    const char* name;
    uint32_t segments;
    double ring_spacing, skeleton_spacing, voxel_size;
};
constexpr Resolution resolutions[] = {
    {"coarse", 8, 1.0, 0.5, 0.5},
    {"default", 16, 0.5, 0.25, 1.0 / 3.0},
    {"fine", 32, 0.25, 0.125, 0.25},
};

void skin_benchmark(benchmark::State& state, int32_t method, Resolution resolution) {
    ent_scene* scene = settled_bowel();
    if (scene == nullptr) {
        state.SkipWithError(ent_last_error());
        return;
    }
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    desc.method = method;
    desc.segments = resolution.segments;
    desc.ring_spacing_radii = resolution.ring_spacing;
    desc.skeleton_spacing_radii = resolution.skeleton_spacing;
    desc.voxel_size_radii = resolution.voxel_size;
    ent_skin* skin = nullptr;
    if (ent_skin_create(scene, &desc, &skin) != ENT_OK || ent_skin_update(skin) != ENT_OK ||
        ent_skin_update(skin) != ENT_OK) {
        state.SkipWithError(ent_last_error());
        ent_skin_destroy(skin);
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) {
        if (ent_skin_update(skin) != ENT_OK) {
            state.SkipWithError(ent_last_error());
            break;
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    struct ent_skin_metrics m;
    std::memset(&m, 0, sizeof m);
    m.struct_size = sizeof m;
    if (ent_skin_metrics(skin, &m) == ENT_OK) {
        state.counters["ms_per_update"] = 1e3 * seconds / double(state.iterations());
        state.counters["updates_per_s"] = double(state.iterations()) / seconds;
        state.counters["triangles"] = m.triangle_count;
        state.counters["radius_rms_pct"] = 100.0 * m.radius_error_rms;
        state.counters["radius_max_pct"] = 100.0 * m.radius_error_max;
        state.counters["blended"] = m.blended_vertices;
        state.counters["inverted"] = m.inverted_triangles;
        state.counters["watertight"] = m.watertight;
    }
    ent_skin_destroy(skin);
}

}  // namespace

int main(int argc, char** argv) {
    const struct {
        const char* name;
        int32_t id;
    } methods[] = {{"tube", ENT_SKIN_TUBE}, {"point_skeleton", ENT_SKIN_POINT_SKELETON}, {"convolution", ENT_SKIN_CONVOLUTION}};
    for (const auto& method : methods)
        for (const Resolution& resolution : resolutions) {
            const std::string name = std::string("skin/") + method.name + "/" + resolution.name;
            benchmark::RegisterBenchmark(name.c_str(), skin_benchmark, method.id, resolution)
                ->Unit(benchmark::kMillisecond);
        }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    ent_scene_destroy(settled_bowel());
    return 0;
}
