/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Enteron C++ layer: a header-only C++17 wrapper over the C ABI of enteron.h.
 *
 * Nothing here is exported or compiled into the library: every function is inline and
 * calls the C functions, so a program built against this header depends only on the C ABI
 * (the same shared library, the same compatibility rules). docs/cpp.md is its manual.
 *
 * - RAII handles: enteron::Scene, enteron::Skin and enteron::Exposure own their C object
 *   and destroy it; enteron::Tool names a tool of a scene. All four are move-only. Every
 *   exported C function has its counterpart here (docs/cpp.md has the table; ctest
 *   docs.cpp_api checks it): obstacles, pins, attachments, gravity, tools, contacts, skins,
 *   exposure, save and restore.
 * - Errors: every failing C call throws enteron::Error, which carries the ent_status and
 *   the message of ent_last_error() (what failed and why). A step the guard cannot save
 *   throws Error with status() == ENT_ERROR_UNSTABLE, the scene unchanged.
 * - Descriptions: enteron::SceneDesc, ToolDesc, ObstacleDesc, SkinDesc and Callbacks are the
 *   C structs filled with the library's defaults on construction (struct_size set); change
 *   the fields you need. The defaults come from the library at run time, never from this
 *   header.
 * - Spans: enteron::Span<T> views a contiguous array (the mesh's arrays; with C++20 it
 *   converts to std::span).
 * - Eigen: include <Eigen/Core> before this header and enteron::as_matrix views an x y z
 *   array (the axis, the control points, the mesh positions and normals, the triangle
 *   indices) as an Eigen::Map of an N x 3 row-major matrix, without copying.
 *
 * Threads are those of the C API (enteron.h): a Scene's step, add_obstacle, add_tool,
 * save_state and restore_state are driving calls (one at a time per scene); its queries
 * and a Tool's commands and reads are safe from any thread.
 */
#ifndef ENTERON_ENTERON_HPP
#define ENTERON_ENTERON_HPP

#include <enteron/enteron.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#if __cplusplus >= 202002L && defined(__has_include)
#if __has_include(<span>)
#include <span>
#define ENTERON_HPP_HAS_STD_SPAN 1
#endif
#endif

