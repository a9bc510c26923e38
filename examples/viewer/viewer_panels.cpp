// SPDX-License-Identifier: Apache-2.0
// The viewer's panels (Dear ImGui): on the left the simulation's controls, the tool and its
// force plot, what is shown and the scene's text; on the right the statistics and the
// skin; the help; the status line along the bottom.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "clock.h"
#include "viewer.h"

namespace viewer {

namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

bool drag_double(const char* label, double* value, double speed, double low, double high, const char* format) {
    return ImGui::DragScalar(label, ImGuiDataType_Double, value, static_cast<float>(speed), &low, &high, format,
                             ImGuiSliderFlags_AlwaysClamp);
}

void force_plot(const char* label, const Series& series, float top_N, float height) {
    ImGui::PlotLines(label, series.data(), series.size(), series.offset(), nullptr, 0.0f, top_N,
                     ImVec2(ImGui::GetContentRegionAvail().x, height));
}

const ImVec4 kErrorColour(1.0f, 0.40f, 0.35f, 1.0f);

}  // namespace

void Viewer::build_ui() {
    if (settings_.ui == UiMode::full) {
        build_panels();
        build_status_line(true);
    } else if (settings_.ui == UiMode::hud) {
        build_hud();
        build_status_line(false);
    }
    if (show_help_) build_help();
}

