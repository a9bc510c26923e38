// SPDX-License-Identifier: Apache-2.0
// Save and restore (ent_scene_save_state, ent_scene_restore_state; docs/scoring-and-state.md).
//
// A restored scene continues bit-identically: the test runs a scripted trainee (a tool
// pushing through a self-colliding pile in a box, grasping and pulling, releasing) for N
// steps after a save, restores, runs the same N steps again and compares every control
// point's bits, the tool's wrench and the contact list, step by step; the same in a fresh
// scene made from the same description. A bad image (truncated, changed, another version,
// another scene, a non-finite value, random corruption) is refused with a message and
// leaves the scene exactly as it was (its saved image compares equal byte for byte).
#include "capi_test_support.h"
#include "saved_state_image.h"

#include <cstdint>
#include <random>

#include "test_helpers.h"

using namespace capi_test;
using saved_state_image::kHeaderSize;
using saved_state_image::reseal;

namespace {

using enteron_test::kIdentity;

// A serpentine pile in a box, self-colliding, with a tool (implicit Euler).
const char* const kPile = R"({
  "intestine": {"length": 1.0, "control_points": 24, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                "shape": {"kind": "serpentine", "leg_length": 0.12, "center": [0, 0, -0.05]}},
  "solver": {"max_substeps": 100}, "gravity": [0, 0, -9.81], "damping": {},
  "environment": [{"type": "box_inside", "half_extents": [0.1, 0.1, 0.1]}], "self_collision": {},
  "tools": [{"position": [0, 0, 0.02]}]})";

constexpr double kDt = 1e-3;

// Where the tool goes down: over control point 6 of the pile at its start (x, y).
double g_aim[2] = {0.0, 0.0};

ScenePtr create_pile() {
    ScenePtr scene = create_json(kPile);
    if (scene) {
        const std::vector<double> q = control_points(scene.get());
        g_aim[0] = q[3 * 6];
        g_aim[1] = q[3 * 6 + 1];
    }
    return scene;
}

// The trainee's hand at step k: down onto the pile as it falls to the floor, grasp at step
// 120, pull up, release at 200.
void script(ent_scene* scene, int k) {
    const double depth = std::min(0.001 * k, 0.1);
    const double lift = k > 120 ? 0.0005 * (k - 120) : 0.0;
    const double tip[3] = {g_aim[0] + 0.003 * std::sin(0.02 * k), g_aim[1], 0.02 - depth + lift};
    ASSERT_EQ(ent_tool_set_pose(scene, 0, tip, kIdentity), ENT_OK) << ent_last_error();
    if (k == 120) {
        ASSERT_EQ(ent_tool_grasp(scene, 0), ENT_OK) << ent_last_error();
    }
    if (k == 200) {
        ASSERT_EQ(ent_tool_release(scene, 0), ENT_OK) << ent_last_error();
    }
}

std::vector<unsigned char> save(ent_scene* scene) {
    size_t size = 0;
    EXPECT_EQ(ent_scene_save_state(scene, nullptr, 0, &size), ENT_OK) << ent_last_error();
    std::vector<unsigned char> image(size);
    size_t written = 0;
    EXPECT_EQ(ent_scene_save_state(scene, image.data(), image.size(), &written), ENT_OK) << ent_last_error();
    EXPECT_EQ(written, size);
    return image;
}

// Everything a step publishes that the test compares, as bytes.
std::vector<unsigned char> published(const ent_scene* scene) {
    std::vector<unsigned char> bytes;
    auto append = [&bytes](const void* data, std::size_t size) {
        const auto* at = static_cast<const unsigned char*>(data);
        bytes.insert(bytes.end(), at, at + size);
    };
    const std::vector<double> q = control_points(scene);
    append(q.data(), q.size() * sizeof(double));
    double force[3], torque[3];
    EXPECT_EQ(ent_tool_wrench(scene, 0, force, torque), ENT_OK) << ent_last_error();
    append(force, sizeof force);
    append(torque, sizeof torque);
    uint32_t count = 0;
    EXPECT_EQ(ent_scene_contacts(scene, 0, nullptr, &count), ENT_OK) << ent_last_error();
    std::vector<ent_contact> contacts(std::max<uint32_t>(count, 1));
    contacts[0].struct_size = sizeof(ent_contact);
    EXPECT_EQ(ent_scene_contacts(scene, count, contacts.data(), &count), ENT_OK) << ent_last_error();
    append(contacts.data(), count * sizeof(ent_contact));
    const ent_stats s = stats(scene);
    append(&s.time_s, sizeof s.time_s);
    append(&s.steps, sizeof s.steps);
    return bytes;
}

