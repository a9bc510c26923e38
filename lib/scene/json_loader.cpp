// SPDX-License-Identifier: Apache-2.0
#include "scene/json_loader.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/error.h"
#include "scene/mesh_file.h"
#include "scene/points_length.h"
#include "scene/validate.h"

namespace enteron::scene {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& message) {
    throw Error(ErrorCode::invalid_scene, message);
}

// Cuts long text for a message, never inside a UTF-8 sequence.
std::string shorten(std::string text) {
    constexpr std::size_t kMaxChars = 60;
    if (text.size() <= kMaxChars) return text;
    std::size_t cut = kMaxChars;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    return text.substr(0, cut) + "...";
}

std::string quote(const std::string& text) { return json(shorten(text)).dump(); }

// A value as a message shows it. Containers are only described, so a huge or deeply
// nested value cannot blow up the message (or the stack, through dump()).
std::string describe(const json& value) {
    if (value.is_object()) return "an object";
    if (value.is_array()) {
        return "an array of " + std::to_string(value.size()) + (value.size() == 1 ? " element" : " elements");
    }
    if (value.is_string()) return quote(value.get<std::string>());
    return value.dump();  // a number, true, false or null: short
}

std::string child(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
}
std::string element(const std::string& path, std::size_t index) {
    return path + "[" + std::to_string(index) + "]";
}
std::string place(const std::string& path) {
    return path.empty() ? "at the top level" : "in " + path;
}

// ---- values ------------------------------------------------------------------------

double read_number(const json& value, const std::string& path) {
    if (!value.is_number()) fail(path + " must be a number, got " + describe(value));
    return value.get<double>();
}

// A count or index. JSON has one number type, so 1e5, 240.0 and -0 are integers too.
std::uint64_t read_count(const json& value, const std::string& path,
                         std::uint64_t max = std::numeric_limits<std::size_t>::max()) {
    std::uint64_t count = 0;
    if (value.is_number_unsigned()) {
        count = value.get<std::uint64_t>();
    } else {
        if (!value.is_number() || std::floor(value.get<double>()) != value.get<double>()) {
            fail(path + " must be an integer, got " + describe(value));
        }
        const double number = value.get<double>();
        if (number < 0.0) fail(path + " must be a non-negative integer, got " + describe(value));
        constexpr double kTwoTo64 = 18446744073709551616.0;
        if (number >= kTwoTo64) fail(path + " must be <= " + std::to_string(max) + ", got " + describe(value));
        count = static_cast<std::uint64_t>(number);
    }
    if (count > max) fail(path + " must be <= " + std::to_string(max) + ", got " + describe(value));
    return count;
}

bool read_bool(const json& value, const std::string& path) {
    if (!value.is_boolean()) fail(path + " must be true or false, got " + describe(value));
    return value.get<bool>();
}

Vec3 read_vec3(const json& value, const std::string& path) {
    if (!value.is_array() || value.size() != 3) {
        fail(path + " must be an array of 3 numbers [x, y, z], got " + describe(value));
    }
    return {read_number(value[0], element(path, 0)), read_number(value[1], element(path, 1)),
            read_number(value[2], element(path, 2))};
}

template <typename T>
using Choice = std::pair<const char*, T>;

template <typename T, std::size_t N>
T read_choice(const json& value, const std::string& path, const Choice<T> (&choices)[N]) {
    if (value.is_string()) {
        for (const auto& [name, choice] : choices) {
            if (value.get<std::string>() == name) return choice;
        }
    }
    std::string names;
    for (const auto& choice : choices) {
        names += (names.empty() ? "\"" : ", \"") + std::string(choice.first) + "\"";
    }
    fail(path + " must be one of " + names + ", got " + describe(value));
}

template <typename T, std::size_t N>
const char* choice_name(T choice, const Choice<T> (&choices)[N]) {
    for (const auto& [name, value] : choices) {
        if (value == choice) return name;
    }
    return "?";
}

