/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Enteron C++ layer: a header-only C++17 wrapper over the C ABI of enteron.h.
 *
 * Nothing here is exported or compiled into the library: every function is inline and
 * calls the C functions, so a program built against this header depends only on the C ABI
 * (the same shared library, the same compatibility rules). docs/cpp.md is its manual.
 *
 * - RAII handles: enteron::Scene and enteron::Skin own their C object and destroy it;
 *   enteron::Tool names a tool of a scene. All three are move-only. Every exported C
 *   function has its counterpart here (docs/cpp.md has the table; ctest docs.cpp_api
 *   checks it): obstacles, pins, attachments, gravity, tools, contacts, skins, save and
 *   restore.
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
#include <stdexcept>
#include <string>
#include <string_view>
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

/** ent_scene_desc with the library's defaults (ent_scene_desc_default). */
struct SceneDesc : ent_scene_desc {
    SceneDesc() noexcept : ent_scene_desc() { ent_scene_desc_default(this); }
};
/** ent_tool_desc with the library's defaults. */
struct ToolDesc : ent_tool_desc {
    ToolDesc() noexcept : ent_tool_desc() { ent_tool_desc_default(this); }
};
/** ent_obstacle_desc with the library's defaults. */
struct ObstacleDesc : ent_obstacle_desc {
    ObstacleDesc() noexcept : ent_obstacle_desc() { ent_obstacle_desc_default(this); }
};
/** ent_skin_desc with the library's defaults. */
struct SkinDesc : ent_skin_desc {
    SkinDesc() noexcept : ent_skin_desc() { ent_skin_desc_default(this); }
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
    ent_stats stats() const {
        ent_stats out = sized<ent_stats>();
        detail::check(ent_scene_stats(scene_, &out));
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