// Steps k = first .. first + count - 1 of a script (the trainee's by default); what each published.
std::vector<std::vector<unsigned char>> save_restore_run(ent_scene* scene, int first, int count,
                                            void (*script_step)(ent_scene*, int) = script) {
    std::vector<std::vector<unsigned char>> out;
    for (int k = first; k < first + count; ++k) {
        script_step(scene, k);
        EXPECT_EQ(ent_scene_step(scene, kDt), ENT_OK) << "step " << k << ": " << ent_last_error();
        out.push_back(published(scene));
    }
    return out;
}

void expect_same_runs(const std::vector<std::vector<unsigned char>>& a,
                      const std::vector<std::vector<unsigned char>>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) ASSERT_TRUE(a[k] == b[k]) << "the runs differ at step " << k;
}

// Restoring `image` must fail with `status` and a message holding `words`, and change nothing.
void expect_refused(ent_scene* scene, const std::vector<unsigned char>& image, ent_status status,
                    const std::string& words) {
    const std::vector<unsigned char> before = save(scene);
    const std::vector<unsigned char> shown = published(scene);
    EXPECT_EQ(ent_scene_restore_state(scene, image.data(), image.size()), status);
    EXPECT_NE(std::string(ent_last_error()).find(words), std::string::npos) << ent_last_error();
    EXPECT_TRUE(save(scene) == before) << "the scene changed";
    EXPECT_TRUE(published(scene) == shown) << "the published state changed";
}

TEST(SaveRestore, ARestoredSceneContinuesBitIdentically) {
    ScenePtr scene = create_pile();
    ASSERT_TRUE(scene);
    save_restore_run(scene.get(), 0, 100);
    const std::vector<unsigned char> image = save(scene.get());
    const std::vector<unsigned char> at_save = published(scene.get());
    // Through the grasp (step 120), the pull and the release (200).
    const auto first = save_restore_run(scene.get(), 100, 150);
    ASSERT_EQ(ent_scene_restore_state(scene.get(), image.data(), image.size()), ENT_OK) << ent_last_error();
    EXPECT_TRUE(published(scene.get()) == at_save) << "the restore publishes the saved instant";
    EXPECT_TRUE(save(scene.get()) == image) << "save after restore gives the same image";
    const auto second = save_restore_run(scene.get(), 100, 150);
    expect_same_runs(first, second);
    // The run touched and grasped: the comparison covered contacts and a grasp.
    ent_tool_contacts t{};
    t.struct_size = sizeof t;
    ASSERT_EQ(ent_tool_read_contacts(scene.get(), 0, &t), ENT_OK) << ent_last_error();
    EXPECT_GT(t.contact_impulse_magnitude_Ns, 0.0);
    ent_contact_summary s{};
    s.struct_size = sizeof s;
    ASSERT_EQ(ent_scene_contact_summary(scene.get(), &s), ENT_OK);
    EXPECT_GT(s.self_contacts + s.obstacle_contacts, 0u);
}

