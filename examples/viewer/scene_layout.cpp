// SPDX-License-Identifier: Apache-2.0
#include "scene_layout.h"

#include <enteron/enteron.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace viewer {

namespace {

using nlohmann::json;

// Copies a JSON [x, y, z] (or [w, x, y, z]) into out when the key is present.
template <std::size_t N>
void read_vector(const json& object, const char* key, double (&out)[N]) {
    const auto it = object.find(key);
    if (it == object.end() || !it->is_array() || it->size() != N) return;
    for (std::size_t c = 0; c < N; ++c) out[c] = (*it)[c].get<double>();
}

void read_number(const json& object, const char* key, double& out) {
    const auto it = object.find(key);
    if (it != object.end() && it->is_number()) out = it->get<double>();
}

void normalise(double* v, int n) {
    double norm = 0.0;
    for (int c = 0; c < n; ++c) norm += v[c] * v[c];
    norm = std::sqrt(norm);
    if (norm > 0.0)
        for (int c = 0; c < n; ++c) v[c] /= norm;
}

ObstacleShape read_obstacle(const json& item) {
    ent_obstacle_desc desc;
    ent_obstacle_desc_default(&desc);
    ObstacleShape shape;
    const std::string type = item.value("type", "");
    shape.kind = type == "plane" ? ENT_OBSTACLE_PLANE
                 : type == "sphere" ? ENT_OBSTACLE_SPHERE
                 : type == "capsule" ? ENT_OBSTACLE_CAPSULE
                 : type == "mesh" ? ENT_OBSTACLE_MESH
                                  : ENT_OBSTACLE_BOX_INSIDE;
    std::copy(desc.center_m, desc.center_m + 3, shape.center_m);
    std::copy(desc.normal, desc.normal + 3, shape.normal);
    std::copy(desc.start_m, desc.start_m + 3, shape.start_m);
    std::copy(desc.end_m, desc.end_m + 3, shape.end_m);
    shape.radius_m = desc.radius_m;
    read_vector(item, shape.kind == ENT_OBSTACLE_PLANE ? "point" : "center", shape.center_m);
    read_vector(item, "half_extents", shape.half_extents_m);
    read_vector(item, "normal", shape.normal);
    normalise(shape.normal, 3);
    read_vector(item, "start", shape.start_m);
    read_vector(item, "end", shape.end_m);
    read_number(item, "radius", shape.radius_m);
    std::copy(desc.position_m, desc.position_m + 3, shape.position_m);
    std::copy(desc.orientation_wxyz, desc.orientation_wxyz + 4, shape.orientation_wxyz);
    read_vector(item, "position", shape.position_m);
    read_vector(item, "orientation", shape.orientation_wxyz);
    normalise(shape.orientation_wxyz, 4);
    shape.name = item.value("file", type);
    return shape;
}

ToolShape read_tool(const json& item) {
    ent_tool_desc desc;
    ent_tool_desc_default(&desc);
    ToolShape tool;
    tool.radius_m = desc.radius_m;
    tool.length_m = desc.length_m;
    tool.max_force_N = desc.max_force_N;
    std::copy(desc.position_m, desc.position_m + 3, tool.initial.position_m);
    std::copy(desc.orientation_wxyz, desc.orientation_wxyz + 4, tool.initial.orientation_wxyz);
    read_number(item, "radius", tool.radius_m);
    read_number(item, "length", tool.length_m);
    read_number(item, "max_force", tool.max_force_N);
    read_number(item, "blade_width", tool.blade_width_m);
    read_number(item, "blade_length", tool.blade_length_m);
    read_vector(item, "position", tool.initial.position_m);
    read_vector(item, "orientation", tool.initial.orientation_wxyz);
    normalise(tool.initial.orientation_wxyz, 4);
    return tool;
}

}  // namespace

