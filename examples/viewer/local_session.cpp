// SPDX-License-Identifier: Apache-2.0
#include "local_session.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace viewer {

namespace {

using Clock = std::chrono::steady_clock;

// Points along the axis polyline per tube radius: smooth at any zoom.
constexpr double kAxisPointsPerRadius = 2.0;

}  // namespace

bool read_text_file(const std::string& path, std::string& text, std::string& error) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        error = "cannot read " + path + ": " + std::strerror(errno);
        return false;
    }
    std::ostringstream contents;
    contents << file.rdbuf();
    if (file.bad()) {
        error = "cannot read " + path;
        return false;
    }
    text = contents.str();
    return true;
}

std::unique_ptr<LocalSession> LocalSession::open(const std::string& json, const std::string& name,
                                                 const std::string& scene_dir, const LocalSessionOptions& options,
                                                 std::string& error) {
    std::unique_ptr<LocalSession> session(new LocalSession());
    session->json_ = json;
    session->name_ = name;
    session->scene_dir_ = scene_dir;
    session->options_ = options;
    if (session->options_.skin.struct_size == 0) ent_skin_desc_default(&session->options_.skin);
    if (!session->start(error)) return nullptr;
    return session;
}

LocalSession::~LocalSession() { stop(); }

bool LocalSession::start(std::string& error) {
    const std::string json = with_mesh_files_from(json_, scene_dir_);
    const ent_status status = ent_scene_create_json(json.data(), json.size(), &scene_);
    if (status != ENT_OK) {
        error = name_ + ": " + ent_last_error() + " (" + status_name(status) + ")";
        return false;
    }
    if (!read_scene_layout(json_, layout_, error) || !read_meshes(error)) {
        stop();
        return false;
    }
    for (const ObstaclePath& path : options_.obstacle_paths) {
        if (path.obstacle >= 0 && static_cast<std::size_t>(path.obstacle) < layout_.obstacles.size()) continue;
        error = name_ + ": the script moves obstacle " + std::to_string(path.obstacle) + ", the scene has " +
                std::to_string(layout_.obstacles.size());
        stop();
        return false;
    }
    ent_skin* skin = nullptr;
    const ent_status skin_status = ent_skin_create(scene_, &options_.skin, &skin);
    if (skin_status != ENT_OK) {
        error = std::string("ent_skin_create: ") + ent_last_error();
        stop();
        return false;
    }
    skin_ = skin;
    PhysicsSettings settings;
    settings.scene = scene_;
    settings.tool_count = static_cast<std::uint32_t>(std::min<std::size_t>(layout_.tools.size(), kMaxTools));
    for (std::uint32_t i = 0; i < settings.tool_count; ++i) settings.initial[i] = layout_.tools[i].initial;
    settings.tool0_path = options_.tool0_path;
    settings.obstacle_paths = options_.obstacle_paths;
    settings.step_s = options_.step_s > 0.0 ? options_.step_s : layout_.timestep_s;
    settings.rate = options_.rate;
    settings.paused = options_.paused;
    settings.gate_s = options_.gate_s;
    report_ = PhysicsReport();
    physics_failures_seen_ = 0;
    std::fill(std::begin(jaws_closed_), std::end(jaws_closed_), false);
    physics_ = std::make_unique<PhysicsThread>(settings);
    return true;
}

bool LocalSession::read_meshes(std::string& error) {
    // ent_obstacle_mesh is a driving call: here, before the physics thread drives the scene.
    for (std::size_t i = 0; i < layout_.obstacles.size(); ++i) {
        ObstacleShape& obstacle = layout_.obstacles[i];
        if (obstacle.kind != ENT_OBSTACLE_MESH) continue;
        const auto id = static_cast<std::int32_t>(i);
        std::uint32_t vertex_count = 0, triangle_count = 0;
        ent_status status = ent_obstacle_mesh(scene_, id, 0, nullptr, &vertex_count, 0, nullptr, &triangle_count);
        std::vector<double> vertices(3 * static_cast<std::size_t>(vertex_count));
        std::vector<std::uint32_t> triangles(3 * static_cast<std::size_t>(triangle_count));
        if (status == ENT_OK)
            status = ent_obstacle_mesh(scene_, id, vertex_count, vertices.data(), &vertex_count, triangle_count,
                                       triangles.data(), &triangle_count);
        if (status != ENT_OK) {
            error = "ent_obstacle_mesh of obstacle " + std::to_string(i) + " (" + obstacle.name + "): " +
                    ent_last_error() + " (" + status_name(status) + ")";
            return false;
        }
        obstacle.mesh = make_organ_mesh(vertices, triangles);
    }
    frame_on_cavity(layout_);
    return true;
}

void LocalSession::stop() {
    if (physics_) {
        // Keep the controls for the next start (a reset keeps pace, step and pause).
        options_.step_s = physics_->step();
        options_.rate = physics_->rate();
        options_.paused = physics_->paused();
    }
    physics_.reset();          // joins: nothing drives the scene after this
    ent_skin_destroy(skin_);   // skins before their scene
    skin_ = nullptr;
    ent_scene_destroy(scene_);
    scene_ = nullptr;
}

bool LocalSession::reset(std::string& error) {
    stop();
    return start(error);
}

void LocalSession::record(const char* call, ent_status status) {
    ++problem_.count;
    problem_.status = status;
    problem_.call = call;
    problem_.message = ent_last_error();
    problem_.time_s = report_.time_s;
}