namespace enteron {

/** A failed call: the C status (ENT_ERROR_*) and the library's message naming the problem. */
class Error : public std::runtime_error {
public:
    Error(ent_status status, const std::string& message) : std::runtime_error(message), status_(status) {}
    ent_status status() const noexcept { return status_; }

private:
    ent_status status_;
};

namespace detail {
/** Throws Error with ent_last_error() unless status is ENT_OK. */
inline void check(ent_status status) {
    if (status != ENT_OK) {
        const char* message = ent_last_error();
        throw Error(status, std::string(ent_status_string(status)) + ": " + (message != nullptr ? message : ""));
    }
}
/** The element count of an array the library reads as `what` (3 values per point for
 *  `per_item` 3), as the uint32_t the C struct holds; throws Error naming `what` when the
 *  size is not a whole number of items or the count does not fit. */
inline uint32_t item_count(std::size_t values, std::size_t per_item, const char* what) {
    if (values % per_item != 0 || values / per_item > std::numeric_limits<uint32_t>::max())
        throw Error(ENT_ERROR_INVALID_ARGUMENT, std::string(what) + " must hold a whole number of " +
                                                    std::to_string(per_item) + "-value items that fits uint32_t, got " +
                                                    std::to_string(values) + " values");
    return static_cast<uint32_t>(values / per_item);
}

/** A container's data() as const T*, after checking its element type is T. */
template <class T, class Container>
const T* data_of(const Container& values) {
    static_assert(std::is_same_v<std::remove_cv_t<std::remove_reference_t<decltype(*std::data(values))>>, T>,
                  "the container's elements must be of the C field's type");
    return std::data(values);
}
}  // namespace detail

/** A view of `size` contiguous elements (not owned). */
template <class T>
class Span {
public:
    constexpr Span() noexcept = default;
    constexpr Span(T* data, std::size_t size) noexcept : data_(data), size_(size) {}
    constexpr T* data() const noexcept { return data_; }
    constexpr std::size_t size() const noexcept { return size_; }
    constexpr bool empty() const noexcept { return size_ == 0; }
    constexpr T* begin() const noexcept { return data_; }
    constexpr T* end() const noexcept { return data_ + size_; }
    constexpr T& operator[](std::size_t i) const noexcept { return data_[i]; }
#ifdef ENTERON_HPP_HAS_STD_SPAN
    constexpr operator std::span<T>() const noexcept { return {data_, size_}; }
#endif

private:
    T* data_ = nullptr;
    std::size_t size_ = 0;
};

/** ent_scene_desc with the library's defaults (ent_scene_desc_default). Its arrays are best
 *  set with shape_points() and pinned(), which take the pointer and the count from one
 *  container: the library cannot see an array's length, and reads as many values as the
 *  count says. The container must outlive the scene's creation (it is not copied here). */
struct SceneDesc : ent_scene_desc {
    SceneDesc() noexcept : ent_scene_desc() { ent_scene_desc_default(this); }
    /** A points shape through `xyz` (x y z per point, m: doubles): shape, shape_points_xyz_m,
     *  control_points, and length_m 0 (the length of the spline through them: the bowel starts
     *  at rest; set length_m afterwards to give another). Throws Error when its size is not a
     *  multiple of 3. */
    template <class Container>
    SceneDesc& shape_points(const Container& xyz) {
        control_points = detail::item_count(std::size(xyz), 3, "shape_points_xyz_m");
        shape_points_xyz_m = detail::data_of<double>(xyz);
        shape = ENT_SHAPE_POINTS;
        length_m = 0.0;
        return *this;
    }
    /** The control points to hold (uint32_t indices): pinned_points and pinned_point_count,
     *  and the pinned effect's bit. */
    template <class Container>
    SceneDesc& pinned(const Container& indices) {
        pinned_point_count = detail::item_count(std::size(indices), 1, "pinned_points");
        pinned_points = detail::data_of<uint32_t>(indices);
        effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
        return *this;
    }
    /** A property along the length from `pairs` (s m, value: doubles, 2 per pair), in place of
     *  its constant: radius_profile_m and radius_profile_count, and the same for the others.
     *  Throws Error when its size is odd. */
    template <class Container>
    SceneDesc& radius_profile(const Container& pairs) {
        return profile(pairs, radius_profile_m, radius_profile_count, "radius_profile_m");
    }
    template <class Container>
    SceneDesc& linear_density_profile(const Container& pairs) {
        return profile(pairs, linear_density_profile_kg_per_m, linear_density_profile_count,
                       "linear_density_profile_kg_per_m");
    }
    template <class Container>
    SceneDesc& stretch_stiffness_profile(const Container& pairs) {
        return profile(pairs, stretch_stiffness_profile_N, stretch_stiffness_profile_count,
                       "stretch_stiffness_profile_N");
    }
    template <class Container>
    SceneDesc& bend_stiffness_profile(const Container& pairs) {
        return profile(pairs, bend_stiffness_profile_N_m2, bend_stiffness_profile_count, "bend_stiffness_profile_N_m2");
    }