std::array<double, 3> mesentery_root_point(const SceneLayout& layout, double f) {
    const std::vector<double>& m = layout.root_mapping;
    double t = f;
    if (m.size() >= 4) {
        const double s = f * layout.length_m;
        const std::size_t pairs = m.size() / 2;
        std::size_t k = 0;
        while (k + 2 < pairs && s > m[2 * (k + 1)]) ++k;
        const double u = std::clamp((s - m[2 * k]) / (m[2 * k + 2] - m[2 * k]), 0.0, 1.0);
        t = (1.0 - u) * m[2 * k + 1] + u * m[2 * k + 3];
    }
    const std::vector<double>& r = layout.root_m;
    const std::size_t points = r.size() / 3;
    auto at = [&](std::size_t i, double w, std::size_t j) {
        return std::array<double, 3>{r[3 * i] + w * (r[3 * j] - r[3 * i]), r[3 * i + 1] + w * (r[3 * j + 1] - r[3 * i + 1]),
                                     r[3 * i + 2] + w * (r[3 * j + 2] - r[3 * i + 2])};
    };
    if (points == 2) return at(0, t, 1);
    std::vector<double> lengths;
    double total = 0.0;
    for (std::size_t i = 1; i < points; ++i) {
        lengths.push_back(std::hypot(r[3 * i] - r[3 * i - 3], r[3 * i + 1] - r[3 * i - 2], r[3 * i + 2] - r[3 * i - 1]));
        total += lengths.back();
    }
    double remaining = std::clamp(t, 0.0, 1.0) * total;
    for (std::size_t i = 1; i < points; ++i) {
        if (remaining <= lengths[i - 1] && lengths[i - 1] > 0.0) return at(i - 1, remaining / lengths[i - 1], i);
        remaining -= lengths[i - 1];
    }
    return at(points - 1, 0.0, points - 1);
}

bool read_scene_layout(const std::string& text, SceneLayout& layout, std::string& error) {
    const json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded() || !document.is_object()) {
        error = "the scene description is not a JSON object";
        return false;
    }
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    layout = SceneLayout();
    layout.length_m = desc.length_m;
    layout.radius_m = desc.radius_m;
    layout.control_points = desc.control_points;
    layout.timestep_s = desc.timestep_s;
    layout.root_m.assign(desc.mesentery_root_start_m, desc.mesentery_root_start_m + 3);
    layout.root_m.insert(layout.root_m.end(), desc.mesentery_root_end_m, desc.mesentery_root_end_m + 3);
    layout.attachments = desc.mesentery_attachments;

    const json empty = json::object();
    const json& intestine = document.contains("intestine") ? document["intestine"] : empty;
    read_number(intestine, "length", layout.length_m);
    read_number(intestine, "radius", layout.radius_m);
    if (intestine.contains("control_points")) layout.control_points = intestine["control_points"].get<std::uint32_t>();
    if (intestine.contains("shape") && intestine["shape"].contains("points"))
        layout.control_points = static_cast<std::uint32_t>(intestine["shape"]["points"].size());
    if (document.contains("solver")) read_number(document["solver"], "timestep", layout.timestep_s);

    double spacing = 0.0;  // 0: R / 2
    if (document.contains("collision")) read_number(document["collision"], "sphere_spacing", spacing);
    if (spacing <= 0.0) spacing = 0.5 * layout.radius_m;
    layout.collision_spheres = static_cast<std::uint32_t>(std::lround(layout.length_m / spacing)) + 1;

    if (document.contains("mesentery")) {
        const json& mesentery = document["mesentery"];
        layout.mesentery = true;
        if (mesentery.contains("root")) {
            layout.root_m.clear();
            for (const json& p : mesentery["root"])
                for (int c = 0; c < 3; ++c) layout.root_m.push_back(p[c].get<double>());
        }
        for (const auto& [key, at] : {std::pair{"root_start", 0}, std::pair{"root_end", 3}})
            if (mesentery.contains(key))
                for (int c = 0; c < 3; ++c) layout.root_m[at + c] = mesentery[key][c].get<double>();
        if (mesentery.contains("root_mapping"))
            for (const json& pair : mesentery["root_mapping"])
                for (int c = 0; c < 2; ++c) layout.root_mapping.push_back(pair[c].get<double>());
        if (mesentery.contains("attachments")) layout.attachments = mesentery["attachments"].get<std::uint32_t>();
    }
    if (document.contains("environment"))
        for (const json& item : document["environment"]) layout.obstacles.push_back(read_obstacle(item));
    if (document.contains("tools"))
        for (const json& item : document["tools"]) layout.tools.push_back(read_tool(item));

    frame_on_cavity(layout);
    return true;
}