const Choice<ShapeKind> kShapeKinds[] = {{"line", ShapeKind::line},
                                         {"serpentine", ShapeKind::serpentine},
                                         {"helix", ShapeKind::helix},
                                         {"points", ShapeKind::points}};
const Choice<IntegratorKind> kIntegrators[] = {{"rk4", IntegratorKind::rk4},
                                               {"symplectic_euler", IntegratorKind::symplectic_euler},
                                               {"implicit_euler", IntegratorKind::implicit_euler},
                                               {"bdf2", IntegratorKind::bdf2}};
const Choice<collision::ToolMode> kToolModes[] = {{"proxy", collision::ToolMode::proxy},
                                                  {"direct", collision::ToolMode::direct}};
const Choice<int32_t> kPinnedEnds[] = {
    {"none", pin_none}, {"first", pin_first}, {"last", pin_last}, {"both", pin_both}};

// ---- objects -----------------------------------------------------------------------

// One key an object may hold and how its value goes into the config part T. A key with
// no reader is reserved: a later version of the format will accept it.
template <typename T>
struct Key {
    const char* name;
    void (*read)(const json& value, const std::string& path, T& target);
};

template <typename T, std::size_t N>
void read_object(const json& object, const std::string& path, const Key<T> (&keys)[N], T& target) {
    if (!object.is_object()) {
        const std::string subject = path.empty() ? "the scene" : path;
        fail(subject + " must be an object, got " + describe(object));
    }
    for (const auto& [name, value] : object.items()) {
        const Key<T>* known = nullptr;
        for (const Key<T>& key : keys) {
            if (name == key.name) known = &key;
        }
        if (known != nullptr && known->read == nullptr) {
            fail(child(path, name) + " is not supported by this version");
        }
        if (known == nullptr) {
            std::string expected;
            for (const Key<T>& key : keys) {
                if (key.read != nullptr) expected += (expected.empty() ? "" : ", ") + std::string(key.name);
            }
            fail("unknown key " + quote(name) + " " + place(path) + " (expected one of: " + expected + ")");
        }
        known->read(value, child(path, name), target);
    }
}

// The shape keys that each kind uses; any other is a mistake worth reporting.
constexpr unsigned kind_bit(ShapeKind kind) { return 1u << static_cast<unsigned>(kind); }
const std::pair<const char*, unsigned> kShapeKeyKinds[] = {
    {"center", kind_bit(ShapeKind::line) | kind_bit(ShapeKind::serpentine) | kind_bit(ShapeKind::helix)},
    {"direction", kind_bit(ShapeKind::line)},
    {"leg_length", kind_bit(ShapeKind::serpentine)},
    {"leg_spacing", kind_bit(ShapeKind::serpentine)},
    {"helix_radius", kind_bit(ShapeKind::helix)},
    {"helix_pitch", kind_bit(ShapeKind::helix)},
    {"points", kind_bit(ShapeKind::points)},
};

void read_points(const json& value, const std::string& path, ShapeConfig& shape) {
    if (!value.is_array()) fail(path + " must be an array of [x, y, z] points, got " + describe(value));
    shape.points.clear();
    shape.points.reserve(3 * value.size());
    for (std::size_t i = 0; i < value.size(); ++i) {
        const Vec3 point = read_vec3(value[i], element(path, i));
        shape.points.insert(shape.points.end(), point.begin(), point.end());
    }
}

const Key<ShapeConfig> kShapeKeys[] = {
    {"kind", [](auto& v, auto& p, auto& c) { c.kind = read_choice(v, p, kShapeKinds); }},
    {"center", [](auto& v, auto& p, auto& c) { c.center = read_vec3(v, p); }},
    {"direction", [](auto& v, auto& p, auto& c) { c.direction = read_vec3(v, p); }},
    {"leg_length", [](auto& v, auto& p, auto& c) { c.leg_length = read_number(v, p); }},
    {"leg_spacing", [](auto& v, auto& p, auto& c) { c.leg_spacing = read_number(v, p); }},
    {"helix_radius", [](auto& v, auto& p, auto& c) { c.helix_radius = read_number(v, p); }},
    {"helix_pitch", [](auto& v, auto& p, auto& c) { c.helix_pitch = read_number(v, p); }},
    {"points", read_points},
};

