// SPDX-License-Identifier: Apache-2.0
// Cost and accuracy of each skinning method on the two settled piles of bench/skin_piles.h,
// at three resolutions, through the C API: the demo's 6 m bowel (dropped as a helix into the
// abdominal cavity, held by its mesentery, its folds piled on each other with
// self-collision; 2 s simulated first), skin/<method>/<resolution>, and the tight-fold pile
// (more than half of its axis bends with a radius under 4 R, U-turns down to 1.5 R; 6 s),
// tight_fold_pile/<method>/<resolution>. Every benchmark iteration is one ent_skin_update of
// the same state (after two untimed updates, so temporal coherence and buffers are warm, as
// on a render thread following a slowly moving bowel). Counters: ms per update (wall),
// updates per second, triangles, radius and facet error RMS / max (% of R),
// unwanted-blending vertices, inverted triangles and watertightness, from ent_skin_metrics;
// and what a renderer uploads (ent_mesh_view): vertex_bytes (positions, normals, tangents:
// every update), index_bytes (only when topology_changed), topology_changes over the timed
// updates. How tightly each pile bends is printed first (bend_radii()).
//
// skin/convolution_rings/*: the level of detail of the convolution skin, even rings
// (ring_spacing_radii) against rings closer where the axis bends
// (ring_chord_error_radii, at most R apart), at 16 segments: error against triangles.
//
// Contacts (docs/skinning.md): every row has the contact measures of ent_skin_metrics as
// counters (overlap_pct: the deepest vertex inside another fold's skin, % of R;
// overlap_area_mm2; tube_overlap_pct: inside another fold's ideal tube; gap_pct: the contact
// surfaces' largest gap; shape_volume_pct; volume_pct, the volume error; free_rms_pct: the
// radius error away from contacts and bends tighter than R), and <pile>/<method>/default_no_contacts the same skin
// with contact_surfaces 0, for the cost of the contacts. <pile>/convolution/skeleton_*: the
// skeleton following the curvature (skeleton_spacing_radii h, skeleton_chord_error_radii e)
// against even ones. popping/<pile>/<method>: a tool sweeps through the settled pile, the
// skin updated every 16 ms of simulation: the largest motion of a vertex beyond the motion
// of its axis point between two updates (excess_pct, % of R), over 40 updates.
//
// colon/{constant,tapered}/<method>: a 1.5 m colon settled in a serpentine on a floor, of
// 3.5 cm throughout or tapering to 1.3 cm (a radius profile), each method at the default
// resolution (its knobs scaled by the largest radius): the update rate, and the radius,
// facet and volume errors against the profile (docs/skinning.md, "A radius that changes");
// colon/tapered/point_skeleton_thin_voxel: its voxel a third of the thin end's radius.
//
// marching_cubes/*: our marching cubes against VTK's vtkFlyingEdges3D and vtkMarchingCubes
// (when Debian's libvtk9-dev is found, ENTERON_HAVE_VTK), on the same scalar field and
// grid: the point-skeleton field of the settled demo pile (the library's internals, not the
// C API), sampled on the dense lattice of voxel R / 3 that covers its band (0 outside the
// band). Counter voxels_per_s: lattice cells / time. marching_cubes/enteron_band is ours
// on the band alone, as the skin runs it.
//
//   build/bench/enteron_skin_bench --benchmark_min_time=0.5 [--mesh_dir=DIR]
//
// --mesh_dir=DIR also writes the mesh of each method at its default resolution, all of the
// same state of the demo pile, as DIR/<method>.ply and DIR/<method>.obj
// (scripts/render_mesh.py draws them). --contact_mesh_dir=DIR writes a fold pressed 0.3 R
// into another (two legs of a U-turn), each method with contact surfaces and without, as
// DIR/<method>_{contacts,through}.ply (scripts/render_contacts.py draws their cross-sections
// through the contact: docs/images/skin_contacts.png).
#include <enteron/enteron.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "skin_piles.h"
#include "skinning/marching_cubes.h"
#include "skinning/mesh_writers.h"
#include "skinning/point_skeleton_skin.h"
#include "skinning/sparse_voxel_grid.h"
#ifdef ENTERON_HAVE_VTK
#include "peers/vtk_iso_surface.h"
#endif