void frame_on_cavity(SceneLayout& layout) {
    // The camera frames the cavity if there is one, else it is framed on the first frame
    // by the bowel itself (scene_size_m 0).
    layout.scene_size_m = 0.0;
    layout.port_known = false;
    for (const ObstacleShape& obstacle : layout.obstacles) {
        if (obstacle.kind == ENT_OBSTACLE_BOX_INSIDE) {
            for (int c = 0; c < 3; ++c) layout.scene_center_m[c] = obstacle.position_m[c] + obstacle.center_m[c];
            layout.scene_size_m = 2.0 * *std::max_element(obstacle.half_extents_m, obstacle.half_extents_m + 3);
            for (int c = 0; c < 3; ++c) layout.port_m[c] = layout.scene_center_m[c];
            layout.port_m[2] += obstacle.half_extents_m[2];
            layout.port_known = true;
            return;
        }
        if (obstacle.kind == ENT_OBSTACLE_MESH && obstacle.mesh && obstacle.mesh->cavity) {
            // The box around it in its frame, moved to its origin (a wall is not turned); the
            // size that counts is across the view (x and z: the camera looks along +y).
            const OrganMesh& wall = *obstacle.mesh;
            for (int c = 0; c < 3; ++c)
                layout.scene_center_m[c] = obstacle.position_m[c] + 0.5 * (wall.low_m[c] + wall.high_m[c]);
            layout.scene_size_m = std::max(wall.high_m[0] - wall.low_m[0], wall.high_m[2] - wall.low_m[2]);
            // The umbilicus: the dome's top above the centre (a supine abdomen, +z anterior).
            for (int c = 0; c < 3; ++c) layout.port_m[c] = layout.scene_center_m[c];
            layout.port_m[2] = obstacle.position_m[2] + wall.high_m[2];
            layout.port_known = true;
            return;
        }
    }
}

std::shared_ptr<const OrganMesh> make_organ_mesh(const std::vector<double>& vertices_xyz_m,
                                                 const std::vector<std::uint32_t>& triangles) {
    auto mesh = std::make_shared<OrganMesh>();
    mesh->positions.assign(vertices_xyz_m.begin(), vertices_xyz_m.end());
    mesh->indices = triangles;
    mesh->normals.assign(mesh->positions.size(), 0.0f);
    const std::size_t vertex_count = vertices_xyz_m.size() / 3;
    for (int c = 0; c < 3; ++c) {
        mesh->low_m[c] = vertex_count > 0 ? mesh->positions[c] : 0.0f;
        mesh->high_m[c] = mesh->low_m[c];
    }
    for (std::size_t v = 0; v < vertex_count; ++v)
        for (int c = 0; c < 3; ++c) {
            mesh->low_m[c] = std::min(mesh->low_m[c], mesh->positions[3 * v + c]);
            mesh->high_m[c] = std::max(mesh->high_m[c], mesh->positions[3 * v + c]);
        }
    // Each triangle adds its cross product (twice its area along its normal) to its corners,
    // and its share of the signed volume, (a . (b x c)) / 6, to the mesh's.
    double volume = 0.0;
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const double* a = &vertices_xyz_m[3 * static_cast<std::size_t>(triangles[t])];
        const double* b = &vertices_xyz_m[3 * static_cast<std::size_t>(triangles[t + 1])];
        const double* c = &vertices_xyz_m[3 * static_cast<std::size_t>(triangles[t + 2])];
        const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n[3] = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]};
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
        for (std::size_t corner = 0; corner < 3; ++corner)
            for (int k = 0; k < 3; ++k) mesh->normals[3 * static_cast<std::size_t>(triangles[t + corner]) + k] += static_cast<float>(n[k]);
    }
    for (std::size_t v = 0; v < vertex_count; ++v) {
        float* n = &mesh->normals[3 * v];
        const float norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (norm > 0.0f)
            for (int k = 0; k < 3; ++k) n[k] /= norm;
    }
    mesh->cavity = volume < 0.0;
    return mesh;
}

std::string with_mesh_files_from(const std::string& text, const std::string& scene_dir) {
    if (scene_dir.empty()) return text;
    json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded() || !document.is_object() || !document.contains("environment") ||
        !document["environment"].is_array())
        return text;
    bool changed = false;
    for (json& item : document["environment"]) {
        if (!item.is_object() || !item.contains("file") || !item["file"].is_string()) continue;
        const std::string file = item["file"].get<std::string>();
        if (file.empty() || file[0] == '/') continue;
        item["file"] = scene_dir + "/" + file;
        changed = true;
    }
    return changed ? document.dump() : text;
}

}  // namespace viewer