void read_shape(const json& value, const std::string& path, ShapeConfig& shape) {
    read_object(value, path, kShapeKeys, shape);
    for (const auto& [key, kinds] : kShapeKeyKinds) {
        if (value.contains(key) && (kinds & kind_bit(shape.kind)) == 0) {
            const std::string kind = choice_name(shape.kind, kShapeKinds);
            fail(child(path, key) + " does not apply to kind \"" + kind + "\"");
        }
    }
}

const Key<IntestineConfig> kIntestineKeys[] = {
    {"length", [](auto& v, auto& p, auto& c) { c.length = read_number(v, p); }},
    {"radius", [](auto& v, auto& p, auto& c) { c.radius = read_number(v, p); }},
    {"control_points", [](auto& v, auto& p, auto& c) { c.control_points = read_count(v, p); }},
    {"linear_density", [](auto& v, auto& p, auto& c) { c.linear_density = read_number(v, p); }},
    {"stretch_stiffness", [](auto& v, auto& p, auto& c) { c.stretch_stiffness = read_number(v, p); }},
    {"bend_stiffness", [](auto& v, auto& p, auto& c) { c.bend_stiffness = read_number(v, p); }},
    {"shape", [](auto& v, auto& p, auto& c) { read_shape(v, p, c.shape); }},
};

void read_intestine(const json& value, const std::string& path, IntestineConfig& intestine) {
    read_object(value, path, kIntestineKeys, intestine);
    // Explicit points set the control point count unless it is given too, and the length:
    // the spline's through them (points_length.h).
    if (intestine.shape.kind == ShapeKind::points && !value.contains("control_points")) {
        intestine.control_points = intestine.shape.points.size() / 3;
    }
    if (intestine.shape.kind == ShapeKind::points && !value.contains("length")) intestine.length = kLengthOfThePoints;
}

const Key<SolverConfig> kSolverKeys[] = {
    {"integrator", [](auto& v, auto& p, auto& c) { c.integrator = read_choice(v, p, kIntegrators); }},
    {"timestep", [](auto& v, auto& p, auto& c) { c.timestep = read_number(v, p); }},
    {"max_substeps", [](auto& v, auto& p, auto& c) { c.max_substeps = read_count(v, p); }},
    {"max_subdivisions", [](auto& v, auto& p, auto& c) { c.max_subdivisions = read_count(v, p); }},
    {"max_speed", [](auto& v, auto& p, auto& c) { c.max_speed = read_number(v, p); }},
};

const Key<DampingConfig> kDampingKeys[] = {
    {"drag", [](auto& v, auto& p, auto& c) { c.drag = read_number(v, p); }},
    {"stretch", [](auto& v, auto& p, auto& c) { c.stretch = read_number(v, p); }},
    {"bend", [](auto& v, auto& p, auto& c) { c.bend = read_number(v, p); }},
};

void read_root(const json& value, const std::string& path, MesenteryConfig& mesentery) {
    if (!value.is_array() || value.size() != 2) {
        fail(path + " must be an array of 2 points [[x, y, z], [x, y, z]], got " + describe(value));
    }
    mesentery.root_start = read_vec3(value[0], element(path, 0));
    mesentery.root_end = read_vec3(value[1], element(path, 1));
}

const Key<MesenteryConfig> kMesenteryKeys[] = {
    {"root", read_root},
    {"obstacle", [](auto& v, auto& p, auto& c) { c.obstacle = read_count(v, p); }},
    {"stiffness", [](auto& v, auto& p, auto& c) { c.stiffness = read_number(v, p); }},
    {"attachments", [](auto& v, auto& p, auto& c) { c.attachments = read_count(v, p); }},
    {"rest_length", [](auto& v, auto& p, auto& c) { c.rest_length = read_number(v, p); }},
};