namespace {

namespace sk = enteron::skinning;

constexpr double kRadius = 0.0125;  // m

// The settled piles, made once each (NULL if a pile could not be made).
ent_scene* settled(const enteron::bench::SkinPile& pile) {
    static ent_scene* scenes[std::size(enteron::bench::kSkinPiles)] = {};
    static bool tried[std::size(enteron::bench::kSkinPiles)] = {};
    const std::size_t i = std::size_t(&pile - enteron::bench::kSkinPiles);
    if (!tried[i]) {
        tried[i] = true;
        scenes[i] = enteron::bench::settle_pile(pile);
    }
    return scenes[i];
}
ent_scene* settled_bowel() { return settled(enteron::bench::kSkinPiles[0]); }

struct Resolution {
    const char* name;
    uint32_t segments;
    double ring_spacing, skeleton_spacing, voxel_size;
    double ring_chord_error = 0.0;
    int32_t contact_surfaces = 1;
    double skeleton_chord_error = 0.0;
};
constexpr Resolution kResolutions[] = {
    {"coarse", 8, 1.0, 0.5, 0.5},
    {"default", 16, 0.5, 0.25, 1.0 / 3.0},
    {"fine", 32, 0.25, 0.125, 0.25},
};
constexpr Resolution kDefault = kResolutions[1];

struct Method {
    const char* name;
    int32_t id;
};
constexpr Method kMethods[] = {
    {"tube", ENT_SKIN_TUBE}, {"point_skeleton", ENT_SKIN_POINT_SKELETON}, {"convolution", ENT_SKIN_CONVOLUTION}};

ent_skin* make_skin(ent_scene* scene, int32_t method, const Resolution& resolution) {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    desc.method = method;
    desc.segments = resolution.segments;
    desc.ring_spacing_radii = resolution.ring_spacing;
    desc.skeleton_spacing_radii = resolution.skeleton_spacing;
    desc.voxel_size_radii = resolution.voxel_size;
    desc.ring_chord_error_radii = resolution.ring_chord_error;
    desc.contact_surfaces = resolution.contact_surfaces;
    desc.skeleton_chord_error_radii = resolution.skeleton_chord_error;
    ent_skin* skin = nullptr;
    if (ent_skin_create(scene, &desc, &skin) != ENT_OK || ent_skin_update(skin) != ENT_OK ||
        ent_skin_update(skin) != ENT_OK) {
        ent_skin_destroy(skin);
        return nullptr;
    }
    return skin;
}

// Times ent_skin_update of a skin of `scene` and reports its counters.
void skin_updates_benchmark(benchmark::State& state, ent_scene* scene, int32_t method, const Resolution& resolution) {
    ent_skin* skin = scene != nullptr ? make_skin(scene, method, resolution) : nullptr;
    if (skin == nullptr) {
        state.SkipWithError(ent_last_error());
        return;
    }
    const uint64_t serial_before = enteron::bench::mesh_of(skin).topology_serial;
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) {
        if (ent_skin_update(skin) != ENT_OK) {
            state.SkipWithError(ent_last_error());
            break;
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const ent_mesh_view view = enteron::bench::mesh_of(skin);
    // What a renderer uploads: the vertex data every update, the indices on a topology change.
    state.counters["vertex_bytes"] = double(view.vertex_count) * 3 * 3 * sizeof(float);
    state.counters["index_bytes"] = double(view.triangle_count) * 3 * sizeof(uint32_t);
    state.counters["topology_changes"] = double(view.topology_serial - serial_before);
    struct ent_skin_metrics m;
    std::memset(&m, 0, sizeof m);
    m.struct_size = sizeof m;
    if (ent_skin_metrics(skin, &m) == ENT_OK) {
        state.counters["ms_per_update"] = 1e3 * seconds / double(state.iterations());
        state.counters["updates_per_s"] = double(state.iterations()) / seconds;
        state.counters["triangles"] = m.triangle_count;
        state.counters["radius_rms_pct"] = 100.0 * m.radius_error_rms;
        state.counters["radius_max_pct"] = 100.0 * m.radius_error_max;
        state.counters["facet_rms_pct"] = 100.0 * m.facet_error_rms;
        state.counters["facet_max_pct"] = 100.0 * m.facet_error_max;
        state.counters["blended"] = m.blended_vertices;
        state.counters["inverted"] = m.inverted_triangles;
        state.counters["watertight"] = m.watertight;
        state.counters["overlap_pct"] = 100.0 * m.overlap_depth_max;
        state.counters["overlap_area_mm2"] = 1e6 * m.overlap_area_m2;
        state.counters["tube_overlap_pct"] = 100.0 * m.tube_overlap_depth_max;
        state.counters["gap_pct"] = 100.0 * m.contact_gap_max;
        state.counters["shape_volume_pct"] = 100.0 * m.shape_volume_error;
        state.counters["free_rms_pct"] = 100.0 * m.free_radius_error_rms;
        state.counters["volume_pct"] = 100.0 * m.volume_error;
    }
    ent_skin_destroy(skin);
}

void skin_benchmark(benchmark::State& state, const enteron::bench::SkinPile* pile, int32_t method,
                    Resolution resolution) {
    skin_updates_benchmark(state, settled(*pile), method, resolution);
}

// A tool sweeps through the settled pile while the skin follows at 60 Hz: the largest
// motion of a vertex beyond the motion of its axis point between two updates.
void popping_benchmark(benchmark::State& state, const enteron::bench::SkinPile* pile, int32_t method) {
    for (auto _ : state) {
        ent_scene* scene = enteron::bench::settle_pile(*pile);
        ent_skin* skin = scene != nullptr ? make_skin(scene, method, kDefault) : nullptr;
        if (skin == nullptr) {
            state.SkipWithError(ent_last_error());
            ent_scene_destroy(scene);
            return;
        }
        // The tool: vertical, from one side of the pile to the other 2 R above its floor.
        double box[6];
        enteron::bench::axis_bounds(scene, box);
        ent_tool_desc tool;
        ent_tool_desc_default(&tool);
        tool.max_force_N = 8.0;
        const double y = 0.5 * (box[1] + box[4]), z = box[2] + 2.0 * kRadius;
        tool.position_m[0] = box[0] - 2.0 * kRadius;
        tool.position_m[1] = y;
        tool.position_m[2] = z;
        int32_t id = -1;
        const double identity[4] = {1.0, 0.0, 0.0, 0.0};
        double excess = 0.0, motion = 0.0;
        constexpr int kFrames = 40;
        if (ent_tool_add(scene, &tool, &id) == ENT_OK) {
            for (int frame = 1; frame <= kFrames; ++frame) {
                for (int step = 0; step < 16; ++step) {
                    const double a = double((frame - 1) * 16 + step) / (kFrames * 16.0);
                    const double p[3] = {box[0] - 2.0 * kRadius + a * (box[3] - box[0] + 4.0 * kRadius), y, z};
                    ent_tool_set_pose(scene, id, p, identity);
                    ent_scene_step(scene, 1e-3);
                }
                ent_skin_update(skin);
                struct ent_skin_metrics m;
                std::memset(&m, 0, sizeof m);
                m.struct_size = sizeof m;
                if (ent_skin_metrics(skin, &m) == ENT_OK) {
                    excess = std::max(excess, m.vertex_excess_motion_max);
                    motion = std::max(motion, m.vertex_motion_max);
                }
            }
        }
        state.counters["excess_pct"] = 100.0 * excess;
        state.counters["motion_pct"] = 100.0 * motion;
        state.counters["updates"] = kFrames;
        ent_skin_destroy(skin);
        ent_scene_destroy(scene);
    }
}

// ---- a tube whose radius changes along it -----------------------------------------------

// A 1.5 m colon (N = 61) laid as a serpentine of 0.3 m legs 8 cm apart on a floor, settled
// 1 s: tapered from 3.5 to 1.3 cm (the caecum to the sigmoid), or of 3.5 cm throughout.
ent_scene* settled_colon(bool tapered) {
    static ent_scene* scenes[2] = {};
    static bool tried[2] = {};
    if (tried[tapered]) return scenes[tapered];
    tried[tapered] = true;
    static const double profile[4] = {0.0, 0.035, 1.5, 0.013};
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.control_points = 61;
    desc.length_m = 1.5;
    if (tapered) {
        desc.radius_profile_m = profile;
        desc.radius_profile_count = 2;
    } else {
        desc.radius_m = 0.035;
    }
    desc.shape = ENT_SHAPE_SERPENTINE;
    desc.shape_leg_length_m = 0.3;
    desc.shape_leg_spacing_m = 0.08;
    desc.shape_center_m[2] = 0.036;
    desc.integrator = ENT_INTEGRATOR_IMPLICIT_EULER;
    ent_scene* scene = nullptr;
    if (ent_scene_create(&desc, &scene) != ENT_OK) return nullptr;
    ent_obstacle_desc floor;
    ent_obstacle_desc_default(&floor);
    floor.kind = ENT_OBSTACLE_PLANE;
    int32_t index = -1;
    bool ok = ent_scene_add_obstacle(scene, &floor, &index) == ENT_OK;
    for (int k = 0; ok && k < 1000; ++k) ok = ent_scene_step(scene, 1e-3) == ENT_OK;
    if (!ok) {
        ent_scene_destroy(scene);
        return nullptr;
    }
    scenes[tapered] = scene;
    return scene;
}

// A skin of each method on the settled colon (skin_updates_benchmark's counters: the radius
// errors are against the profile).
void colon_benchmark(benchmark::State& state, bool tapered, int32_t method, Resolution resolution) {
    skin_updates_benchmark(state, settled_colon(tapered), method, resolution);
}

// ---- meshes for people ----------------------------------------------------------------

bool write_meshes(const std::string& dir) {
    ent_scene* scene = settled_bowel();
    if (scene == nullptr) return false;
    for (const Method& method : kMethods) {
        ent_skin* skin = make_skin(scene, method.id, kDefault);
        ent_mesh_view view;
        std::memset(&view, 0, sizeof view);
        view.struct_size = sizeof view;
        if (skin == nullptr || ent_skin_mesh(skin, &view) != ENT_OK) {
            std::fprintf(stderr, "skin %s: %s\n", method.name, ent_last_error());
            ent_skin_destroy(skin);
            return false;
        }
        sk::Mesh mesh;
        mesh.positions.assign(view.positions_xyz_m, view.positions_xyz_m + 3 * std::size_t(view.vertex_count));
        mesh.normals.assign(view.normals_xyz, view.normals_xyz + 3 * std::size_t(view.vertex_count));
        mesh.u.assign(view.axis_u, view.axis_u + view.vertex_count);
        mesh.indices.assign(view.indices, view.indices + 3 * std::size_t(view.triangle_count));
        ent_skin_destroy(skin);
        const std::string base = dir + "/" + method.name;
        std::ofstream ply(base + ".ply", std::ios::binary), obj(base + ".obj");
        if (!sk::write_ply(mesh, ply) || !sk::write_obj(mesh, obj)) {
            std::fprintf(stderr, "cannot write %s.ply / .obj\n", base.c_str());
            return false;
        }
        std::fprintf(stderr, "wrote %s.ply and %s.obj (%u triangles)\n", base.c_str(), base.c_str(),
                     view.triangle_count);
    }
    return true;
}

// A fold pressed into another: the legs of a U-turn 3 R apart along -x, the middle of the
// second (x = -0.1 m) pushed 1.3 R towards the first over 6 R either way, so that their
// tubes overlap by 0.3 R there; each method with and without contact surfaces.
bool write_contact_meshes(const std::string& dir) {
    std::vector<double> q;
    const double leg = 0.2, r = 1.5 * kRadius, step = 0.25 * kRadius, pi = 3.14159265358979323846;
    for (double x = -leg; x < 0.0; x += step) q.insert(q.end(), {x, -r, 0.0});
    for (int i = 0; i < 12; ++i) q.insert(q.end(), {r * std::sin(pi * i / 12), -r * std::cos(pi * i / 12), 0.0});
    for (double x = 0.0; x >= -leg - 1e-9; x -= step) {
        const double c = std::fabs(x + 0.1) < 6.0 * kRadius ? std::cos(0.5 * pi * (x + 0.1) / (6.0 * kRadius)) : 0.0;
        q.insert(q.end(), {x, r - 1.3 * kRadius * c * c, 0.0});
    }
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.effects = 0;
    desc.shape = ENT_SHAPE_POINTS;
    desc.control_points = uint32_t(q.size() / 3);
    desc.shape_points_xyz_m = q.data();
    desc.radius_m = kRadius;
    ent_scene* scene = nullptr;
    if (ent_scene_create(&desc, &scene) != ENT_OK) return false;
    bool ok = true;
    for (const Method& method : kMethods)
        for (int32_t contacts : {1, 0}) {
            Resolution resolution = kDefault;
            resolution.contact_surfaces = contacts;
            ent_skin* skin = make_skin(scene, method.id, resolution);
            const ent_mesh_view view = skin != nullptr ? enteron::bench::mesh_of(skin) : ent_mesh_view{};
            if (skin == nullptr || view.vertex_count == 0) {
                std::fprintf(stderr, "skin %s: %s\n", method.name, ent_last_error());
                ent_skin_destroy(skin);
                ok = false;
                continue;
            }
            sk::Mesh mesh;
            mesh.positions.assign(view.positions_xyz_m, view.positions_xyz_m + 3 * std::size_t(view.vertex_count));
            mesh.normals.assign(view.normals_xyz, view.normals_xyz + 3 * std::size_t(view.vertex_count));
            mesh.u.assign(view.axis_u, view.axis_u + view.vertex_count);
            mesh.indices.assign(view.indices, view.indices + 3 * std::size_t(view.triangle_count));
            ent_skin_destroy(skin);
            const std::string path = dir + "/" + method.name + (contacts ? "_contacts.ply" : "_through.ply");
            std::ofstream ply(path, std::ios::binary);
            if (!sk::write_ply(mesh, ply)) {
                std::fprintf(stderr, "cannot write %s\n", path.c_str());
                ok = false;
                continue;
            }
            std::fprintf(stderr, "wrote %s (%zu triangles)\n", path.c_str(), mesh.triangle_count());
        }
    ent_scene_destroy(scene);
    return ok;
}

// ---- marching cubes against VTK on the same field ---------------------------------------

// The point-skeleton field of the settled bowel at the default resolution, and the dense
// lattice of voxel R / 3 over the blocks of its band (outside the band: 0, below the iso).
struct BandField {
    sk::PointSkeletonSkin skin;
    std::vector<float> dense;
    int size[3] = {0, 0, 0};     // corners per axis
    int32_t first[3] = {0, 0, 0};  // lattice index of the dense lattice's first corner
    sk::SparseVoxelGrid dense_grid;  // the dense lattice as blocks, every corner in the band

    static sk::SkinSettings settings() {
        sk::SkinSettings s;
        s.method = sk::SkinMethod::point_skeleton;
        s.radius = kRadius;
        s.skeleton_spacing = kDefault.skeleton_spacing * kRadius;
        s.voxel_size = kDefault.voxel_size * kRadius;
        s.window = kRadius;
        return s;
    }
    BandField() : skin(settings()) {}

    bool build() {
        ent_scene* scene = settled_bowel();
        uint32_t count = 0;
        if (scene == nullptr || ent_scene_control_points(scene, 0, nullptr, &count) != ENT_OK) return false;
        std::vector<double> points(3 * std::size_t(count));
        if (ent_scene_control_points(scene, count, points.data(), &count) != ENT_OK) return false;
        skin.update(points.data(), count);
        const sk::SparseVoxelGrid& band = skin.band();
        int32_t lo[3] = {INT32_MAX, INT32_MAX, INT32_MAX}, hi[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
        for (std::size_t b = 0; b < band.block_count(); ++b)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], band.block(b).coordinates[std::size_t(a)]);
                hi[a] = std::max(hi[a], band.block(b).coordinates[std::size_t(a)]);
            }
        for (int a = 0; a < 3; ++a) {
            first[a] = lo[a] * sk::kBlockSize;
            size[a] = (hi[a] - lo[a] + 1) * sk::kBlockSize;
        }
        dense.assign(std::size_t(size[0]) * std::size_t(size[1]) * std::size_t(size[2]), 0.0f);
        for (std::size_t b = 0; b < band.block_count(); ++b) {
            const sk::VoxelBlock& block = band.block(b);
            for (int z = 0; z < sk::kBlockSize; ++z)
                for (int y = 0; y < sk::kBlockSize; ++y)
                    for (int x = 0; x < sk::kBlockSize; ++x) {
                        const std::size_t i = dense_index(block.coordinates[0] * sk::kBlockSize + x - first[0],
                                                          block.coordinates[1] * sk::kBlockSize + y - first[1],
                                                          block.coordinates[2] * sk::kBlockSize + z - first[2]);
                        dense[i] = std::max(0.0f, block.field[sk::SparseVoxelGrid::local_index(x, y, z)]);
                    }
        }
        // The same lattice as blocks for our marching cubes: every block of the box.
        dense_grid.reset(band.voxel_size(), std::size_t(size[0] * size[1] * size[2]) / sk::kBlockCorners);
        for (int32_t bz = lo[2]; bz <= hi[2]; ++bz)
            for (int32_t by = lo[1]; by <= hi[1]; ++by)
                for (int32_t bx = lo[0]; bx <= hi[0]; ++bx) {
                    sk::VoxelBlock& block = dense_grid.block(dense_grid.touch(bx, by, bz));
                    for (int z = 0; z < sk::kBlockSize; ++z)
                        for (int y = 0; y < sk::kBlockSize; ++y)
                            for (int x = 0; x < sk::kBlockSize; ++x) {
                                const std::size_t i = sk::SparseVoxelGrid::local_index(x, y, z);
                                block.field[i] = dense[dense_index(bx * sk::kBlockSize + x - first[0],
                                                                   by * sk::kBlockSize + y - first[1],
                                                                   bz * sk::kBlockSize + z - first[2])];
                                block.nearest[i] = sk::nearest_key(0.0f, 0);
                            }
                }
        return true;
    }
    std::size_t dense_index(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(size[0]) * (std::size_t(y) + std::size_t(size[1]) * std::size_t(z));
    }
    // Cells of the dense lattice: the voxels each implementation is charged for.
    double cells() const { return double(size[0] - 1) * double(size[1] - 1) * double(size[2] - 1); }
};

