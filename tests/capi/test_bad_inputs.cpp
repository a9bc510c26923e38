// SPDX-License-Identifier: Apache-2.0
// Bad input through every entry point of the C API, as one table: each row is a function
// and one bad input (NULL handles and pointers, NaN and Inf, negative or zero sizes, dt <= 0
// or absurd, wrong struct_size, unknown JSON keys and wrong types, huge inputs). Every row
// must return its status (or, for the calls that return no status, its documented value),
// leave a message naming the input in ent_last_error(), leave out-parameters untouched, and
// leave a live scene, its skin and its tool bit-identical: control points, stats, effect
// stats, the mesh, the tool's wrench and grasp, and (checked by stepping a twin scene that
// never saw a bad call) the velocities and the tool's target pose.
//
// BadInputs.EveryExportedFunctionHasRows reads the library's exported symbols (nm at build
// time, ENTERON_EXPORTS_FILE) and fails when a function has no row: a new entry point must
// come with its bad inputs.
#include "capi_test_support.h"

#include <cfloat>
#include <cstddef>
#include <climits>
#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <set>

#include "test_helpers.h"

using namespace capi_test;

namespace {

using enteron_test::contains;
using enteron_test::kNaN;

const double kInf = std::numeric_limits<double>::infinity();


// A recognisable value that no successful create would write.
template <class T>
T* sentinel() {
    static char storage;
    return reinterpret_cast<T*>(&storage);
}

struct BadInputsSkinDeleter {
    void operator()(ent_skin* skin) const { ent_skin_destroy(skin); }
};
using BadInputsSkinPtr = std::unique_ptr<ent_skin, BadInputsSkinDeleter>;

// ---- the live objects every row is tried against ---------------------------------------------

ent_scene_desc small_desc() {
    ent_scene_desc desc = default_desc();
    desc.control_points = 12;
    desc.length_m = 1.0;
    return desc;
}

// A small moving bowel: serpentine, hung from a mesentery, self-colliding.
ent_scene_desc moving_desc(int32_t integrator) {
    ent_scene_desc desc = small_desc();
    desc.shape = ENT_SHAPE_SERPENTINE;
    desc.shape_leg_length_m = 0.2;
    desc.integrator = integrator;
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_SELF_COLLISION);
    desc.mesentery_attachments = 5;
    return desc;
}

struct Live {
    ent_scene* scene;
    ent_skin* skin;
    int32_t tool;  // a tool of the scene, touching the bowel
};

// Everything a caller can observe of a scene and its skin.
struct Observed {
    std::vector<double> points;
    ent_stats stats;
    std::vector<ent_effect_stats> effects;
    ent_mesh_view mesh;
    double wrench[6];
    int32_t grasping;
};

Observed observe(const Live& live) {
    Observed o;
    o.points = control_points(live.scene);
    o.stats = stats(live.scene);
    for (int32_t e = 0; e < ENT_EFFECT_COUNT; ++e) o.effects.push_back(effect_stats(live.scene, e));
    std::memset(&o.mesh, 0, sizeof o.mesh);
    o.mesh.struct_size = sizeof o.mesh;
    EXPECT_EQ(ent_skin_mesh(live.skin, &o.mesh), ENT_OK) << ent_last_error();
    EXPECT_EQ(ent_tool_wrench(live.scene, live.tool, o.wrench, o.wrench + 3), ENT_OK) << ent_last_error();
    EXPECT_EQ(ent_tool_state(live.scene, live.tool, &o.grasping), ENT_OK) << ent_last_error();
    return o;
}

bool same_bits(const void* a, const void* b, std::size_t size) { return std::memcmp(a, b, size) == 0; }

::testing::AssertionResult unchanged(const Observed& before, const Observed& after) {
    if (before.points.size() != after.points.size() ||
        !same_bits(before.points.data(), after.points.data(), before.points.size() * sizeof(double)))
        return ::testing::AssertionFailure() << "control points changed";
    ent_stats a = before.stats, b = after.stats;
    a.last_step_ns = b.last_step_ns = 0;  // wall time, not state
    if (!same_bits(&a, &b, sizeof a)) return ::testing::AssertionFailure() << "ent_stats changed";
    for (std::size_t e = 0; e < before.effects.size(); ++e)
        if (before.effects[e].calls != after.effects[e].calls || before.effects[e].enabled != after.effects[e].enabled)
            return ::testing::AssertionFailure() << "ent_effect_stats of effect " << e << " changed";
    if (!same_bits(&before.mesh, &after.mesh, sizeof before.mesh))
        return ::testing::AssertionFailure() << "the skin's mesh view changed";
    if (!same_bits(before.wrench, after.wrench, sizeof before.wrench) || before.grasping != after.grasping)
        return ::testing::AssertionFailure() << "the tool's wrench or grasp changed";
    return ::testing::AssertionSuccess();
}

// ---- the table ---------------------------------------------------------------------------------

// One bad input to one function. call() makes the call (checking its own out-parameters)
// and returns its status; functions that return no status return ENT_OK when they gave
// their documented answer to the bad input, and have no message.
struct BadInput {
    const char* function;
    std::string input;
    std::function<ent_status(const Live&)> call;
    ent_status status;
    const char* message_part;  // must appear in ent_last_error(); nullptr: no message
};

// A description with one change, created into a sentinel that must stay untouched.
template <class Change>
std::function<ent_status(const Live&)> create_with(Change change) {
    return [change](const Live&) {
        ent_scene_desc desc = small_desc();
        change(desc);
        ent_scene* out = sentinel<ent_scene>();
        const ent_status status = ent_scene_create(&desc, &out);
        EXPECT_EQ(out, sentinel<ent_scene>()) << "out_scene written on failure";
        return status;
    };
}

std::function<ent_status(const Live&)> json(std::string text) {
    return [text](const Live&) {
        ent_scene* out = sentinel<ent_scene>();
        const ent_status status = ent_scene_create_json(text.data(), text.size(), &out);
        EXPECT_EQ(out, sentinel<ent_scene>()) << "out_scene written on failure";
        return status;
    };
}

// A description filled by its _init function, changed, then passed to `call` with an
// out-parameter holding `untouched`, which a failing call must leave as it was.
template <class Desc, class Out, class Call, class Change>
std::function<ent_status(const Live&)> desc_with(ent_status (*init)(Desc*, uint32_t), Out untouched, Call call,
                                                 Change change) {
    return [=](const Live& live) {
        Desc desc;
        init(&desc, static_cast<uint32_t>(sizeof desc));
        change(desc);
        Out out = untouched;
        const ent_status status = call(live, &desc, &out);
        EXPECT_EQ(out, untouched) << "out-parameter written on failure";
        return status;
    };
}

template <class Change>
std::function<ent_status(const Live&)> obstacle_with(Change change) {
    return desc_with(&ent_obstacle_desc_init, int32_t{-7},
                     [](const Live& l, const ent_obstacle_desc* d, int32_t* out) {
                         return ent_scene_add_obstacle(l.scene, d, out);
                     },
                     change);
}

template <class Change>
std::function<ent_status(const Live&)> skin_with(Change change) {
    return desc_with(&ent_skin_desc_init, sentinel<ent_skin>(),
                     [](const Live& l, const ent_skin_desc* d, ent_skin** out) {
                         return ent_skin_create(l.scene, d, out);
                     },
                     change);
}

template <class Change>
std::function<ent_status(const Live&)> tool_with(Change change) {
    return desc_with(&ent_tool_desc_init, int32_t{-7},
                     [](const Live& l, const ent_tool_desc* d, int32_t* out) { return ent_tool_add(l.scene, d, out); },
                     change);
}

// A pose with one change, for the live tool.
template <class Change>
std::function<ent_status(const Live&)> pose_with(Change change) {
    return [change](const Live& live) {
        double position[3] = {0.0, 0.0, 0.0}, orientation[4] = {1.0, 0.0, 0.0, 0.0};
        change(position, orientation);
        return ent_tool_set_pose(live.scene, live.tool, position, orientation);
    };
}

// An _init function given a bad size writes nothing.
template <class T>
std::function<ent_status(const Live&)> init_with_size(ent_status (*init)(T*, uint32_t), uint32_t size) {
    return [init, size](const Live&) {
        T value;
        std::memset(&value, 0x5a, sizeof value);
        T copy = value;
        const ent_status status = init(&value, size);
        EXPECT_TRUE(same_bits(&value, &copy, sizeof value)) << "written although refused";
        return status;
    };
}

// A struct whose caller-set struct_size is wrong is refused and not written.
template <class T, class Call>
std::function<ent_status(const Live&)> out_struct_with_size(uint32_t size, Call call) {
    return [size, call](const Live& live) {
        T value;
        std::memset(&value, 0x5a, sizeof value);
        value.struct_size = size;
        T copy = value;
        const ent_status status = call(live, &value);
        EXPECT_TRUE(same_bits(&value, &copy, sizeof value)) << "written although refused";
        return status;
    };
}

// A target of one point for ent_exposure_create, with one change, created into a sentinel
// that must stay untouched.
const double kTargetPoints[6] = {0.0, 0.0, -0.5, 0.01, 0.0, -0.5};
const uint32_t kTargetTriangle[3] = {0, 1, 0};
template <class Change>
std::function<ent_status(const Live&)> exposure_with(Change change) {
    return desc_with(&ent_exposure_desc_init, sentinel<ent_exposure>(),
                     [](const Live& l, const ent_exposure_desc* d, ent_exposure** out) {
                         return ent_exposure_create(l.scene, d, out);
                     },
                     [change](ent_exposure_desc& d) {
                         d.points_xyz_m = kTargetPoints;
                         d.point_count = 1;
                         change(d);
                     });
}

// ent_scene_exposure on a target prepared for the live scene (or for `other`, a second
// scene), with a result whose arrays are NULL; the result must stay untouched on failure.
template <class Call>
std::function<ent_status(const Live&)> measuring(Call call, bool for_another_scene = false) {
    return [call, for_another_scene](const Live& live) {
        ent_scene* other = nullptr;
        if (for_another_scene) {
            const ent_scene_desc desc = small_desc();
            EXPECT_EQ(ent_scene_create(&desc, &other), ENT_OK) << ent_last_error();
        }
        ent_exposure_desc desc;
        ent_exposure_desc_default(&desc);
        desc.points_xyz_m = kTargetPoints;
        desc.point_count = 1;
        ent_exposure* exposure = nullptr;
        EXPECT_EQ(ent_exposure_create(other != nullptr ? other : live.scene, &desc, &exposure), ENT_OK)
            << ent_last_error();
        ent_exposure_result result;
        std::memset(&result, 0x5a, sizeof result);
        result.struct_size = sizeof result;
        result.span_capacity = 0;
        result.spans_u = nullptr;
        result.span_hidden_fractions = nullptr;
        result.span_intestines = nullptr;
        result.element_visible = nullptr;
        const ent_status status = call(live, exposure, &result);
        ent_exposure_result untouched;
        std::memset(&untouched, 0x5a, sizeof untouched);
        untouched.struct_size = result.struct_size;
        untouched.span_capacity = result.span_capacity;
        untouched.spans_u = result.spans_u;
        untouched.span_hidden_fractions = nullptr;
        untouched.span_intestines = nullptr;
        untouched.element_visible = nullptr;
        EXPECT_TRUE(same_bits(&result, &untouched, sizeof result)) << "written although refused";
        ent_exposure_destroy(exposure);
        ent_scene_destroy(other);
        return status;
    };
}

const uint32_t kPinnedTooFar[1] = {12};
// Radius profiles (s m, R m) over small_desc's 1 m: decreasing s, short of the length, a
// radius of 0.
const double kProfileBackwards[6] = {0.0, 0.01, 0.6, 0.012, 0.5, 0.01};
const double kProfileShort[4] = {0.0, 0.01, 0.8, 0.012};
const double kProfileZero[4] = {0.0, 0.01, 1.0, 0.0};
const double kProfileFine[4] = {0.0, 0.012, 1.0, 0.008};
// The fan mesentery's root and mapping and the pinned spans, over small_desc's 1 m: a root
// of one point, a root point that is not a number, a mapping going back in s, a t past the
// root's end, spans backwards, past the length and before the first end.
const double kRootOnePoint[3] = {0.0, 0.0, 0.0};
const double kRootNaN[9] = {0.0, 0.0, 0.0, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 0.1, 0.0, 0.0};
const double kRootFine[9] = {-0.072, 0.0, 0.0, 0.0, 0.021, 0.0, 0.072, 0.0, 0.0};
const double kMappingBackwards[4] = {0.5, 0.0, 0.4, 1.0};
const double kMappingPastTheRoot[4] = {0.0, 0.0, 1.0, 1.5};
const double kSpanBackwards[2] = {0.5, 0.2};
const double kSpanPastTheLength[2] = {0.5, 1.5};
const double kSpanBeforeTheStart[2] = {-0.1, 0.5};
const uint32_t kSizes[] = {0u, 3u, 0xdeadbeefu};