// bdf2 keeps a history of the previous substep (its own section): restored with the rest.
// Issue 27, defect 8: two runs that are bit-identical save bit-identical images. Before, 23
// bytes differed: the wall-clock figures (the last step's time, each effect's time) and the
// checksum over them.
TEST(SaveRestore, TwoIdenticalRunsSaveIdenticalImages) {
    std::vector<unsigned char> images[2];
    std::vector<std::vector<unsigned char>> runs[2];
    for (int r = 0; r < 2; ++r) {
        ScenePtr scene = create_pile();
        ASSERT_TRUE(scene);
        runs[r] = save_restore_run(scene.get(), 0, 150);
        images[r] = save(scene.get());
        ASSERT_GT(stats(scene.get()).last_step_ns, 0u) << "the scene does time its steps";
    }
    expect_same_runs(runs[0], runs[1]);
    ASSERT_EQ(images[0].size(), images[1].size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < images[0].size(); ++i) differing += images[0][i] != images[1][i] ? 1 : 0;
    EXPECT_EQ(differing, 0u) << "bytes differ between the images of two identical runs";
}

// The images of before (scene section version 1 and dynamics version 2, which held those
// wall-clock figures) still restore: the figures are read and dropped, and the scene
// continues as from the current image.
std::vector<unsigned char> with_wall_clock_figures(const std::vector<unsigned char>& image, uint32_t control_points) {
    using saved_state_image::kSectionHeaderSize;
    std::vector<unsigned char> old(image.begin(), image.begin() + kHeaderSize);
    const uint64_t figure = 123456789;  // ns
    for (std::size_t at = kHeaderSize; at < image.size();) {
        std::vector<unsigned char> header(image.begin() + at, image.begin() + at + kSectionHeaderSize);
        uint64_t size = 0;
        std::memcpy(&size, header.data() + 24, sizeof size);
        std::vector<unsigned char> payload(image.begin() + at + kSectionHeaderSize,
                                           image.begin() + at + kSectionHeaderSize + size);
        at += kSectionHeaderSize + size;
        const std::string name(reinterpret_cast<const char*>(header.data()));
        uint32_t version = 0;
        std::memcpy(&version, header.data() + 16, sizeof version);
        const auto insert_figure = [&](std::size_t offset) {
            payload.insert(payload.begin() + offset, reinterpret_cast<const unsigned char*>(&figure),
                           reinterpret_cast<const unsigned char*>(&figure) + sizeof figure);
        };
        if (name == "scene") {
            EXPECT_EQ(version, 2u);
            version = 1;  // the last step's time after the counters of steps, substeps, rollbacks
            insert_figure(4 + 8 + 2 * 3 * 8 * std::size_t{control_points} + 3 * 8);
        } else if (name == "dynamics") {
            EXPECT_EQ(version, 3u);
            version = 2;  // each effect's time after its calls
            for (int effect = ENT_EFFECT_COUNT - 1; effect >= 0; --effect) insert_figure(8 * std::size_t(effect + 1));
        }
        std::memcpy(header.data() + 16, &version, sizeof version);
        size = payload.size();
        std::memcpy(header.data() + 24, &size, sizeof size);
        old.insert(old.end(), header.begin(), header.end());
        old.insert(old.end(), payload.begin(), payload.end());
    }
    reseal(old);
    return old;
}

TEST(SaveRestore, ImagesWithWallClockFiguresStillRestore) {
    ScenePtr scene = create_pile();
    ASSERT_TRUE(scene);
    save_restore_run(scene.get(), 0, 120);
    const std::vector<unsigned char> image = save(scene.get());
    const std::vector<unsigned char> old = with_wall_clock_figures(image, 24);
    ASSERT_EQ(old.size(), image.size() + 8 + 8 * ENT_EFFECT_COUNT);
    ScenePtr from_new = create_pile(), from_old = create_pile();
    ASSERT_EQ(ent_scene_restore_state(from_new.get(), image.data(), image.size()), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_scene_restore_state(from_old.get(), old.data(), old.size()), ENT_OK) << ent_last_error();
    EXPECT_EQ(stats(from_old.get()).last_step_ns, 0u) << "a restore leaves this scene's wall-clock figures alone";
    // And what its steps did: this scene's run, not the saved state (ent_stats), but for the
    // full contact searches, which the restored scene continues from the saved count.
    EXPECT_EQ(stats(from_old.get()).max_step_ns, 0u);
    EXPECT_EQ(stats(from_old.get()).late_steps, 0u);
    EXPECT_EQ(stats(from_old.get()).last_step_attempts, 0u);
    EXPECT_EQ(stats(from_old.get()).last_step_substeps, 0u);
    EXPECT_EQ(stats(from_old.get()).full_contact_searches, stats(scene.get()).full_contact_searches);
    EXPECT_EQ(effect_stats(from_old.get(), ENT_EFFECT_STRETCH).total_time_ns, 0u);
    EXPECT_EQ(effect_stats(from_old.get(), ENT_EFFECT_STRETCH).calls,
              effect_stats(scene.get(), ENT_EFFECT_STRETCH).calls) << "the work counters are restored";
    EXPECT_TRUE(save(from_old.get()) == image) << "the old image restores the same state";
    expect_same_runs(save_restore_run(from_new.get(), 120, 60), save_restore_run(from_old.get(), 120, 60));
}

