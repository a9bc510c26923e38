// SPDX-License-Identifier: Apache-2.0
// A mesh a GPU can keep (ent_skin_desc.stable_topology, ent_mesh_view's around_v,
// tangents_xyz, topology_serial, topology_changed, stable_topology): on a bowel that swings
// and stretches, the tube and the convolution skins keep their vertex count and indices
// across updates; with levels of detail they change in counted steps; point_skeleton says
// it changes every time. v stays in [0, 1), does not twist along the bowel or jump between
// frames; tangents are unit, perpendicular to the normals, along increasing u.
#include "skin_test_support.h"

#include <cmath>

using namespace capi_test;
using namespace skin_test;

namespace {

constexpr double kSkinTopologyPi = 3.14159265358979323846;

// The public header only: a small vector of our own.
struct Vec3 {
    double x, y, z;
    Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    double dot(const Vec3& o) const { return x * o.x + y * o.y + z * o.z; }
    double norm() const { return std::sqrt(dot(*this)); }
};


// A 1 m bowel released as a helix, held by its mesentery: it falls, swings and stretches.
ScenePtr swinging_scene() {
    ent_scene_desc desc = default_desc();
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
    desc.length_m = 1.0;
    desc.control_points = 40;
    desc.shape = ENT_SHAPE_HELIX;
    return create(desc);
}

SkinPtr make(ent_scene* scene, int32_t method, double chord_error = 0.0, int32_t stable = 1) {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    EXPECT_EQ(desc.stable_topology, 1);  // the default
    desc.method = method;
    desc.ring_chord_error_radii = chord_error;
    desc.stable_topology = stable;
    ent_skin* skin = nullptr;
    EXPECT_EQ(ent_skin_create(scene, &desc, &skin), ENT_OK) << ent_last_error();
    return SkinPtr(skin);
}

std::vector<uint32_t> indices_of(const ent_mesh_view& v) {
    return std::vector<uint32_t>(v.indices, v.indices + 3 * std::size_t{v.triangle_count});
}

Vec3 vec(const float* xyz, uint32_t i) { return Vec3{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}; }

// The distance between two values of v on the circle [0, 1).
double v_distance(float a, float b) {
    const double d = std::fabs(double(a) - double(b));
    return std::min(d, 1.0 - d);
}

// Tangents unit (to float rounding), perpendicular to the normal, and along increasing u:
// towards the neighbour with the larger u wherever u changes across a triangle edge.
void expect_good_tangents(const ent_mesh_view& v) {
    double worst_length = 0.0, worst_dot = 0.0;
    for (uint32_t i = 0; i < v.vertex_count; ++i) {
        const Vec3 t = vec(v.tangents_xyz, i), n = vec(v.normals_xyz, i);
        worst_length = std::max(worst_length, std::fabs(t.norm() - 1.0));
        worst_dot = std::max(worst_dot, std::fabs(t.dot(n)));
    }
    EXPECT_LT(worst_length, 1e-6);
    EXPECT_LT(worst_dot, 1e-5);
    std::size_t along = 0, against = 0;
    for (uint32_t k = 0; k < 3 * v.triangle_count; ++k) {
        const uint32_t a = v.indices[k], b = v.indices[k - k % 3 + (k + 1) % 3];
        if (std::fabs(v.axis_u[b] - v.axis_u[a]) < 1e-6f) continue;
        const Vec3 edge = vec(v.positions_xyz_m, b) - vec(v.positions_xyz_m, a);
        const double sign = v.axis_u[b] > v.axis_u[a] ? 1.0 : -1.0;
        (sign * edge.dot(vec(v.tangents_xyz, a)) > 0.0 ? along : against) += 1;
    }
    EXPECT_GT(along, 0u);
    EXPECT_LE(against, along / 100) << "tangents against increasing u";
}

TEST(SkinTopology, RingSkinsKeepTheirIndicesWhileTheBowelMoves) {
    for (int32_t method : {ENT_SKIN_TUBE, ENT_SKIN_CONVOLUTION}) {
        SCOPED_TRACE(method);
        ScenePtr scene = swinging_scene();
        ASSERT_TRUE(scene);
        SkinPtr skin = make(scene.get(), method);
        ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
        const ent_mesh_view first = mesh(skin.get());
        EXPECT_EQ(first.stable_topology, 1);
        EXPECT_EQ(first.topology_changed, 1);  // the first update makes the indices
        EXPECT_EQ(first.topology_serial, 1u);
        const std::vector<uint32_t> indices = indices_of(first);
        const std::vector<float> v(first.around_v, first.around_v + first.vertex_count);
        const std::vector<float> start(first.positions_xyz_m, first.positions_xyz_m + 3 * first.vertex_count);
        for (int frame = 0; frame < 40; ++frame) {
            ASSERT_TRUE(step_n(scene.get(), 1e-3, 25));
            ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
            const ent_mesh_view now = mesh(skin.get());
            ASSERT_EQ(now.topology_changed, 0) << "frame " << frame;
            ASSERT_EQ(now.topology_serial, 1u);
            ASSERT_EQ(now.vertex_count, first.vertex_count);
            ASSERT_EQ(indices_of(now), indices);
            ASSERT_TRUE(std::equal(v.begin(), v.end(), now.around_v));
            expect_good_tangents(now);
        }
        // It did move: a renderer that kept the indices drew the new positions.
        const ent_mesh_view last = mesh(skin.get());
        double moved = 0.0;
        for (uint32_t i = 0; i < 3 * last.vertex_count; ++i)
            moved = std::max(moved, double(std::fabs(last.positions_xyz_m[i] - start[i])));
        EXPECT_GT(moved, 0.05);
    }
}

TEST(SkinTopology, WithoutStableTopologyTheRingsFollowTheStretch) {
    // The same swing with stable_topology 0: rings every ring_spacing of the current
    // length, so their count follows the stretch, and each change is flagged and counted.
    ScenePtr scene = swinging_scene();
    SkinPtr skin = make(scene.get(), ENT_SKIN_TUBE, 0.0, 0);
    ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK);
    EXPECT_EQ(mesh(skin.get()).stable_topology, 0);
    uint64_t serial = mesh(skin.get()).topology_serial, flagged = 0;
    uint32_t previous = mesh(skin.get()).vertex_count;
    for (int frame = 0; frame < 40; ++frame) {
        ASSERT_TRUE(step_n(scene.get(), 1e-3, 25));
        ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK);
        const ent_mesh_view now = mesh(skin.get());
        EXPECT_EQ(now.topology_changed == 1, now.vertex_count != previous) << "frame " << frame;
        flagged += uint64_t(now.topology_changed);
        previous = now.vertex_count;
    }
    EXPECT_GT(flagged, 0u);
    EXPECT_EQ(mesh(skin.get()).topology_serial, serial + flagged);
}