ent_callbacks callbacks_with(bool allocate_only, uint32_t size) {
    ent_callbacks c;
    ent_callbacks_default(&c);
    if (allocate_only) c.allocate = [](void*, size_t, size_t) -> void* { return nullptr; };
    c.struct_size = size;
    return c;
}
const ent_callbacks kAllocateOnly = callbacks_with(true, sizeof(ent_callbacks));
const ent_callbacks kZeroSizeCallbacks = callbacks_with(false, 0);

const double* points_with_nan() {
    static double points[3 * 12];
    for (int i = 0; i < 12; ++i) points[3 * i] = 0.1 * i;
    points[3 * 7 + 1] = kNaN;
    return points;
}

std::string deeply_nested(std::size_t depth, bool closed) {
    return std::string(depth, '[') + (closed ? std::string(depth, ']') : std::string());
}

std::vector<BadInput> table() {
    using L = const Live&;
    const ent_status kArg = ENT_ERROR_INVALID_ARGUMENT, kVersion = ENT_ERROR_VERSION, kParse = ENT_ERROR_PARSE,
                     kScene = ENT_ERROR_INVALID_SCENE;
    std::vector<BadInput> rows = {
        // ---- calls without a scene
        {"ent_version", "(takes no input)", [](L) { return ent_version() == ENT_VERSION ? ENT_OK : ENT_ERROR_INTERNAL; },
         ENT_OK, nullptr},
        {"ent_last_error", "(takes no input)", [](L) { return ent_last_error() != nullptr ? ENT_OK : ENT_ERROR_INTERNAL; },
         ENT_OK, nullptr},
        {"ent_status_string", "unknown codes -1, 11, INT32_MIN, INT32_MAX",
         [](L) {
             for (ent_status s : {-1, 11, INT32_MIN, INT32_MAX})
                 if (std::string(ent_status_string(s)) != "unknown status") return ENT_ERROR_INTERNAL;
             return ENT_OK;
         },
         ENT_OK, nullptr},
        {"ent_effect_name", "unknown effects -1, ENT_EFFECT_COUNT, INT32_MIN, INT32_MAX",
         [](L) {
             for (int32_t e : {-1, ENT_EFFECT_COUNT, INT32_MIN, INT32_MAX})
                 if (ent_effect_name(e) != nullptr) return ENT_ERROR_INTERNAL;
             return ENT_OK;
         },
         ENT_OK, nullptr},
        {"ent_callbacks_init", "callbacks NULL", [](L) { return ent_callbacks_init(nullptr, sizeof(ent_callbacks)); },
         kArg, "callbacks"},
        {"ent_scene_desc_init", "desc NULL", [](L) { return ent_scene_desc_init(nullptr, sizeof(ent_scene_desc)); },
         kArg, "desc"},
        {"ent_obstacle_desc_init", "desc NULL",
         [](L) { return ent_obstacle_desc_init(nullptr, sizeof(ent_obstacle_desc)); }, kArg, "desc"},
        {"ent_skin_desc_init", "desc NULL", [](L) { return ent_skin_desc_init(nullptr, sizeof(ent_skin_desc)); }, kArg,
         "desc"},

        // ---- ent_scene_create
        {"ent_scene_create", "desc NULL",
         [](L) {
             ent_scene* out = sentinel<ent_scene>();
             const ent_status status = ent_scene_create(nullptr, &out);
             EXPECT_EQ(out, sentinel<ent_scene>());
             return status;
         },
         kArg, "desc"},
        {"ent_scene_create", "out_scene NULL",
         [](L) {
             const ent_scene_desc desc = small_desc();
             return ent_scene_create(&desc, nullptr);
         },
         kArg, "out_scene"},
        {"ent_scene_create", "struct_size 0", create_with([](ent_scene_desc& d) { d.struct_size = 0; }), kVersion,
         "struct_size"},
        {"ent_scene_create", "struct_size of a newer header",
         create_with([](ent_scene_desc& d) { d.struct_size = sizeof(ent_scene_desc) + 8; }), kVersion, "struct_size"},
        {"ent_scene_create", "struct_size garbage", create_with([](ent_scene_desc& d) { d.struct_size = 0xdeadbeef; }),
         kVersion, "struct_size"},
        {"ent_scene_create", "radius_m -1", create_with([](ent_scene_desc& d) { d.radius_m = -1.0; }), kArg, "radius_m"},
        {"ent_scene_create", "radius_m NaN", create_with([](ent_scene_desc& d) { d.radius_m = kNaN; }), kArg,
         "radius_m"},
        {"ent_scene_create", "length_m NaN", create_with([](ent_scene_desc& d) { d.length_m = kNaN; }), kArg,
         "length_m"},
        {"ent_scene_create", "length_m Inf", create_with([](ent_scene_desc& d) { d.length_m = kInf; }), kArg,
         "length_m"},
        {"ent_scene_create", "length_m 0", create_with([](ent_scene_desc& d) { d.length_m = 0.0; }), kArg, "length_m"},
        {"ent_scene_create", "length_m DBL_MAX", create_with([](ent_scene_desc& d) { d.length_m = DBL_MAX; }), kArg,
         "length_m"},
        {"ent_scene_create", "control_points 0", create_with([](ent_scene_desc& d) { d.control_points = 0; }), kArg,
         "control_points"},
        {"ent_scene_create", "control_points 3", create_with([](ent_scene_desc& d) { d.control_points = 3; }), kArg,
         "control_points"},
        {"ent_scene_create", "control_points UINT32_MAX (huge)",
         create_with([](ent_scene_desc& d) { d.control_points = 0xffffffffu; }), kArg, "control_points"},
        {"ent_scene_create", "linear_density_kg_per_m 0",
         create_with([](ent_scene_desc& d) { d.linear_density_kg_per_m = 0.0; }), kArg, "linear_density_kg_per_m"},
        {"ent_scene_create", "stretch_stiffness_N NaN",
         create_with([](ent_scene_desc& d) { d.stretch_stiffness_N = kNaN; }), kArg, "stretch_stiffness_N"},
        {"ent_scene_create", "bend_stiffness_N_m2 -1",
         create_with([](ent_scene_desc& d) { d.bend_stiffness_N_m2 = -1.0; }), kArg, "bend_stiffness_N_m2"},
        {"ent_scene_create", "shape 9", create_with([](ent_scene_desc& d) { d.shape = 9; }), kArg, "shape"},
        {"ent_scene_create", "shape -1", create_with([](ent_scene_desc& d) { d.shape = -1; }), kArg, "shape"},
        {"ent_scene_create", "shape_direction zero",
         create_with([](ent_scene_desc& d) {
             d.shape = ENT_SHAPE_LINE;
             d.shape_direction[0] = d.shape_direction[1] = d.shape_direction[2] = 0.0;
         }),
         kArg, "shape_direction"},
        {"ent_scene_create", "shape_direction Inf",
         create_with([](ent_scene_desc& d) {
             d.shape = ENT_SHAPE_LINE;
             d.shape_direction[1] = kInf;
         }),
         kArg, "shape_direction"},
        {"ent_scene_create", "shape_center_m NaN", create_with([](ent_scene_desc& d) { d.shape_center_m[2] = kNaN; }),
         kArg, "shape_center_m"},
        {"ent_scene_create", "shape_helix_pitch_m below 2 R",
         create_with([](ent_scene_desc& d) { d.shape_helix_pitch_m = 0.001; }), kArg, "shape_helix_pitch_m"},
        {"ent_scene_create", "shape_points_xyz_m NULL",
         create_with([](ent_scene_desc& d) {
             d.shape = ENT_SHAPE_POINTS;
             d.shape_points_xyz_m = nullptr;
         }),
         kArg, "shape_points_xyz_m"},
        {"ent_scene_create", "shape_points_xyz_m with a NaN",
         create_with([](ent_scene_desc& d) {
             d.shape = ENT_SHAPE_POINTS;
             d.shape_points_xyz_m = points_with_nan();
         }),
         kArg, "shape_points_xyz_m"},
        {"ent_scene_create", "integrator 4", create_with([](ent_scene_desc& d) { d.integrator = 4; }), kArg,
         "integrator"},
        {"ent_scene_create", "integrator -1", create_with([](ent_scene_desc& d) { d.integrator = -1; }), kArg,
         "integrator"},
        {"ent_scene_create", "timestep_s 0", create_with([](ent_scene_desc& d) { d.timestep_s = 0.0; }), kArg,
         "timestep_s"},
        {"ent_scene_create", "timestep_s NaN", create_with([](ent_scene_desc& d) { d.timestep_s = kNaN; }), kArg,
         "timestep_s"},
        {"ent_scene_create", "timestep_s -1", create_with([](ent_scene_desc& d) { d.timestep_s = -1.0; }), kArg,
         "timestep_s"},
        {"ent_scene_create", "timestep_s 1e300 (absurd)", create_with([](ent_scene_desc& d) { d.timestep_s = 1e300; }),
         kArg, "timestep_s"},
        {"ent_scene_create", "max_substeps 0", create_with([](ent_scene_desc& d) { d.max_substeps = 0; }), kArg,
         "max_substeps"},
        {"ent_scene_create", "max_subdivisions UINT32_MAX",
         create_with([](ent_scene_desc& d) { d.max_subdivisions = 0xffffffffu; }), kArg, "max_subdivisions"},
        {"ent_scene_create", "max_speed_m_per_s 0", create_with([](ent_scene_desc& d) { d.max_speed_m_per_s = 0.0; }),
         kArg, "max_speed_m_per_s"},
        {"ent_scene_create", "gravity_m_per_s2 NaN",
         create_with([](ent_scene_desc& d) { d.gravity_m_per_s2[1] = kNaN; }), kArg, "gravity_m_per_s2"},
        {"ent_scene_create", "drag_N_s_per_m2 -1", create_with([](ent_scene_desc& d) { d.drag_N_s_per_m2 = -1.0; }),
         kArg, "drag_N_s_per_m2"},
        {"ent_scene_create", "effects with an unknown bit", create_with([](ent_scene_desc& d) { d.effects |= 1u << 31; }),
         kArg, "effects"},
        {"ent_scene_create", "mesentery_attachments 0",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
             d.mesentery_attachments = 0;
         }),
         kArg, "mesentery_attachments"},
        {"ent_scene_create", "mesentery_stiffness_N_per_m Inf",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
             d.mesentery_stiffness_N_per_m = kInf;
         }),
         kArg, "mesentery_stiffness_N_per_m"},
        {"ent_scene_create", "pinned_points index out of range",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
             d.pinned_points = kPinnedTooFar;
             d.pinned_point_count = 1;
         }),
         kArg, "pinned_points"},
        {"ent_scene_create", "pinned_points NULL with a count",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
             d.pinned_points = nullptr;
             d.pinned_point_count = 2;
         }),
         kArg, "pinned_points"},
        {"ent_scene_create", "radius_profile_m not increasing in s",
         create_with([](ent_scene_desc& d) {
             d.radius_profile_m = kProfileBackwards;
             d.radius_profile_count = 3;
         }),
         kArg, "radius_profile_m[4]"},
        {"ent_scene_create", "radius_profile_m short of the length",
         create_with([](ent_scene_desc& d) {
             d.radius_profile_m = kProfileShort;
             d.radius_profile_count = 2;
         }),
         kArg, "radius_profile_m[2]"},
        {"ent_scene_create", "radius_profile_m with a radius of 0",
         create_with([](ent_scene_desc& d) {
             d.radius_profile_m = kProfileZero;
             d.radius_profile_count = 2;
         }),
         kArg, "radius_profile_m[3]"},
        {"ent_scene_create", "radius_profile_m NULL with a count",
         create_with([](ent_scene_desc& d) { d.radius_profile_count = 2; }), kArg, "radius_profile_m"},
        {"ent_scene_create", "radius_profile_m with radius_m given too",
         create_with([](ent_scene_desc& d) {
             d.radius_profile_m = kProfileFine;
             d.radius_profile_count = 2;
             d.radius_m = 0.01;
         }),
         kArg, "radius_m"},
        {"ent_scene_create", "stretch_stiffness_profile_N with the stretch effect off",
         create_with([](ent_scene_desc& d) {
             d.stretch_stiffness_profile_N = kProfileFine;
             d.stretch_stiffness_profile_count = 2;
             d.effects &= ~ENT_EFFECT_BIT(ENT_EFFECT_STRETCH);
         }),
         kArg, "stretch_stiffness_profile_N"},
        {"ent_scene_create", "mesentery_root_points_m of one point",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
             d.mesentery_root_points_m = kRootOnePoint;
             d.mesentery_root_point_count = 1;
         }),
         kArg, "mesentery_root_points_m must have at least 2 points"},
        {"ent_scene_create", "mesentery_root_points_m NaN",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
             d.mesentery_root_points_m = kRootNaN;
             d.mesentery_root_point_count = 3;
         }),
         kArg, "mesentery_root_points_m[3]"},
        {"ent_scene_create", "mesentery_root_points_m NULL with a count",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
             d.mesentery_root_point_count = 3;
         }),
         kArg, "mesentery_root_points_m"},
        {"ent_scene_create", "mesentery_root_points_m with mesentery_root_end_m given too",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
             d.mesentery_root_points_m = kRootFine;
             d.mesentery_root_point_count = 3;
             d.mesentery_root_end_m[2] = 0.01;
         }),
         kArg, "mesentery_root_end_m are both given"},
        {"ent_scene_create", "mesentery_root_points_m with the mesentery off",
         create_with([](ent_scene_desc& d) {
             d.mesentery_root_points_m = kRootFine;
             d.mesentery_root_point_count = 3;
         }),
         kArg, "mesentery_root_points_m is given, but effects leaves ENT_EFFECT_MESENTERY off"},
        {"ent_scene_create", "mesentery_root_mapping not increasing in s",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
             d.mesentery_root_mapping = kMappingBackwards;
             d.mesentery_root_mapping_count = 2;
         }),
         kArg, "mesentery_root_mapping[2]"},
        {"ent_scene_create", "mesentery_root_mapping with t past the root",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY);
             d.mesentery_root_mapping = kMappingPastTheRoot;
             d.mesentery_root_mapping_count = 2;
         }),
         kArg, "mesentery_root_mapping[3] must be in [0, 1]"},
        {"ent_scene_create", "pinned_spans_m from > to",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
             d.pinned_spans_m = kSpanBackwards;
             d.pinned_span_count = 1;
         }),
         kArg, "pinned_spans_m[0].to must be >= pinned_spans_m[0].from"},
        {"ent_scene_create", "pinned_spans_m past the length",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
             d.pinned_spans_m = kSpanPastTheLength;
             d.pinned_span_count = 1;
         }),
         kArg, "pinned_spans_m[0].to must be <= length_m"},
        {"ent_scene_create", "pinned_spans_m before the first end",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
             d.pinned_spans_m = kSpanBeforeTheStart;
             d.pinned_span_count = 1;
         }),
         kArg, "pinned_spans_m[0].from must be >= 0"},
        {"ent_scene_create", "pinned_spans_m with the pinned effect off",
         create_with([](ent_scene_desc& d) {
             d.pinned_spans_m = kSpanBackwards;
             d.pinned_span_count = 1;
         }),
         kArg, "pinned_spans_m is given, but effects leaves ENT_EFFECT_PINNED off"},
        {"ent_scene_create", "pinned_span_count UINT32_MAX (huge)",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
             d.pinned_spans_m = kSpanBackwards;
             d.pinned_span_count = 0xffffffffu;
         }),
         kArg, "pinned_span_count must be <="},
        {"ent_scene_create", "linear_density_profile_count UINT32_MAX (huge)",
         create_with([](ent_scene_desc& d) {
             d.linear_density_profile_kg_per_m = kProfileFine;
             d.linear_density_profile_count = 0xffffffffu;
         }),
         kArg, "linear_density_profile_kg_per_m_count"},
        {"ent_scene_create", "pinned_point_count UINT32_MAX (huge)",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
             d.pinned_points = kPinnedTooFar;
             d.pinned_point_count = 0xffffffffu;
         }),
         kArg, "pinned_point_count"},
        {"ent_scene_create", "pinned_ends 4",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
             d.pinned_ends = 4;
         }),
         kArg, "pinned_ends"},
        {"ent_scene_create", "clamped_ends 4",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
             d.clamped_ends = 4;
         }),
         kArg, "clamped_ends"},
        {"ent_scene_create", "clamped_ends both with 5 control points",
         create_with([](ent_scene_desc& d) {
             d.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
             d.control_points = 5;
             d.clamped_ends = ENT_PIN_BOTH;
         }),
         kArg, "clamped_ends"},
        {"ent_scene_create", "collision_sphere_spacing_m above R",
         create_with([](ent_scene_desc& d) { d.collision_sphere_spacing_m = 1.0; }), kArg,
         "collision_sphere_spacing_m"},
        {"ent_scene_create", "contact_stiffness_N_per_m NaN",
         create_with([](ent_scene_desc& d) { d.contact_stiffness_N_per_m = kNaN; }), kArg,
         "contact_stiffness_N_per_m"},
        {"ent_scene_create", "contact_slip_speed_m_per_s 0",
         create_with([](ent_scene_desc& d) { d.contact_slip_speed_m_per_s = 0.0; }), kArg,
         "contact_slip_speed_m_per_s"},
        {"ent_scene_create", "callbacks allocate without release",
         create_with([](ent_scene_desc& d) { d.callbacks = &kAllocateOnly; }), kArg, "release"},
        {"ent_scene_create", "callbacks struct_size 0",
         create_with([](ent_scene_desc& d) { d.callbacks = &kZeroSizeCallbacks; }), kVersion, "struct_size"},

        // ---- ent_scene_create_json / _with
        {"ent_scene_create_json", "json NULL",
         [](L) {
             ent_scene* out = sentinel<ent_scene>();
             const ent_status status = ent_scene_create_json(nullptr, 5, &out);
             EXPECT_EQ(out, sentinel<ent_scene>());
             return status;
         },
         kArg, "json"},
        {"ent_scene_create_json", "out_scene NULL", [](L) { return ent_scene_create_json("{}", 2, nullptr); }, kArg,
         "out_scene"},
        {"ent_scene_create_json", "empty text", json(""), kParse, "byte"},
        {"ent_scene_create_json", "unterminated object", json("{"), kParse, "byte"},
        {"ent_scene_create_json", "trailing garbage", json("{} x"), kParse, "byte"},
        {"ent_scene_create_json", "a number too large for a double", json(R"({"gravity": [0, 0, 1e400]})"), kParse,
         "1e400"},
        {"ent_scene_create_json", "NaN literal", json(R"({"gravity": [0, 0, NaN]})"), kParse, "byte"},
        {"ent_scene_create_json", "not an object", json("[1, 2]"), kScene, "object"},
        {"ent_scene_create_json", "unknown top-level key", json(R"({"intestnie": {}})"), kScene, "intestnie"},
        {"ent_scene_create_json", "unknown nested key", json(R"({"intestine": {"lenght": 1.0}})"), kScene, "lenght"},
        {"ent_scene_create_json", "radius_profile not increasing in s",
         json(R"({"intestine": {"length": 1, "radius_profile": [[0, 0.01], [0.6, 0.01], [0.5, 0.01], [1, 0.01]]}})"),
         kScene, "intestine.radius_profile[2][0]"},
        {"ent_scene_create_json", "radius_profile not covering the length",
         json(R"({"intestine": {"length": 1, "radius_profile": [[0.1, 0.01], [1, 0.01]]}})"), kScene,
         "intestine.radius_profile[0][0]"},
        {"ent_scene_create_json", "radius_profile with a negative radius",
         json(R"({"intestine": {"length": 1, "radius_profile": [[0, 0.01], [1, -0.01]]}})"), kScene,
         "intestine.radius_profile[1][1]"},
        {"ent_scene_create_json", "radius_profile and radius both given",
         json(R"({"intestine": {"length": 1, "radius": 0.01, "radius_profile": [[0, 0.01], [1, 0.01]]}})"), kScene,
         "both given"},
        {"ent_scene_create_json", "bend_stiffness_profile not of pairs",
         json(R"({"intestine": {"length": 1, "bend_stiffness_profile": [[0, 0.01, 3]]}})"), kScene,
         "intestine.bend_stiffness_profile[0]"},
        {"ent_scene_create_json", "mesentery root of one point", json(R"({"mesentery": {"root": [[0, 0, 0]]}})"),
         kScene, "mesentery.root must have at least 2 points"},
        {"ent_scene_create_json", "mesentery root and root_start both given",
         json(R"({"mesentery": {"root": [[0, 0, 0], [0.1, 0, 0]], "root_start": [0, 0, 0]}})"), kScene,
         "both given"},
        {"ent_scene_create_json", "mesentery root_mapping not increasing in s",
         json(R"({"intestine": {"length": 1}, "mesentery": {"root_mapping": [[0.5, 0], [0.4, 1]]}})"), kScene,
         "mesentery.root_mapping[1][0]"},
        {"ent_scene_create_json", "mesentery root_mapping with t past the root",
         json(R"({"intestine": {"length": 1}, "mesentery": {"root_mapping": [[0, 0], [1, 1.5]]}})"), kScene,
         "mesentery.root_mapping[1][1]"},
        {"ent_scene_create_json", "pinned span from > to",
         json(R"({"intestine": {"length": 1}, "pinned": {"spans": [{"from": 0.5, "to": 0.2}]}})"), kScene,
         "pinned.spans[0].to"},
        {"ent_scene_create_json", "pinned span past the length",
         json(R"({"intestine": {"length": 1}, "pinned": {"spans": [{"from": 0.5, "to": 1.5}]}})"), kScene,
         "pinned.spans[0].to must be <= intestine.length"},
        {"ent_scene_create_json", "pinned span on an obstacle that does not exist",
         json(R"({"intestine": {"length": 1}, "pinned": {"spans": [{"from": 0.2, "to": 0.5, "obstacle": 3}]}})"),
         kScene, "pinned.spans[0].obstacle"},
        {"ent_scene_create_json", "wrong type (string for a number)", json(R"({"intestine": {"radius": "big"}})"),
         kScene, "intestine.radius"},
        {"ent_scene_create_json", "wrong type (number for an object)", json(R"({"solver": 3})"), kScene, "solver"},
        {"ent_scene_create_json", "wrong type (float for an integer)",
         json(R"({"intestine": {"control_points": 10.5}})"), kScene, "intestine.control_points"},
        {"ent_scene_create_json", "negative length", json(R"({"intestine": {"length": -1}})"), kScene,
         "intestine.length"},
        {"ent_scene_create_json", "control_points 2", json(R"({"intestine": {"control_points": 2}})"), kScene,
         "intestine.control_points"},
        {"ent_scene_create_json", "control_points 1e12 (huge)", json(R"({"intestine": {"control_points": 1000000000000}})"),
         kScene, "intestine.control_points"},
        {"ent_scene_create_json", "unknown integrator", json(R"({"solver": {"integrator": "rk5"}})"), kScene,
         "solver.integrator"},
        {"ent_scene_create_json", "timestep 0", json(R"({"solver": {"timestep": 0}})"), kScene, "solver.timestep"},
        {"ent_scene_create_json", "timestep 1e300 (absurd)", json(R"({"solver": {"timestep": 1e300}})"), kScene,
         "solver.timestep"},
        {"ent_scene_create_json", "gravity of two numbers", json(R"({"gravity": [0, -9.81]})"), kScene, "gravity"},
        {"ent_scene_create_json", "duplicate key", json(R"({"intestine": {"radius": 0.01, "radius": 0.02}})"), kScene,
         "radius"},
        {"ent_scene_create_json", "obstacle of an unknown type", json(R"({"environment": [{"type": "cube"}]})"), kScene,
         "environment[0].type"},
        {"ent_scene_create_json", "obstacle key of another type",
         json(R"({"environment": [{"type": "box_inside", "half_extents": [1, 1, 1], "radius": 1}]})"), kScene,
         "radius"},
        // Nested deeper than any recursive parser's stack would hold.
        {"ent_scene_create_json", "arrays nested 131072 deep", json(deeply_nested(1 << 17, true)), kScene, "object"},
        {"ent_scene_create_json", "arrays nested 131072 deep, unclosed", json(deeply_nested(1 << 17, false)), kParse,
         "byte"},
        {"ent_scene_create_json", "a 1 MB key", json("{\"" + std::string(1 << 20, 'k') + "\": 1}"), kScene,
         "unknown key"},
        {"ent_scene_create_json_with", "callbacks struct_size 0",
         [](L) {
             ent_scene* out = sentinel<ent_scene>();
             const ent_status status = ent_scene_create_json_with("{}", 2, &kZeroSizeCallbacks, &out);
             EXPECT_EQ(out, sentinel<ent_scene>());
             return status;
         },
         kVersion, "struct_size"},
        {"ent_scene_create_json_with", "callbacks allocate without release",
         [](L) {
             ent_scene* out = sentinel<ent_scene>();
             const ent_status status = ent_scene_create_json_with("{}", 2, &kAllocateOnly, &out);
             EXPECT_EQ(out, sentinel<ent_scene>());
             return status;
         },
         kArg, "release"},
        {"ent_scene_create_json_with", "json NULL and out_scene NULL",
         [](L) { return ent_scene_create_json_with(nullptr, 2, nullptr, nullptr); }, kArg, "json"},
        {"ent_scene_destroy", "scene NULL (ignored)",
         [](L) {
             ent_scene_destroy(nullptr);
             return ENT_OK;
         },
         ENT_OK, nullptr},

        // ---- ent_scene_step
        {"ent_scene_step", "scene NULL", [](L) { return ent_scene_step(nullptr, 1e-3); }, kArg, "scene"},
        {"ent_scene_step", "dt_s 0", [](L l) { return ent_scene_step(l.scene, 0.0); }, kArg, "dt_s"},
        {"ent_scene_step", "dt_s -1", [](L l) { return ent_scene_step(l.scene, -1.0); }, kArg, "dt_s"},
        {"ent_scene_step", "dt_s -0", [](L l) { return ent_scene_step(l.scene, -0.0); }, kArg, "dt_s"},
        {"ent_scene_step", "dt_s -DBL_MIN", [](L l) { return ent_scene_step(l.scene, -DBL_MIN); }, kArg, "dt_s"},
        {"ent_scene_step", "dt_s NaN", [](L l) { return ent_scene_step(l.scene, kNaN); }, kArg, "dt_s"},
        {"ent_scene_step", "dt_s Inf", [](L l) { return ent_scene_step(l.scene, kInf); }, kArg, "dt_s"},
        {"ent_scene_step", "dt_s -Inf", [](L l) { return ent_scene_step(l.scene, -kInf); }, kArg, "dt_s"},
        {"ent_scene_step", "dt_s 1e9 (absurd: more than max_substeps)", [](L l) { return ent_scene_step(l.scene, 1e9); },
         kArg, "max_substeps"},
        {"ent_scene_step", "dt_s DBL_MAX", [](L l) { return ent_scene_step(l.scene, DBL_MAX); }, kArg, "max_substeps"},
        {"ent_scene_step", "dt_s just over max_substeps x timestep",
         [](L l) { return ent_scene_step(l.scene, 1000 * 1e-3 * 1.01); }, kArg, "max_substeps"},

        // ---- queries
        {"ent_scene_axis", "scene NULL",
         [](L) {
             double b[6];
             return ent_scene_axis(nullptr, 2, b);
         },
         kArg, "scene"},
        {"ent_scene_axis", "count 0",
         [](L l) {
             double b[6];
             return ent_scene_axis(l.scene, 0, b);
         },
         kArg, "count"},
        {"ent_scene_axis", "count 1",
         [](L l) {
             double b[6];
             return ent_scene_axis(l.scene, 1, b);
         },
         kArg, "count"},
        {"ent_scene_axis", "points_xyz_m NULL", [](L l) { return ent_scene_axis(l.scene, 10, nullptr); }, kArg,
         "points_xyz_m"},
        {"ent_scene_intestine_count", "scene NULL",
         [](L) {
             int32_t count = 77;
             const ent_status status = ent_scene_intestine_count(nullptr, &count);
             EXPECT_EQ(count, 77) << "out-parameter untouched";
             return status;
         },
         kArg, "scene"},
        {"ent_scene_intestine_count", "count NULL", [](L l) { return ent_scene_intestine_count(l.scene, nullptr); },
         kArg, "count"},
        {"ent_scene_intestine_axis", "scene NULL",
         [](L) {
             double b[6];
             return ent_scene_intestine_axis(nullptr, 0, 2, b);
         },
         kArg, "scene"},
        {"ent_scene_intestine_axis", "intestine -1",
         [](L l) {
             std::vector<double> b(6, -7.0);
             const ent_status status = ent_scene_intestine_axis(l.scene, -1, 2, b.data());
             for (double v : b) EXPECT_EQ(v, -7.0) << "nothing written";
             return status;
         },
         kArg, "intestine"},
        {"ent_scene_intestine_axis", "intestine out of range (the scene has 1)",
         [](L l) {
             std::vector<double> b(6, -7.0);
             const ent_status status = ent_scene_intestine_axis(l.scene, 1, 2, b.data());
             for (double v : b) EXPECT_EQ(v, -7.0) << "nothing written";
             return status;
         },
         kArg, "1 intestine"},
        {"ent_scene_intestine_axis", "intestine INT32_MAX",
         [](L l) {
             double b[6];
             return ent_scene_intestine_axis(l.scene, INT32_MAX, 2, b);
         },
         kArg, "intestine"},
        {"ent_scene_intestine_axis", "count 1",
         [](L l) {
             double b[6];
             return ent_scene_intestine_axis(l.scene, 0, 1, b);
         },
         kArg, "count"},
        {"ent_scene_intestine_axis", "count SIZE_MAX",
         [](L l) {
             double b[6];
             return ent_scene_intestine_axis(l.scene, 0, SIZE_MAX, b);
         },
         kArg, "count"},
        {"ent_scene_intestine_axis", "points_xyz_m NULL",
         [](L l) { return ent_scene_intestine_axis(l.scene, 0, 10, nullptr); }, kArg, "points_xyz_m"},
        {"ent_scene_control_points", "scene NULL",
         [](L) {
             double b[3];
             uint32_t count = 77;
             const ent_status status = ent_scene_control_points(nullptr, 1, b, &count);
             EXPECT_EQ(count, 77u);
             return status;
         },
         kArg, "scene"},
        {"ent_scene_control_points", "out_count NULL",
         [](L l) {
             double b[3 * 12];
             return ent_scene_control_points(l.scene, 12, b, nullptr);
         },
         kArg, "out_count"},
        {"ent_scene_control_points", "capacity too small",
         [](L l) {
             std::vector<double> b(3 * 12, -7.0);
             uint32_t count = 0;
             const ent_status status = ent_scene_control_points(l.scene, 11, b.data(), &count);
             EXPECT_EQ(count, 12u) << "the needed count is reported";
             for (double v : b) EXPECT_EQ(v, -7.0) << "nothing copied";
             return status;
         },
         ENT_ERROR_BUFFER_TOO_SMALL, "capacity"},
        {"ent_scene_stats", "scene NULL",
         [](L) {
             ent_stats s;
             s.struct_size = sizeof s;
             return ent_scene_stats(nullptr, &s);
         },
         kArg, "scene"},
        {"ent_scene_stats", "out NULL", [](L l) { return ent_scene_stats(l.scene, nullptr); }, kArg, "out"},
        {"ent_scene_read_desc", "scene NULL",
         [](L) {
             ent_scene_desc d;
             ent_scene_desc_default(&d);
             return ent_scene_read_desc(nullptr, &d);
         },
         kArg, "scene"},
        {"ent_scene_read_desc", "out NULL", [](L l) { return ent_scene_read_desc(l.scene, nullptr); }, kArg, "out"},
        {"ent_scene_effect_stats", "scene NULL",
         [](L) {
             ent_effect_stats s;
             s.struct_size = sizeof s;
             return ent_scene_effect_stats(nullptr, 0, &s);
         },
         kArg, "scene"},
        {"ent_scene_effect_stats", "out NULL", [](L l) { return ent_scene_effect_stats(l.scene, 0, nullptr); }, kArg,
         "out"},

        // ---- moving anatomy (the live scene has no obstacle: every id is unknown)
        {"ent_scene_create_json_file", "path NULL",
         [](L) {
             ent_scene* out = sentinel<ent_scene>();
             const ent_status status = ent_scene_create_json_file(nullptr, nullptr, &out);
             EXPECT_EQ(out, sentinel<ent_scene>());
             return status;
         },
         kArg, "path"},
        {"ent_scene_create_json_file", "no such file",
         [](L) {
             ent_scene* out = sentinel<ent_scene>();
             const ent_status status = ent_scene_create_json_file("/nonexistent/enteron/scene.json", nullptr, &out);
             EXPECT_EQ(out, sentinel<ent_scene>());
             return status;
         },
         kArg, "/nonexistent/enteron/scene.json"},
        {"ent_scene_create_json_file", "out_scene NULL",
         [](L) { return ent_scene_create_json_file("/nonexistent/enteron/scene.json", nullptr, nullptr); }, kArg,
         "out_scene"},
        {"ent_obstacle_set_pose", "scene NULL",
         [](L) {
             const double p[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0};
             return ent_obstacle_set_pose(nullptr, 0, p, q);
         },
         kArg, "scene"},
        {"ent_obstacle_set_pose", "position_m NaN",
         [](L l) {
             const double p[3] = {0, kNaN, 0}, q[4] = {1, 0, 0, 0};
             return ent_obstacle_set_pose(l.scene, 0, p, q);
         },
         kArg, "position_m"},
        {"ent_obstacle_set_pose", "orientation_wxyz zero",
         [](L l) {
             const double p[3] = {0, 0, 0}, q[4] = {0, 0, 0, 0};
             return ent_obstacle_set_pose(l.scene, 0, p, q);
         },
         kArg, "orientation_wxyz"},
        {"ent_obstacle_set_pose", "unknown obstacle 0",
         [](L l) {
             const double p[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0};
             return ent_obstacle_set_pose(l.scene, 0, p, q);
         },
         ENT_ERROR_NOT_FOUND, "obstacle 0"},
        {"ent_obstacle_set_velocity", "angular_rad_per_s Inf",
         [](L l) {
             const double v[3] = {0, 0, 0}, w[3] = {0, 0, kInf};
             return ent_obstacle_set_velocity(l.scene, 0, v, w);
         },
         kArg, "angular_rad_per_s"},
        {"ent_obstacle_set_velocity", "unknown obstacle -5",
         [](L l) {
             const double v[3] = {0, 0, 0}, w[3] = {0, 0, 0};
             return ent_obstacle_set_velocity(l.scene, -5, v, w);
         },
         ENT_ERROR_NOT_FOUND, "obstacle -5"},
        {"ent_obstacle_set_friction", "friction NaN", [](L l) { return ent_obstacle_set_friction(l.scene, 0, kNaN); },
         kArg, "friction"},
        {"ent_obstacle_set_friction", "unknown obstacle 3", [](L l) { return ent_obstacle_set_friction(l.scene, 3, 0.5); },
         ENT_ERROR_NOT_FOUND, "obstacle 3"},
        {"ent_scene_remove_obstacle", "scene NULL", [](L) { return ent_scene_remove_obstacle(nullptr, 0); }, kArg,
         "scene"},
        {"ent_scene_remove_obstacle", "unknown obstacle 0", [](L l) { return ent_scene_remove_obstacle(l.scene, 0); },
         ENT_ERROR_NOT_FOUND, "obstacle 0"},
        {"ent_scene_obstacle_count", "scene NULL",
         [](L) {
             uint32_t count = 7;
             const ent_status status = ent_scene_obstacle_count(nullptr, &count);
             EXPECT_EQ(count, 7u);
             return status;
         },
         kArg, "scene"},
        {"ent_scene_obstacle_count", "out_count NULL", [](L l) { return ent_scene_obstacle_count(l.scene, nullptr); },
         kArg, "out_count"},
        {"ent_obstacle_pose", "position_m NULL",
         [](L l) {
             double q[4];
             return ent_obstacle_pose(l.scene, 0, nullptr, q);
         },
         kArg, "position_m"},
        {"ent_obstacle_pose", "unknown obstacle 0",
         [](L l) {
             double p[3] = {7, 7, 7}, q[4] = {7, 7, 7, 7};
             const ent_status status = ent_obstacle_pose(l.scene, 0, p, q);
             EXPECT_EQ(p[0], 7.0);
             EXPECT_EQ(q[0], 7.0);
             return status;
         },
         ENT_ERROR_NOT_FOUND, "obstacle 0"},
        {"ent_obstacle_mesh", "out_vertex_count NULL",
         [](L l) {
             uint32_t triangles = 7;
             return ent_obstacle_mesh(l.scene, 0, 0, nullptr, nullptr, 0, nullptr, &triangles);
         },
         kArg, "out_vertex_count"},
        {"ent_obstacle_mesh", "unknown obstacle 0",
         [](L l) {
             uint32_t vertices = 7, triangles = 7;
             const ent_status status = ent_obstacle_mesh(l.scene, 0, 0, nullptr, &vertices, 0, nullptr, &triangles);
             EXPECT_EQ(vertices, 7u);
             EXPECT_EQ(triangles, 7u);
             return status;
         },
         ENT_ERROR_NOT_FOUND, "obstacle 0"},
        {"ent_scene_set_gravity", "scene NULL",
         [](L) {
             const double g[3] = {0, 0, -9.81};
             return ent_scene_set_gravity(nullptr, g);
         },
         kArg, "scene"},
        {"ent_scene_set_gravity", "gravity NULL", [](L l) { return ent_scene_set_gravity(l.scene, nullptr); }, kArg,
         "gravity_m_per_s2"},
        {"ent_scene_set_gravity", "gravity -Inf",
         [](L l) {
             const double g[3] = {0, 0, -kInf};
             return ent_scene_set_gravity(l.scene, g);
         },
         kArg, "gravity_m_per_s2"},
        {"ent_scene_pin_point", "control_point 12 of 12", [](L l) { return ent_scene_pin_point(l.scene, 12, -1); },
         kArg, "control_point"},
        {"ent_scene_pin_point", "unknown obstacle 2", [](L l) { return ent_scene_pin_point(l.scene, 3, 2); },
         ENT_ERROR_NOT_FOUND, "obstacle 2"},
        {"ent_scene_unpin_point", "control_point UINT32_MAX",
         [](L l) { return ent_scene_unpin_point(l.scene, UINT32_MAX); }, kArg, "control_point"},
        {"ent_scene_unpin_point", "not pinned", [](L l) { return ent_scene_unpin_point(l.scene, 4); },
         ENT_ERROR_NOT_FOUND, "not pinned"},
        {"ent_scene_attach_mesentery", "scene NULL", [](L) { return ent_scene_attach_mesentery(nullptr, -1); }, kArg,
         "scene"},
        {"ent_scene_attach_mesentery", "unknown obstacle 1",
         [](L l) { return ent_scene_attach_mesentery(l.scene, 1); }, ENT_ERROR_NOT_FOUND, "obstacle 1"},
        {"ent_scene_attach_clamped_end", "scene NULL",
         [](L) { return ent_scene_attach_clamped_end(nullptr, ENT_PIN_FIRST, -1); }, kArg, "scene"},
        {"ent_scene_attach_clamped_end", "ends 0", [](L l) { return ent_scene_attach_clamped_end(l.scene, 0, -1); },
         kArg, "ends"},
        {"ent_scene_attach_clamped_end", "an end not clamped",
         [](L l) { return ent_scene_attach_clamped_end(l.scene, ENT_PIN_FIRST, -1); }, ENT_ERROR_NOT_FOUND,
         "not clamped"},
        {"ent_scene_add_obstacle", "mesh vertex NaN",
         obstacle_with([](ent_obstacle_desc& d) {
             static const double v[9] = {0, 0, -1, 1, 0, -1, 0, kNaN, -1};
             static const uint32_t t[3] = {0, 1, 2};
             d.kind = ENT_OBSTACLE_MESH;
             d.mesh_vertices_xyz_m = v, d.mesh_vertex_count = 3, d.mesh_triangles = t, d.mesh_triangle_count = 1;
         }),
         kArg, "vertices[2]"},
        {"ent_scene_add_obstacle", "mesh index past the vertices",
         obstacle_with([](ent_obstacle_desc& d) {
             static const double v[9] = {0, 0, -1, 1, 0, -1, 0, 1, -1};
             static const uint32_t t[3] = {0, 1, 3};
             d.kind = ENT_OBSTACLE_MESH;
             d.mesh_vertices_xyz_m = v, d.mesh_vertex_count = 3, d.mesh_triangles = t, d.mesh_triangle_count = 1;
         }),
         kArg, "triangles[0]"},
        {"ent_scene_add_obstacle", "mesh claims a billion triangles",
         obstacle_with([](ent_obstacle_desc& d) {
             static const double v[9] = {0, 0, -1, 1, 0, -1, 0, 1, -1};
             static const uint32_t t[3] = {0, 1, 2};
             d.kind = ENT_OBSTACLE_MESH;
             d.mesh_vertices_xyz_m = v, d.mesh_vertex_count = 3, d.mesh_triangles = t;
             d.mesh_triangle_count = 1000000000u;
         }),
         kArg, "1000000000"},

        // ---- ent_scene_add_obstacle
        {"ent_scene_add_obstacle", "scene NULL",
         [](L) {
             ent_obstacle_desc d;
             ent_obstacle_desc_default(&d);
             return ent_scene_add_obstacle(nullptr, &d, nullptr);
         },
         kArg, "scene"},
        {"ent_scene_add_obstacle", "desc NULL", [](L l) { return ent_scene_add_obstacle(l.scene, nullptr, nullptr); },
         kArg, "desc"},
        {"ent_scene_add_obstacle", "kind 9", obstacle_with([](ent_obstacle_desc& d) { d.kind = 9; }), kArg, "kind"},
        {"ent_scene_add_obstacle", "kind -1", obstacle_with([](ent_obstacle_desc& d) { d.kind = -1; }), kArg, "kind"},
        {"ent_scene_add_obstacle", "box half_extents_m 0",
         obstacle_with([](ent_obstacle_desc& d) { d.half_extents_m[1] = 0.0; }), kArg, "half_extents"},
        {"ent_scene_add_obstacle", "box half_extents_m Inf",
         obstacle_with([](ent_obstacle_desc& d) { d.half_extents_m[0] = kInf; }), kArg, "half_extents"},
        {"ent_scene_add_obstacle", "box center_m NaN", obstacle_with([](ent_obstacle_desc& d) { d.center_m[2] = kNaN; }),
         kArg, "center"},
        {"ent_scene_add_obstacle", "plane normal zero",
         obstacle_with([](ent_obstacle_desc& d) {
             d.kind = ENT_OBSTACLE_PLANE;
             d.normal[2] = 0.0;
         }),
         kArg, "normal"},
        {"ent_scene_add_obstacle", "plane normal 1e300 (length overflows)",
         obstacle_with([](ent_obstacle_desc& d) {
             d.kind = ENT_OBSTACLE_PLANE;
             d.normal[2] = 1e300;
         }),
         kArg, "normal"},
        {"ent_scene_add_obstacle", "sphere radius_m -1",
         obstacle_with([](ent_obstacle_desc& d) {
             d.kind = ENT_OBSTACLE_SPHERE;
             d.radius_m = -1.0;
         }),
         kArg, "radius"},
        {"ent_scene_add_obstacle", "sphere radius_m NaN",
         obstacle_with([](ent_obstacle_desc& d) {
             d.kind = ENT_OBSTACLE_SPHERE;
             d.radius_m = kNaN;
         }),
         kArg, "radius"},
        {"ent_scene_add_obstacle", "capsule end_m -Inf",
         obstacle_with([](ent_obstacle_desc& d) {
             d.kind = ENT_OBSTACLE_CAPSULE;
             d.end_m[0] = -kInf;
         }),
         kArg, "end"},

        // ---- skins
        {"ent_skin_create", "scene NULL",
         [](L) {
             ent_skin_desc d;
             ent_skin_desc_default(&d);
             ent_skin* out = sentinel<ent_skin>();
             const ent_status status = ent_skin_create(nullptr, &d, &out);
             EXPECT_EQ(out, sentinel<ent_skin>());
             return status;
         },
         kArg, "scene"},
        {"ent_skin_create", "desc NULL",
         [](L l) {
             ent_skin* out = sentinel<ent_skin>();
             return ent_skin_create(l.scene, nullptr, &out);
         },
         kArg, "desc"},
        {"ent_skin_create", "out_skin NULL",
         [](L l) {
             ent_skin_desc d;
             ent_skin_desc_default(&d);
             return ent_skin_create(l.scene, &d, nullptr);
         },
         kArg, "out_skin"},
        {"ent_skin_create", "method 3", skin_with([](ent_skin_desc& d) { d.method = 3; }), kArg, "method"},
        {"ent_skin_create", "method -1", skin_with([](ent_skin_desc& d) { d.method = -1; }), kArg, "method"},
        {"ent_skin_create", "segments 2", skin_with([](ent_skin_desc& d) { d.segments = 2; }), kArg, "segments"},
        {"ent_skin_create", "segments UINT32_MAX (huge)", skin_with([](ent_skin_desc& d) { d.segments = 0xffffffffu; }),
         kArg, "segments"},
        {"ent_skin_create", "ring_spacing_radii NaN", skin_with([](ent_skin_desc& d) { d.ring_spacing_radii = kNaN; }),
         kArg, "ring_spacing_radii"},
        {"ent_skin_create", "ring_spacing_radii 0", skin_with([](ent_skin_desc& d) { d.ring_spacing_radii = 0.0; }),
         kArg, "ring_spacing_radii"},
        {"ent_skin_create", "cap_rings 65", skin_with([](ent_skin_desc& d) { d.cap_rings = 65; }), kArg, "cap_rings"},
        {"ent_skin_create", "skeleton_spacing_radii -Inf",
         skin_with([](ent_skin_desc& d) { d.skeleton_spacing_radii = -kInf; }), kArg, "skeleton_spacing_radii"},
        {"ent_skin_create", "voxel_size_radii NaN", skin_with([](ent_skin_desc& d) { d.voxel_size_radii = kNaN; }),
         kArg, "voxel_size_radii"},
        {"ent_skin_create", "window_radii 2 (must stay below 2 R)",
         skin_with([](ent_skin_desc& d) { d.window_radii = 2.0; }), kArg, "window_radii"},
        {"ent_skin_create", "ring_chord_error_radii -0.1",
         skin_with([](ent_skin_desc& d) { d.ring_chord_error_radii = -0.1; }), kArg, "ring_chord_error_radii"},
        {"ent_skin_create", "ring_chord_error_radii NaN",
         skin_with([](ent_skin_desc& d) { d.ring_chord_error_radii = kNaN; }), kArg, "ring_chord_error_radii"},
        {"ent_skin_create", "contact_surfaces 2", skin_with([](ent_skin_desc& d) { d.contact_surfaces = 2; }), kArg,
         "contact_surfaces"},
        {"ent_skin_create", "contact_surfaces -1", skin_with([](ent_skin_desc& d) { d.contact_surfaces = -1; }), kArg,
         "contact_surfaces"},
        {"ent_skin_create", "skeleton_chord_error_radii -0.01",
         skin_with([](ent_skin_desc& d) { d.skeleton_chord_error_radii = -0.01; }), kArg, "skeleton_chord_error_radii"},
        {"ent_skin_create", "skeleton_chord_error_radii 0.2",
         skin_with([](ent_skin_desc& d) { d.skeleton_chord_error_radii = 0.2; }), kArg, "skeleton_chord_error_radii"},
        {"ent_skin_create", "skeleton_chord_error_radii NaN",
         skin_with([](ent_skin_desc& d) { d.skeleton_chord_error_radii = kNaN; }), kArg, "skeleton_chord_error_radii"},
        {"ent_skin_update", "skin NULL", [](L) { return ent_skin_update(nullptr); }, kArg, "skin"},
        {"ent_skin_mesh", "skin NULL",
         [](L) {
             ent_mesh_view v;
             v.struct_size = sizeof v;
             return ent_skin_mesh(nullptr, &v);
         },
         kArg, "skin"},
        {"ent_skin_mesh", "out NULL", [](L l) { return ent_skin_mesh(l.skin, nullptr); }, kArg, "out"},
        {"ent_skin_metrics", "skin NULL",
         [](L) {
             struct ent_skin_metrics m;
             m.struct_size = sizeof m;
             return ent_skin_metrics(nullptr, &m);
         },
         kArg, "skin"},
        {"ent_skin_metrics", "out NULL", [](L l) { return ent_skin_metrics(l.skin, nullptr); }, kArg, "out"},
        {"ent_skin_destroy", "skin NULL (ignored)",
         [](L) {
             ent_skin_destroy(nullptr);
             return ENT_OK;
         },
         ENT_OK, nullptr},

        // ---- tools
        {"ent_tool_desc_init", "desc NULL", [](L) { return ent_tool_desc_init(nullptr, sizeof(ent_tool_desc)); }, kArg,
         "desc"},
        {"ent_tool_add", "scene NULL",
         [](L) {
             ent_tool_desc d;
             ent_tool_desc_default(&d);
             return ent_tool_add(nullptr, &d, nullptr);
         },
         kArg, "scene"},
        {"ent_tool_add", "desc NULL", [](L l) { return ent_tool_add(l.scene, nullptr, nullptr); }, kArg, "desc"},
        {"ent_tool_add", "radius_m NaN", tool_with([](ent_tool_desc& d) { d.radius_m = kNaN; }), kArg, "radius_m"},
        {"ent_tool_add", "radius_m 0", tool_with([](ent_tool_desc& d) { d.radius_m = 0.0; }), kArg, "radius_m"},
        {"ent_tool_add", "radius_m 1e200 (huge; its contacts' energy overflowed)",
         tool_with([](ent_tool_desc& d) { d.radius_m = 1e200; }), kArg, "radius_m"},
        {"ent_tool_add", "length_m -1", tool_with([](ent_tool_desc& d) { d.length_m = -1.0; }), kArg, "length_m"},
        {"ent_tool_add", "length_m 1e300 (huge)", tool_with([](ent_tool_desc& d) { d.length_m = 1e300; }), kArg,
         "length_m"},
        {"ent_tool_add", "grasp_margin_m DBL_MAX (huge)", tool_with([](ent_tool_desc& d) { d.grasp_margin_m = DBL_MAX; }),
         kArg, "grasp_margin_m"},
        {"ent_tool_add", "max_force_N 0", tool_with([](ent_tool_desc& d) { d.max_force_N = 0.0; }), kArg,
         "max_force_N"},
        {"ent_tool_add", "max_force_N Inf", tool_with([](ent_tool_desc& d) { d.max_force_N = kInf; }), kArg,
         "max_force_N"},
        {"ent_tool_add", "jaw_length_m -0.01", tool_with([](ent_tool_desc& d) { d.jaw_length_m = -0.01; }), kArg,
         "jaw_length_m"},
        {"ent_tool_add", "jaw_opening_m NaN", tool_with([](ent_tool_desc& d) { d.jaw_opening_m = kNaN; }), kArg,
         "jaw_opening_m"},
        {"ent_tool_add", "jaw_opening_m 2 (wider than a metre)",
         tool_with([](ent_tool_desc& d) { d.jaw_opening_m = 2.0; }), kArg, "jaw_opening_m"},
        {"ent_tool_add", "blade_width_m -0.06", tool_with([](ent_tool_desc& d) { d.blade_width_m = -0.06; }), kArg,
         "blade_width_m"},
        {"ent_tool_add", "blade_length_m Inf", tool_with([](ent_tool_desc& d) { d.blade_length_m = kInf; }), kArg,
         "blade_length_m"},
        {"ent_tool_add", "grasp_margin_m -1", tool_with([](ent_tool_desc& d) { d.grasp_margin_m = -1.0; }), kArg,
         "grasp_margin_m"},
        {"ent_tool_add", "grasp_stiffness_N_per_m 0",
         tool_with([](ent_tool_desc& d) { d.grasp_stiffness_N_per_m = 0.0; }), kArg, "grasp_stiffness_N_per_m"},
        {"ent_tool_add", "grasp_damping_N_s_per_m NaN",
         tool_with([](ent_tool_desc& d) { d.grasp_damping_N_s_per_m = kNaN; }), kArg, "grasp_damping_N_s_per_m"},
        {"ent_tool_add", "position_m -Inf", tool_with([](ent_tool_desc& d) { d.position_m[1] = -kInf; }), kArg,
         "position_m"},
        {"ent_tool_add", "orientation_wxyz zero",
         tool_with([](ent_tool_desc& d) { d.orientation_wxyz[0] = 0.0; }), kArg, "orientation_wxyz"},
        {"ent_tool_add", "orientation_wxyz NaN", tool_with([](ent_tool_desc& d) { d.orientation_wxyz[2] = kNaN; }),
         kArg, "orientation_wxyz"},
        {"ent_tool_set_pose", "scene NULL",
         [](L) {
             const double p[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0};
             return ent_tool_set_pose(nullptr, 0, p, q);
         },
         kArg, "scene"},
        {"ent_tool_set_pose", "position_m NULL",
         [](L l) {
             const double q[4] = {1, 0, 0, 0};
             return ent_tool_set_pose(l.scene, l.tool, nullptr, q);
         },
         kArg, "position_m"},
        {"ent_tool_set_pose", "orientation_wxyz NULL",
         [](L l) {
             const double p[3] = {0, 0, 0};
             return ent_tool_set_pose(l.scene, l.tool, p, nullptr);
         },
         kArg, "orientation_wxyz"},
        {"ent_tool_set_pose", "unknown tool 99",
         [](L l) {
             const double p[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0};
             return ent_tool_set_pose(l.scene, 99, p, q);
         },
         ENT_ERROR_NOT_FOUND, "tool 99"},
        {"ent_tool_set_pose", "position_m NaN", pose_with([](double* p, double*) { p[0] = kNaN; }), kArg,
         "position_m"},
        {"ent_tool_set_pose", "position_m Inf", pose_with([](double* p, double*) { p[2] = kInf; }), kArg,
         "position_m"},
        {"ent_tool_set_pose", "orientation_wxyz zero", pose_with([](double*, double* q) { q[0] = 0.0; }), kArg,
         "orientation_wxyz"},
        {"ent_tool_set_pose", "orientation_wxyz Inf", pose_with([](double*, double* q) { q[3] = kInf; }), kArg,
         "orientation_wxyz"},
        {"ent_tool_set_pose", "orientation_wxyz 1e-300 (norm underflows)",
         pose_with([](double*, double* q) { q[0] = 1e-300; }), kArg, "orientation_wxyz"},
        {"ent_tool_wrench", "scene NULL",
         [](L) {
             double f[3], t[3];
             return ent_tool_wrench(nullptr, 0, f, t);
         },
         kArg, "scene"},
        {"ent_tool_wrench", "force_N NULL",
         [](L l) {
             double t[3];
             return ent_tool_wrench(l.scene, l.tool, nullptr, t);
         },
         kArg, "force_N"},
        {"ent_tool_wrench", "torque_Nm NULL",
         [](L l) {
             double f[3];
             return ent_tool_wrench(l.scene, l.tool, f, nullptr);
         },
         kArg, "torque_Nm"},
        {"ent_tool_wrench", "unknown tool -1",
         [](L l) {
             double f[3] = {7, 7, 7}, t[3] = {7, 7, 7};
             const ent_status status = ent_tool_wrench(l.scene, -1, f, t);
             EXPECT_EQ(f[0], 7.0) << "force_N written on failure";
             return status;
         },
         ENT_ERROR_NOT_FOUND, "tool -1"},
        {"ent_tool_grasp", "scene NULL", [](L) { return ent_tool_grasp(nullptr, 0); }, kArg, "scene"},
        {"ent_tool_grasp", "unknown tool INT32_MAX", [](L l) { return ent_tool_grasp(l.scene, INT32_MAX); },
         ENT_ERROR_NOT_FOUND, "tool"},
        {"ent_tool_release", "scene NULL", [](L) { return ent_tool_release(nullptr, 0); }, kArg, "scene"},
        {"ent_tool_release", "unknown tool INT32_MIN", [](L l) { return ent_tool_release(l.scene, INT32_MIN); },
         ENT_ERROR_NOT_FOUND, "tool"},
        {"ent_tool_state", "scene NULL",
         [](L) {
             int32_t g = 7;
             const ent_status status = ent_tool_state(nullptr, 0, &g);
             EXPECT_EQ(g, 7);
             return status;
         },
         kArg, "scene"},
        {"ent_tool_state", "out_grasping NULL", [](L l) { return ent_tool_state(l.scene, l.tool, nullptr); }, kArg,
         "out_grasping"},
        {"ent_tool_state", "unknown tool 1",
         [](L l) {
             int32_t g = 7;
             const ent_status status = ent_tool_state(l.scene, l.tool + 1, &g);
             EXPECT_EQ(g, 7);
             return status;
         },
         ENT_ERROR_NOT_FOUND, "tool 1"},
        {"ent_tool_read_feedback", "scene NULL",
         [](L) {
             ent_tool_feedback f;
             f.struct_size = sizeof f;
             return ent_tool_read_feedback(nullptr, 0, &f);
         },
         kArg, "scene"},
        {"ent_tool_read_feedback", "out NULL", [](L l) { return ent_tool_read_feedback(l.scene, l.tool, nullptr); },
         kArg, "out"},
        {"ent_tool_read_feedback", "unknown tool -3",
         [](L l) {
             ent_tool_feedback f;
             std::memset(&f, 0x5a, sizeof f);
             f.struct_size = sizeof f;
             const ent_tool_feedback before = f;
             const ent_status status = ent_tool_read_feedback(l.scene, -3, &f);
             EXPECT_TRUE(same_bits(&f, &before, sizeof f)) << "written on failure";
             return status;
         },
         ENT_ERROR_NOT_FOUND, "tool -3"},
        {"ent_tool_read_feedback", "struct_size between the sizes before and with saturated",
         [](L l) {
             ent_tool_feedback f;
             f.struct_size = offsetof(ent_tool_feedback, saturated) + 2;
             return ent_tool_read_feedback(l.scene, l.tool, &f);
         },
         kVersion, "struct_size"},
        // Contacts (queries) and save/restore (driving calls).
        {"ent_scene_contacts", "scene NULL",
         [](L) {
             uint32_t count = 7;
             const ent_status status = ent_scene_contacts(nullptr, 0, nullptr, &count);
             EXPECT_EQ(count, 7u);
             return status;
         },
         kArg, "scene"},
        {"ent_scene_contacts", "out_count NULL", [](L l) { return ent_scene_contacts(l.scene, 0, nullptr, nullptr); },
         kArg, "out_count"},
        {"ent_scene_contact_summary", "scene NULL",
         [](L) {
             ent_contact_summary s;
             s.struct_size = sizeof s;
             return ent_scene_contact_summary(nullptr, &s);
         },
         kArg, "scene"},
        {"ent_scene_contact_summary", "out NULL", [](L l) { return ent_scene_contact_summary(l.scene, nullptr); },
         kArg, "out"},
        {"ent_tool_read_contacts", "scene NULL",
         [](L) {
             ent_tool_contacts t{};
             t.struct_size = sizeof t;
             return ent_tool_read_contacts(nullptr, 0, &t);
         },
         kArg, "scene"},
        {"ent_tool_read_contacts", "out NULL", [](L l) { return ent_tool_read_contacts(l.scene, l.tool, nullptr); },
         kArg, "out"},
        {"ent_tool_read_contacts", "ranges_u NULL with a range_capacity",
         [](L l) {
             ent_tool_contacts t{};
             t.struct_size = sizeof t;
             t.range_capacity = 4;
             return ent_tool_read_contacts(l.scene, l.tool, &t);
         },
         kArg, "ranges_u"},
        {"ent_tool_read_contacts", "unknown tool 9",
         [](L l) {
             ent_tool_contacts t;
             std::memset(&t, 0x5a, sizeof t);
             t.struct_size = sizeof t;
             t.range_capacity = 0;
             t.ranges_u = nullptr;
             const ent_tool_contacts before = t;
             const ent_status status = ent_tool_read_contacts(l.scene, 9, &t);
             EXPECT_TRUE(same_bits(&t, &before, sizeof t)) << "written on failure";
             return status;
         },
         ENT_ERROR_NOT_FOUND, "tool 9"},
        {"ent_scene_save_state", "scene NULL",
         [](L) {
             size_t size = 7;
             const ent_status status = ent_scene_save_state(nullptr, nullptr, 0, &size);
             EXPECT_EQ(size, 7u);
             return status;
         },
         kArg, "scene"},
        {"ent_scene_save_state", "out_size NULL", [](L l) { return ent_scene_save_state(l.scene, nullptr, 0, nullptr); },
         kArg, "out_size"},
        {"ent_scene_save_state", "capacity 16",
         [](L l) {
             unsigned char buffer[16];
             std::memset(buffer, 0x5a, sizeof buffer);
             size_t size = 0;
             const ent_status status = ent_scene_save_state(l.scene, buffer, sizeof buffer, &size);
             EXPECT_GT(size, sizeof buffer) << "the size needed is reported";
             for (const unsigned char b : buffer) EXPECT_EQ(b, 0x5a) << "written on failure";
             return status;
         },
         ENT_ERROR_BUFFER_TOO_SMALL, "capacity"},
        {"ent_scene_restore_state", "scene NULL",
         [](L) {
             const char data[64] = "ENTSTATE";
             return ent_scene_restore_state(nullptr, data, sizeof data);
         },
         kArg, "scene"},
        {"ent_scene_restore_state", "buffer NULL", [](L l) { return ent_scene_restore_state(l.scene, nullptr, 64); },
         kArg, "buffer"},
        {"ent_scene_restore_state", "64 bytes of text",
         [](L l) {
             const std::string text(64, 'x');
             return ent_scene_restore_state(l.scene, text.data(), text.size());
         },
         kArg, "not a saved state"},
        {"ent_scene_restore_state", "size 0",
         [](L l) {
             const char data[1] = {0};
             return ent_scene_restore_state(l.scene, data, 0);
         },
         kArg, "header"},
        {"ent_tool_stiffness", "scene NULL", [](L) { double k[9]; return ent_tool_stiffness(nullptr, 0, k); }, kArg,
         "scene"},
        {"ent_tool_stiffness", "K_N_per_m NULL", [](L l) { return ent_tool_stiffness(l.scene, l.tool, nullptr); }, kArg,
         "K_N_per_m"},
        {"ent_tool_stiffness", "unknown tool 1",
         [](L l) {
             double k[9] = {7, 7, 7, 7, 7, 7, 7, 7, 7};
             const ent_status status = ent_tool_stiffness(l.scene, l.tool + 1, k);
             EXPECT_EQ(k[0], 7.0) << "written on failure";
             return status;
         },
         ENT_ERROR_NOT_FOUND, "tool 1"},
        {"ent_tool_read_stats", "scene NULL",
         [](L) {
             ent_tool_stats s;
             s.struct_size = sizeof s;
             return ent_tool_read_stats(nullptr, 0, &s);
         },
         kArg, "scene"},
        {"ent_tool_read_stats", "out NULL", [](L l) { return ent_tool_read_stats(l.scene, l.tool, nullptr); }, kArg,
         "out"},
        {"ent_tool_read_stats", "unknown tool 1",
         [](L l) {
             ent_tool_stats s;
             s.struct_size = sizeof s;
             return ent_tool_read_stats(l.scene, l.tool + 1, &s);
         },
         ENT_ERROR_NOT_FOUND, "tool 1"},
        {"ent_tool_read_desc", "scene NULL",
         [](L) {
             ent_tool_desc d;
             ent_tool_desc_default(&d);
             return ent_tool_read_desc(nullptr, 0, &d);
         },
         kArg, "scene"},
        {"ent_tool_read_desc", "out NULL", [](L l) { return ent_tool_read_desc(l.scene, l.tool, nullptr); }, kArg,
         "out"},
        {"ent_tool_read_desc", "unknown tool 1",
         [](L l) {
             ent_tool_desc d;
             ent_tool_desc_default(&d);
             const ent_tool_desc copy = d;
             const ent_status status = ent_tool_read_desc(l.scene, l.tool + 1, &d);
             EXPECT_TRUE(same_bits(&d, &copy, sizeof d)) << "written on failure";
             return status;
         },
         ENT_ERROR_NOT_FOUND, "tool 1"},
        {"ent_tool_read_desc", "unknown tool -1",
         [](L l) {
             ent_tool_desc d;
             ent_tool_desc_default(&d);
             return ent_tool_read_desc(l.scene, -1, &d);
         },
         ENT_ERROR_NOT_FOUND, "tool -1"},
        {"ent_tool_remove", "scene NULL", [](L) { return ent_tool_remove(nullptr, 0); }, kArg, "scene"},
        {"ent_tool_remove", "unknown tool 1", [](L l) { return ent_tool_remove(l.scene, l.tool + 1); },
         ENT_ERROR_NOT_FOUND, "tool 1"},
        // ---- the exposure query
        {"ent_exposure_desc_init", "desc NULL", [](L) { return ent_exposure_desc_init(nullptr, sizeof(ent_exposure_desc)); },
         kArg, "desc"},
        {"ent_exposure_create", "scene NULL",
         [](L) {
             ent_exposure_desc d;
             ent_exposure_desc_default(&d);
             d.points_xyz_m = kTargetPoints;
             d.point_count = 1;
             ent_exposure* out = sentinel<ent_exposure>();
             const ent_status status = ent_exposure_create(nullptr, &d, &out);
             EXPECT_EQ(out, sentinel<ent_exposure>());
             return status;
         },
         kArg, "scene"},
        {"ent_exposure_create", "desc NULL",
         [](L l) {
             ent_exposure* out = sentinel<ent_exposure>();
             return ent_exposure_create(l.scene, nullptr, &out);
         },
         kArg, "desc"},
        {"ent_exposure_create", "out_exposure NULL",
         [](L l) {
             ent_exposure_desc d;
             ent_exposure_desc_default(&d);
             d.points_xyz_m = kTargetPoints;
             d.point_count = 1;
             return ent_exposure_create(l.scene, &d, nullptr);
         },
         kArg, "out_exposure"},
        {"ent_exposure_create", "points NULL", exposure_with([](ent_exposure_desc& d) { d.points_xyz_m = nullptr; }),
         kArg, "points_xyz_m"},
        {"ent_exposure_create", "point_count 0", exposure_with([](ent_exposure_desc& d) { d.point_count = 0; }), kArg,
         "point_count"},
        {"ent_exposure_create", "point_count 2^20 + 1 (more than the array: refused before reading)",
         exposure_with([](ent_exposure_desc& d) { d.point_count = (1u << 20) + 1; }), kArg, "point_count"},
        {"ent_exposure_create", "a NaN coordinate",
         exposure_with([](ent_exposure_desc& d) {
             static const double nan_point[3] = {0.0, kNaN, 0.0};
             d.points_xyz_m = nan_point;
         }),
         kArg, "points_xyz_m[0]"},
        {"ent_exposure_create", "triangles NULL with a triangle_count",
         exposure_with([](ent_exposure_desc& d) { d.triangle_count = 2; }), kArg, "triangles"},
        {"ent_exposure_create", "triangle_count 0 with triangles",
         exposure_with([](ent_exposure_desc& d) { d.triangles = kTargetTriangle; }), kArg, "triangle_count"},
        {"ent_exposure_create", "an index past the points",
         exposure_with([](ent_exposure_desc& d) {
             d.triangles = kTargetTriangle;
             d.triangle_count = 1;  // index 1 with one point
         }),
         kArg, "triangles[0]"},
        {"ent_exposure_create", "2^20 triangles x 32^2 samples (refused before the triangles are read)",
         exposure_with([](ent_exposure_desc& d) {
             d.triangles = kTargetTriangle;
             d.triangle_count = 1u << 20;
             d.samples_per_edge = 32;
         }),
         kArg, "samples"},
        {"ent_exposure_create", "every triangle of zero area",
         exposure_with([](ent_exposure_desc& d) {
             d.point_count = 2;
             d.triangles = kTargetTriangle;  // 0, 1, 0: degenerate
             d.triangle_count = 1;
         }),
         kArg, "no weight"},
        {"ent_exposure_create", "samples_per_edge 0", exposure_with([](ent_exposure_desc& d) { d.samples_per_edge = 0; }),
         kArg, "samples_per_edge"},
        {"ent_exposure_create", "samples_per_edge 33",
         exposure_with([](ent_exposure_desc& d) { d.samples_per_edge = 33; }), kArg, "samples_per_edge"},
        {"ent_exposure_create", "axis_chords_per_segment 0",
         exposure_with([](ent_exposure_desc& d) { d.axis_chords_per_segment = 0; }), kArg, "axis_chords_per_segment"},
        {"ent_exposure_create", "axis_chords_per_segment 65",
         exposure_with([](ent_exposure_desc& d) { d.axis_chords_per_segment = 65; }), kArg, "axis_chords_per_segment"},
        {"ent_exposure_create", "a negative weight",
         exposure_with([](ent_exposure_desc& d) {
             static const double weight[1] = {-1.0};
             d.weights = weight;
         }),
         kArg, "weights[0]"},
        {"ent_exposure_create", "a NaN weight",
         exposure_with([](ent_exposure_desc& d) {
             static const double weight[1] = {kNaN};
             d.weights = weight;
         }),
         kArg, "weights[0]"},
        {"ent_exposure_create", "weights all zero",
         exposure_with([](ent_exposure_desc& d) {
             static const double weight[1] = {0.0};
             d.weights = weight;
         }),
         kArg, "all zero"},
        {"ent_exposure_create", "obstacle 99", exposure_with([](ent_exposure_desc& d) { d.obstacle = 99; }),
         ENT_ERROR_NOT_FOUND, "obstacle 99"},
        {"ent_exposure_destroy", "exposure NULL (ignored)",
         [](L) {
             ent_exposure_destroy(nullptr);
             return ENT_OK;
         },
         ENT_OK, nullptr},
        {"ent_scene_exposure", "scene NULL",
         measuring([](L, ent_exposure* e, ent_exposure_result* r) {
             const double eye[3] = {0.0, 0.0, 0.3};
             return ent_scene_exposure(nullptr, e, eye, r);
         }),
         kArg, "scene"},
        {"ent_scene_exposure", "exposure NULL",
         measuring([](L l, ent_exposure*, ent_exposure_result* r) {
             const double eye[3] = {0.0, 0.0, 0.3};
             return ent_scene_exposure(l.scene, nullptr, eye, r);
         }),
         kArg, "exposure"},
        {"ent_scene_exposure", "viewpoint NULL",
         measuring([](L l, ent_exposure* e, ent_exposure_result* r) { return ent_scene_exposure(l.scene, e, nullptr, r); }),
         kArg, "viewpoint_m"},
        {"ent_scene_exposure", "viewpoint NaN",
         measuring([](L l, ent_exposure* e, ent_exposure_result* r) {
             const double eye[3] = {0.0, kNaN, 0.3};
             return ent_scene_exposure(l.scene, e, eye, r);
         }),
         kArg, "viewpoint_m[1]"},
        {"ent_scene_exposure", "out NULL",
         measuring([](L l, ent_exposure* e, ent_exposure_result*) {
             const double eye[3] = {0.0, 0.0, 0.3};
             return ent_scene_exposure(l.scene, e, eye, nullptr);
         }),
         kArg, "out"},
        {"ent_scene_exposure", "spans_u NULL with a span_capacity",
         measuring([](L l, ent_exposure* e, ent_exposure_result* r) {
             const double eye[3] = {0.0, 0.0, 0.3};
             r->span_capacity = 4;
             return ent_scene_exposure(l.scene, e, eye, r);
         }),
         kArg, "spans_u"},
        {"ent_scene_exposure", "an exposure made for another scene",
         measuring(
             [](L l, ent_exposure* e, ent_exposure_result* r) {
                 const double eye[3] = {0.0, 0.0, 0.3};
                 return ent_scene_exposure(l.scene, e, eye, r);
             },
             true),
         kArg, "another scene"},
        {"ent_tool_remove", "unknown tool -1", [](L l) { return ent_tool_remove(l.scene, -1); }, ENT_ERROR_NOT_FOUND,
         "tool -1"},
        {"ent_scene_tool_count", "scene NULL", [](L) { int32_t n; return ent_scene_tool_count(nullptr, &n); }, kArg,
         "scene"},
        {"ent_scene_tool_count", "out_count NULL", [](L l) { return ent_scene_tool_count(l.scene, nullptr); }, kArg,
         "out_count"},
        {"ent_tool_add", "mode 2", tool_with([](ent_tool_desc& d) { d.mode = 2; }), kArg, "mode"},
        {"ent_tool_add", "coupling_stiffness_N_per_m 0",
         tool_with([](ent_tool_desc& d) { d.coupling_stiffness_N_per_m = 0.0; }), kArg, "coupling_stiffness_N_per_m"},
        {"ent_tool_add", "coupling_damping_N_s_per_m NaN",
         tool_with([](ent_tool_desc& d) { d.coupling_damping_N_s_per_m = kNaN; }), kArg, "coupling_damping_N_s_per_m"},
        {"ent_tool_add", "friction Inf",
         tool_with([](ent_tool_desc& d) { d.friction = std::numeric_limits<double>::infinity(); }), kArg, "friction"},
        {"ent_tool_add", "passivity_limiter 3", tool_with([](ent_tool_desc& d) { d.passivity_limiter = 3; }), kArg,
         "passivity_limiter"},
    };

    // Every struct that carries a struct_size, with each size no release has.
    for (uint32_t size : kSizes) {
        const std::string s = std::to_string(size);
        auto add = [&](const char* function, std::function<ent_status(const Live&)> call) {
            rows.push_back({function, "struct_size " + s, std::move(call), kVersion, "struct_size"});
        };
        add("ent_callbacks_init", init_with_size(&ent_callbacks_init, size));
        add("ent_scene_desc_init", init_with_size(&ent_scene_desc_init, size));
        add("ent_obstacle_desc_init", init_with_size(&ent_obstacle_desc_init, size));
        add("ent_skin_desc_init", init_with_size(&ent_skin_desc_init, size));
        add("ent_exposure_desc_init", init_with_size(&ent_exposure_desc_init, size));
        add("ent_exposure_create", exposure_with([size](ent_exposure_desc& d) { d.struct_size = size; }));
        add("ent_scene_exposure", measuring([size](L l, ent_exposure* e, ent_exposure_result* r) {
                const double eye[3] = {0.0, 0.0, 0.3};
                r->struct_size = size;
                return ent_scene_exposure(l.scene, e, eye, r);
            }));
        add("ent_scene_stats",
            out_struct_with_size<ent_stats>(size, [](L l, ent_stats* s) { return ent_scene_stats(l.scene, s); }));
        add("ent_scene_effect_stats", out_struct_with_size<ent_effect_stats>(size, [](L l, ent_effect_stats* s) {
                return ent_scene_effect_stats(l.scene, ENT_EFFECT_GRAVITY, s);
            }));
        add("ent_skin_mesh",
            out_struct_with_size<ent_mesh_view>(size, [](L l, ent_mesh_view* v) { return ent_skin_mesh(l.skin, v); }));
        add("ent_skin_metrics", out_struct_with_size<struct ent_skin_metrics>(
                                    size, [](L l, struct ent_skin_metrics* m) { return ent_skin_metrics(l.skin, m); }));
        add("ent_scene_add_obstacle", obstacle_with([size](ent_obstacle_desc& d) { d.struct_size = size; }));
        add("ent_skin_create", skin_with([size](ent_skin_desc& d) { d.struct_size = size; }));
        add("ent_tool_desc_init", init_with_size(&ent_tool_desc_init, size));
        add("ent_tool_add", tool_with([size](ent_tool_desc& d) { d.struct_size = size; }));
        add("ent_scene_read_desc", out_struct_with_size<ent_scene_desc>(
                                       size, [](L l, ent_scene_desc* d) { return ent_scene_read_desc(l.scene, d); }));
        add("ent_tool_read_desc", out_struct_with_size<ent_tool_desc>(size, [](L l, ent_tool_desc* d) {
                return ent_tool_read_desc(l.scene, l.tool, d);
            }));
        add("ent_tool_read_feedback", out_struct_with_size<ent_tool_feedback>(size, [](L l, ent_tool_feedback* f) {
                return ent_tool_read_feedback(l.scene, l.tool, f);
            }));
        add("ent_scene_contact_summary", out_struct_with_size<ent_contact_summary>(size, [](L l, ent_contact_summary* c) {
                return ent_scene_contact_summary(l.scene, c);
            }));
        add("ent_tool_read_contacts", out_struct_with_size<ent_tool_contacts>(size, [](L l, ent_tool_contacts* t) {
                return ent_tool_read_contacts(l.scene, l.tool, t);
            }));
        add("ent_scene_contacts", [size](L l) {
            ent_contact list[2];
            std::memset(list, 0, sizeof list);
            list[0].struct_size = size;
            uint32_t count = 7;
            const ent_status status = ent_scene_contacts(l.scene, 2, list, &count);
            EXPECT_EQ(count, 7u) << "out_count written on failure";
            return status;
        });
        add("ent_tool_read_stats", out_struct_with_size<ent_tool_stats>(
                                       size, [](L l, ent_tool_stats* s) { return ent_tool_read_stats(l.scene, l.tool, s); }));
    }
    for (int32_t effect : {-1, ENT_EFFECT_COUNT, INT32_MAX}) {
        rows.push_back({"ent_scene_effect_stats", "an effect this library does not know",
                        [effect](L l) {
                            ent_effect_stats s;
                            s.struct_size = sizeof s;
                            return ent_scene_effect_stats(l.scene, effect, &s);
                        },
                        ENT_ERROR_NOT_FOUND, "effect"});
    }
    return rows;
}