TEST(SaveRestore, Bdf2ContinuesBitIdentically) {
    std::string json = kPile;
    json.replace(json.find("\"max_substeps\": 100"), 19, "\"max_substeps\": 100, \"integrator\": \"bdf2\"");
    ScenePtr scene = create_json(json);
    ASSERT_TRUE(scene);
    const std::vector<double> q = control_points(scene.get());
    g_aim[0] = q[3 * 6];
    g_aim[1] = q[3 * 6 + 1];
    save_restore_run(scene.get(), 0, 100);
    const std::vector<unsigned char> image = save(scene.get());
    const auto first = save_restore_run(scene.get(), 100, 60);
    ScenePtr fresh = create_json(json);
    ASSERT_TRUE(fresh);
    ASSERT_EQ(ent_scene_restore_state(fresh.get(), image.data(), image.size()), ENT_OK) << ent_last_error();
    expect_same_runs(first, save_restore_run(fresh.get(), 100, 60));
}

TEST(SaveRestore, AFreshSceneFromTheSameDescriptionContinuesTheSame) {
    ScenePtr scene = create_pile();
    ASSERT_TRUE(scene);
    save_restore_run(scene.get(), 0, 130);  // grasping
    const std::vector<unsigned char> image = save(scene.get());
    const auto original = save_restore_run(scene.get(), 130, 100);

    ScenePtr fresh = create_pile();
    ASSERT_TRUE(fresh);
    ASSERT_EQ(ent_scene_restore_state(fresh.get(), image.data(), image.size()), ENT_OK) << ent_last_error();
    int32_t grasping = 0;
    ASSERT_EQ(ent_tool_state(fresh.get(), 0, &grasping), ENT_OK);
    EXPECT_EQ(grasping, 1) << "the grasp is part of the state";
    expect_same_runs(original, save_restore_run(fresh.get(), 130, 100));
}

// The anatomy the caller moves between steps: the box (obstacle 0) sways and turns a
// little each step, gravity tilts, a point is pinned on the box and the box's friction
// changes. All of it is state: restored with the rest.
void sway(ent_scene* scene, int k) {
    script(scene, k);
    const double position[3] = {0.004 * std::sin(0.05 * k), 0.0, 0.002 * std::sin(0.03 * k)};
    const double half = 0.02 * std::sin(0.04 * k);
    const double turn[4] = {std::cos(half), 0.0, 0.0, std::sin(half)};
    ASSERT_EQ(ent_obstacle_set_pose(scene, 0, position, turn), ENT_OK) << ent_last_error();
    if (k == 60) {
        ASSERT_EQ(ent_scene_pin_point(scene, 23, 0), ENT_OK) << ent_last_error();
        const double tilted[3] = {0.5, 0.0, -9.8};
        ASSERT_EQ(ent_scene_set_gravity(scene, tilted), ENT_OK) << ent_last_error();
        ASSERT_EQ(ent_obstacle_set_friction(scene, 0, 0.6), ENT_OK) << ent_last_error();
    }
}

std::vector<std::vector<unsigned char>> run_swaying(ent_scene* scene, int first, int count) {
    return save_restore_run(scene, first, count, sway);
}