void LocalSession::send(const ToolCommands& commands) {
    // The targets go to the physics thread, which moves the tools toward them at 1 kHz
    // (tool_exchange.h); a change of the jaws is posted from here: the next step takes it.
    physics_->commands().publish(commands);
    for (std::uint32_t i = 0; i < commands.count && i < kMaxTools; ++i) {
        if (commands.grasp[i] == jaws_closed_[i]) continue;
        jaws_closed_[i] = commands.grasp[i];
        const auto tool = static_cast<std::int32_t>(i);
        const ent_status status = jaws_closed_[i] ? ent_tool_grasp(scene_, tool) : ent_tool_release(scene_, tool);
        if (status != ENT_OK) record(jaws_closed_[i] ? "ent_tool_grasp" : "ent_tool_release", status);
    }
}

void LocalSession::read(const FrameRequest& request, FrameState& frame) {
    PhysicsReport fresh;
    if (physics_->reports().take(fresh)) report_ = fresh;
    if (report_.failures != physics_failures_seen_) {
        problem_.count += report_.failures - physics_failures_seen_;
        physics_failures_seen_ = report_.failures;
        problem_.status = report_.last_status;
        problem_.call = report_.last_call;
        problem_.message = report_.last_message;
        problem_.time_s = report_.last_failure_time_s;
    }
    frame.time_s = report_.time_s;
    frame.paused = report_.paused;
    frame.gate_reached_s = report_.gate_reached_s;
    frame.tool_count = report_.tool_count;
    std::copy(report_.tools, report_.tools + report_.tool_count, frame.tools);
    // The obstacles where the newest snapshot has them (a removed one is not found).
    frame.obstacles.resize(layout_.obstacles.size());
    for (std::size_t i = 0; i < frame.obstacles.size(); ++i) {
        ObstaclePose& pose = frame.obstacles[i];
        const ent_status status =
            ent_obstacle_pose(scene_, static_cast<std::int32_t>(i), pose.position_m, pose.orientation_wxyz);
        pose.present = status == ENT_OK;
        if (status != ENT_OK && status != ENT_ERROR_NOT_FOUND) record("ent_obstacle_pose", status);
    }
    frame.new_steps.clear();
    physics_->samples().drain([&frame](const StepSample& sample) { frame.new_steps.push_back(sample); });
    frame.dropped_steps = physics_->samples().dropped();

    // The surface, from the newest snapshot; the physics thread never waits for it.
    const auto start = Clock::now();
    const ent_status updated = ent_skin_update(skin_);
    frame.skin_update_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if (updated != ENT_OK) record("ent_skin_update", updated);
    frame.mesh = ent_mesh_view{};
    frame.mesh.struct_size = sizeof frame.mesh;
    const ent_status meshed = ent_skin_mesh(skin_, &frame.mesh);
    if (meshed != ENT_OK) record("ent_skin_mesh", meshed);

    frame.stats = ent_stats{};
    frame.stats.struct_size = sizeof frame.stats;
    const ent_status stats = ent_scene_stats(scene_, &frame.stats);
    if (stats != ENT_OK) record("ent_scene_stats", stats);
    for (std::int32_t effect = 0; effect < ENT_EFFECT_COUNT; ++effect) {
        frame.effects[effect] = ent_effect_stats{};
        frame.effects[effect].struct_size = sizeof(ent_effect_stats);
        const ent_status effect_stats = ent_scene_effect_stats(scene_, effect, &frame.effects[effect]);
        if (effect_stats != ENT_OK) record("ent_scene_effect_stats", effect_stats);
    }

    // Each read below may see a snapshot a step or two newer than the mesh: invisible.
    auto read_axis = [this](std::uint32_t count, std::vector<double>& points) {
        points.resize(3 * static_cast<std::size_t>(count));
        const ent_status status = ent_scene_axis(scene_, count, points.data());
        if (status != ENT_OK) {
            record("ent_scene_axis", status);
            points.clear();
        }
    };
    if (request.axis)
        read_axis(std::max<std::uint32_t>(
                      2, static_cast<std::uint32_t>(kAxisPointsPerRadius * layout_.length_m / layout_.radius_m)),
                  frame.axis_xyz_m);
    if (request.spheres) read_axis(std::max<std::uint32_t>(2, layout_.collision_spheres), frame.spheres_xyz_m);
    if (request.control_points) {
        std::uint32_t count = 0;
        frame.control_points_xyz_m.resize(3 * static_cast<std::size_t>(layout_.control_points));
        const ent_status status = ent_scene_control_points(scene_, layout_.control_points,
                                                           frame.control_points_xyz_m.data(), &count);
        if (status != ENT_OK) {
            record("ent_scene_control_points", status);
            frame.control_points_xyz_m.clear();
        }
    }
    frame.problem = problem_;
}

bool LocalSession::at_gate(double time_s) {
    PhysicsReport fresh;
    if (physics_->reports().take(fresh)) report_ = fresh;
    return report_.gate_reached_s == time_s || (report_.paused && report_.failures > 0);
}

bool LocalSession::set_skin(const ent_skin_desc& desc, std::string& error) {
    ent_skin* skin = nullptr;
    const ent_status status = ent_skin_create(scene_, &desc, &skin);
    if (status != ENT_OK) {
        error = std::string("ent_skin_create: ") + ent_last_error();
        return false;
    }
    ent_skin_destroy(skin_);
    skin_ = skin;
    options_.skin = desc;
    return true;
}

bool LocalSession::skin_metrics(struct ent_skin_metrics& metrics) {
    metrics = {};
    metrics.struct_size = sizeof metrics;
    const ent_status status = ent_skin_metrics(skin_, &metrics);
    if (status != ENT_OK) record("ent_skin_metrics", status);
    return status == ENT_OK;
}

}  // namespace viewer