void run_table(int32_t integrator) {
    // Twin scenes driven identically, except that `tried` also receives every bad call.
    ScenePtr tried = create(moving_desc(integrator));
    ScenePtr twin = create(moving_desc(integrator));
    ASSERT_TRUE(tried && twin);
    // A tool resting on the bowel's first control point, grasping it.
    const std::vector<double> q = control_points(tried.get());
    ent_tool_desc tool_desc;
    ent_tool_desc_default(&tool_desc);
    for (int c = 0; c < 3; ++c) tool_desc.position_m[c] = q[c];
    tool_desc.position_m[2] += 0.015;
    int32_t tool = -1;
    for (ent_scene* scene : {tried.get(), twin.get()}) {
        ASSERT_EQ(ent_tool_add(scene, &tool_desc, &tool), ENT_OK) << ent_last_error();
        ASSERT_EQ(ent_tool_grasp(scene, tool), ENT_OK) << ent_last_error();
    }
    ASSERT_TRUE(step_n(tried.get(), 1e-3, 20));
    ASSERT_TRUE(step_n(twin.get(), 1e-3, 20));
    ASSERT_GT(stats(tried.get()).kinetic_energy_J, 0.0) << "the scene must be moving";
    ent_skin_desc skin_desc;
    ent_skin_desc_default(&skin_desc);
    ent_skin* skin_raw = nullptr;
    ASSERT_EQ(ent_skin_create(tried.get(), &skin_desc, &skin_raw), ENT_OK) << ent_last_error();
    BadInputsSkinPtr skin(skin_raw);
    ASSERT_EQ(ent_skin_update(skin.get()), ENT_OK) << ent_last_error();
    const Live live{tried.get(), skin.get(), tool};
    int32_t grasping = 0;
    ASSERT_EQ(ent_tool_state(tried.get(), tool, &grasping), ENT_OK);
    EXPECT_EQ(grasping, 1) << "the tool should hold the bowel";

    for (const BadInput& row : table()) {
        SCOPED_TRACE(std::string(row.function) + ": " + row.input);
        const Observed before = observe(live);
        const ent_status status = row.call(live);
        EXPECT_EQ(status, row.status) << ent_last_error();
        if (row.message_part != nullptr) {
            EXPECT_TRUE(contains(ent_last_error(), row.message_part))
                << "message \"" << ent_last_error() << "\" should name " << row.message_part;
        }
        EXPECT_TRUE(unchanged(before, observe(live)));
    }
    // The hidden state (velocities) is untouched too: the next steps agree bit for bit.
    ASSERT_TRUE(step_n(tried.get(), 1e-3, 5));
    ASSERT_TRUE(step_n(twin.get(), 1e-3, 5));
    const auto a = control_points(tried.get());
    const auto b = control_points(twin.get());
    ASSERT_EQ(a.size(), b.size());
    EXPECT_TRUE(same_bits(a.data(), b.data(), a.size() * sizeof(double)));
    const ent_stats sa = stats(tried.get()), sb = stats(twin.get());
    EXPECT_TRUE(same_bits(&sa.kinetic_energy_J, &sb.kinetic_energy_J, sizeof(double)));
    EXPECT_EQ(sa.steps, sb.steps);
}