void Viewer::build_panels() {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(380, static_cast<float>(window_height_) - 52.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.82f);
    ImGui::Begin("Enteron viewer");  // on the left: what the user drives
    ImGui::PushItemWidth(ImGui::GetFontSize() * -9.0f);  // room for the labels on the right
    if (!session_) {
        ImGui::TextColored(kErrorColour, "No scene.");
        ImGui::TextWrapped("%s", load_error_.c_str());
        ImGui::TextWrapped("Drop a scene file (.json) on the window, or edit the text under Scene.");
    }

    if (session_ && frame_.link.remote && ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen)) {
        // The server owns the clock: what arrives, not controls.
        ImGui::TextWrapped("%s", session_->name().c_str());
        ImGui::Text("t = %.3f s   %s", frame_.time_s, link_state_name(frame_.link.state));
        ImGui::TextWrapped("%s", describe_link(frame_.link).c_str());
        if (!frame_.link.last_rejection.empty())
            ImGui::TextWrapped("last rejected: %s", frame_.link.last_rejection.c_str());
        ImGui::Text("step: median %.0f us, largest %.0f us (the server's)", histories_.step_median_us,
                    histories_.step_max_us);
    } else if (session_ && ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::TextWrapped("%s", session_->name().c_str());
        ImGui::Text("t = %.3f s   %s", frame_.time_s, frame_.paused ? "paused" : "running");
        if (ImGui::Button(frame_.paused ? "Run (Space)" : "Pause (Space)")) session_->set_paused(!session_->paused());
        ImGui::SameLine();
        if (ImGui::Button("Step (Right)")) {
            session_->set_paused(true);
            session_->step_once();
        }
        ImGui::SameLine();
        if (ImGui::Button("Reset (Backspace)")) reset();
        float rate = static_cast<float>(session_->rate());
        if (ImGui::SliderFloat("speed", &rate, 1.0f / 64.0f, 1.0f, "x%.3f", ImGuiSliderFlags_Logarithmic))
            session_->set_rate(rate);
        double step_ms = 1e3 * session_->step();
        if (drag_double("step (ms)", &step_ms, 0.01, 0.05, 20.0, "%.3f")) session_->set_step(1e-3 * step_ms);
        ImGui::Text("real-time factor %.2f   %.0f frames/s", histories_.real_time_factor, histories_.frame_rate_hz);
        ImGui::Text("step: median %.0f us, largest %.0f us", histories_.step_median_us, histories_.step_max_us);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("wall time of ent_scene_step over the last 1000 steps");
    }

    if (session_ && tools_.count() > 0 && ImGui::CollapsingHeader("Tool", ImGuiTreeNodeFlags_DefaultOpen)) {
        ToolCommands& commands = tools_.commands();
        const std::uint32_t active = tools_.active();
        if (tools_.count() > 1) {
            int tool = static_cast<int>(active);
            if (ImGui::SliderInt("tool (Tab)", &tool, 0, static_cast<int>(tools_.count()) - 1))
                tools_.set_active(static_cast<std::uint32_t>(tool));
        }
        ToolPose& target = commands.target[active];
        drag_double("x (m)", &target.position_m[0], 0.001, -10.0, 10.0, "%.3f");
        drag_double("y (m)", &target.position_m[1], 0.001, -10.0, 10.0, "%.3f");
        drag_double("z (m)", &target.position_m[2], 0.001, -10.0, 10.0, "%.3f");
        // The shaft's direction from the tip: its tilt from vertical and its heading.
        const Eigen::Quaterniond q(target.orientation_wxyz[0], target.orientation_wxyz[1], target.orientation_wxyz[2],
                                   target.orientation_wxyz[3]);
        const Eigen::Vector3d shaft = q.normalized() * Eigen::Vector3d::UnitZ();
        double tilt_deg = std::acos(std::clamp(shaft.z(), -1.0, 1.0)) * kDegreesPerRadian;
        double heading_deg = std::atan2(shaft.y(), shaft.x()) * kDegreesPerRadian;
        const bool tilted = drag_double("tilt (deg)", &tilt_deg, 0.5, 0.0, 180.0, "%.1f");
        const bool headed = drag_double("heading (deg)", &heading_deg, 1.0, -180.0, 180.0, "%.0f");
        if (tilted || headed) {
            const double theta = tilt_deg / kDegreesPerRadian, phi = heading_deg / kDegreesPerRadian;
            const Eigen::Quaterniond turned(Eigen::AngleAxisd(theta, Eigen::Vector3d(-std::sin(phi), std::cos(phi), 0.0)));
            target.orientation_wxyz[0] = turned.w();
            target.orientation_wxyz[1] = turned.x();
            target.orientation_wxyz[2] = turned.y();
            target.orientation_wxyz[3] = turned.z();
        }
        bool grasp = commands.grasp[active];
        if (ImGui::Checkbox("jaws closed (G)", &grasp)) tools_.set_grasp(grasp);
        const ent_tool_feedback& tool = frame_.tools[active].feedback;
        ImGui::SameLine();
        if (tool.grasping)
            ImGui::TextColored(ImVec4(0.4f, 0.9f, 0.5f, 1.0f), "holding the bowel");
        else
            ImGui::TextDisabled(grasp ? "holding nothing" : "open");
        drag_double("max speed (m/s)", &commands.max_speed_m_per_s, 0.01, 0.01, 10.0, "%.2f");
        const double magnitude = std::sqrt(tool.force_N[0] * tool.force_N[0] + tool.force_N[1] * tool.force_N[1] +
                                           tool.force_N[2] * tool.force_N[2]);
        const double max_force = session_->layout().tools[active].max_force_N;
        ImGui::Text("F = (%+.2f, %+.2f, %+.2f) N  |F| = %.2f N  %u contacts", tool.force_N[0], tool.force_N[1],
                    tool.force_N[2], magnitude, tool.contacts);
        if (frame_.link.remote)
            ImGui::Text("server's status: %s", frame_.link.tool_status[active].empty() ? "ok" : frame_.link.tool_status[active].c_str());
        ImGui::Text("force on the tool, last %.0f s (bound %.1f N):", Histories::kPlotSeconds, max_force);
        const float top = static_cast<float>(std::max(0.5, std::min(max_force, 1.2 * histories_.force_magnitude[active].largest())));
        force_plot("##|F|", histories_.force_magnitude[active], top, 70.0f);
        if (ImGui::TreeNode("components (x, y, z)")) {
            force_plot("##Fx", histories_.force_x, top, 40.0f);
            force_plot("##Fy", histories_.force_y, top, 40.0f);
            force_plot("##Fz", histories_.force_z, top, 40.0f);
            ImGui::TreePop();
        }
        float scale_cm = static_cast<float>(100.0 * force_scale_m_per_N_);
        if (ImGui::SliderFloat("arrow (cm/N)", &scale_cm, 0.2f, 20.0f, "%.1f", ImGuiSliderFlags_Logarithmic))
            force_scale_m_per_N_ = 0.01 * scale_cm;
    }

    if (ImGui::CollapsingHeader("Show", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Checkbox("skin (K)", &toggles_.skin);
        ImGui::SameLine(170);
        ImGui::Checkbox("wireframe (W)", &toggles_.wireframe);
        ImGui::Checkbox("axis (A)", &toggles_.axis);
        ImGui::SameLine(170);
        ImGui::Checkbox("control points (C)", &toggles_.control_points);
        ImGui::Checkbox("collision spheres (S)", &toggles_.spheres);
        ImGui::SameLine(170);
        ImGui::Checkbox("mesentery (M)", &toggles_.mesentery);
        ImGui::Checkbox("obstacles (O)", &toggles_.obstacles);
        ImGui::SameLine(170);
        ImGui::Checkbox("force arrows (F)", &toggles_.force_arrows);
        ImGui::Checkbox("shadows (L)", &toggles_.shadows);
        ImGui::SameLine(170);
        ImGui::Checkbox("tools", &toggles_.tools);
    }

    if (ImGui::CollapsingHeader("Scene", session_ ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::TextWrapped("Every other parameter is fixed when the scene is made: edit the description and "
                           "apply to start it again (docs/scene-json.md).");
        if (!scene_path_.empty() && ImGui::Button("Reload the file (Ctrl+L)")) open_file(scene_path_);
        ImGui::InputTextMultiline("##json", &json_edit_, ImVec2(-1.0f, 260.0f));
        if (ImGui::Button("Apply")) {
            std::string error;
            if (open(json_edit_, session_ ? session_->name() + " (edited)" : "edited scene", scene_path_, error))
                notify("scene applied");
        }
        if (!load_error_.empty()) ImGui::TextColored(kErrorColour, "%s", load_error_.c_str());
    }
    if (ImGui::Button("Help (F1)")) show_help_ = !show_help_;
    ImGui::PopItemWidth();
    ImGui::End();

    // On the right: what the simulation and the skin cost and how good they are.
    if (!session_) return;
    const float width = 370.0f;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(window_width_) - width - 8.0f, 8.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(window_height_) - 52.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.82f);
    ImGui::Begin("Statistics");
    ImGui::PushItemWidth(ImGui::GetFontSize() * -9.0f);
    if (ImGui::CollapsingHeader("Simulation cost", ImGuiTreeNodeFlags_DefaultOpen)) {
        const ent_stats& s = frame_.stats;
        ImGui::Text("steps %llu, substeps %llu, rollbacks %llu", static_cast<unsigned long long>(s.steps),
                    static_cast<unsigned long long>(s.substeps), static_cast<unsigned long long>(s.rollbacks));
        ImGui::Text("contacts %u, deepest %.2f mm", s.contacts, 1e3 * s.max_penetration_m);
        ImGui::Text("energy: kinetic %.4f J, potential %.4f J", s.kinetic_energy_J, s.potential_energy_J);
        if (frame_.dropped_steps > 0)
            ImGui::Text("plot samples dropped %llu", static_cast<unsigned long long>(frame_.dropped_steps));
        if (frame_.link.remote) {
            ImGui::TextDisabled("per-effect times: not in the server's stream");
        } else if (ImGui::BeginTable("effects", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
            ImGui::TableSetupColumn("effect");
            ImGui::TableSetupColumn("us / step");
            ImGui::TableSetupColumn("evaluations");
            ImGui::TableHeadersRow();
            for (int e = 0; e < ENT_EFFECT_COUNT; ++e) {
                const EffectCost& cost = histories_.effects[e];
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                if (cost.enabled)
                    ImGui::TextUnformatted(ent_effect_name(e));
                else
                    ImGui::TextDisabled("%s (off)", ent_effect_name(e));
                ImGui::TableNextColumn();
                ImGui::Text("%.1f", cost.us_per_step);
                ImGui::TableNextColumn();
                ImGui::Text("%llu", static_cast<unsigned long long>(cost.calls));
            }
            ImGui::EndTable();
        }
    }

    if (frame_.link.remote && ImGui::CollapsingHeader("Skin", ImGuiTreeNodeFlags_DefaultOpen)) {
        // The server makes the mesh; the viewer only draws it.
        if (frame_.link.meshes > 0)
            ImGui::TextWrapped("the server's mesh_t (%s; --mesh-skin, --mesh-hz)", skin_method_name(session_->skin().method));
        else
            ImGui::TextWrapped("a tube around the state's axis (the server sends no mesh: --mesh-hz 0)");
        ImGui::Text("%u triangles, %u vertices", frame_.mesh.triangle_count, frame_.mesh.vertex_count);
    } else if (ImGui::CollapsingHeader("Skin", ImGuiTreeNodeFlags_DefaultOpen)) {
        ent_skin_desc desc = session_->skin();
        bool changed = false;
        for (int m = 0; m < 3; ++m) {
            if (m > 0) ImGui::SameLine();
            char label[40];
            std::snprintf(label, sizeof label, "%s (%d)", skin_method_name(m), m + 1);
            changed |= ImGui::RadioButton(label, &desc.method, m);
        }
        int segments = static_cast<int>(desc.segments), cap_rings = static_cast<int>(desc.cap_rings);
        if (desc.method != ENT_SKIN_POINT_SKELETON) {
            changed |= ImGui::SliderInt("segments", &segments, 3, 64);
            changed |= drag_double("ring spacing (R)", &desc.ring_spacing_radii, 0.01, 0.05, 8.0, "%.2f");
            changed |= ImGui::SliderInt("cap rings", &cap_rings, 0, 16);
        }
        if (desc.method != ENT_SKIN_TUBE) {
            changed |= drag_double("skeleton spacing (R)", &desc.skeleton_spacing_radii, 0.01, 0.05, 2.0, "%.2f");
            changed |= drag_double("window (R)", &desc.window_radii, 0.01, 0.25, 1.99, "%.2f");
        }
        if (desc.method == ENT_SKIN_POINT_SKELETON)
            changed |= drag_double("voxel (R)", &desc.voxel_size_radii, 0.01, 0.1, 2.0, "%.2f");
        if (desc.method == ENT_SKIN_CONVOLUTION)
            changed |= drag_double("chord error (R)", &desc.ring_chord_error_radii, 0.005, 0.0, 1.0, "%.3f");
        desc.segments = static_cast<std::uint32_t>(segments);
        desc.cap_rings = static_cast<std::uint32_t>(cap_rings);
        if (changed) set_skin(desc);
        ImGui::Text("%u triangles, %u vertices, update %.2f ms", frame_.mesh.triangle_count, frame_.mesh.vertex_count,
                    histories_.skin_update_ms);
        // The metrics cost more than an update: once a second, while this panel is open.
        const double now = wall_seconds();
        if (now - metrics_wall_s_ > 1.0) {
            metrics_valid_ = session_->skin_metrics(metrics_);
            metrics_wall_s_ = now;
        }
        if (metrics_valid_) {
            ImGui::Text("radius error: RMS %.2f %%, max %.2f %% of R", 100 * metrics_.radius_error_rms,
                        100 * metrics_.radius_error_max);
            ImGui::Text("facet error: RMS %.2f %%, max %.2f %%", 100 * metrics_.facet_error_rms,
                        100 * metrics_.facet_error_max);
            ImGui::Text("normals: RMS %.2f deg, max %.1f deg", metrics_.normal_deviation_rms_rad * kDegreesPerRadian,
                        metrics_.normal_deviation_max_rad * kDegreesPerRadian);
            ImGui::Text("%s, %u open edges, %u blended, %u inverted", metrics_.watertight ? "watertight" : "NOT watertight",
                        metrics_.open_edges, metrics_.blended_vertices, metrics_.inverted_triangles);
            ImGui::Text("volume error %+.2f %%", 100 * metrics_.volume_error);
        }
    }

    ImGui::PopItemWidth();
    ImGui::End();
}

void Viewer::build_hud() {
    if (!session_) return;
    ImGui::SetNextWindowPos(ImVec2(10, 10));
    ImGui::SetNextWindowBgAlpha(0.55f);
    ImGui::Begin("##hud", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                     ImGuiWindowFlags_NoSavedSettings);
    ImGui::Text("Enteron   t = %.2f s", frame_.time_s);
    if (frame_.link.remote) ImGui::Text("%s: %s", frame_.link.url.c_str(), link_state_name(frame_.link.state));
    if (tools_.count() > 0) {
        const ent_tool_feedback& tool = frame_.tools[0].feedback;
        const double magnitude = std::sqrt(tool.force_N[0] * tool.force_N[0] + tool.force_N[1] * tool.force_N[1] +
                                           tool.force_N[2] * tool.force_N[2]);
        const double max_force = session_->layout().tools[0].max_force_N;
        ImGui::Text("force on the tool %.2f N%s", magnitude, tool.grasping ? "   holding" : "");
        if (frame_.link.remote && !frame_.link.tool_status[0].empty())
            ImGui::Text("tool: %s", frame_.link.tool_status[0].c_str());
        ImGui::PlotLines("##hud|F|", histories_.force_magnitude[0].data(), histories_.force_magnitude[0].size(),
                         histories_.force_magnitude[0].offset(), nullptr, 0.0f, static_cast<float>(max_force),
                         ImVec2(220.0f, 40.0f));
    }
    ImGui::End();
}

void Viewer::build_status_line(bool always) {
    const bool failed = frame_.problem.count > 0 || !load_error_.empty() ||
                        (frame_.link.remote && frame_.link.state != LinkStatus::State::live);
    if (!always && !failed) return;
    const ImGuiIO& io = ImGui::GetIO();
    const float height = ImGui::GetFrameHeightWithSpacing() + 4.0f;
    ImGui::SetNextWindowPos(ImVec2(0.0f, io.DisplaySize.y - height));
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("##status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    if (!load_error_.empty()) {
        ImGui::TextColored(kErrorColour, "scene not loaded: %s", load_error_.c_str());
    } else if (frame_.problem.count > 0) {
        const Problem& p = frame_.problem;
        ImGui::TextColored(kErrorColour, "%s from %s at t = %.3f s: %s%s", status_name(p.status), p.call.c_str(),
                           p.time_s, p.message.c_str(),
                           frame_.paused ? "  (paused: Backspace resets, Right steps again)" : "");
    } else if (session_ && frame_.link.remote) {
        const bool live = frame_.link.state == LinkStatus::State::live;
        const std::string line = frame_.link.url + ": " + describe_link(frame_.link);
        if (live)
            ImGui::Text("%s   t = %.3f s", line.c_str(), frame_.time_s);
        else
            ImGui::TextColored(kErrorColour, "%s", line.c_str());
    } else if (session_) {
        ImGui::Text("t = %.3f s   %s x%.3g (real-time factor %.2f)   %.0f frames/s   step %.0f us (largest %.0f)   "
                    "%u contacts",
                    frame_.time_s, frame_.paused ? "paused" : "running", session_->rate(), histories_.real_time_factor,
                    histories_.frame_rate_hz, histories_.step_median_us, histories_.step_max_us,
                    frame_.stats.contacts);
    }
    if (!notice_.empty() && wall_seconds() < notice_until_s_) {
        ImGui::SameLine();
        ImGui::TextDisabled("   %s", notice_.c_str());
    }
    ImGui::End();
}

void Viewer::build_help() {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 430.0f, 10.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.9f);
    ImGui::Begin("Help", &show_help_, ImGuiWindowFlags_AlwaysAutoResize);
    static const char* const rows[][2] = {
        {"left drag", "move the tool on the plane facing you"},
        {"wheel", "move the tool in depth (forward: deeper)"},
        {"G", "close / open the jaws (grasp, release)"},
        {"Tab", "next tool"},
        {"right drag", "orbit the camera"},
        {"middle or Shift+right drag", "pan"},
        {"Ctrl+wheel", "zoom"},
        {"Home", "frame the scene"},
        {"V", "look through the 30-degree laparoscope (right drag: pivot it, Shift+right: turn its optics, Ctrl+wheel: slide it)"},
        {"Space", "pause / run"},
        {"Right", "one step"},
        {"Backspace", "reset"},
        {"[ and ]", "slower / faster (slow motion)"},
        {"1 2 3", "skin: tube, point_skeleton, convolution"},
        {"K W A C S M O F L", "skin, wireframe, axis, control points, spheres, mesentery, obstacles, force, shadows"},
        {"H", "hide / show the panels"},
        {"P", "screenshot (enteron-viewer.png)"},
        {"Ctrl+L", "reload the scene file"},
        {"Ctrl+Q", "quit"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
        for (const auto& row : rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[0]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[1]);
        }
        ImGui::EndTable();
    }
    ImGui::TextDisabled("A scene file dropped on the window opens it.");
    ImGui::End();
}

}  // namespace viewer