void read_pinned_points(const json& value, const std::string& path, PinnedConfig& pinned) {
    if (!value.is_array()) fail(path + " must be an array of control point indices, got " + describe(value));
    pinned.points.clear();
    for (std::size_t i = 0; i < value.size(); ++i) {
        const auto index = read_count(value[i], element(path, i), std::numeric_limits<uint32_t>::max());
        pinned.points.push_back(static_cast<uint32_t>(index));
    }
}

const Key<PinAttachment> kAttachedPinKeys[] = {
    {"control_point", [](auto& v, auto& p, auto& a) {
         a.point = static_cast<uint32_t>(read_count(v, p, std::numeric_limits<uint32_t>::max()));
     }},
    {"obstacle", [](auto& v, auto& p, auto& a) { a.obstacle = read_count(v, p); }},
};

void read_attached_pins(const json& value, const std::string& path, PinnedConfig& pinned) {
    if (!value.is_array())
        fail(path + " must be an array of {\"control_point\": i, \"obstacle\": k}, got " + describe(value));
    pinned.attached.assign(value.size(), PinAttachment{});
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string at = element(path, i);
        if (!value[i].is_object() || !value[i].contains("control_point") || !value[i].contains("obstacle"))
            fail(at + " must be an object with \"control_point\" and \"obstacle\", got " + describe(value[i]));
        read_object(value[i], at, kAttachedPinKeys, pinned.attached[i]);
    }
}

// pinned.clamped_attached: {"first": k, "last": k}, the obstacle each clamped end follows.
using ClampedObstacles = std::optional<std::size_t>[2];
const Key<ClampedObstacles> kClampedAttachedKeys[] = {
    {"first", [](auto& v, auto& p, auto& c) { c[0] = read_count(v, p); }},
    {"last", [](auto& v, auto& p, auto& c) { c[1] = read_count(v, p); }},
};

void read_clamped_attached(const json& value, const std::string& path, PinnedConfig& pinned) {
    if (!value.is_object())
        fail(path + " must be an object {\"first\": k, \"last\": k} naming obstacles, got " + describe(value));
    read_object(value, path, kClampedAttachedKeys, pinned.clamped_obstacle);
}

const Key<PinnedConfig> kPinnedKeys[] = {
    {"ends", [](auto& v, auto& p, auto& c) { c.ends = read_choice(v, p, kPinnedEnds); }},
    {"control_points", read_pinned_points},
    {"attached", read_attached_pins},
    {"clamped", [](auto& v, auto& p, auto& c) { c.clamped = read_choice(v, p, kPinnedEnds); }},
    {"clamped_attached", read_clamped_attached},
};

const Key<CollisionConfig> kCollisionKeys[] = {
    {"sphere_spacing", [](auto& v, auto& p, auto& c) { c.sphere_spacing = read_number(v, p); }},
    {"stiffness", [](auto& v, auto& p, auto& c) { c.contact.stiffness = read_number(v, p); }},
    {"damping", [](auto& v, auto& p, auto& c) { c.contact.damping = read_number(v, p); }},
    {"friction", [](auto& v, auto& p, auto& c) { c.contact.friction = read_number(v, p); }},
    {"slip_speed", [](auto& v, auto& p, auto& c) { c.contact.slip_speed = read_number(v, p); }},
};

using collision::Obstacle;
using collision::ObstacleKind;
const Choice<ObstacleKind> kObstacleKinds[] = {{"box_inside", ObstacleKind::box_inside},
                                               {"plane", ObstacleKind::plane},
                                               {"sphere", ObstacleKind::sphere},
                                               {"capsule", ObstacleKind::capsule},
                                               {"mesh", ObstacleKind::mesh}};

// The directory relative mesh files are found in, while load_scene_json runs on this thread
// (the readers below have no other way to learn it).
thread_local const std::string* t_base_directory = nullptr;