    /** The mesentery's root as a polyline through `xyz` (x y z per point, m: doubles):
     *  mesentery_root_points_m and mesentery_root_point_count. Throws Error when its size is
     *  not a multiple of 3. */
    template <class Container>
    SceneDesc& mesentery_root(const Container& xyz) {
        mesentery_root_point_count = detail::item_count(std::size(xyz), 3, "mesentery_root_points_m");
        mesentery_root_points_m = detail::data_of<double>(xyz);
        return *this;
    }
    /** Where along the root the bowel is tied, from `pairs` (s m, t: doubles, 2 per pair):
     *  mesentery_root_mapping and its count. Throws Error when its size is odd. */
    template <class Container>
    SceneDesc& mesentery_root_mapping_pairs(const Container& pairs) {
        return profile(pairs, mesentery_root_mapping, mesentery_root_mapping_count, "mesentery_root_mapping");
    }
    /** Spans of the bowel held in the world, from `pairs` (from m, to m: doubles, 2 per
     *  pair): pinned_spans_m and pinned_span_count, and the pinned effect's bit. Throws Error
     *  when its size is odd. */
    template <class Container>
    SceneDesc& pinned_spans(const Container& pairs) {
        effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
        return profile(pairs, pinned_spans_m, pinned_span_count, "pinned_spans_m");
    }

private:
    template <class Container>
    SceneDesc& profile(const Container& pairs, const double*& field, uint32_t& count, const char* name) {
        count = detail::item_count(std::size(pairs), 2, name);
        field = detail::data_of<double>(pairs);
        return *this;
    }
};
/** ent_tool_desc with the library's defaults. */
struct ToolDesc : ent_tool_desc {
    ToolDesc() noexcept : ent_tool_desc() { ent_tool_desc_default(this); }
};
/** ent_obstacle_desc with the library's defaults. mesh() sets a mesh's arrays with their
 *  counts, as SceneDesc::shape_points does. */
struct ObstacleDesc : ent_obstacle_desc {
    ObstacleDesc() noexcept : ent_obstacle_desc() { ent_obstacle_desc_default(this); }
    /** A mesh obstacle of `vertices_xyz` (doubles, m, 3 per vertex) and `triangles` (uint32_t,
     *  3 vertex indices per triangle): kind, the two arrays and their counts. */
    template <class Vertices, class Triangles>
    ObstacleDesc& mesh(const Vertices& vertices_xyz, const Triangles& triangles) {
        mesh_vertex_count = detail::item_count(std::size(vertices_xyz), 3, "mesh_vertices_xyz_m");
        mesh_triangle_count = detail::item_count(std::size(triangles), 3, "mesh_triangles");
        mesh_vertices_xyz_m = detail::data_of<double>(vertices_xyz);
        mesh_triangles = detail::data_of<uint32_t>(triangles);
        kind = ENT_OBSTACLE_MESH;
        return *this;
    }
};
/** ent_skin_desc with the library's defaults. */
struct SkinDesc : ent_skin_desc {
    SkinDesc() noexcept : ent_skin_desc() { ent_skin_desc_default(this); }
};

/** ent_exposure_desc with the library's defaults. */
struct ExposureDesc : ent_exposure_desc {
    ExposureDesc() noexcept : ent_exposure_desc() { ent_exposure_desc_default(this); }
};

/** A C output struct with struct_size set (ent_stats, ent_tool_feedback, ...). */
template <class T>
T sized() noexcept {
    T value{};
    value.struct_size = static_cast<uint32_t>(sizeof(T));
    return value;
}

/** ent_callbacks with no hooks (silent, malloc/free); set the ones you need. The functions
 *  and user_data must outlive the scene and its skins (enteron.h, ent_callbacks). */
struct Callbacks : ent_callbacks {
    Callbacks() noexcept : ent_callbacks() { ent_callbacks_default(this); }
};

/** The version of the library loaded (ent_version), packed like ENT_VERSION. */
inline uint32_t version() noexcept { return ent_version(); }
/** Whether the library loaded serves this header: the same major version. */
inline bool compatible_version() noexcept { return (ent_version() >> 16) == ENT_VERSION_MAJOR; }
/** The JSON-style name of an effect (ENT_EFFECT_*: "stretch", "gravity", ...); empty if unknown. */
inline std::string_view effect_name(int32_t effect) noexcept {
    const char* name = ent_effect_name(effect);
    return name != nullptr ? std::string_view(name) : std::string_view();
}

/** Where a rigid frame rests: its origin (m) and orientation (w x y z, unit). */
struct Pose {
    std::array<double, 3> position_m{};
    std::array<double, 4> orientation_wxyz{1.0, 0.0, 0.0, 0.0};
};

/** What the bowel does to a tool: force (N) and torque about its tip (N m). */
struct Wrench {
    std::array<double, 3> force_N{};
    std::array<double, 3> torque_Nm{};
};

/** A mesh obstacle's triangles as the obstacle holds them (its frame, m). */
struct ObstacleMesh {
    std::vector<double> vertices_xyz_m;  /**< 3 per vertex. */
    std::vector<uint32_t> triangles;     /**< 3 vertex indices per triangle. */
    std::size_t vertex_count() const noexcept { return vertices_xyz_m.size() / 3; }
    std::size_t triangle_count() const noexcept { return triangles.size() / 3; }
};

class Scene;

/**
 * A tool of a scene (ent_tool_add). Move-only; it refers to its scene, which must outlive
 * it. Destroying the handle leaves the tool in the scene; remove() takes it out. Its
 * commands and reads are safe from any thread (a haptic thread); remove() is a driving call.
 */
class Tool {
public:
    Tool(ent_scene* scene, int32_t id) noexcept : scene_(scene), id_(id) {}
    Tool(Tool&& other) noexcept : scene_(std::exchange(other.scene_, nullptr)), id_(std::exchange(other.id_, -1)) {}
    Tool& operator=(Tool&& other) noexcept {
        scene_ = std::exchange(other.scene_, nullptr);
        id_ = std::exchange(other.id_, -1);
        return *this;
    }
    Tool(const Tool&) = delete;
    Tool& operator=(const Tool&) = delete;