std::unique_ptr<BandField> band_field_storage;  // made by the first marching_cubes benchmark
bool band_field_tried = false;

BandField* band_field() {
    if (!band_field_tried) {
        band_field_tried = true;
        band_field_storage = std::make_unique<BandField>();
        if (!band_field_storage->build()) band_field_storage.reset();
    }
    return band_field_storage.get();
}

void report_voxels(benchmark::State& state, double voxels, std::size_t triangles) {
    state.counters["voxels"] = voxels;
    state.counters["voxels_per_s"] = benchmark::Counter(voxels, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["triangles"] = double(triangles);
}

void enteron_marching_cubes(benchmark::State& state, bool band_only) {
    BandField* field = band_field();
    if (field == nullptr) {
        state.SkipWithError(ent_last_error());
        return;
    }
    const sk::SparseVoxelGrid& grid = band_only ? field->skin.band() : field->dense_grid;
    sk::MarchingCubes cubes;
    sk::Mesh mesh;
    std::vector<int32_t> seeds;
    for (auto _ : state) {
        cubes.extract(grid, field->skin.iso_value(), mesh, seeds);
        benchmark::DoNotOptimize(mesh.indices.data());
    }
    report_voxels(state, band_only ? double(cubes.cells_in_band()) : field->cells(), mesh.triangle_count());
}

#ifdef ENTERON_HAVE_VTK
void vtk_marching_cubes(benchmark::State& state, enteron::peers::VtkFilter filter) {
    BandField* field = band_field();
    if (field == nullptr) {
        state.SkipWithError(ent_last_error());
        return;
    }
    enteron::peers::DenseField dense;
    dense.nx = field->size[0];
    dense.ny = field->size[1];
    dense.nz = field->size[2];
    dense.spacing = field->skin.band().voxel_size();
    for (int a = 0; a < 3; ++a) dense.origin[a] = field->first[a] * dense.spacing;
    dense.values = field->dense;
    enteron::peers::VtkIsoSurface surface(dense, field->skin.iso_value(), filter);
    std::size_t triangles = 0;
    for (auto _ : state) triangles = surface.run();
    report_voxels(state, field->cells(), triangles);
}
#endif

}  // namespace