TEST(SkinTopology, LevelsOfDetailChangeInCountedSteps) {
    // Rings closer where the bends need them: the topology changes, but rarely, in whole
    // levels, and every change is flagged; between changes the indices stay the same.
    ScenePtr scene = swinging_scene();
    SkinPtr skin = make(scene.get(), ENT_SKIN_CONVOLUTION, 0.01);
    ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK);
    ent_mesh_view previous = mesh(skin.get());
    std::vector<uint32_t> indices = indices_of(previous);
    int changes = 0;
    const int frames = 40;
    for (int frame = 0; frame < frames; ++frame) {
        ASSERT_TRUE(step_n(scene.get(), 1e-3, 25));
        ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK);
        const ent_mesh_view now = mesh(skin.get());
        EXPECT_EQ(now.topology_serial, previous.topology_serial + uint64_t(now.topology_changed));
        if (now.topology_changed == 0) {
            ASSERT_EQ(indices_of(now), indices) << "frame " << frame;
        } else {
            ++changes;
            indices = indices_of(now);
        }
        expect_good_tangents(now);
        previous = now;
    }
    EXPECT_LT(changes, frames / 2);
}

TEST(SkinTopology, PointSkeletonSaysItsTopologyChangesEveryUpdate) {
    ScenePtr scene = swinging_scene();
    SkinPtr skin = make(scene.get(), ENT_SKIN_POINT_SKELETON);
    for (uint64_t update = 1; update <= 3; ++update) {
        ASSERT_TRUE(step_n(scene.get(), 1e-3, 25));
        ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK);
        const ent_mesh_view now = mesh(skin.get());
        EXPECT_EQ(now.stable_topology, 0);
        EXPECT_EQ(now.topology_changed, 1);
        EXPECT_EQ(now.topology_serial, update);
        expect_good_tangents(now);
        for (uint32_t i = 0; i < now.vertex_count; ++i) {
            ASSERT_GE(now.around_v[i], 0.0f);
            ASSERT_LT(now.around_v[i], 1.0f);
        }
    }
}