    int32_t id() const noexcept { return id_; }

    /** Where the tip is at the end of the next step (m) and the orientation (w x y z). */
    void set_pose(const double position_m[3], const double orientation_wxyz[4]) {
        detail::check(ent_tool_set_pose(scene_, id_, position_m, orientation_wxyz));
    }
    void grasp() { detail::check(ent_tool_grasp(scene_, id_)); }
    void release() { detail::check(ent_tool_release(scene_, id_)); }
    bool grasping() const {
        int32_t grasping = 0;
        detail::check(ent_tool_state(scene_, id_, &grasping));
        return grasping != 0;
    }
    /** The last published step's wrench, grasp and contacts, from one snapshot. */
    ent_tool_feedback feedback() const {
        ent_tool_feedback out = sized<ent_tool_feedback>();
        detail::check(ent_tool_read_feedback(scene_, id_, &out));
        return out;
    }
    /** The last published step's wrench (ent_tool_wrench): never above max_force_N. */
    Wrench wrench() const {
        Wrench out;
        detail::check(ent_tool_wrench(scene_, id_, out.force_N.data(), out.torque_Nm.data()));
        return out;
    }
    /** d(force_N)/d(tip position) at the last published step, row-major, N/m (ent_tool_stiffness). */
    std::array<double, 9> stiffness() const {
        std::array<double, 9> out{};
        detail::check(ent_tool_stiffness(scene_, id_, out.data()));
        return out;
    }
    /** Its passivity observer and counters since it was added (ent_tool_read_stats). */
    ent_tool_stats stats() const {
        ent_tool_stats out = sized<ent_tool_stats>();
        detail::check(ent_tool_read_stats(scene_, id_, &out));
        return out;
    }
    /** The settings it was added with and the pose it was added at (ent_tool_read_desc). */
    ToolDesc desc() const {
        ToolDesc out;
        detail::check(ent_tool_read_desc(scene_, id_, &out));
        return out;
    }
    /** Takes the tool out of the scene from the next step on (ent_tool_remove; a driving
     *  call); its id is not reused, and this handle's calls then throw ENT_ERROR_NOT_FOUND. */
    void remove() { detail::check(ent_tool_remove(scene_, id_)); }

    /** What it touched and held in the last published step; the ranges of u it touched,
     *  [first, last] pairs, go into *ranges_u when given (resized to 2 per range). */
    ent_tool_contacts contacts(std::vector<double>* ranges_u = nullptr) const {
        ent_tool_contacts out = sized<ent_tool_contacts>();
        detail::check(ent_tool_read_contacts(scene_, id_, &out));
        if (ranges_u != nullptr && out.range_count > 0) {
            ranges_u->resize(2 * std::size_t{out.range_count});
            out.range_capacity = out.range_count;
            out.ranges_u = ranges_u->data();
            detail::check(ent_tool_read_contacts(scene_, id_, &out));
            // A later step may have touched fewer ranges in between.
            ranges_u->resize(2 * std::size_t{std::min(out.range_count, out.range_capacity)});
        } else if (ranges_u != nullptr) {
            ranges_u->clear();
        }
        out.ranges_u = nullptr;
        out.range_capacity = 0;
        return out;
    }

private:
    ent_scene* scene_;
    int32_t id_;
};

/** A scene (ent_scene): move-only, destroyed with its handle. */
class Scene {
public:
    /** ent_scene_create; throws Error naming the bad field. */
    explicit Scene(const ent_scene_desc& desc) { detail::check(ent_scene_create(&desc, &scene_)); }
    /** ent_scene_create_json (docs/scene-json.md). */
    static Scene from_json(std::string_view json) {
        ent_scene* scene = nullptr;
        detail::check(ent_scene_create_json(json.data(), json.size(), &scene));
        return Scene(scene);
    }
    /** ent_scene_create_json_with: with log and allocator hooks. */
    static Scene from_json(std::string_view json, const ent_callbacks& callbacks) {
        ent_scene* scene = nullptr;
        detail::check(ent_scene_create_json_with(json.data(), json.size(), &callbacks, &scene));
        return Scene(scene);
    }
    /** ent_scene_create_json_file: a scene file, its mesh files found beside it (slow: the
     *  meshes' distance fields are built; not on a real-time thread). callbacks may be null. */
    static Scene from_json_file(const std::string& path, const ent_callbacks* callbacks = nullptr) {
        ent_scene* scene = nullptr;
        detail::check(ent_scene_create_json_file(path.c_str(), callbacks, &scene));
        return Scene(scene);
    }
    /** Takes ownership of a scene made with the C API. */
    explicit Scene(ent_scene* owned) noexcept : scene_(owned) {}
    Scene(Scene&& other) noexcept : scene_(std::exchange(other.scene_, nullptr)) {}
    Scene& operator=(Scene&& other) noexcept {
        if (this != &other) {
            ent_scene_destroy(scene_);
            scene_ = std::exchange(other.scene_, nullptr);
        }
        return *this;
    }
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;
    ~Scene() { ent_scene_destroy(scene_); }