TEST(SaveRestore, MovingAnatomyContinuesBitIdentically) {
    ScenePtr scene = create_pile();
    ASSERT_TRUE(scene);
    run_swaying(scene.get(), 0, 100);
    const std::vector<unsigned char> image = save(scene.get());
    const auto first = run_swaying(scene.get(), 100, 120);
    // Changed after the save: another pose, gravity, friction, the pin released.
    ASSERT_EQ(ent_scene_unpin_point(scene.get(), 23), ENT_OK) << ent_last_error();
    const double level[3] = {0.0, 0.0, -9.81};
    ASSERT_EQ(ent_scene_set_gravity(scene.get(), level), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_obstacle_set_friction(scene.get(), 0, 0.1), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_scene_restore_state(scene.get(), image.data(), image.size()), ENT_OK) << ent_last_error();
    EXPECT_TRUE(save(scene.get()) == image) << "save after restore gives the same image";
    expect_same_runs(first, run_swaying(scene.get(), 100, 120));

    // A fresh scene: pins exist only once one is made (the fingerprint counts the effects),
    // so pin one first; the restore puts the saved pins in its place.
    ScenePtr fresh = create_pile();
    ASSERT_TRUE(fresh);
    expect_refused(fresh.get(), image, ENT_ERROR_INVALID_ARGUMENT, "another scene");
    ASSERT_EQ(ent_scene_pin_point(fresh.get(), 0, ENT_NO_OBSTACLE), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_scene_restore_state(fresh.get(), image.data(), image.size()), ENT_OK) << ent_last_error();
    EXPECT_TRUE(save(fresh.get()) == image);
    expect_same_runs(first, run_swaying(fresh.get(), 100, 120));
}

TEST(SaveRestore, AnObstacleRemovedInOneSceneOnlyIsRefused) {
    ent_obstacle_desc plane;
    ent_obstacle_desc_default(&plane);
    plane.kind = ENT_OBSTACLE_PLANE;
    plane.center_m[2] = -0.2;
    ScenePtr scene = create_pile();
    ASSERT_TRUE(scene);
    ASSERT_EQ(ent_scene_add_obstacle(scene.get(), &plane, nullptr), ENT_OK) << ent_last_error();
    save_restore_run(scene.get(), 0, 10);
    ASSERT_EQ(ent_scene_remove_obstacle(scene.get(), 1), ENT_OK) << ent_last_error();
    const std::vector<unsigned char> image = save(scene.get());
    ScenePtr fresh = create_pile();
    ASSERT_TRUE(fresh);
    ASSERT_EQ(ent_scene_add_obstacle(fresh.get(), &plane, nullptr), ENT_OK) << ent_last_error();
    expect_refused(fresh.get(), image, ENT_ERROR_INVALID_ARGUMENT, "obstacle 1 was removed from the saved scene");
    ASSERT_EQ(ent_scene_remove_obstacle(fresh.get(), 1), ENT_OK) << ent_last_error();
    EXPECT_EQ(ent_scene_restore_state(fresh.get(), image.data(), image.size()), ENT_OK) << ent_last_error();
}

TEST(SaveRestore, AStateOfAnotherSceneIsRefused) {
    ScenePtr scene = create_pile();
    ASSERT_TRUE(scene);
    save_restore_run(scene.get(), 0, 10);
    const std::vector<unsigned char> image = save(scene.get());
    // Another length; and the same description with one more obstacle added.
    std::string longer = kPile;
    longer.replace(longer.find("\"length\": 1.0"), 13, "\"length\": 1.1");
    ScenePtr other = create_json(longer);
    ASSERT_TRUE(other);
    expect_refused(other.get(), image, ENT_ERROR_INVALID_ARGUMENT, "another scene");
    ScenePtr more = create_json(kPile);
    ASSERT_TRUE(more);
    ent_obstacle_desc plane;
    ent_obstacle_desc_default(&plane);
    plane.kind = ENT_OBSTACLE_PLANE;
    plane.center_m[2] = -0.2;
    ASSERT_EQ(ent_scene_add_obstacle(more.get(), &plane, nullptr), ENT_OK) << ent_last_error();
    expect_refused(more.get(), image, ENT_ERROR_INVALID_ARGUMENT, "another scene");
}