TEST(SkinTopology, AroundVIsContinuousAlongTheBowelAndBetweenFrames) {
    ScenePtr scene = swinging_scene();
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 300));
    for (int32_t method : {ENT_SKIN_TUBE, ENT_SKIN_CONVOLUTION, ENT_SKIN_POINT_SKELETON}) {
        SCOPED_TRACE(method);
        SkinPtr skin = make(scene.get(), method);
        ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK);
        const ent_mesh_view view = mesh(skin.get());
        // In range, and continuous over the surface: across every triangle edge of the body
        // v changes by little (on the circle: it wraps from just below 1 to 0).
        double largest_step = 0.0;
        for (uint32_t i = 0; i < view.vertex_count; ++i) {
            ASSERT_GE(view.around_v[i], 0.0f);
            ASSERT_LT(view.around_v[i], 1.0f);
        }
        for (uint32_t k = 0; k < 3 * view.triangle_count; ++k) {
            const uint32_t a = view.indices[k], b = view.indices[k - k % 3 + (k + 1) % 3];
            const bool body = view.axis_u[a] > 0.02f && view.axis_u[a] < 0.98f && view.axis_u[b] > 0.02f &&
                              view.axis_u[b] < 0.98f;
            if (body) largest_step = std::max(largest_step, v_distance(view.around_v[a], view.around_v[b]));
        }
        // Ring skins: neighbours are one segment (1/16) apart at most; marching cubes' edges
        // are a third of R, a sixth of a turn where the surface is most curved.
        EXPECT_LT(largest_step, method == ENT_SKIN_POINT_SKELETON ? 0.2 : 1.0 / 16.0 + 1e-6);
    }
    // Along the bowel v = 0 does not twist: from one body ring of the tube to the next, its
    // direction turns no more than the axis does (the tube's normals and tangents are the
    // exact radial direction and axis tangent).
    {
        SkinPtr tube = make(scene.get(), ENT_SKIN_TUBE);
        ASSERT_EQ(ent_skin_update(tube.get()), ENT_OK);
        const ent_mesh_view v = mesh(tube.get());
        const uint32_t rings = (v.vertex_count - 2) / 16 - 2 * 4;
        auto angle = [](Vec3 a, Vec3 b) { return std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0)); };
        for (uint32_t k = 0; k + 1 < rings; ++k) {
            const uint32_t i = 1 + (4 + k) * 16, j = i + 16;
            ASSERT_EQ(v.around_v[i], 0.0f);
            ASSERT_LE(angle(vec(v.normals_xyz, i), vec(v.normals_xyz, j)),
                      angle(vec(v.tangents_xyz, i), vec(v.tangents_xyz, j)) + 1e-3)
                << "ring " << k;
        }
    }
    // v = 0 is the rotation-minimising normal: from one frame to the next it moves with the
    // bowel, it does not spin. The direction of the first body ring's v = 0 vertex turns by
    // about as much as the bowel's end does between two frames 5 ms apart.
    SkinPtr tube = make(scene.get(), ENT_SKIN_TUBE);
    ASSERT_EQ(ent_skin_update(tube.get()), ENT_OK);
    auto seam = [&](const ent_mesh_view& v) {
        // Vertex 1 + cap_rings * segments is the first body ring's v = 0 (ring grid layout).
        const uint32_t i = 1 + 4 * 16;
        EXPECT_EQ(v.around_v[i], 0.0f);
        return vec(v.normals_xyz, i);
    };
    Vec3 before = seam(mesh(tube.get()));
    for (int frame = 0; frame < 20; ++frame) {
        ASSERT_TRUE(step_n(scene.get(), 1e-3, 5));
        ASSERT_EQ(ent_skin_update(tube.get()), ENT_OK);
        const Vec3 after = seam(mesh(tube.get()));
        EXPECT_LT(std::acos(std::min(1.0, before.dot(after))), 0.1 * kSkinTopologyPi) << "frame " << frame;
        before = after;
    }
}

TEST(SkinTopology, OldMeshViewsAndDescsAreServedAsBefore) {
    ScenePtr scene = swinging_scene();
    // An ent_skin_desc from before stable_topology: the skin keeps its topology (default 1).
    ent_skin_desc old;
    std::memset(&old, 0xcd, sizeof old);
    ASSERT_EQ(ent_skin_desc_init(&old, uint32_t(offsetof(ent_skin_desc, stable_topology))), ENT_OK)
        << ent_last_error();
    ent_skin* raw = nullptr;
    ASSERT_EQ(ent_skin_create(scene.get(), &old, &raw), ENT_OK) << ent_last_error();
    SkinPtr skin(raw);
    ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK);
    EXPECT_EQ(mesh(skin.get()).stable_topology, 1);
    // An ent_mesh_view from before around_v: nothing written past it.
    ent_mesh_view view;
    std::memset(&view, 0xcd, sizeof view);
    view.struct_size = uint32_t(offsetof(ent_mesh_view, around_v));
    ASSERT_EQ(ent_skin_mesh(skin.get(), &view), ENT_OK) << ent_last_error();
    EXPECT_GT(view.vertex_count, 0u);
    const unsigned char* bytes = reinterpret_cast<const unsigned char*>(&view);
    for (std::size_t i = offsetof(ent_mesh_view, around_v); i < sizeof view; ++i) ASSERT_EQ(bytes[i], 0xcd) << i;
    // stable_topology out of {0, 1} is refused by name.
    ent_skin_desc bad;
    ent_skin_desc_default(&bad);
    bad.stable_topology = 2;
    raw = nullptr;
    EXPECT_EQ(ent_skin_create(scene.get(), &bad, &raw), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(raw, nullptr);
    EXPECT_NE(std::string(ent_last_error()).find("stable_topology"), std::string::npos) << ent_last_error();
}

}  // namespace