    ent_scene* get() const noexcept { return scene_; }
    /** Gives up ownership: the caller destroys the scene. */
    ent_scene* release() noexcept { return std::exchange(scene_, nullptr); }

    /** Advances dt_s seconds (a driving call). Throws Error (ENT_ERROR_UNSTABLE: unchanged). */
    void step(double dt_s) { detail::check(ent_scene_step(scene_, dt_s)); }

    /** The control points of the last published state, x y z each (m), into `out`. */
    void control_points(std::vector<double>& out) const {
        uint32_t count = 0;
        detail::check(ent_scene_control_points(scene_, 0, nullptr, &count));
        out.resize(3 * std::size_t{count});
        detail::check(ent_scene_control_points(scene_, count, out.data(), &count));
    }
    std::vector<double> control_points() const {
        std::vector<double> out;
        control_points(out);
        return out;
    }
    /** `count` (>= 2) axis points evenly spaced in arc length, x y z each (m). */
    void axis(uint32_t count, std::vector<double>& out) const {
        out.resize(3 * std::size_t{count});
        detail::check(ent_scene_axis(scene_, count, out.data()));
    }
    std::vector<double> axis(uint32_t count) const {
        std::vector<double> out;
        axis(count, out);
        return out;
    }
    /** The number of intestines (tubes), each its own axis (ent_scene_intestine_count). */
    int32_t intestine_count() const {
        int32_t out = 0;
        detail::check(ent_scene_intestine_count(scene_, &out));
        return out;
    }
    /** `count` (>= 2) points of intestine `intestine`'s axis, evenly spaced in arc length, x y z each (m). */
    void intestine_axis(int32_t intestine, std::size_t count, std::vector<double>& out) const {
        out.resize(3 * count);
        detail::check(ent_scene_intestine_axis(scene_, intestine, count, out.data()));
    }
    std::vector<double> intestine_axis(int32_t intestine, std::size_t count) const {
        std::vector<double> out;
        intestine_axis(intestine, count, out);
        return out;
    }
    ent_stats stats() const {
        ent_stats out = sized<ent_stats>();
        detail::check(ent_scene_stats(scene_, &out));
        return out;
    }
    /** The description it was made from, without its arrays (ent_scene_read_desc). */
    SceneDesc desc() const {
        SceneDesc out;
        detail::check(ent_scene_read_desc(scene_, &out));
        return out;
    }
    ent_effect_stats effect_stats(int32_t effect) const {
        ent_effect_stats out = sized<ent_effect_stats>();
        detail::check(ent_scene_effect_stats(scene_, effect, &out));
        return out;
    }