std::array<double, 4> read_quaternion(const json& value, const std::string& path);

// The keys every obstacle type has besides its shape: its frame and friction.
void read_position(const json& v, const std::string& p, Obstacle& o) { o.pose.position = read_vec3(v, p); }
void read_orientation(const json& v, const std::string& p, Obstacle& o) {
    const std::array<double, 4> q = read_quaternion(v, p);
    // Normalised (and checked for zero) by the validation.
    o.pose.orientation.coeffs() << q[1], q[2], q[3], q[0];
}
void read_friction(const json& v, const std::string& p, Obstacle& o) {
    o.friction = read_number(v, p);
    if (!(o.friction >= 0.0)) fail(p + " must be >= 0, got " + describe(v));
}

// A mesh given inline: [[x, y, z], ...] and [[a, b, c], ...].
collision::TriangleMesh& inline_mesh(Obstacle& o) {
    if (!o.mesh) o.mesh = std::make_shared<collision::TriangleMesh>();
    return const_cast<collision::TriangleMesh&>(*o.mesh);
}
void read_vertices(const json& value, const std::string& path, Obstacle& o) {
    if (!value.is_array()) fail(path + " must be an array of [x, y, z] points, got " + describe(value));
    collision::TriangleMesh& mesh = inline_mesh(o);
    mesh.vertices.clear();
    for (std::size_t i = 0; i < value.size(); ++i) {
        const Vec3 point = read_vec3(value[i], element(path, i));
        mesh.vertices.insert(mesh.vertices.end(), point.begin(), point.end());
    }
}
void read_triangles(const json& value, const std::string& path, Obstacle& o) {
    if (!value.is_array()) fail(path + " must be an array of [a, b, c] vertex indices, got " + describe(value));
    collision::TriangleMesh& mesh = inline_mesh(o);
    mesh.indices.clear();
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string at = element(path, i);
        if (!value[i].is_array() || value[i].size() != 3)
            fail(at + " must be an array of 3 vertex indices [a, b, c], got " + describe(value[i]));
        for (std::size_t k = 0; k < 3; ++k)
            mesh.indices.push_back(static_cast<uint32_t>(
                read_count(value[i][k], element(at, k), std::numeric_limits<uint32_t>::max())));
    }
}
// A mesh file: read at once, relative to the scene file's directory.
void read_mesh_file_key(const json& value, const std::string& path, Obstacle& o) {
    if (!value.is_string() || value.get<std::string>().empty())
        fail(path + " must be the path of an OBJ or PLY file, got " + describe(value));
    std::string file = value.get<std::string>();
    if (file.front() != '/' && t_base_directory != nullptr && !t_base_directory->empty())
        file = *t_base_directory + "/" + file;
    o.mesh = std::make_shared<collision::TriangleMesh>(read_mesh_file(file, 1.0, path, ErrorCode::invalid_scene));
}
// The mesh's scale (a CT mesh in millimetres: 0.001), applied once every key of the
// obstacle is read, whatever their order.
thread_local double t_mesh_scale = 1.0;
void read_scale(const json& value, const std::string& path, Obstacle&) {
    t_mesh_scale = read_number(value, path);
    if (!(t_mesh_scale > 0.0) || !std::isfinite(t_mesh_scale)) fail(path + " must be > 0, got " + describe(value));
}

// The keys of each obstacle type (besides "type") and where they go.
#define ENTERON_OBSTACLE_FRAME_KEYS \
    {"position", read_position}, {"orientation", read_orientation}, {"friction", read_friction}