int main(int argc, char** argv) {
    // Our own flag first (Google Benchmark refuses flags it does not know).
    std::string mesh_dir, contact_mesh_dir;
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument.rfind("--mesh_dir=", 0) == 0) {
            mesh_dir = argument.substr(std::strlen("--mesh_dir="));
        } else if (argument.rfind("--contact_mesh_dir=", 0) == 0) {
            contact_mesh_dir = argument.substr(std::strlen("--contact_mesh_dir="));
        } else {
            argv[kept++] = argv[i];
        }
    }
    argc = kept;

    // The demo pile keeps its names of before (skin/...), the tight-fold pile has its own.
    for (const enteron::bench::SkinPile& pile : enteron::bench::kSkinPiles)
        for (const Method& method : kMethods)
            for (const Resolution& resolution : kResolutions) {
                const std::string prefix = &pile == &enteron::bench::kSkinPiles[0] ? "skin" : pile.name;
                const std::string name = prefix + "/" + method.name + "/" + resolution.name;
                benchmark::RegisterBenchmark(name.c_str(), skin_benchmark, &pile, method.id, resolution)
                    ->Unit(benchmark::kMillisecond);
            }
    // Contacts: the default skins without contact surfaces, for their cost; the convolution's
    // skeleton following the curvature.
    for (const enteron::bench::SkinPile& pile : enteron::bench::kSkinPiles) {
        const std::string prefix = &pile == &enteron::bench::kSkinPiles[0] ? "skin" : pile.name;
        for (const Method& method : kMethods) {
            if (method.id == ENT_SKIN_TUBE) continue;  // no contact surfaces
            Resolution without = kDefault;
            without.contact_surfaces = 0;
            benchmark::RegisterBenchmark((prefix + "/" + method.name + "/default_no_contacts").c_str(), skin_benchmark,
                                         &pile, method.id, without)
                ->Unit(benchmark::kMillisecond);
        }
        for (const auto& [h, e] : {std::pair{1.0, 0.0}, {1.0, 0.01}, {1.0, 0.005}, {1.0, 0.002}, {0.5, 0.002}}) {
            char name[96];
            std::snprintf(name, sizeof name, "%s/convolution/skeleton_h%.2f_e%.3f", prefix.c_str(), h, e);
            Resolution follows = kDefault;
            follows.skeleton_spacing = h;
            follows.skeleton_chord_error = e;
            benchmark::RegisterBenchmark(name, skin_benchmark, &pile, ENT_SKIN_CONVOLUTION, follows)
                ->Unit(benchmark::kMillisecond);
        }
        for (const Method& method : kMethods)
            benchmark::RegisterBenchmark((std::string("popping/") + pile.name + "/" + method.name).c_str(),
                                         popping_benchmark, &pile, method.id)
                ->Unit(benchmark::kMillisecond)
                ->Iterations(1);
    }
    // A radius profile: the tapered colon beside the same colon of its largest radius.
    for (const Method& method : kMethods)
        for (const bool tapered : {false, true})
            benchmark::RegisterBenchmark(
                (std::string("colon/") + (tapered ? "tapered/" : "constant/") + method.name).c_str(), colon_benchmark,
                tapered, method.id, kDefault)
                ->Unit(benchmark::kMillisecond);
    // The point skeleton's voxel a third of the thin end's radius instead of the largest's.
    Resolution thin_voxel = kDefault;
    thin_voxel.voxel_size = 0.013 / 0.035 / 3.0;
    benchmark::RegisterBenchmark("colon/tapered/point_skeleton_thin_voxel", colon_benchmark, true,
                                 ENT_SKIN_POINT_SKELETON, thin_voxel)
        ->Unit(benchmark::kMillisecond);
    // Level of detail: even rings against adaptive ones (at most R apart), 16 segments.
    for (double spacing : {1.0, 0.75, 0.5, 0.35, 0.25}) {
        char name[64];
        std::snprintf(name, sizeof name, "skin/convolution_rings/even_%.2f", spacing);
        benchmark::RegisterBenchmark(name, skin_benchmark, &enteron::bench::kSkinPiles[0], ENT_SKIN_CONVOLUTION,
                                     Resolution{"even", 16, spacing, 0.25, 1.0 / 3.0, 0.0})
            ->Unit(benchmark::kMillisecond);
    }
    for (double chord_error : {0.02, 0.01, 0.005, 0.0025}) {
        char name[64];
        std::snprintf(name, sizeof name, "skin/convolution_rings/lod_%.4f", chord_error);
        benchmark::RegisterBenchmark(name, skin_benchmark, &enteron::bench::kSkinPiles[0], ENT_SKIN_CONVOLUTION,
                                     Resolution{"lod", 16, 1.0, 0.25, 1.0 / 3.0, chord_error})
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::RegisterBenchmark("marching_cubes/enteron_dense", enteron_marching_cubes, false)
        ->Unit(benchmark::kMillisecond);
#ifdef ENTERON_HAVE_VTK
    benchmark::RegisterBenchmark("marching_cubes/vtkFlyingEdges3D", vtk_marching_cubes,
                                 enteron::peers::VtkFilter::flying_edges)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("marching_cubes/vtkMarchingCubes", vtk_marching_cubes,
                                 enteron::peers::VtkFilter::marching_cubes)
        ->Unit(benchmark::kMillisecond);
#else
    std::fprintf(stderr, "VTK not found at build time (libvtk9-dev): the VTK marching cubes peers are skipped\n");
#endif
    benchmark::RegisterBenchmark("marching_cubes/enteron_band", enteron_marching_cubes, true)
        ->Unit(benchmark::kMillisecond);

    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    if (!mesh_dir.empty() && !write_meshes(mesh_dir)) return 1;
    if (!contact_mesh_dir.empty() && !write_contact_meshes(contact_mesh_dir)) return 1;
    for (const enteron::bench::SkinPile& pile : enteron::bench::kSkinPiles) {
        const ent_scene* scene = settled(pile);
        if (scene == nullptr) continue;
        const enteron::bench::BendRadii bends = enteron::bench::bend_radii(scene, kRadius);
        std::fprintf(stderr, "%s: axis bending with a radius under", pile.name);
        for (std::size_t k = 0; k < std::size(bends.fraction_under); ++k)
            std::fprintf(stderr, " %g R %.0f %%%s", enteron::bench::BendRadii::kThresholds[k],
                         100.0 * bends.fraction_under[k], k + 1 < std::size(bends.fraction_under) ? "," : ";");
        std::fprintf(stderr, " smallest radius %.2f R, tightest U-turn %.2f R\n", bends.smallest, bends.tightest_u_turn);
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    band_field_storage.reset();
    for (const enteron::bench::SkinPile& pile : enteron::bench::kSkinPiles) ent_scene_destroy(settled(pile));
    for (const bool tapered : {false, true}) ent_scene_destroy(settled_colon(tapered));
    return 0;
}