    /** Adds an obstacle (a driving call); returns its index. */
    int32_t add_obstacle(const ent_obstacle_desc& desc) {
        int32_t index = -1;
        detail::check(ent_scene_add_obstacle(scene_, &desc, &index));
        return index;
    }
    /** Moves an obstacle: it reaches this pose at the end of the next step (ent_obstacle_set_pose;
     *  the driving thread, between steps). */
    void set_obstacle_pose(int32_t obstacle, const double position_m[3], const double orientation_wxyz[4]) {
        detail::check(ent_obstacle_set_pose(scene_, obstacle, position_m, orientation_wxyz));
    }
    void set_obstacle_pose(int32_t obstacle, const Pose& pose) {
        set_obstacle_pose(obstacle, pose.position_m.data(), pose.orientation_wxyz.data());
    }
    /** The velocity its contacts see in the next step (ent_obstacle_set_velocity): m/s, rad/s. */
    void set_obstacle_velocity(int32_t obstacle, const double linear_m_per_s[3], const double angular_rad_per_s[3]) {
        detail::check(ent_obstacle_set_velocity(scene_, obstacle, linear_m_per_s, angular_rad_per_s));
    }
    /** Its Coulomb friction from the next step on (ent_obstacle_set_friction; negative: the scene's). */
    void set_obstacle_friction(int32_t obstacle, double friction) {
        detail::check(ent_obstacle_set_friction(scene_, obstacle, friction));
    }
    /** Removes it from the next step on (ent_scene_remove_obstacle); the others keep their ids. */
    void remove_obstacle(int32_t obstacle) { detail::check(ent_scene_remove_obstacle(scene_, obstacle)); }
    /** Obstacles in the last published state, removed ones not counted. */
    uint32_t obstacle_count() const {
        uint32_t count = 0;
        detail::check(ent_scene_obstacle_count(scene_, &count));
        return count;
    }
    /** Where its frame rests in the last published state (ent_obstacle_pose; any thread). */
    Pose obstacle_pose(int32_t obstacle) const {
        Pose pose;
        detail::check(ent_obstacle_pose(scene_, obstacle, pose.position_m.data(), pose.orientation_wxyz.data()));
        return pose;
    }
    /** A mesh obstacle's vertices and triangles (ent_obstacle_mesh; the driving thread,
     *  between steps: a removal frees the mesh). */
    ObstacleMesh obstacle_mesh(int32_t obstacle) const {
        uint32_t vertices = 0, triangles = 0;
        detail::check(ent_obstacle_mesh(scene_, obstacle, 0, nullptr, &vertices, 0, nullptr, &triangles));
        ObstacleMesh mesh;
        mesh.vertices_xyz_m.resize(3 * std::size_t{vertices});
        mesh.triangles.resize(3 * std::size_t{triangles});
        detail::check(ent_obstacle_mesh(scene_, obstacle, vertices, mesh.vertices_xyz_m.data(), &vertices, triangles,
                                        mesh.triangles.data(), &triangles));
        return mesh;
    }

    /** Gravity from the next step on, m/s^2 (ent_scene_set_gravity; the driving thread). */
    void set_gravity(const double gravity_m_per_s2[3]) { detail::check(ent_scene_set_gravity(scene_, gravity_m_per_s2)); }
    /** Holds a control point where it is, in the world or on an obstacle's frame
     *  (ent_scene_pin_point; the driving thread, between steps). */
    void pin_point(uint32_t control_point, int32_t obstacle = ENT_NO_OBSTACLE) {
        detail::check(ent_scene_pin_point(scene_, control_point, obstacle));
    }
    /** Lets a pinned control point go (ent_scene_unpin_point). */
    void unpin_point(uint32_t control_point) { detail::check(ent_scene_unpin_point(scene_, control_point)); }
    /** The mesentery's root follows an obstacle from where it is now (ENT_NO_OBSTACLE: the world). */
    void attach_mesentery(int32_t obstacle) { detail::check(ent_scene_attach_mesentery(scene_, obstacle)); }
    /** Clamped ends (ENT_PIN_FIRST, ENT_PIN_LAST or ENT_PIN_BOTH) follow an obstacle
     *  (ent_scene_attach_clamped_end; ENT_NO_OBSTACLE: the world). */
    void attach_clamped_end(int32_t ends, int32_t obstacle) {
        detail::check(ent_scene_attach_clamped_end(scene_, ends, obstacle));
    }

    /** Adds a tool (a driving call). */
    Tool add_tool(const ent_tool_desc& desc) {
        int32_t id = -1;
        detail::check(ent_tool_add(scene_, &desc, &id));
        return Tool(scene_, id);
    }
    /** A handle of a tool already in the scene (listed in its JSON, say). */
    Tool tool(int32_t id) const {
        ent_tool_feedback probe = sized<ent_tool_feedback>();
        detail::check(ent_tool_read_feedback(scene_, id, &probe));  // ENT_ERROR_NOT_FOUND if none
        return Tool(scene_, id);
    }

    /** Tools added and not removed (ent_scene_tool_count); ids run up to those ever added. */
    int32_t tool_count() const {
        int32_t count = 0;
        detail::check(ent_scene_tool_count(scene_, &count));
        return count;
    }