TEST(BadInputs, EveryRowFailsCleanlyAndChangesNothing) {
    for (int32_t integrator : kIntegrators) {
        SCOPED_TRACE(integrator_name(integrator));
        run_table(integrator);
    }
}

// A clamped end's end point is pinned by its clamp: pinning or unpinning it alone would
// leave the clamp half attached. Refused, naming the clamp, nothing changed (the saved
// state, pins and clamps among it, is the same bytes).
TEST(BadInputs, AClampedEndPointIsNeitherPinnedNorUnpinnedAlone) {
    ent_scene_desc desc = moving_desc(ENT_INTEGRATOR_IMPLICIT_EULER);
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.clamped_ends = ENT_PIN_BOTH;
    ScenePtr scene = create(desc);
    ASSERT_TRUE(scene);
    ent_obstacle_desc sphere;
    ent_obstacle_desc_default(&sphere);
    sphere.kind = ENT_OBSTACLE_SPHERE;
    sphere.radius_m = 0.01;
    sphere.center_m[2] = -1.0;
    int32_t obstacle = -1;
    ASSERT_EQ(ent_scene_add_obstacle(scene.get(), &sphere, &obstacle), ENT_OK) << ent_last_error();
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 5));
    const auto saved = [&] {
        size_t size = 0;
        EXPECT_EQ(ent_scene_save_state(scene.get(), nullptr, 0, &size), ENT_OK) << ent_last_error();
        std::vector<unsigned char> bytes(size);
        EXPECT_EQ(ent_scene_save_state(scene.get(), bytes.data(), size, &size), ENT_OK) << ent_last_error();
        return bytes;
    };
    const std::vector<unsigned char> before = saved();
    const uint32_t last = desc.control_points - 1;
    for (const uint32_t point : {0u, last}) {
        SCOPED_TRACE(point);
        const std::string named = "control point " + std::to_string(point);
        for (const int32_t frame : {ENT_NO_OBSTACLE, obstacle}) {
            EXPECT_EQ(ent_scene_pin_point(scene.get(), point, frame), ENT_ERROR_INVALID_ARGUMENT);
            EXPECT_TRUE(contains(ent_last_error(), named) && contains(ent_last_error(), "clamped end"))
                << ent_last_error();
        }
        EXPECT_EQ(ent_scene_unpin_point(scene.get(), point), ENT_ERROR_INVALID_ARGUMENT);
        EXPECT_TRUE(contains(ent_last_error(), named) && contains(ent_last_error(), "clamped end")) << ent_last_error();
    }
    EXPECT_EQ(saved(), before);
    // Attaching both clamped ends together still works, and a point between them pins.
    EXPECT_EQ(ent_scene_attach_clamped_end(scene.get(), ENT_PIN_BOTH, obstacle), ENT_OK) << ent_last_error();
    EXPECT_EQ(ent_scene_pin_point(scene.get(), 1, ENT_NO_OBSTACLE), ENT_OK) << ent_last_error();
    EXPECT_TRUE(step_n(scene.get(), 1e-3, 5));
}