TEST(SaveRestore, BadImagesAreRefusedWithTheSceneUntouched) {
    ScenePtr scene = create_pile();
    ASSERT_TRUE(scene);
    save_restore_run(scene.get(), 0, 20);
    const std::vector<unsigned char> good = save(scene.get());
    save_restore_run(scene.get(), 20, 5);  // so that a wrongly applied restore would show

    std::vector<unsigned char> image(good.begin(), good.end() - 1);
    expect_refused(scene.get(), image, ENT_ERROR_INVALID_ARGUMENT, "truncated");
    image.assign(good.begin(), good.begin() + 20);
    expect_refused(scene.get(), image, ENT_ERROR_INVALID_ARGUMENT, "header");
    image = good;
    image[0] = 'X';
    expect_refused(scene.get(), image, ENT_ERROR_INVALID_ARGUMENT, "ENTSTATE");
    image = good;
    image[image.size() / 2] ^= 0x10;
    expect_refused(scene.get(), image, ENT_ERROR_INVALID_ARGUMENT, "checksum");
    image = good;
    image[saved_state_image::kVersionAt] = 99;
    expect_refused(scene.get(), image, ENT_ERROR_VERSION, "format version 99");
    // The time made NaN, resealed: the value check names it.
    image = good;
    const double nan = std::nan("");
    std::memcpy(image.data() + saved_state_image::kTimeAt, &nan, 8);
    reseal(image);
    expect_refused(scene.get(), image, ENT_ERROR_INVALID_ARGUMENT, "time");
    // A position made infinite, resealed: the last section applied nothing either.
    image = good;
    const double infinite = HUGE_VAL;
    std::memcpy(image.data() + saved_state_image::kPositionsAt + 8 * 5, &infinite, 8);
    reseal(image);
    expect_refused(scene.get(), image, ENT_ERROR_INVALID_ARGUMENT, "positions");

    EXPECT_EQ(ent_scene_restore_state(scene.get(), nullptr, 100), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_scene_restore_state(nullptr, good.data(), good.size()), ENT_ERROR_INVALID_ARGUMENT);
    // After all that, the good image still restores.
    EXPECT_EQ(ent_scene_restore_state(scene.get(), good.data(), good.size()), ENT_OK) << ent_last_error();
    EXPECT_TRUE(save(scene.get()) == good);
}

TEST(SaveRestore, ASmallBufferGetsTheSizeAndNothingWritten) {
    ScenePtr scene = create_pile();
    ASSERT_TRUE(scene);
    size_t size = 0;
    ASSERT_EQ(ent_scene_save_state(scene.get(), nullptr, 0, &size), ENT_OK);
    ASSERT_GT(size, 48u);
    std::vector<unsigned char> buffer(size - 1, 0xa5);
    size_t reported = 0;
    EXPECT_EQ(ent_scene_save_state(scene.get(), buffer.data(), buffer.size(), &reported), ENT_ERROR_BUFFER_TOO_SMALL);
    EXPECT_EQ(reported, size);
    EXPECT_TRUE(std::all_of(buffer.begin(), buffer.end(), [](unsigned char b) { return b == 0xa5; }));
    EXPECT_EQ(ent_scene_save_state(scene.get(), buffer.data(), buffer.size(), nullptr), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_scene_save_state(nullptr, nullptr, 0, &reported), ENT_ERROR_INVALID_ARGUMENT);
}