    /** The contacts of the last published step, into `out` (its capacity is kept across calls). */
    void contacts(std::vector<ent_contact>& out) const {
        for (;;) {
            uint32_t count = 0;
            detail::check(ent_scene_contacts(scene_, 0, nullptr, &count));
            out.resize(count > 0 ? count : 1);
            out[0].struct_size = static_cast<uint32_t>(sizeof(ent_contact));
            const ent_status status =
                ent_scene_contacts(scene_, static_cast<uint32_t>(out.size()), out.data(), &count);
            if (status == ENT_ERROR_BUFFER_TOO_SMALL) continue;  // a newer step listed more
            detail::check(status);
            out.resize(count);
            return;
        }
    }
    std::vector<ent_contact> contacts() const {
        std::vector<ent_contact> out;
        contacts(out);
        return out;
    }
    ent_contact_summary contact_summary() const {
        ent_contact_summary out = sized<ent_contact_summary>();
        detail::check(ent_scene_contact_summary(scene_, &out));
        return out;
    }

    /** The whole state (ent_scene_save_state), into `out` (a driving call). */
    void save_state(std::vector<unsigned char>& out) {
        std::size_t size = 0;
        detail::check(ent_scene_save_state(scene_, nullptr, 0, &size));
        out.resize(size);
        detail::check(ent_scene_save_state(scene_, out.data(), out.size(), &size));
        out.resize(size);
    }
    std::vector<unsigned char> save_state() {
        std::vector<unsigned char> out;
        save_state(out);
        return out;
    }
    /** Back to a saved state (ent_scene_restore_state); a bad one throws, the scene unchanged. */
    void restore_state(const void* data, std::size_t size) { detail::check(ent_scene_restore_state(scene_, data, size)); }
    void restore_state(const std::vector<unsigned char>& state) { restore_state(state.data(), state.size()); }

private:
    ent_scene* scene_ = nullptr;
};

/** A skin's mesh as spans; valid until the skin's next update or its destruction. */
struct Mesh {
    Span<const float> positions_xyz_m;  /**< 3 per vertex. */
    Span<const float> normals_xyz;      /**< 3 per vertex. */
    Span<const float> axis_u;           /**< 1 per vertex. */
    Span<const uint32_t> indices;       /**< 3 per triangle. */
    double time_s = 0.0;
    uint64_t updates = 0;
    std::size_t vertex_count() const noexcept { return axis_u.size(); }
    std::size_t triangle_count() const noexcept { return indices.size() / 3; }
};

/** A skin of a scene (ent_skin): move-only, destroyed with its handle; it may outlive the scene. */
class Skin {
public:
    Skin(const Scene& scene, const ent_skin_desc& desc) { detail::check(ent_skin_create(scene.get(), &desc, &skin_)); }
    Skin(Skin&& other) noexcept : skin_(std::exchange(other.skin_, nullptr)) {}
    Skin& operator=(Skin&& other) noexcept {
        if (this != &other) {
            ent_skin_destroy(skin_);
            skin_ = std::exchange(other.skin_, nullptr);
        }
        return *this;
    }
    Skin(const Skin&) = delete;
    Skin& operator=(const Skin&) = delete;
    ~Skin() { ent_skin_destroy(skin_); }

    ent_skin* get() const noexcept { return skin_; }