TEST(BadInputs, EveryExportedFunctionHasRows) {
    std::ifstream exports(ENTERON_EXPORTS_FILE);
    ASSERT_TRUE(exports) << "no export list at " << ENTERON_EXPORTS_FILE;
    std::set<std::string> exported;
    for (std::string name; std::getline(exports, name);)
        if (!name.empty()) exported.insert(name);
    ASSERT_GT(exported.size(), 10u) << "the export list looks wrong";
    std::set<std::string> covered;
    for (const BadInput& row : table()) covered.insert(row.function);
    for (const std::string& name : exported)
        EXPECT_TRUE(covered.count(name)) << name << " is exported but has no row in the bad-input table";
    for (const std::string& name : covered)
        EXPECT_TRUE(exported.count(name)) << name << " has rows but is not exported";
}

TEST(BadInputs, TheBaseDescriptionsAreFine) {
    // Guards the table: each ent_scene_create row fails because of its one change.
    EXPECT_TRUE(create(small_desc()));
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create_json("{}", 2, &scene), ENT_OK) << ent_last_error();
    ent_scene_destroy(scene);
}

// ---- exact messages and behaviours the table cannot express ------------------------------------

TEST(BadInputs, RadiusMessageNamesTheFieldAndTheValue) {
    ent_scene_desc desc = small_desc();
    desc.radius_m = -1.0;
    ent_scene* out = sentinel<ent_scene>();
    ASSERT_EQ(ent_scene_create(&desc, &out), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(ent_last_error(), "radius_m must be > 0, got -1");
}

TEST(BadInputs, JsonRadiusMessageIsExact) {
    const std::string text = R"({"intestine": {"radius": -1}})";
    ent_scene* out = sentinel<ent_scene>();
    ASSERT_EQ(ent_scene_create_json(text.data(), text.size(), &out), ENT_ERROR_INVALID_SCENE);
    EXPECT_STREQ(ent_last_error(), "intestine.radius must be > 0, got -1");
    EXPECT_EQ(out, sentinel<ent_scene>());
}

TEST(BadInputs, JsonNeedNotBeNulTerminated) {
    // Only `length` bytes are read: what follows them (here a stray brace) is not part of it.
    const std::string buffer = R"({"intestine": {"length": 1.0, "control_points": 10}}})";
    ent_scene* scene = nullptr;
    ASSERT_EQ(ent_scene_create_json(buffer.data(), buffer.size() - 1, &scene), ENT_OK) << ent_last_error();
    ent_scene_destroy(scene);
    // ...and a length that cuts the document short is a parse error.
    ent_scene* out = sentinel<ent_scene>();
    EXPECT_EQ(ent_scene_create_json(buffer.data(), buffer.size() - 3, &out), ENT_ERROR_PARSE);
    EXPECT_EQ(out, sentinel<ent_scene>());
}

TEST(BadInputs, ControlPointsWithANullBufferReportTheCountOnly) {
    ScenePtr scene = create(small_desc());
    ASSERT_TRUE(scene);
    uint32_t count = 0;
    EXPECT_EQ(ent_scene_control_points(scene.get(), 0, nullptr, &count), ENT_OK);
    EXPECT_EQ(count, 12u);
    // Exactly enough is enough; more is fine and the rest is left alone.
    std::vector<double> bigger(3 * 13, -7.0);
    EXPECT_EQ(ent_scene_control_points(scene.get(), 13, bigger.data(), &count), ENT_OK);
    EXPECT_EQ(count, 12u);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(bigger[3 * 12 + c], -7.0);
}

}  // namespace