const Key<Obstacle> kBoxKeys[] = {
    {"center", [](auto& v, auto& p, auto& o) { o.center = read_vec3(v, p); }},
    {"half_extents", [](auto& v, auto& p, auto& o) { o.extent = read_vec3(v, p); }},
    ENTERON_OBSTACLE_FRAME_KEYS,
};
const Key<Obstacle> kPlaneKeys[] = {
    {"point", [](auto& v, auto& p, auto& o) { o.center = read_vec3(v, p); }},
    {"normal", [](auto& v, auto& p, auto& o) { o.extent = read_vec3(v, p); }},
    ENTERON_OBSTACLE_FRAME_KEYS,
};
const Key<Obstacle> kSphereKeys[] = {
    {"center", [](auto& v, auto& p, auto& o) { o.center = read_vec3(v, p); }},
    {"radius", [](auto& v, auto& p, auto& o) { o.radius = read_number(v, p); }},
    ENTERON_OBSTACLE_FRAME_KEYS,
};
const Key<Obstacle> kCapsuleKeys[] = {
    {"start", [](auto& v, auto& p, auto& o) { o.center = read_vec3(v, p); }},
    {"end", [](auto& v, auto& p, auto& o) { o.extent = read_vec3(v, p); }},
    {"radius", [](auto& v, auto& p, auto& o) { o.radius = read_number(v, p); }},
    ENTERON_OBSTACLE_FRAME_KEYS,
};
const Key<Obstacle> kMeshKeys[] = {
    {"file", read_mesh_file_key},
    {"vertices", read_vertices},
    {"triangles", read_triangles},
    {"scale", read_scale},
    {"voxel_size", [](auto& v, auto& p, auto& o) { o.voxel_size = read_number(v, p); }},
    ENTERON_OBSTACLE_FRAME_KEYS,
};
#undef ENTERON_OBSTACLE_FRAME_KEYS

void read_obstacle(const json& value, const std::string& path, Obstacle& obstacle) {
    if (!value.is_object() || !value.contains("type"))
        fail(path + " must be an object with a \"type\", got " + describe(value));
    obstacle = default_obstacle(read_choice(value.at("type"), child(path, "type"), kObstacleKinds));
    json rest = value;
    rest.erase("type");
    switch (obstacle.kind) {
        case ObstacleKind::box_inside: read_object(rest, path, kBoxKeys, obstacle); break;
        case ObstacleKind::plane: read_object(rest, path, kPlaneKeys, obstacle); break;
        case ObstacleKind::sphere: read_object(rest, path, kSphereKeys, obstacle); break;
        case ObstacleKind::capsule: read_object(rest, path, kCapsuleKeys, obstacle); break;
        case ObstacleKind::mesh: {
            if (rest.contains("file") == (rest.contains("vertices") || rest.contains("triangles")))
                fail(path + " (mesh) must have either \"file\" or both \"vertices\" and \"triangles\"");
            if (rest.contains("vertices") != rest.contains("triangles"))
                fail(path + " (mesh) must have both \"vertices\" and \"triangles\"");
            t_mesh_scale = 1.0;
            read_object(rest, path, kMeshKeys, obstacle);
            for (double& coordinate : inline_mesh(obstacle).vertices) coordinate *= t_mesh_scale;
            break;
        }
    }
}

void read_environment(const json& value, const std::string& path, std::vector<Obstacle>& environment) {
    if (!value.is_array()) fail(path + " must be an array of obstacles, got " + describe(value));
    environment.assign(value.size(), Obstacle{});
    for (std::size_t i = 0; i < value.size(); ++i) read_obstacle(value[i], element(path, i), environment[i]);
}

using collision::ToolConfig;

std::array<double, 4> read_quaternion(const json& value, const std::string& path) {
    if (!value.is_array() || value.size() != 4)
        fail(path + " must be an array of 4 numbers [w, x, y, z], got " + describe(value));
    return {read_number(value[0], element(path, 0)), read_number(value[1], element(path, 1)),
            read_number(value[2], element(path, 2)), read_number(value[3], element(path, 3))};
}

