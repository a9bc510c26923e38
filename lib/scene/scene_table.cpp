// SPDX-License-Identifier: Apache-2.0
#include "scene/scene_table.h"

#include <cstring>
#include <limits>

#include "collision/obstacle.h"
#include "collision/tool.h"
#include "mechanics/rigid_frames.h"
#include "scene/plausible_ranges.h"
#include "scene/scene_config.h"
#include "spline/catmull_rom.h"

namespace enteron::scene {
namespace {

using collision::Obstacle;
using collision::ObstacleKind;
using collision::ToolConfig;
using collision::ToolMode;
using collision::ToolPose;
using collision::ToolSettings;
using mechanics::RigidPose;
using Relation = Agreement::Relation;

// ---- limits ------------------------------------------------------------------------------

// Limits beyond which a scene is a mistake rather than a wish (they also keep counts far
// from overflow in the buffers sized from them).
constexpr double kMaxLength = 1000.0;  // m
constexpr double kMaxControlPoints = 100000;
constexpr double kMaxTimestep = 0.1;  // s
constexpr double kMaxSubsteps = 1000000;
constexpr double kMaxSubdivisions = 30;  // 2^-30 of the timestep is already below 1 ns
constexpr double kMaxAttachments = 100000;
// A tool 1e200 m wide is finite but gave the bowel an infinite potential energy: upper
// bounds on its sizes keep every contact's depth, and so its energy, finite.
constexpr double kMaxToolRadius = 1.0;   // m, also the largest grasp margin
constexpr double kMaxToolLength = 10.0;  // m

// ---- plausible ranges (plausible_ranges.h) --------------------------------------------------

constexpr UnitSlip kMillimetres{1e3, "millimetres"};
constexpr UnitSlip kCentimetres{1e2, "centimetres"};
constexpr UnitSlip kNone{0.0, nullptr};

// Generous bounds: a value outside is far from anything a human abdomen has.
constexpr PlausibleRange kLength{"a human small bowel's length", 0.05, 10.0, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kRadius{"a human small bowel's radius", 0.004, 0.03, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kLinearDensity{"a human small bowel's mass per metre", 0.05, 2.0, "kg/m",
                                        {{1e3, "g/m (or is it a density in kg/m^3?)"}, kNone}};
constexpr PlausibleRange kStretchStiffness{"a human small bowel's axial stiffness EA", 1.0, 1e4, "N", {kNone, kNone}};
constexpr PlausibleRange kBendStiffness{"a human small bowel's bending stiffness EI", 1e-6, 0.1, "N m^2",
                                        {kNone, kNone}};
constexpr PlausibleRange kShapeSize{"an abdominal cavity's size", 0.005, 1.0, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kGravity{"the Earth's gravity (9.81 m/s^2; 0 turns it off)", 5.0, 20.0, "m/s^2",
                                  {{1e3, "mm/s^2"}, {1.0 / 9.81, "g"}}};
constexpr PlausibleRange kTimestep{"a real-time substep", 1e-6, 0.01, "s", {{1e3, "milliseconds"}, kNone}};
constexpr PlausibleRange kDrag{"the drag of a bowel in the abdomen", 0.0, 10.0, "N s/m^2", {kNone, kNone}};
constexpr PlausibleRange kAxialDamping{"a bowel's internal damping", 0.0, 10.0, "N s", {kNone, kNone}};
constexpr PlausibleRange kMesenteryStiffness{"a mesentery spring's stiffness", 0.01, 1e3, "N/m", {{1e3, "N/mm"}, kNone}};
constexpr PlausibleRange kContactStiffness{"a soft-tissue contact's stiffness", 10.0, 1e5, "N/m",
                                           {{1e3, "N/mm"}, kNone}};
constexpr PlausibleRange kContactDamping{"a soft-tissue contact's damping", 0.0, 100.0, "N s/m", {kNone, kNone}};
constexpr PlausibleRange kFriction{"a friction coefficient of wet tissue", 0.0, 2.0, "", {kNone, kNone}};
constexpr PlausibleRange kCavityHalfSize{"an abdominal cavity's half size", 0.02, 1.0, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kOrganRadius{"an abdominal organ's or vessel's radius", 0.002, 0.5, "m",
                                      {kMillimetres, kCentimetres}};
constexpr PlausibleRange kToolRadius{"a laparoscopic tool's radius", 0.001, 0.02, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kToolLength{"a laparoscopic tool's shaft", 0.0, 1.0, "m", {kMillimetres, kCentimetres}};
constexpr PlausibleRange kToolForce{"a force a haptic device renders", 0.01, 100.0, "N", {kNone, kNone}};

// ---- the names of choices ------------------------------------------------------------------

template <typename Enum>
constexpr ChoiceName named(const char* name, Enum value) {
    return {name, static_cast<int32_t>(value)};
}

const ChoiceName kShapeKinds[] = {named("line", ShapeKind::line), named("serpentine", ShapeKind::serpentine),
                                  named("helix", ShapeKind::helix), named("points", ShapeKind::points)};
const ChoiceName kIntegrators[] = {named("rk4", IntegratorKind::rk4),
                                   named("symplectic_euler", IntegratorKind::symplectic_euler),
                                   named("implicit_euler", IntegratorKind::implicit_euler),
                                   named("bdf2", IntegratorKind::bdf2)};
const ChoiceName kPinnedEnds[] = {{"none", pin_none}, {"first", pin_first}, {"last", pin_last}, {"both", pin_both}};
const ChoiceName kToolModes[] = {named("proxy", ToolMode::proxy), named("direct", ToolMode::direct)};
const ChoiceName kObstacleKinds[] = {named("box_inside", ObstacleKind::box_inside), named("plane", ObstacleKind::plane),
                                     named("sphere", ObstacleKind::sphere), named("capsule", ObstacleKind::capsule),
                                     named("mesh", ObstacleKind::mesh)};

constexpr uint32_t kLine = kind_bit(ShapeKind::line);
constexpr uint32_t kSerpentine = kind_bit(ShapeKind::serpentine);
constexpr uint32_t kHelix = kind_bit(ShapeKind::helix);
constexpr uint32_t kPoints = kind_bit(ShapeKind::points);

constexpr uint32_t kBox = kind_bit(ObstacleKind::box_inside);
constexpr uint32_t kPlane = kind_bit(ObstacleKind::plane);
constexpr uint32_t kSphere = kind_bit(ObstacleKind::sphere);
constexpr uint32_t kCapsule = kind_bit(ObstacleKind::capsule);
constexpr uint32_t kMesh = kind_bit(ObstacleKind::mesh);

// ---- the tables ----------------------------------------------------------------------------
// Each row: the JSON key, the C field, where the value goes, its rule, its plausible range.
// The order of the rows is the order of the keys in messages and of the checks.

const Field kShapeFields[] = {
    choice<&ShapeConfig::kind>("kind", "shape", kShapeKinds),
    point<&ShapeConfig::center>("center", "shape_center_m").for_kinds(kLine | kSerpentine | kHelix),
    direction<&ShapeConfig::direction>("direction", "shape_direction").for_kinds(kLine),
    // Sizes up to kMaxLength: a helix 1e200 m wide squares its radius to infinity and has
    // no points to place.
    number<&ShapeConfig::leg_length>("leg_length", "shape_leg_length_m")
        .above(0.0)
        .at_most(kMaxLength)
        .plausible_in(kShapeSize)
        .for_kinds(kSerpentine),
    // Neighbouring legs or turns closer than a diameter would start interpenetrated.
    number<&ShapeConfig::leg_spacing>("leg_spacing", "shape_leg_spacing_m")
        .at_most(kMaxLength)
        .must_be(Relation::at_least, 2.0, "radius")
        .plausible_in(kShapeSize)
        .for_kinds(kSerpentine),
    number<&ShapeConfig::helix_radius>("helix_radius", "shape_helix_radius_m")
        .above(0.0)
        .at_most(kMaxLength)
        .plausible_in(kShapeSize)
        .for_kinds(kHelix),
    number<&ShapeConfig::helix_pitch>("helix_pitch", "shape_helix_pitch_m")
        .at_most(kMaxLength)
        .must_be(Relation::at_least, 2.0, "radius")
        .plausible_in(kShapeSize)
        .for_kinds(kHelix),
    custom("points", Special::shape_points, "shape_points_xyz_m").for_kinds(kPoints),
};
const Block kShape{kShapeFields, std::size(kShapeFields), &kShapeFields[0]};

// A profile follows the constant it replaces, which then takes the profile's largest value
// and is checked again by its row (validate.cpp): the constant's rules hold for every value.
const Field kIntestineFields[] = {
    number<&IntestineConfig::length>("length", "length_m").above(0.0).at_most(kMaxLength).plausible_in(kLength),
    number<&IntestineConfig::radius>("radius", "radius_m")
        .above(0.0)
        .must_be(Relation::below, 1.0, "length")
        .plausible_in(kRadius),
    length_profile<&IntestineConfig::radius_profile>("radius_profile", "radius_profile_m", "radius"),
    count<&IntestineConfig::control_points>("control_points", "control_points")
        .at_least(static_cast<double>(spline::kMinControlPoints))
        .at_most(kMaxControlPoints),
    number<&IntestineConfig::linear_density>("linear_density", "linear_density_kg_per_m")
        .above(0.0)
        .plausible_in(kLinearDensity),
    length_profile<&IntestineConfig::linear_density_profile>("linear_density_profile",
                                                             "linear_density_profile_kg_per_m", "linear_density"),
    // 0 turns an elasticity off: a choice, not a mistake.
    number<&IntestineConfig::stretch_stiffness>("stretch_stiffness", "stretch_stiffness_N")
        .at_least(0.0)
        .plausible_in(kStretchStiffness, true),
    length_profile<&IntestineConfig::stretch_stiffness_profile>("stretch_stiffness_profile",
                                                                "stretch_stiffness_profile_N", "stretch_stiffness"),
    number<&IntestineConfig::bend_stiffness>("bend_stiffness", "bend_stiffness_N_m2")
        .at_least(0.0)
        .plausible_in(kBendStiffness, true),
    length_profile<&IntestineConfig::bend_stiffness_profile>("bend_stiffness_profile", "bend_stiffness_profile_N_m2",
                                                             "bend_stiffness"),
    object<&IntestineConfig::shape>("shape", kShape),
};
const Block kIntestine = block_of(kIntestineFields);

const Field kSolverFields[] = {
    choice<&SolverConfig::integrator>("integrator", "integrator", kIntegrators),
    number<&SolverConfig::timestep>("timestep", "timestep_s").above(0.0).at_most(kMaxTimestep).plausible_in(kTimestep),
    count<&SolverConfig::max_substeps>("max_substeps", "max_substeps").at_least(1.0).at_most(kMaxSubsteps),
    count<&SolverConfig::max_subdivisions>("max_subdivisions", "max_subdivisions").at_most(kMaxSubdivisions),
    number<&SolverConfig::max_speed>("max_speed", "max_speed_m_per_s").above(0.0),
};
const Block kSolver = block_of(kSolverFields);

const Field kDampingFields[] = {
    number<&DampingConfig::drag>("drag", "drag_N_s_per_m2").at_least(0.0).plausible_in(kDrag),
    number<&DampingConfig::stretch>("stretch", "stretch_damping_N_s").at_least(0.0).plausible_in(kAxialDamping),
    number<&DampingConfig::bend>("bend", "bend_damping_N_m2_s").at_least(0.0).plausible_in(kAxialDamping),
};
const Block kDamping = block_of(kDampingFields);

// The root: a polyline (root), or the segment of its two ends (root_start, root_end).
const Field kMesenteryFields[] = {
    numbers<&MesenteryConfig::root_points>("root", "mesentery_root_points_m", Special::root_polyline),
    point<&MesenteryConfig::root_start>("root_start", "mesentery_root_start_m"),
    point<&MesenteryConfig::root_end>("root_end", "mesentery_root_end_m"),
    numbers<&MesenteryConfig::root_mapping>("root_mapping", "mesentery_root_mapping", Special::root_mapping),
    count<&MesenteryConfig::obstacle>("obstacle").indexing_obstacles(),
    number<&MesenteryConfig::stiffness>("stiffness", "mesentery_stiffness_N_per_m")
        .at_least(0.0)
        .plausible_in(kMesenteryStiffness),
    count<&MesenteryConfig::attachments>("attachments", "mesentery_attachments").at_least(1.0).at_most(kMaxAttachments),
    number<&MesenteryConfig::rest_length>("rest_length", "mesentery_rest_length_m").at_least(0.0),
};
const Block kMesentery = block_of(kMesenteryFields);

constexpr std::uint64_t kMaxIndex = std::numeric_limits<uint32_t>::max();

// pinned.attached: a control point held on an obstacle's frame.
const Field kAttachedPinFields[] = {
    count<&PinAttachment::point>("control_point", nullptr, kMaxIndex).below("intestine.control_points"),
    count<&PinAttachment::obstacle>("obstacle").indexing_obstacles(),
};
const Block kAttachedPin{kAttachedPinFields, std::size(kAttachedPinFields), nullptr, false, nullptr, nullptr, true,
                         Block::Check::attached_pin};

// pinned.spans: a span of the bowel held, in the world or on an obstacle's frame.
const Field kPinSpanFields[] = {
    number<&PinSpan::from>("from").at_least(0.0),
    number<&PinSpan::to>("to").at_least(0.0),
    count<&PinSpan::obstacle>("obstacle").indexing_obstacles(),
};
const Block kPinSpan{kPinSpanFields, std::size(kPinSpanFields), nullptr, false, nullptr, nullptr, true,
                     Block::Check::pin_span};

// pinned.clamped_attached: the obstacle each clamped end follows.
std::optional<std::size_t>& first_clamp_obstacle(PinnedConfig& pinned) { return pinned.clamped_obstacle[0]; }
std::optional<std::size_t>& last_clamp_obstacle(PinnedConfig& pinned) { return pinned.clamped_obstacle[1]; }
const Field kClampedAttachedFields[] = {
    count<&first_clamp_obstacle>("first").indexing_obstacles(),
    count<&last_clamp_obstacle>("last").indexing_obstacles(),
};
const Block kClampedAttached{kClampedAttachedFields,
                             std::size(kClampedAttachedFields),
                             nullptr,
                             false,
                             nullptr,
                             "{\"first\": k, \"last\": k} naming obstacles",
                             false,
                             Block::Check::clamped_attached};

const Field kPinnedFields[] = {
    choice<&PinnedConfig::ends>("ends", "pinned_ends", kPinnedEnds),
    custom("control_points", Special::pinned_points, "pinned_points"),
    list<&PinnedConfig::attached>("attached", kAttachedPin, "{\"control_point\": i, \"obstacle\": k}"),
    choice<&PinnedConfig::clamped>("clamped", "clamped_ends", kPinnedEnds),
    object_here("clamped_attached", kClampedAttached),
    list<&PinnedConfig::spans>("spans", kPinSpan, "spans {\"from\": s0, \"to\": s1, \"obstacle\": k}",
                               "pinned_spans_m"),
};
const Block kPinned{kPinnedFields, std::size(kPinnedFields), nullptr, false, nullptr, nullptr, false,
                    Block::Check::pinned};

const Field kCollisionFields[] = {
    number<&CollisionConfig::sphere_spacing>("sphere_spacing", "collision_sphere_spacing_m")
        .at_least(0.0)
        .must_be(Relation::at_most, 1.0, "intestine.radius"),
    number<&CollisionConfig::contact, &collision::ContactParameters::stiffness>("stiffness",
                                                                                "contact_stiffness_N_per_m")
        .at_least(0.0)
        .plausible_in(kContactStiffness),
    number<&CollisionConfig::contact, &collision::ContactParameters::damping>("damping", "contact_damping_N_s_per_m")
        .at_least(0.0)
        .plausible_in(kContactDamping),
    number<&CollisionConfig::contact, &collision::ContactParameters::friction>("friction", "contact_friction")
        .at_least(0.0)
        .plausible_in(kFriction),
    number<&CollisionConfig::contact, &collision::ContactParameters::slip_speed>("slip_speed",
                                                                                 "contact_slip_speed_m_per_s")
        .above(0.0),
};
const Block kCollision = block_of(kCollisionFields);

void start_obstacle(void* part, int32_t kind) {
    *static_cast<Obstacle*>(part) = default_obstacle(static_cast<ObstacleKind>(kind));
}

// Each type's shape shares the members center and extent (collision/obstacle.h).
const Field kObstacleFields[] = {
    choice<&Obstacle::kind>("type", "kind", kObstacleKinds),
    point<&Obstacle::center>("center").for_kinds(kBox | kSphere),
    point<&Obstacle::extent>("half_extents").above(0.0).plausible_in(kCavityHalfSize).for_kinds(kBox),
    point<&Obstacle::center>("point").for_kinds(kPlane),
    direction<&Obstacle::extent>("normal").for_kinds(kPlane),
    point<&Obstacle::center>("start").for_kinds(kCapsule),
    point<&Obstacle::extent>("end").for_kinds(kCapsule),
    number<&Obstacle::radius>("radius").above(0.0).plausible_in(kOrganRadius).for_kinds(kSphere | kCapsule),
    custom("file", Special::mesh_file).for_kinds(kMesh),
    custom("vertices", Special::mesh_vertices).for_kinds(kMesh),
    custom("triangles", Special::mesh_triangles).for_kinds(kMesh),
    custom("scale", Special::mesh_scale).for_kinds(kMesh),
    number<&Obstacle::voxel_size>("voxel_size").at_least(0.0).for_kinds(kMesh),
    // Every type: its frame, and its friction (negative: the scene's).
    point<&Obstacle::pose, &RigidPose::position>("position"),
    rotation<&Obstacle::pose, &RigidPose::orientation>("orientation"),
    number<&Obstacle::friction>("friction"),
};
const Block kObstacle{kObstacleFields, std::size(kObstacleFields), &kObstacleFields[0], true, &start_obstacle,
                      nullptr, false, Block::Check::obstacle};

const Field kToolFields[] = {
    number<&ToolConfig::settings, &ToolSettings::radius>("radius", "radius_m")
        .above(0.0)
        .at_most(kMaxToolRadius)
        .plausible_in(kToolRadius),
    number<&ToolConfig::settings, &ToolSettings::length>("length", "length_m")
        .at_least(0.0)
        .at_most(kMaxToolLength)
        .plausible_in(kToolLength),
    number<&ToolConfig::settings, &ToolSettings::max_force>("max_force", "max_force_N").above(0.0).plausible_in(kToolForce),
    number<&ToolConfig::settings, &ToolSettings::grasp_margin>("grasp_margin", "grasp_margin_m")
        .at_least(0.0)
        .at_most(kMaxToolRadius),
    number<&ToolConfig::settings, &ToolSettings::grasp_stiffness>("grasp_stiffness", "grasp_stiffness_N_per_m")
        .above(0.0),
    number<&ToolConfig::settings, &ToolSettings::grasp_damping>("grasp_damping", "grasp_damping_N_s_per_m")
        .at_least(0.0),
    point<&ToolConfig::pose, &ToolPose::position>("position", "position_m"),
    rotation<&ToolConfig::pose, &ToolPose::orientation>("orientation", "orientation_wxyz"),
    choice<&ToolConfig::settings, &ToolSettings::mode>("mode", "mode", kToolModes),
    number<&ToolConfig::settings, &ToolSettings::coupling_stiffness>("coupling_stiffness",
                                                                     "coupling_stiffness_N_per_m")
        .above(0.0),
    number<&ToolConfig::settings, &ToolSettings::coupling_damping>("coupling_damping", "coupling_damping_N_s_per_m")
        .at_least(0.0),
    // Finite; < 0: the scene's.
    number<&ToolConfig::settings, &ToolSettings::friction>("friction", "friction"),
    flag<&ToolConfig::settings, &ToolSettings::passivity_limiter>("passivity_limiter", "passivity_limiter"),
    number<&ToolConfig::settings, &ToolSettings::jaw_length>("jaw_length", "jaw_length_m")
        .at_least(0.0)
        .at_most(kMaxToolRadius),
    number<&ToolConfig::settings, &ToolSettings::jaw_opening>("jaw_opening", "jaw_opening_m")
        .at_least(0.0)
        .at_most(kMaxToolRadius),
    number<&ToolConfig::settings, &ToolSettings::blade_width>("blade_width", "blade_width_m")
        .at_least(0.0)
        .at_most(kMaxToolRadius),
    number<&ToolConfig::settings, &ToolSettings::blade_length>("blade_length", "blade_length_m")
        .at_least(0.0)
        .at_most(kMaxToolLength),
};
const Block kTool = block_of(kToolFields);

// self_collision: an object, for now without keys: present means on.
const Block kNoKeys{};

// A present object turns its effect on, starting from its defaults.
const Field kSceneFields[] = {
    custom("version", Special::version),
    object<&SceneConfig::intestine>("intestine", kIntestine),
    object<&SceneConfig::solver>("solver", kSolver),
    point<&SceneConfig::gravity>("gravity", "gravity_m_per_s2").plausible_length_in(kGravity),
    object<&SceneConfig::damping>("damping", kDamping),
    object<&SceneConfig::mesentery>("mesentery", kMesentery),
    object<&SceneConfig::pinned>("pinned", kPinned),
    object<&SceneConfig::collision>("collision", kCollision),
    // C adds obstacles one at a time (ent_scene_add_obstacle), naming each "obstacle[i]".
    list<&SceneConfig::environment>("environment", kObstacle, "obstacles", "obstacle"),
    switch_object<&SceneConfig::self_collision>("self_collision", kNoKeys),
    list<&SceneConfig::tools>("tools", kTool, "tools"),
};
const Block kScene = block_of(kSceneFields);

// The object row of `key` in `block`, or null.
const Field* object_row(const Block& block, const std::string& key) {
    const Field* row = block.find(key.c_str());
    return row != nullptr && std::holds_alternative<Object>(row->value) ? row : nullptr;
}

bool find_c_name_in(const Block& block, const char* c_name, FieldPath& path) {
    for (const Field& field : block) {
        if (field.c_name != nullptr && std::strcmp(field.c_name, c_name) == 0) {
            path.field = &field;
            return true;
        }
        const Object* object = std::get_if<Object>(&field.value);
        if (object == nullptr || path.depth == std::size(path.objects)) continue;
        path.objects[path.depth++] = &field;
        if (find_c_name_in(*object->block, c_name, path)) return true;
        --path.depth;
    }
    return false;
}

}  // namespace

const Block& scene_block() { return kScene; }
const Block& obstacle_block() { return kObstacle; }
const Block& tool_block() { return kTool; }

const void* FieldPath::part(const void* top) const {
    for (std::size_t i = 0; i < depth && top != nullptr; ++i) top = std::get<Object>(objects[i]->value).find(top);
    return top;
}

void* FieldPath::make_part(void* top) const {
    for (std::size_t i = 0; i < depth; ++i) top = std::get<Object>(objects[i]->value).make(top);
    return top;
}

FieldPath find_path(const Block& top, const std::string& path) {
    FieldPath found;
    const Block* block = &top;
    std::size_t start = 0;
    for (std::size_t dot = path.find('.'); dot != std::string::npos; dot = path.find('.', start)) {
        const Field* row = object_row(*block, path.substr(start, dot - start));
        if (row == nullptr || found.depth == std::size(found.objects)) return {};
        found.objects[found.depth++] = row;
        block = std::get<Object>(row->value).block;
        start = dot + 1;
    }
    found.field = block->find(path.substr(start).c_str());
    return found.field != nullptr ? found : FieldPath{};
}

FieldPath find_c_name(const Block& top, const char* c_name) {
    FieldPath found;
    return find_c_name_in(top, c_name, found) ? found : FieldPath{};
}

}  // namespace enteron::scene