    /** Rebuilds the mesh from the scene's last published state (ent_skin_update). */
    void update() { detail::check(ent_skin_update(skin_)); }
    Mesh mesh() const {
        ent_mesh_view view = sized<ent_mesh_view>();
        detail::check(ent_skin_mesh(skin_, &view));
        Mesh mesh;
        const std::size_t vertices = view.vertex_count, triangles = view.triangle_count;
        mesh.positions_xyz_m = {view.positions_xyz_m, 3 * vertices};
        mesh.normals_xyz = {view.normals_xyz, 3 * vertices};
        mesh.axis_u = {view.axis_u, vertices};
        mesh.indices = {view.indices, 3 * triangles};
        mesh.time_s = view.time_s;
        mesh.updates = view.updates;
        return mesh;
    }
    struct ent_skin_metrics metrics() const {
        struct ent_skin_metrics out = sized<struct ent_skin_metrics>();
        detail::check(ent_skin_metrics(skin_, &out));
        return out;
    }

private:
    ent_skin* skin_ = nullptr;
};

/** What Exposure::measure found: the C result, and the spans and elements it wrote. */
struct ExposureReport {
    ent_exposure_result result{};          /**< visible_fraction, span_count, samples, time_s, ... */
    std::vector<double> spans_u;           /**< [first u, last u] of each span written (2 per span) */
    std::vector<double> span_hidden_fractions;  /**< the fraction of the target each span hides */
    std::vector<int32_t> span_intestines;  /**< the tube of each span */
    std::vector<double> element_visible;   /**< the fraction seen of each point or triangle */
    double visible_fraction() const noexcept { return result.visible_fraction; }
    std::size_t spans() const noexcept { return span_intestines.size(); }
};

/**
 * A target prepared for ent_scene_exposure (ent_exposure_create): move-only, destroyed with
 * its handle; it may outlive the scene (measuring then needs a live scene). measure() fills
 * a report the object keeps, sized at construction: measuring allocates nothing. One
 * thread at a time per Exposure (a second measure on another thread throws ENT_ERROR_BUSY).
 */
class Exposure {
public:
    Exposure(const Scene& scene, const ent_exposure_desc& desc, uint32_t span_capacity = 16)
        : scene_(scene.get()), span_capacity_(span_capacity) {
        detail::check(ent_exposure_create(scene_, &desc, &exposure_));
        const std::size_t elements = desc.triangles != nullptr ? desc.triangle_count : desc.point_count;
        report_.spans_u.reserve(2 * std::size_t{span_capacity});
        report_.span_hidden_fractions.reserve(span_capacity);
        report_.span_intestines.reserve(span_capacity);
        report_.element_visible.assign(elements, 0.0);
    }
    Exposure(Exposure&& other) noexcept
        : scene_(other.scene_), exposure_(std::exchange(other.exposure_, nullptr)),
          span_capacity_(other.span_capacity_), report_(std::move(other.report_)) {}
    Exposure& operator=(Exposure&& other) noexcept {
        if (this != &other) {
            ent_exposure_destroy(exposure_);
            scene_ = other.scene_;
            exposure_ = std::exchange(other.exposure_, nullptr);
            span_capacity_ = other.span_capacity_;
            report_ = std::move(other.report_);
        }
        return *this;
    }
    Exposure(const Exposure&) = delete;
    Exposure& operator=(const Exposure&) = delete;
    ~Exposure() { ent_exposure_destroy(exposure_); }

    ent_exposure* get() const noexcept { return exposure_; }

    /** How much of the target the bowel leaves in sight from `viewpoint_m` (x y z, m), on the
     *  scene's last published state; valid until the next measure. */
    const ExposureReport& measure(const double viewpoint_m[3]) {
        report_.spans_u.resize(2 * std::size_t{span_capacity_});
        report_.span_hidden_fractions.resize(span_capacity_);
        report_.span_intestines.resize(span_capacity_);
        ent_exposure_result& r = report_.result;
        r = sized<ent_exposure_result>();
        r.span_capacity = span_capacity_;
        r.spans_u = report_.spans_u.data();
        r.span_hidden_fractions = report_.span_hidden_fractions.data();
        r.span_intestines = report_.span_intestines.data();
        r.element_visible = report_.element_visible.data();
        detail::check(ent_scene_exposure(scene_, exposure_, viewpoint_m, &r));
        const std::size_t written = std::min(r.span_count, span_capacity_);
        report_.spans_u.resize(2 * written);
        report_.span_hidden_fractions.resize(written);
        report_.span_intestines.resize(written);
        r.spans_u = nullptr;
        r.span_hidden_fractions = nullptr;
        r.span_intestines = nullptr;
        r.element_visible = nullptr;
        return report_;
    }

private:
    const ent_scene* scene_ = nullptr;
    ent_exposure* exposure_ = nullptr;
    uint32_t span_capacity_ = 16;
    ExposureReport report_;
};

#ifdef EIGEN_WORLD_VERSION
/** An x y z array (3 per row) as an N x 3 row-major Eigen matrix, without copying. */
template <class T>
using XyzMap = Eigen::Map<const Eigen::Matrix<T, Eigen::Dynamic, 3, Eigen::RowMajor>>;

template <class T>
XyzMap<T> as_matrix(Span<const T> xyz) {
    return XyzMap<T>(xyz.data(), static_cast<Eigen::Index>(xyz.size() / 3), 3);
}
/** The axis or the control points (Scene::axis, Scene::control_points). */
inline XyzMap<double> as_matrix(const std::vector<double>& xyz) {
    return as_matrix(Span<const double>(xyz.data(), xyz.size()));
}
#endif

}  // namespace enteron

#endif  // ENTERON_ENTERON_HPP