// A bowel falling against drag under a speed limit it soon exceeds whatever the substep
// (test_unstable.cpp works out the speeds): step 1 passes, step 2 fails with
// ENT_ERROR_UNSTABLE. Restoring the state saved at rest gets it going again, and its step 1
// is bit for bit the first run's.
TEST(SaveRestore, RestoreRecoversFromUnstable) {
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) | ENT_EFFECT_BIT(ENT_EFFECT_DAMPING);
    desc.control_points = 10;
    desc.length_m = 1.0;
    desc.linear_density_kg_per_m = 0.3;
    desc.shape = ENT_SHAPE_LINE;
    desc.integrator = ENT_INTEGRATOR_SYMPLECTIC_EULER;
    desc.timestep_s = 0.01;
    desc.drag_N_s_per_m2 = 3.0;
    desc.stretch_damping_N_s = 0.0;
    desc.bend_damping_N_m2_s = 0.0;
    desc.max_speed_m_per_s = 0.097;
    desc.max_subdivisions = 4;
    ScenePtr scene = create(desc);
    ASSERT_TRUE(scene);
    const std::vector<unsigned char> at_rest = save(scene.get());
    ASSERT_EQ(ent_scene_step(scene.get(), 0.01), ENT_OK) << ent_last_error();
    const std::vector<double> after_one = control_points(scene.get());
    ASSERT_EQ(ent_scene_step(scene.get(), 0.01), ENT_ERROR_UNSTABLE);
    ASSERT_EQ(ent_scene_step(scene.get(), 0.01), ENT_ERROR_UNSTABLE) << "stuck";
    ASSERT_EQ(ent_scene_restore_state(scene.get(), at_rest.data(), at_rest.size()), ENT_OK) << ent_last_error();
    EXPECT_EQ(stats(scene.get()).steps, 0u);
    EXPECT_EQ(stats(scene.get()).rollbacks, 0u) << "the counters are part of the state";
    ASSERT_EQ(ent_scene_step(scene.get(), 0.01), ENT_OK) << ent_last_error();
    const std::vector<double> again = control_points(scene.get());
    ASSERT_EQ(again.size(), after_one.size());
    EXPECT_EQ(std::memcmp(again.data(), after_one.data(), again.size() * sizeof(double)), 0);
}

// Random corruption of a saved image (a few bytes changed, resealed or not; cut or padded):
// every restore returns ENT_OK or a status with a message; a refused one changes nothing;
// an accepted one leaves a finite scene that steps or fails cleanly.
TEST(SaveRestore, FuzzedImagesFailCleanly) {
    ScenePtr scene = create_pile();
    ASSERT_TRUE(scene);
    save_restore_run(scene.get(), 0, 130);
    const std::vector<unsigned char> good = save(scene.get());
    std::mt19937_64 random(22);
    int accepted = 0, refused = 0;
    std::vector<unsigned char> before = good;
    for (int trial = 0; trial < 1500; ++trial) {
        std::vector<unsigned char> image = good;
        const int kind = trial % 4;
        if (kind == 3) {
            image.resize(std::uniform_int_distribution<std::size_t>(0, 2 * good.size())(random));
        } else {
            const int changes = 1 + int(random() % 8);
            for (int c = 0; c < changes; ++c) {
                // Header and section headers more often: they hold the sizes and counts.
                const std::size_t at = random() % 2 == 0 ? random() % std::min<std::size_t>(image.size(), 256)
                                                          : random() % image.size();
                image[at] = static_cast<unsigned char>(random());
            }
        }
        if (kind != 0 && image.size() >= kHeaderSize) reseal(image);
        const ent_status status = ent_scene_restore_state(scene.get(), image.data(), image.size());
        if (status != ENT_OK) {
            ASSERT_NE(std::string(ent_last_error()), "") << "trial " << trial;
            ASSERT_TRUE(save(scene.get()) == before) << "trial " << trial << ": a refused restore changed the scene";
            ++refused;
            continue;
        }
        ++accepted;
        for (const double x : control_points(scene.get())) ASSERT_TRUE(std::isfinite(x)) << "trial " << trial;
        const ent_status step = ent_scene_step(scene.get(), kDt);
        ASSERT_TRUE(step == ENT_OK || step == ENT_ERROR_UNSTABLE) << "trial " << trial << ": " << ent_last_error();
        ASSERT_EQ(ent_scene_restore_state(scene.get(), good.data(), good.size()), ENT_OK) << ent_last_error();
        before = save(scene.get());
    }
    EXPECT_GT(refused, 1000);
    std::cout << "[ fuzzed restores ] " << refused << " refused, " << accepted << " accepted\n";
}

}  // namespace
