// Bad input never crashes, gives the documented status and a message naming the input, leaves
// out_scene untouched, and leaves an existing scene exactly as it was.
#include "capi_test_support.h"

#include <functional>
#include <limits>

using namespace capi_test;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// A recognisable value that no successful create would write.
ent_scene* sentinel() {
    static char storage;
    return reinterpret_cast<ent_scene*>(&storage);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

ent_scene_desc small_desc() {
    ent_scene_desc desc = default_desc();
    desc.control_points = 12;
    desc.length_m = 1.0;
    return desc;
}

// ---- ent_scene_create ----------------------------------------------------------------------

struct DescCase {
    const char* name;
    std::function<void(ent_scene_desc&)> change;
    ent_status status;
    const char* message_part;  // must appear in ent_last_error()
};

const uint32_t kPinnedTooFar[1] = {12};
const double kShortPoints[3 * 12] = {};
ent_callbacks allocate_only() {
    ent_callbacks c;
    ent_callbacks_default(&c);
    c.allocate = [](void*, size_t, size_t) -> void* { return nullptr; };
    return c;
}
const ent_callbacks kAllocateOnly = allocate_only();
ent_callbacks zero_size_callbacks() {
    ent_callbacks c;
    ent_callbacks_default(&c);
    c.struct_size = 0;
    return c;
}
const ent_callbacks kZeroSizeCallbacks = zero_size_callbacks();

const DescCase kDescCases[] = {
    {"struct_size 0", [](ent_scene_desc& d) { d.struct_size = 0; }, ENT_ERROR_VERSION, "struct_size"},
    {"struct_size too large", [](ent_scene_desc& d) { d.struct_size = sizeof(ent_scene_desc) + 8; },
     ENT_ERROR_VERSION, "struct_size"},
    {"struct_size garbage", [](ent_scene_desc& d) { d.struct_size = 0xdeadbeef; }, ENT_ERROR_VERSION,
     "struct_size"},
    {"radius -1", [](ent_scene_desc& d) { d.radius_m = -1.0; }, ENT_ERROR_INVALID_ARGUMENT, "radius_m"},
    {"radius NaN", [](ent_scene_desc& d) { d.radius_m = kNaN; }, ENT_ERROR_INVALID_ARGUMENT, "radius_m"},
    {"length NaN", [](ent_scene_desc& d) { d.length_m = kNaN; }, ENT_ERROR_INVALID_ARGUMENT, "length_m"},
    {"length infinite", [](ent_scene_desc& d) { d.length_m = kInf; }, ENT_ERROR_INVALID_ARGUMENT, "length_m"},
    {"length 0", [](ent_scene_desc& d) { d.length_m = 0.0; }, ENT_ERROR_INVALID_ARGUMENT, "length_m"},
    {"control_points 2", [](ent_scene_desc& d) { d.control_points = 2; }, ENT_ERROR_INVALID_ARGUMENT,
     "control_points"},
    {"control_points 3", [](ent_scene_desc& d) { d.control_points = 3; }, ENT_ERROR_INVALID_ARGUMENT,
     "control_points"},
    {"control_points 0", [](ent_scene_desc& d) { d.control_points = 0; }, ENT_ERROR_INVALID_ARGUMENT,
     "control_points"},
    {"control_points huge", [](ent_scene_desc& d) { d.control_points = 0xffffffffu; },
     ENT_ERROR_INVALID_ARGUMENT, "control_points"},
    {"linear density 0", [](ent_scene_desc& d) { d.linear_density_kg_per_m = 0.0; }, ENT_ERROR_INVALID_ARGUMENT,
     "linear_density_kg_per_m"},
    {"stretch stiffness NaN", [](ent_scene_desc& d) { d.stretch_stiffness_N = kNaN; },
     ENT_ERROR_INVALID_ARGUMENT, "stretch_stiffness_N"},
    {"bend stiffness -1", [](ent_scene_desc& d) { d.bend_stiffness_N_m2 = -1.0; }, ENT_ERROR_INVALID_ARGUMENT,
     "bend_stiffness_N_m2"},
    {"shape 9", [](ent_scene_desc& d) { d.shape = 9; }, ENT_ERROR_INVALID_ARGUMENT, "shape"},
    {"shape -1", [](ent_scene_desc& d) { d.shape = -1; }, ENT_ERROR_INVALID_ARGUMENT, "shape"},
    {"line direction zero",
     [](ent_scene_desc& d) {
         d.shape = ENT_SHAPE_LINE;
         d.shape_direction[0] = d.shape_direction[1] = d.shape_direction[2] = 0.0;
     },
     ENT_ERROR_INVALID_ARGUMENT, "shape_direction"},
    {"points NULL",
     [](ent_scene_desc& d) {
         d.shape = ENT_SHAPE_POINTS;
         d.shape_points_xyz_m = nullptr;
     },
     ENT_ERROR_INVALID_ARGUMENT, "shape_points_xyz_m"},
    {"points with NaN",
     [](ent_scene_desc& d) {
         static double points[3 * 12];
         for (int i = 0; i < 12; ++i) points[3 * i] = 0.1 * i;
         points[3 * 7 + 1] = kNaN;
         d.shape = ENT_SHAPE_POINTS;
         d.shape_points_xyz_m = points;
     },
     ENT_ERROR_INVALID_ARGUMENT, "shape_points_xyz_m"},
    {"integrator 3", [](ent_scene_desc& d) { d.integrator = 3; }, ENT_ERROR_INVALID_ARGUMENT, "integrator"},
    {"integrator -1", [](ent_scene_desc& d) { d.integrator = -1; }, ENT_ERROR_INVALID_ARGUMENT, "integrator"},
    {"timestep 0", [](ent_scene_desc& d) { d.timestep_s = 0.0; }, ENT_ERROR_INVALID_ARGUMENT, "timestep_s"},
    {"timestep NaN", [](ent_scene_desc& d) { d.timestep_s = kNaN; }, ENT_ERROR_INVALID_ARGUMENT, "timestep_s"},
    {"timestep -1", [](ent_scene_desc& d) { d.timestep_s = -1.0; }, ENT_ERROR_INVALID_ARGUMENT, "timestep_s"},
    {"max_substeps 0", [](ent_scene_desc& d) { d.max_substeps = 0; }, ENT_ERROR_INVALID_ARGUMENT,
     "max_substeps"},
    {"max_speed 0", [](ent_scene_desc& d) { d.max_speed_m_per_s = 0.0; }, ENT_ERROR_INVALID_ARGUMENT,
     "max_speed_m_per_s"},
    {"gravity NaN", [](ent_scene_desc& d) { d.gravity_m_per_s2[1] = kNaN; }, ENT_ERROR_INVALID_ARGUMENT,
     "gravity_m_per_s2"},
    {"drag -1", [](ent_scene_desc& d) { d.drag_N_s_per_m2 = -1.0; }, ENT_ERROR_INVALID_ARGUMENT,
     "drag_N_s_per_m2"},
    {"unknown effect bit", [](ent_scene_desc& d) { d.effects |= 1u << 31; }, ENT_ERROR_INVALID_ARGUMENT,
     "effects"},
    {"mesentery without attachments",
     [](ent_scene_desc& d) {
         d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
         d.mesentery_attachments = 0;
     },
     ENT_ERROR_INVALID_ARGUMENT, "mesentery_attachments"},
    {"pinned point out of range",
     [](ent_scene_desc& d) {
         d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
         d.pinned_points = kPinnedTooFar;
         d.pinned_point_count = 1;
     },
     ENT_ERROR_INVALID_ARGUMENT, "pinned_points"},
    {"pinned points NULL with a count",
     [](ent_scene_desc& d) {
         d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
         d.pinned_points = nullptr;
         d.pinned_point_count = 2;
     },
     ENT_ERROR_INVALID_ARGUMENT, "pinned_points"},
    {"pinned ends 4",
     [](ent_scene_desc& d) {
         d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
         d.pinned_ends = 4;
     },
     ENT_ERROR_INVALID_ARGUMENT, "pinned_ends"},
    {"allocate without release", [](ent_scene_desc& d) { d.callbacks = &kAllocateOnly; },
     ENT_ERROR_INVALID_ARGUMENT, "release"},
    {"callbacks struct_size 0", [](ent_scene_desc& d) { d.callbacks = &kZeroSizeCallbacks; }, ENT_ERROR_VERSION,
     "struct_size"},
};

TEST(BadInputs, SceneCreateRejectsEachBadDescription) {
    (void)kShortPoints;
    for (const DescCase& c : kDescCases) {
        SCOPED_TRACE(c.name);
        ent_scene_desc desc = small_desc();
        c.change(desc);
        ent_scene* out = sentinel();
        EXPECT_EQ(ent_scene_create(&desc, &out), c.status) << ent_last_error();
        EXPECT_EQ(out, sentinel()) << "out_scene written on failure";
        EXPECT_TRUE(contains(ent_last_error(), c.message_part))
            << "message \"" << ent_last_error() << "\" should name " << c.message_part;
    }
}

TEST(BadInputs, TheSmallDescriptionItselfIsFine) {
    // Guards the table above: each case fails because of its one change.
    ent_scene_desc desc = small_desc();
    ScenePtr scene = create(desc);
    EXPECT_TRUE(scene);
}

TEST(BadInputs, RadiusMessageNamesTheFieldAndTheValue) {
    ent_scene_desc desc = small_desc();
    desc.radius_m = -1.0;
    ent_scene* out = sentinel();
    ASSERT_EQ(ent_scene_create(&desc, &out), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(ent_last_error(), "radius_m must be > 0, got -1");
}

TEST(BadInputs, NullDescOrOutPointer) {
    ent_scene* out = sentinel();
    EXPECT_EQ(ent_scene_create(nullptr, &out), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(out, sentinel());
    EXPECT_TRUE(contains(ent_last_error(), "desc")) << ent_last_error();
    ent_scene_desc desc = small_desc();
    EXPECT_EQ(ent_scene_create(&desc, nullptr), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_TRUE(contains(ent_last_error(), "out_scene")) << ent_last_error();
}

// ---- ent_scene_create_json -----------------------------------------------------------------

struct JsonCase {
    const char* name;
    std::string json;
    ent_status status;
    const char* message_part;
};

const JsonCase kJsonCases[] = {
    {"unterminated object", "{", ENT_ERROR_PARSE, "byte"},
    {"empty text", "", ENT_ERROR_PARSE, "byte"},
    {"trailing garbage", "{} x", ENT_ERROR_PARSE, "byte"},
    {"not an object", "[1, 2]", ENT_ERROR_INVALID_SCENE, "object"},
    {"unknown top-level key", R"({"intestnie": {}})", ENT_ERROR_INVALID_SCENE, "intestnie"},
    {"unknown nested key", R"({"intestine": {"lenght": 1.0}})", ENT_ERROR_INVALID_SCENE, "lenght"},
    {"wrong type", R"({"intestine": {"radius": "big"}})", ENT_ERROR_INVALID_SCENE, "intestine.radius"},
    {"control points 2", R"({"intestine": {"control_points": 2}})", ENT_ERROR_INVALID_SCENE,
     "intestine.control_points"},
    {"unknown integrator", R"({"solver": {"integrator": "rk5"}})", ENT_ERROR_INVALID_SCENE, "solver.integrator"},
    {"timestep 0", R"({"solver": {"timestep": 0}})", ENT_ERROR_INVALID_SCENE, "solver.timestep"},
    {"gravity of two numbers", R"({"gravity": [0, -9.81]})", ENT_ERROR_INVALID_SCENE, "gravity"},
    {"duplicate key", R"({"intestine": {"radius": 0.01, "radius": 0.02}})", ENT_ERROR_INVALID_SCENE, "radius"},
};

TEST(BadInputs, SceneCreateJsonRejectsEachBadDocument) {
    for (const JsonCase& c : kJsonCases) {
        SCOPED_TRACE(c.name);
        ent_scene* out = sentinel();
        EXPECT_EQ(ent_scene_create_json(c.json.data(), c.json.size(), &out), c.status) << ent_last_error();
        EXPECT_EQ(out, sentinel());
        EXPECT_TRUE(contains(ent_last_error(), c.message_part))
            << "message \"" << ent_last_error() << "\" should contain " << c.message_part;
    }
}

TEST(BadInputs, JsonRadiusMessageIsExact) {
    const std::string json = R"({"intestine": {"radius": -1}})";
    ent_scene* out = sentinel();
    ASSERT_EQ(ent_scene_create_json(json.data(), json.size(), &out), ENT_ERROR_INVALID_SCENE);
    EXPECT_STREQ(ent_last_error(), "intestine.radius must be > 0, got -1");
    EXPECT_EQ(out, sentinel());
}

TEST(BadInputs, JsonNeedNotBeNulTerminated) {
    // Only `length` bytes are read: what follows them (here a stray brace) is not part of it.
    const std::string buffer = R"({"intestine": {"length": 1.0, "control_points": 10}}})";
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create_json(buffer.data(), buffer.size() - 1, &scene), ENT_OK) << ent_last_error();
    ent_scene_destroy(scene);
    // ...and a length that cuts the document short is a parse error.
    ent_scene* out = sentinel();
    EXPECT_EQ(ent_scene_create_json(buffer.data(), buffer.size() - 3, &out), ENT_ERROR_PARSE);
    EXPECT_EQ(out, sentinel());
}

TEST(BadInputs, JsonNullTextOrOutPointer) {
    ent_scene* out = sentinel();
    EXPECT_EQ(ent_scene_create_json(nullptr, 5, &out), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(out, sentinel());
    const std::string json = "{}";
    EXPECT_EQ(ent_scene_create_json(json.data(), json.size(), nullptr), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_scene_create_json_with(json.data(), json.size(), nullptr, nullptr), ENT_ERROR_INVALID_ARGUMENT);
}

// ---- calls on NULL scenes ------------------------------------------------------------------

TEST(BadInputs, NullSceneToEveryFunction) {
    double buffer[30];
    uint32_t count = 77;
    ent_stats s;
    s.struct_size = sizeof s;
    ent_effect_stats e;
    e.struct_size = sizeof e;
    EXPECT_EQ(ent_scene_step(nullptr, 1e-3), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_TRUE(contains(ent_last_error(), "scene")) << ent_last_error();
    EXPECT_EQ(ent_scene_axis(nullptr, 10, buffer), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_scene_control_points(nullptr, 10, buffer, &count), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(count, 77u);
    EXPECT_EQ(ent_scene_stats(nullptr, &s), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_scene_effect_stats(nullptr, ENT_EFFECT_GRAVITY, &e), ENT_ERROR_INVALID_ARGUMENT);
    ent_scene_destroy(nullptr);  // ignored
}

// ---- failing calls on an existing scene change nothing --------------------------------------

// Everything a caller can observe of a scene.
struct Observed {
    std::vector<double> points;
    ent_stats stats;
};

Observed observe(const ent_scene* scene) {
    Observed o;
    o.points = control_points(scene);
    o.stats = capi_test::stats(scene);
    return o;
}

::testing::AssertionResult unchanged(const Observed& before, const Observed& after) {
    if (before.points.size() != after.points.size() ||
        std::memcmp(before.points.data(), after.points.data(), before.points.size() * sizeof(double)) != 0)
        return ::testing::AssertionFailure() << "control points changed";
    const ent_stats& a = before.stats;
    const ent_stats& b = after.stats;
    if (std::memcmp(&a.time_s, &b.time_s, sizeof a.time_s) != 0) return ::testing::AssertionFailure() << "time_s changed";
    if (a.steps != b.steps) return ::testing::AssertionFailure() << "steps changed";
    if (a.substeps != b.substeps) return ::testing::AssertionFailure() << "substeps changed";
    if (a.rollbacks != b.rollbacks) return ::testing::AssertionFailure() << "rollbacks changed";
    if (std::memcmp(&a.kinetic_energy_J, &b.kinetic_energy_J, sizeof(double)) != 0)
        return ::testing::AssertionFailure() << "kinetic energy changed";
    if (std::memcmp(&a.potential_energy_J, &b.potential_energy_J, sizeof(double)) != 0)
        return ::testing::AssertionFailure() << "potential energy changed";
    return ::testing::AssertionSuccess();
}

struct SceneCallCase {
    const char* name;
    std::function<ent_status(ent_scene*)> call;
    ent_status status;
    const char* message_part;
};

std::vector<SceneCallCase> scene_call_cases() {
    return {
        {"step dt 0", [](ent_scene* s) { return ent_scene_step(s, 0.0); }, ENT_ERROR_INVALID_ARGUMENT, "dt"},
        {"step dt -1", [](ent_scene* s) { return ent_scene_step(s, -1.0); }, ENT_ERROR_INVALID_ARGUMENT, "dt"},
        {"step dt -0", [](ent_scene* s) { return ent_scene_step(s, -0.0); }, ENT_ERROR_INVALID_ARGUMENT, "dt"},
        {"step dt NaN", [](ent_scene* s) { return ent_scene_step(s, kNaN); }, ENT_ERROR_INVALID_ARGUMENT, "dt"},
        {"step dt inf", [](ent_scene* s) { return ent_scene_step(s, kInf); }, ENT_ERROR_INVALID_ARGUMENT, "dt"},
        {"step dt -inf", [](ent_scene* s) { return ent_scene_step(s, -kInf); }, ENT_ERROR_INVALID_ARGUMENT, "dt"},
        {"step dt 1e9 (more than max_substeps)", [](ent_scene* s) { return ent_scene_step(s, 1e9); },
         ENT_ERROR_INVALID_ARGUMENT, "max_substeps"},
        {"step dt just over max_substeps", [](ent_scene* s) { return ent_scene_step(s, 1000 * 1e-3 * 1.01); },
         ENT_ERROR_INVALID_ARGUMENT, "max_substeps"},
        {"axis count 0",
         [](ent_scene* s) {
             double b[6];
             return ent_scene_axis(s, 0, b);
         },
         ENT_ERROR_INVALID_ARGUMENT, "count"},
        {"axis count 1",
         [](ent_scene* s) {
             double b[6];
             return ent_scene_axis(s, 1, b);
         },
         ENT_ERROR_INVALID_ARGUMENT, "count"},
        {"axis NULL buffer", [](ent_scene* s) { return ent_scene_axis(s, 10, nullptr); }, ENT_ERROR_INVALID_ARGUMENT,
         "points_xyz_m"},
        {"control points NULL out_count",
         [](ent_scene* s) {
             double b[3 * 12];
             return ent_scene_control_points(s, 12, b, nullptr);
         },
         ENT_ERROR_INVALID_ARGUMENT, "out_count"},
        {"stats NULL", [](ent_scene* s) { return ent_scene_stats(s, nullptr); }, ENT_ERROR_INVALID_ARGUMENT, "out"},
        {"stats struct_size 0",
         [](ent_scene* s) {
             ent_stats st;
             std::memset(&st, 0, sizeof st);
             return ent_scene_stats(s, &st);
         },
         ENT_ERROR_VERSION, "struct_size"},
        {"stats struct_size too large",
         [](ent_scene* s) {
             ent_stats st;
             std::memset(&st, 0, sizeof st);
             st.struct_size = sizeof st + 8;
             return ent_scene_stats(s, &st);
         },
         ENT_ERROR_VERSION, "struct_size"},
        {"effect stats NULL", [](ent_scene* s) { return ent_scene_effect_stats(s, 0, nullptr); },
         ENT_ERROR_INVALID_ARGUMENT, "out"},
        {"effect stats struct_size 0",
         [](ent_scene* s) {
             ent_effect_stats st;
             std::memset(&st, 0, sizeof st);
             return ent_scene_effect_stats(s, 0, &st);
         },
         ENT_ERROR_VERSION, "struct_size"},
        {"effect stats unknown effect",
         [](ent_scene* s) {
             ent_effect_stats st;
             st.struct_size = sizeof st;
             return ent_scene_effect_stats(s, 99, &st);
         },
         ENT_ERROR_NOT_FOUND, "99"},
    };
}

ent_scene_desc moving_desc(int32_t integrator) {
    ent_scene_desc desc = small_desc();
    desc.shape = ENT_SHAPE_SERPENTINE;
    desc.shape_leg_length_m = 0.2;
    desc.integrator = integrator;
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
    desc.mesentery_attachments = 5;
    return desc;
}

TEST(BadInputs, FailingCallsLeaveTheSceneExactlyAsItWas) {
    for (int32_t integrator : kIntegrators) {
        SCOPED_TRACE(integrator_name(integrator));
        // Twin scenes driven identically, except that `tried` also receives every bad call.
        ScenePtr tried = create(moving_desc(integrator));
        ScenePtr twin = create(moving_desc(integrator));
        ASSERT_TRUE(tried && twin);
        ASSERT_TRUE(step_n(tried.get(), 1e-3, 20));
        ASSERT_TRUE(step_n(twin.get(), 1e-3, 20));
        ASSERT_GT(stats(tried.get()).kinetic_energy_J, 0.0) << "the scene must be moving";

        for (const SceneCallCase& c : scene_call_cases()) {
            SCOPED_TRACE(c.name);
            const Observed before = observe(tried.get());
            EXPECT_EQ(c.call(tried.get()), c.status) << ent_last_error();
            EXPECT_TRUE(contains(ent_last_error(), c.message_part))
                << "message \"" << ent_last_error() << "\" should contain " << c.message_part;
            EXPECT_TRUE(unchanged(before, observe(tried.get())));
        }
        // The hidden state (velocities) is untouched too: the next steps agree bit for bit.
        ASSERT_TRUE(step_n(tried.get(), 1e-3, 5));
        ASSERT_TRUE(step_n(twin.get(), 1e-3, 5));
        const auto a = control_points(tried.get());
        const auto b = control_points(twin.get());
        ASSERT_EQ(a.size(), b.size());
        EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
        const ent_stats sa = stats(tried.get()), sb = stats(twin.get());
        EXPECT_EQ(std::memcmp(&sa.kinetic_energy_J, &sb.kinetic_energy_J, sizeof(double)), 0);
        EXPECT_EQ(sa.steps, sb.steps);
    }
}

TEST(BadInputs, ControlPointsBufferTooSmallReportsTheCountAndCopiesNothing) {
    ScenePtr scene = create(small_desc());
    ASSERT_TRUE(scene);
    std::vector<double> buffer(3 * 12, -7.0);
    uint32_t count = 0;
    EXPECT_EQ(ent_scene_control_points(scene.get(), 11, buffer.data(), &count), ENT_ERROR_BUFFER_TOO_SMALL);
    EXPECT_EQ(count, 12u);
    for (double v : buffer) EXPECT_EQ(v, -7.0);
    EXPECT_TRUE(contains(ent_last_error(), "12")) << ent_last_error();
    EXPECT_EQ(ent_scene_control_points(scene.get(), 0, buffer.data(), &count), ENT_ERROR_BUFFER_TOO_SMALL);
    EXPECT_EQ(count, 12u);
    // NULL buffer: the count only, whatever the capacity.
    count = 0;
    EXPECT_EQ(ent_scene_control_points(scene.get(), 0, nullptr, &count), ENT_OK);
    EXPECT_EQ(count, 12u);
    // Exactly enough is enough; more is fine and the rest is left alone.
    std::vector<double> bigger(3 * 13, -7.0);
    EXPECT_EQ(ent_scene_control_points(scene.get(), 13, bigger.data(), &count), ENT_OK);
    EXPECT_EQ(count, 12u);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(bigger[3 * 12 + c], -7.0);
}

TEST(BadInputs, RejectedStatsStructsAreNotWritten) {
    ScenePtr scene = create(small_desc());
    ASSERT_TRUE(scene);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 3));
    for (uint32_t size : {0u, uint32_t(sizeof(ent_stats) + 8), 3u}) {
        ent_stats s;
        std::memset(&s, 0x5a, sizeof s);
        s.struct_size = size;
        ent_stats copy;
        std::memcpy(&copy, &s, sizeof s);
        EXPECT_EQ(ent_scene_stats(scene.get(), &s), ENT_ERROR_VERSION) << size;
        EXPECT_EQ(std::memcmp(&s, &copy, sizeof s), 0) << size;
    }
}

}  // namespace