const Key<ToolConfig> kToolKeys[] = {
    {"radius", [](auto& v, auto& p, auto& t) { t.settings.radius = read_number(v, p); }},
    {"length", [](auto& v, auto& p, auto& t) { t.settings.length = read_number(v, p); }},
    {"max_force", [](auto& v, auto& p, auto& t) { t.settings.max_force = read_number(v, p); }},
    {"grasp_margin", [](auto& v, auto& p, auto& t) { t.settings.grasp_margin = read_number(v, p); }},
    {"grasp_stiffness", [](auto& v, auto& p, auto& t) { t.settings.grasp_stiffness = read_number(v, p); }},
    {"grasp_damping", [](auto& v, auto& p, auto& t) { t.settings.grasp_damping = read_number(v, p); }},
    {"position", [](auto& v, auto& p, auto& t) {
         const Vec3 position = read_vec3(v, p);
         for (int c = 0; c < 3; ++c) t.pose.position[c] = position[c];
     }},
    {"orientation", [](auto& v, auto& p, auto& t) { t.pose.orientation = read_quaternion(v, p); }},
    {"mode", [](auto& v, auto& p, auto& t) { t.settings.mode = read_choice(v, p, kToolModes); }},
    {"coupling_stiffness", [](auto& v, auto& p, auto& t) { t.settings.coupling_stiffness = read_number(v, p); }},
    {"coupling_damping", [](auto& v, auto& p, auto& t) { t.settings.coupling_damping = read_number(v, p); }},
    {"friction", [](auto& v, auto& p, auto& t) { t.settings.friction = read_number(v, p); }},
    {"passivity_limiter", [](auto& v, auto& p, auto& t) { t.settings.passivity_limiter = read_bool(v, p); }},
};

void read_tools(const json& value, const std::string& path, std::vector<ToolConfig>& tools) {
    if (!value.is_array()) fail(path + " must be an array of tools, got " + describe(value));
    tools.assign(value.size(), ToolConfig{});
    for (std::size_t i = 0; i < value.size(); ++i) read_object(value[i], element(path, i), kToolKeys, tools[i]);
}

const Key<SceneConfig> kNoKeys[] = {{"", nullptr}};

void read_version(const json& value, const std::string& path, SceneConfig&) {
    if (!value.is_number() || value.get<double>() != 1.0) fail(path + " must be 1, got " + describe(value));
}

// Present object = effect on, starting from its defaults.
const Key<SceneConfig> kSceneKeys[] = {
    {"version", read_version},
    {"intestine", [](auto& v, auto& p, auto& c) { read_intestine(v, p, c.intestine); }},
    {"solver", [](auto& v, auto& p, auto& c) { read_object(v, p, kSolverKeys, c.solver); }},
    {"gravity", [](auto& v, auto& p, auto& c) { c.gravity = read_vec3(v, p); }},
    {"damping", [](auto& v, auto& p, auto& c) { read_object(v, p, kDampingKeys, c.damping.emplace()); }},
    {"mesentery",
     [](auto& v, auto& p, auto& c) { read_object(v, p, kMesenteryKeys, c.mesentery.emplace()); }},
    {"pinned", [](auto& v, auto& p, auto& c) { read_object(v, p, kPinnedKeys, c.pinned.emplace()); }},
    {"collision", [](auto& v, auto& p, auto& c) { read_object(v, p, kCollisionKeys, c.collision); }},
    {"environment", [](auto& v, auto& p, auto& c) { read_environment(v, p, c.environment); }},
    {"self_collision",
     [](auto& v, auto& p, auto& c) {
         // An object, for now without keys: present means on.
         read_object(v, p, kNoKeys, c);
         c.self_collision = true;
     }},
    {"tools", [](auto& v, auto& p, auto& c) { read_tools(v, p, c.tools); }},
};

// ---- parsing -----------------------------------------------------------------------

// nlohmann silently keeps the last of two equal keys; a scene that says "radius" twice is a
// mistake to report. Follows the parser's events to know which object holds the key.
class DuplicateKeyCheck {
public:
    void on_event(json::parse_event_t event, const json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start: open_.push_back({false, 0, {}, {}}); break;
            case json::parse_event_t::array_start: open_.push_back({true, 0, {}, {}}); break;
            case json::parse_event_t::key: {
                Container& object = open_.back();
                object.key = parsed.get<std::string>();
                if (!object.keys.insert(object.key).second) {
                    fail("duplicate key " + quote(object.key) + " " + place(shorten(innermost_path())));
                }
                break;
            }
            case json::parse_event_t::value: count_element(); break;
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                open_.pop_back();
                count_element();
                break;
        }
    }

private:
    struct Container {
        bool is_array;
        std::size_t elements;        // arrays: elements completed so far
        std::string key;             // objects: the key being read
        std::set<std::string> keys;  // objects: keys seen
    };

    void count_element() {
        if (!open_.empty() && open_.back().is_array) ++open_.back().elements;
    }

    std::string innermost_path() const {
        std::string path;
        for (std::size_t i = 0; i + 1 < open_.size(); ++i) {
            path = open_[i].is_array ? element(path, open_[i].elements) : child(path, open_[i].key);
        }
        return path;
    }

    std::vector<Container> open_;
};

// nlohmann's what() reads "[json.exception.parse_error.101] parse error at line 1,
// column 2: <detail>"; keep the location and the detail.
[[noreturn]] void fail_parse(const json::parse_error& error) {
    const std::string what = error.what();
    const std::string marker = "parse error at ";
    const std::size_t at = what.find(marker);
    const std::size_t colon = at == std::string::npos ? at : what.find(": ", at);
    std::string message = "JSON parse error at byte " + std::to_string(error.byte);
    if (colon != std::string::npos) {
        const std::size_t location = at + marker.size();
        message += " (" + what.substr(location, colon - location) + "): " + what.substr(colon + 2);
    } else {
        message += ": " + what;
    }
    throw Error(ErrorCode::parse, message);
}

json parse(const char* text, std::size_t length) {
    DuplicateKeyCheck duplicates;
    try {
        return json::parse(text, text + length, [&duplicates](int, json::parse_event_t event, json& parsed) {
            duplicates.on_event(event, parsed);
            return true;
        });
    } catch (const json::parse_error& error) {
        fail_parse(error);
    } catch (const json::exception& error) {  // e.g. out_of_range 406: a number that overflows a double
        const std::string what = error.what();
        const std::size_t prefix_end = what.find("] ");
        const std::string detail = prefix_end == std::string::npos ? what : what.substr(prefix_end + 2);
        throw Error(ErrorCode::parse, "JSON parse error: " + detail);
    }
}

// The fields the document gives a value, found by their paths ("mesentery.root[0]" is
// given with "mesentery.root"): the validation's messages blame what the user wrote.
FieldSet given_fields(const json& document) {
    FieldSet given;
    const FieldNames& names = json_field_names();
    for (std::size_t i = 0; i < kFieldCount; ++i) {
        const std::string path = std::string(names.names[i]).substr(0, std::string(names.names[i]).find('['));
        const json* node = &document;
        bool present = true;
        for (std::size_t start = 0; present;) {
            const std::size_t dot = path.find('.', start);
            const std::string key = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
            present = node->is_object() && node->contains(key);
            if (present) node = &(*node)[key];
            if (dot == std::string::npos) break;
            start = dot + 1;
        }
        given[i] = present;
    }
    return given;
}

}  // namespace

SceneConfig load_scene_json(const char* text, std::size_t length, const std::string& base_directory) {
    if (text == nullptr && length != 0) throw Error(ErrorCode::invalid_argument, "json is NULL");
    struct BaseDirectory {
        explicit BaseDirectory(const std::string* directory) { t_base_directory = directory; }
        ~BaseDirectory() { t_base_directory = nullptr; }
    } base(&base_directory);
    static const char kEmpty[] = "";
    const json document = parse(text != nullptr ? text : kEmpty, length);
    SceneConfig config;
    read_object(document, "", kSceneKeys, config);
    return validate(std::move(config), json_field_names(), given_fields(document));
}

}  // namespace enteron::scene
