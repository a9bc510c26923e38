// SPDX-License-Identifier: Apache-2.0
#include "renderer.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

#include "shaders.h"

namespace viewer {

namespace {

// Display components (as a colour picker shows them) to the linear values the shader
// lights; its output takes the square root back (gamma 2).
Eigen::Vector3f linear(float r, float g, float b) { return Eigen::Vector3f(r * r, g * g, b * b); }

// A frame whose z axis is the unit vector z.
Eigen::Matrix3d frame_along(const Eigen::Vector3d& z) {
    const Eigen::Vector3d helper = std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d x = helper.cross(z).normalized();
    Eigen::Matrix3d frame;
    frame << x, z.cross(x), z;
    return frame;
}

Eigen::Matrix4f affine(const Eigen::Matrix3d& linear_part, const Eigen::Vector3d& translation) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.block<3, 3>(0, 0) = linear_part;
    m.block<3, 1>(0, 3) = translation;
    return m.cast<float>();
}

// The unit shapes are along z from 0 to 1 with radius 1: stretch one from a to b.
Eigen::Matrix4f segment_transform(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius) {
    const Eigen::Vector3d d = b - a;
    const double length = std::max(d.norm(), 1e-9);
    const Eigen::Matrix3d frame = frame_along(d.norm() > 1e-12 ? Eigen::Vector3d(d / length) : Eigen::Vector3d::UnitZ());
    return affine(frame * Eigen::Vector3d(radius, radius, length).asDiagonal(), a);
}

Eigen::Matrix4f orthographic(double half_size, double near_m, double far_m) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m(0, 0) = 1.0 / half_size;
    m(1, 1) = 1.0 / half_size;
    m(2, 2) = -2.0 / (far_m - near_m);
    m(2, 3) = -(far_m + near_m) / (far_m - near_m);
    return m.cast<float>();
}

Eigen::Vector3d point(const double* xyz) { return Eigen::Vector3d(xyz[0], xyz[1], xyz[2]); }

// An obstacle's frame as a model matrix.
Eigen::Matrix4f frame_transform(const double* position_m, const double* orientation_wxyz) {
    const Eigen::Quaterniond q(orientation_wxyz[0], orientation_wxyz[1], orientation_wxyz[2], orientation_wxyz[3]);
    return affine(q.normalized().toRotationMatrix(), point(position_m));
}

Eigen::Vector3d rotate(const ToolPose& pose, const Eigen::Vector3d& v) {
    const Eigen::Quaterniond q(pose.orientation_wxyz[0], pose.orientation_wxyz[1], pose.orientation_wxyz[2],
                               pose.orientation_wxyz[3]);
    return q.normalized() * v;
}

// A point of the axis at spline parameter s in [0, n - 1]: the uniform Catmull-Rom spline
// through the control points, with the library's phantom ends q_{-1} = 2 q_0 - q_1 and
// q_n = 2 q_{n-1} - q_{n-2} (docs/viewer.md: where the mesentery is drawn).
Eigen::Vector3d axis_point(const std::vector<double>& control_points, double s) {
    const auto n = static_cast<long>(control_points.size() / 3);
    const long segment = std::clamp(static_cast<long>(std::floor(s)), 0L, n - 2);
    const double t = s - static_cast<double>(segment);
    auto q = [&](long i) -> Eigen::Vector3d {
        if (i < 0) return 2.0 * point(&control_points[0]) - point(&control_points[3]);
        if (i >= n) return 2.0 * point(&control_points[3 * (n - 1)]) - point(&control_points[3 * (n - 2)]);
        return point(&control_points[3 * static_cast<std::size_t>(i)]);
    };
    const double t2 = t * t, t3 = t2 * t;
    return 0.5 * ((-t3 + 2 * t2 - t) * q(segment - 1) + (3 * t3 - 5 * t2 + 2) * q(segment) +
                  (-3 * t3 + 4 * t2 + t) * q(segment + 1) + (t3 - t2) * q(segment + 2));
}

// The background: a dark vertical gradient, lighter below, cleared band by band (a
// full-screen pass would cost a software renderer as much as the scene).
void clear_background(int width_px, int height_px) {
    constexpr int kBands = 32;
    const Eigen::Vector3f bottom(0.20f, 0.21f, 0.23f), top(0.07f, 0.075f, 0.085f);
    glEnable(GL_SCISSOR_TEST);
    for (int band = 0; band < kBands; ++band) {
        const int y0 = height_px * band / kBands, y1 = height_px * (band + 1) / kBands;
        const Eigen::Vector3f c = bottom + (top - bottom) * ((band + 0.5f) / kBands);
        glScissor(0, y0, width_px, y1 - y0);
        glClearColor(c.x(), c.y(), c.z(), 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
    glClear(GL_DEPTH_BUFFER_BIT);
}

}  // namespace

namespace {
// The palette: a pink, glossy, slightly translucent bowel; a grey cavity with a 5 cm grid;
// tan organs; blue-grey steel tools.
Material make(Eigen::Vector3f color, float specular, float shininess, float wrap, int pattern = 0,
              float alpha = 1.0f) {
    Material m;
    m.color = color;
    m.specular = specular;
    m.shininess = shininess;
    m.wrap = wrap;
    m.pattern = pattern;
    m.alpha = alpha;
    return m;
}

const Material& bowel_material() {
    static const Material m = make(linear(0.84f, 0.42f, 0.40f), 0.40f, 110.0f, 0.5f, 1);
    return m;
}
const Material& cavity_material() {
    static const Material m = make(linear(0.40f, 0.40f, 0.42f), 0.03f, 20.0f, 0.0f, 2);
    return m;
}
const Material& organ_material() {
    static const Material m = make(linear(0.74f, 0.60f, 0.40f), 0.15f, 40.0f, 0.3f);
    return m;
}
// An organ mesh by its file's name, in the colours a laparoscope shows: a dark red-brown
// liver, a pale stomach, a grey-pink abdominal wall (with the 5 cm grid, for scale).
Material organ_mesh_material(const ObstacleShape& obstacle) {
    const std::string& name = obstacle.name;
    auto named = [&name](const char* word) { return name.find(word) != std::string::npos; };
    if (obstacle.mesh && obstacle.mesh->cavity) return make(linear(0.60f, 0.50f, 0.49f), 0.05f, 20.0f, 0.2f, 2);
    if (named("liver")) return make(linear(0.50f, 0.20f, 0.10f), 0.15f, 60.0f, 0.3f, 0, 0.85f);
    if (named("stomach")) return make(linear(0.88f, 0.72f, 0.55f), 0.30f, 50.0f, 0.4f, 0, 0.85f);
    if (named("colon")) return make(linear(0.80f, 0.62f, 0.48f), 0.30f, 50.0f, 0.4f, 0, 0.85f);
    Material m = organ_material();
    m.alpha = 0.85f;
    return m;
}
const Material& steel_material() {
    static const Material m = make(linear(0.40f, 0.52f, 0.70f), 0.55f, 50.0f, 0.0f);
    return m;
}
}  // namespace

Renderer::Renderer() = default;

Renderer::~Renderer() {
    if (shadow_fbo_ != 0) glDeleteFramebuffers(1, &shadow_fbo_);
    if (shadow_texture_ != 0) glDeleteTextures(1, &shadow_texture_);
}

bool Renderer::init(std::string& error) {
    if (!surface_.build("surface", shaders::kSurfaceVertex, shaders::kSurfaceFragment, error) ||
        !depth_.build("depth", shaders::kSurfaceVertex, shaders::kDepthFragment, error) ||
        !flat_.build("flat", shaders::kFlatVertex, shaders::kFlatFragment, error))
        return false;
    bowel_ = std::make_unique<GlMesh>();
    sphere_ = std::make_unique<GlMesh>();
    sphere_instances_ = std::make_unique<GlMesh>();
    cylinder_ = std::make_unique<GlMesh>();
    cone_ = std::make_unique<GlMesh>();
    box_ = std::make_unique<GlMesh>();
    square_ = std::make_unique<GlMesh>();
    lines_ = std::make_unique<GlMesh>();
    sphere_->upload(unit_sphere(32, 16));
    sphere_instances_->upload(unit_sphere(16, 8));
    cylinder_->upload(unit_cylinder(32));
    cone_->upload(unit_cone(24));
    box_->upload(inward_box());
    square_->upload(unit_square());

    glGenTextures(1, &shadow_texture_);
    glBindTexture(GL_TEXTURE_2D, shadow_texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, shadow_size_, shadow_size_, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glGenFramebuffers(1, &shadow_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_texture_, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    const GLenum complete = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (complete != GL_FRAMEBUFFER_COMPLETE) {
        error = "the shadow map's framebuffer is incomplete";
        return false;
    }
    return true;
}

void Renderer::set_material(const Material& material) {
    if (active_ != &surface_) return;  // the depth pass needs none
    surface_.set("base_color", material.color);
    surface_.set("alpha", material.alpha);
    surface_.set("specular", material.specular);
    surface_.set("shininess", material.shininess);
    surface_.set("wrap", material.wrap);
    surface_.set("pattern", material.pattern);
}

void Renderer::draw_shape(const GlMesh& mesh, const Eigen::Matrix4f& model, const Material& material) {
    active_->set("model", model);
    if (active_ == &surface_) {
        const Eigen::Matrix3f normal_matrix = model.block<3, 3>(0, 0).inverse().transpose();
        surface_.set("normal_matrix", normal_matrix);
    }
    set_material(material);
    mesh.draw();
}

void Renderer::draw_capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius,
                            const Material& material) {
    draw_shape(*cylinder_, segment_transform(a, b, radius), material);
    for (const Eigen::Vector3d& end : {a, b})
        draw_shape(*sphere_, affine(radius * Eigen::Matrix3d::Identity(), end), material);
}

void Renderer::draw_arrow(const Eigen::Vector3d& from, const Eigen::Vector3d& vector, double radius,
                          const Material& material) {
    const double length = vector.norm();
    if (length < 2.0 * radius) return;
    const double head = std::min(0.4 * length, 6.0 * radius);
    const Eigen::Vector3d direction = vector / length;
    const Eigen::Vector3d neck = from + (length - head) * direction;
    draw_shape(*cylinder_, segment_transform(from, neck, radius), material);
    draw_shape(*cone_, segment_transform(neck, from + vector, 2.5 * radius), material);
}

void Renderer::upload_frame(const SceneView& view) {
    const ent_mesh_view& mesh = view.frame->mesh;
    bowel_->upload(mesh.positions_xyz_m, mesh.normals_xyz, mesh.axis_u, mesh.vertex_count, mesh.indices,
                   3 * mesh.triangle_count);
    bounds_ = mesh_bounds(mesh);
    const SceneLayout& layout = *view.layout;
    if (layout.scene_size_m > 0.0) {
        const Eigen::Vector3d centre = point(layout.scene_center_m);
        bounds_.extend(centre - Eigen::Vector3d::Constant(0.5 * layout.scene_size_m));
        bounds_.extend(centre + Eigen::Vector3d::Constant(0.5 * layout.scene_size_m));
    }
    if (bounds_.isEmpty()) bounds_.extend(Eigen::Vector3d::Zero());
}

Eigen::AlignedBox3d mesh_bounds(const ent_mesh_view& mesh) {
    Eigen::AlignedBox3d box;  // empty
    for (std::uint32_t i = 0; i < mesh.vertex_count; ++i)
        box.extend(Eigen::Vector3f(mesh.positions_xyz_m + 3 * i).cast<double>());
    return box;
}

void Renderer::prepare_shadow_map(const SceneView& view) {
    const Eigen::Vector3d centre = bounds_.center();
    const double radius = std::max(0.5 * bounds_.diagonal().norm(), 1e-3);
    const Eigen::Vector3d toward_light = key_direction_.cast<double>();
    light_view_projection_ = orthographic(radius, 0.0, 4.0 * radius) *
                             look_at(centre + 2.0 * radius * toward_light, centre, Eigen::Vector3d::UnitY());
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    GLint framebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
    glViewport(0, 0, shadow_size_, shadow_size_);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    active_ = &depth_;
    depth_.use();
    depth_.set("view_projection", light_view_projection_);
    depth_.set("light_view_projection", light_view_projection_);
    draw_casters(view, false);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
}

void Renderer::draw(const SceneView& view, const Camera& camera, int width_px, int height_px) {
    const double aspect = static_cast<double>(width_px) / std::max(1, height_px);
    view_projection_ = camera.projection(aspect) * camera.view();
    eye_ = camera.eye().cast<float>();
    key_direction_ = Eigen::Vector3f(-0.35f, -0.45f, 1.0f).normalized();
    upload_frame(view);

    glViewport(0, 0, width_px, height_px);
    // Through the laparoscope its light at the tip is the only one: no key light, no shadow
    // map, a black cavity beyond the light's reach.
    const bool scope = camera.scope();
    const bool shadows = view.toggles.shadows && !scope;
    if (shadows) prepare_shadow_map(view);

    if (scope) {
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    } else {
        clear_background(width_px, height_px);
    }
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);

    active_ = &surface_;
    surface_.use();
    surface_.set("view_projection", view_projection_);
    surface_.set("light_view_projection", light_view_projection_);
    surface_.set("eye", eye_);
    surface_.set("key_direction", key_direction_);
    surface_.set("axis_length", static_cast<float>(view.layout->length_m));
    surface_.set("shadows", shadows ? 1 : 0);
    surface_.set("scope", scope ? 1 : 0);
    surface_.set("view_direction", Eigen::Vector3f(camera.forward().cast<float>()));
    // The scope's round field: a circle a little taller than the picture, as on a monitor.
    surface_.set("scope_circle",
                 Eigen::Vector3f(0.5f * float(width_px), 0.5f * float(height_px), 0.55f * float(height_px)));
    surface_.set("shadow_map", 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, shadow_texture_);

    // Near things first: the depth test then skips the walls' pixels they hide, which
    // matters to a software renderer.
    draw_casters(view, true);
    draw_obstacles(view, ObstaclePass::opaque);
    draw_obstacles(view, ObstaclePass::translucent);
    draw_overlays(view);
    active_ = nullptr;
}

void Renderer::draw_casters(const SceneView& view, bool colour_pass) {
    const SceneLayout& layout = *view.layout;
    const FrameState& frame = *view.frame;
    if (view.toggles.skin) {
        if (colour_pass && view.toggles.wireframe) {
            glEnable(GL_POLYGON_OFFSET_FILL);  // the wire drawn over it stays visible
            glPolygonOffset(1.0f, 1.0f);
        }
        draw_shape(*bowel_, Eigen::Matrix4f::Identity(), bowel_material());
        glDisable(GL_POLYGON_OFFSET_FILL);
    }
    if (!colour_pass) draw_obstacles(view, ObstaclePass::shadow);
    if (view.toggles.tools) draw_tools(view, colour_pass);
    if (view.toggles.control_points && !frame.control_points_xyz_m.empty()) {
        scratch_.clear();
        for (std::size_t i = 0; i + 2 < frame.control_points_xyz_m.size(); i += 3)
            scratch_.insert(scratch_.end(), {static_cast<float>(frame.control_points_xyz_m[i]),
                                             static_cast<float>(frame.control_points_xyz_m[i + 1]),
                                             static_cast<float>(frame.control_points_xyz_m[i + 2]),
                                             static_cast<float>(0.3 * layout.radius_m)});
        sphere_instances_->upload_instances(scratch_.data(), static_cast<std::uint32_t>(scratch_.size() / 4));
        active_->set("model", Eigen::Matrix4f::Identity().eval());
        if (colour_pass) surface_.set("normal_matrix", Eigen::Matrix3f::Identity().eval());
        set_material(make(linear(1.0f, 0.82f, 0.20f), 0.4f, 40.0f, 0.0f));
        if (colour_pass && view.toggles.skin) glDisable(GL_DEPTH_TEST);  // seen through the skin
        sphere_instances_->draw_instanced();
        glEnable(GL_DEPTH_TEST);
    }
}

const GlMesh* Renderer::organ_buffer(std::size_t obstacle, const std::shared_ptr<const OrganMesh>& mesh) {
    if (!mesh || mesh->indices.empty()) return nullptr;
    if (organs_.size() <= obstacle) organs_.resize(obstacle + 1);
    OrganBuffer& organ = organs_[obstacle];
    if (organ.mesh != mesh) {
        if (!organ.buffer) organ.buffer = std::make_unique<GlMesh>();
        organ.buffer->upload(mesh->positions.data(), mesh->normals.data(), nullptr,
                             static_cast<std::uint32_t>(mesh->positions.size() / 3), mesh->indices.data(),
                             static_cast<std::uint32_t>(mesh->indices.size()), GL_STATIC_DRAW);
        organ.mesh = mesh;
    }
    return organ.buffer.get();
}

void Renderer::draw_obstacles(const SceneView& view, ObstaclePass pass) {
    if (!view.toggles.obstacles) return;
    const std::vector<ObstacleShape>& obstacles = view.layout->obstacles;
    const std::vector<ObstaclePose>& poses = view.frame->obstacles;
    const bool shadow = pass == ObstaclePass::shadow;
    if (pass == ObstaclePass::translucent) {
        // Front faces only, and no depth written: the bowel and the tools behind or inside
        // an organ show through it, and its far side does not darken its near side.
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
        const ObstacleShape& obstacle = obstacles[i];
        // Where it is now (a retractor moves it); as described where the session has no
        // poses (a remote one); not at all once removed.
        if (i < poses.size() && !poses[i].present) continue;
        const Eigen::Matrix4f frame = i < poses.size()
                                          ? frame_transform(poses[i].position_m, poses[i].orientation_wxyz)
                                          : frame_transform(obstacle.position_m, obstacle.orientation_wxyz);
        const bool translucent = obstacle.kind == ENT_OBSTACLE_MESH && obstacle.mesh && !obstacle.mesh->cavity;
        if (!shadow && translucent != (pass == ObstaclePass::translucent)) continue;
        switch (obstacle.kind) {
            case ENT_OBSTACLE_BOX_INSIDE:
                if (shadow) break;  // the cavity receives shadows, casts none
                // Only the walls seen from inside: the near walls face away and are culled.
                glEnable(GL_CULL_FACE);
                draw_shape(*box_,
                           frame * affine(Eigen::Vector3d(obstacle.half_extents_m[0], obstacle.half_extents_m[1],
                                                          obstacle.half_extents_m[2])
                                              .asDiagonal(),
                                          point(obstacle.center_m)),
                           cavity_material());
                glDisable(GL_CULL_FACE);
                break;
            case ENT_OBSTACLE_PLANE: {
                if (shadow) break;
                const Eigen::Matrix3d plane = frame_along(point(obstacle.normal));
                const double half = std::max(1.0, 2.0 * view.layout->scene_size_m);
                draw_shape(*square_,
                           frame * affine(plane * Eigen::Vector3d(half, half, 1.0).asDiagonal(), point(obstacle.center_m)),
                           cavity_material());
                break;
            }
            case ENT_OBSTACLE_SPHERE:
                draw_shape(*sphere_, frame * affine(obstacle.radius_m * Eigen::Matrix3d::Identity(), point(obstacle.center_m)),
                           organ_material());
                break;
            case ENT_OBSTACLE_CAPSULE: {
                const Eigen::Matrix3d turn = frame.block<3, 3>(0, 0).cast<double>();
                const Eigen::Vector3d shift = frame.block<3, 1>(0, 3).cast<double>();
                draw_capsule(turn * point(obstacle.start_m) + shift, turn * point(obstacle.end_m) + shift, obstacle.radius_m,
                             organ_material());
                break;
            }
            case ENT_OBSTACLE_MESH: {
                const GlMesh* mesh = organ_buffer(i, obstacle.mesh);
                if (mesh == nullptr || (shadow && !translucent)) break;  // a wall casts no shadow
                // A wall is seen from inside (its near side, facing away, is culled); an
                // organ shows its near side.
                if (!shadow) glEnable(GL_CULL_FACE);
                draw_shape(*mesh, frame, organ_mesh_material(obstacle));
                glDisable(GL_CULL_FACE);
                break;
            }
            default:
                break;
        }
    }
    if (pass == ObstaclePass::translucent) {
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
}

void Renderer::draw_tools(const SceneView& view, bool colour_pass) {
    const SceneLayout& layout = *view.layout;
    const FrameState& frame = *view.frame;
    for (std::uint32_t i = 0; i < frame.tool_count && i < layout.tools.size(); ++i) {
        const ToolShape& shape = layout.tools[i];
        const ToolReadback& tool = frame.tools[i];
        const Eigen::Vector3d tip = point(tool.pose.position_m);
        const Eigen::Vector3d end = tip + shape.length_m * rotate(tool.pose, Eigen::Vector3d::UnitZ());
        draw_capsule(tip, end, shape.radius_m, steel_material());
        if (shape.blade_width_m > 0.0) {
            // A retractor's blade: side by side capsules, no farther apart than the shaft's
            // radius, fill the rounded plate the bowel meets.
            const Eigen::Vector3d across = rotate(tool.pose, Eigen::Vector3d::UnitX());
            const Eigen::Vector3d blade = std::min(shape.blade_length_m, shape.length_m) * (end - tip) /
                                          std::max(shape.length_m, 1e-12);
            const int strips = 1 + static_cast<int>(std::ceil(shape.blade_width_m / shape.radius_m));
            for (int k = 0; k <= strips; ++k) {
                const Eigen::Vector3d offset = (k / static_cast<double>(strips) - 0.5) * shape.blade_width_m * across;
                draw_capsule(tip + offset, tip + offset + blade, shape.radius_m, steel_material());
            }
        }
        // The jaws: green while they hold the bowel, amber when closed on nothing.
        const bool closed = view.targets != nullptr && i < view.targets->count && view.targets->grasp[i];
        if (tool.feedback.grasping || closed) {
            const Material jaws = make(tool.feedback.grasping ? linear(0.30f, 0.85f, 0.40f) : linear(1.0f, 0.70f, 0.20f), 0.5f,
                                       40.0f, 0.0f);
            draw_shape(*sphere_, affine(1.35 * shape.radius_m * Eigen::Matrix3d::Identity(), tip), jaws);
        }
        if (!colour_pass || !view.toggles.force_arrows) continue;
        // The force on the tool (what a haptic device would render), from the tip: green
        // when small, yellow at the tool's max_force (colours the pink bowel does not have).
        const Eigen::Vector3d force = point(tool.feedback.force_N);
        const float load = static_cast<float>(std::min(1.0, force.norm() / std::max(shape.max_force_N, 1e-9)));
        const Material arrow = make(linear(0.25f + 0.75f * load, 0.90f - 0.05f * load, 0.30f - 0.20f * load), 0.3f,
                                    30.0f, 0.0f);
        draw_arrow(tip, view.force_scale_m_per_N * force, 0.6 * shape.radius_m, arrow);
    }
}

void Renderer::draw_overlays(const SceneView& view) {
    const SceneLayout& layout = *view.layout;
    const FrameState& frame = *view.frame;
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

    // Lines: the mesentery's springs and the wireframe, depth-tested.
    flat_.use();
    flat_.set("view_projection", view_projection_);
    if (view.toggles.mesentery && layout.mesentery && frame.control_points_xyz_m.size() >= 12) {
        scratch_.clear();
        const double n = static_cast<double>(frame.control_points_xyz_m.size() / 3);
        for (std::uint32_t k = 0; k < layout.attachments; ++k) {
            // Attachment k: spline parameter (k + 1/2) / K (n - 1), pulled toward the root
            // point at the same fraction along the root, or where the mapping says
            // (lib/mechanics/mesentery_force.h).
            const double fraction = (k + 0.5) / layout.attachments;
            const Eigen::Vector3d on_axis = axis_point(frame.control_points_xyz_m, fraction * (n - 1.0));
            const Eigen::Vector3d root = point(mesentery_root_point(layout, fraction).data());
            scratch_.insert(scratch_.end(), {static_cast<float>(on_axis.x()), static_cast<float>(on_axis.y()),
                                             static_cast<float>(on_axis.z()), static_cast<float>(root.x()),
                                             static_cast<float>(root.y()), static_cast<float>(root.z())});
        }
        lines_->upload(scratch_.data(), nullptr, nullptr, static_cast<std::uint32_t>(scratch_.size() / 3), nullptr, 0);
        flat_.set("flat_color", Eigen::Vector4f(0.98f, 0.88f, 0.55f, 0.8f));
        lines_->draw(GL_LINES);
    }
    if (view.toggles.wireframe) {
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        flat_.set("flat_color", view.toggles.skin ? Eigen::Vector4f(0.25f, 0.08f, 0.08f, 0.55f)
                                                  : Eigen::Vector4f(0.95f, 0.60f, 0.55f, 0.9f));
        bowel_->draw();
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    }
    // The axis: on top of everything, or it would hide inside its own skin.
    if (view.toggles.axis && !frame.axis_xyz_m.empty()) {
        scratch_.assign(frame.axis_xyz_m.begin(), frame.axis_xyz_m.end());
        lines_->upload(scratch_.data(), nullptr, nullptr, static_cast<std::uint32_t>(scratch_.size() / 3), nullptr, 0);
        glDisable(GL_DEPTH_TEST);
        flat_.set("flat_color", Eigen::Vector4f(0.35f, 1.0f, 0.45f, 1.0f));
        lines_->draw(GL_LINE_STRIP);
        glEnable(GL_DEPTH_TEST);
    }

    // Translucent last: the collision spheres and where the mouse wants the tool.
    active_ = &surface_;
    surface_.use();
    glDepthMask(GL_FALSE);
    if (view.toggles.mesentery && layout.mesentery)
        for (std::size_t i = 3; i + 2 < layout.root_m.size(); i += 3)
            draw_capsule(point(&layout.root_m[i - 3]), point(&layout.root_m[i]), 0.25 * layout.radius_m,
                         make(linear(0.98f, 0.88f, 0.55f), 0.2f, 30.0f, 0.3f));
    if (view.toggles.spheres && !frame.spheres_xyz_m.empty()) {
        scratch_.clear();
        for (std::size_t i = 0; i + 2 < frame.spheres_xyz_m.size(); i += 3)
            scratch_.insert(scratch_.end(),
                            {static_cast<float>(frame.spheres_xyz_m[i]), static_cast<float>(frame.spheres_xyz_m[i + 1]),
                             static_cast<float>(frame.spheres_xyz_m[i + 2]), static_cast<float>(layout.radius_m)});
        sphere_instances_->upload_instances(scratch_.data(), static_cast<std::uint32_t>(scratch_.size() / 4));
        surface_.set("model", Eigen::Matrix4f::Identity().eval());
        surface_.set("normal_matrix", Eigen::Matrix3f::Identity().eval());
        set_material(make(linear(0.45f, 0.78f, 0.95f), 0.3f, 30.0f, 0.0f, 0, 0.35f));
        sphere_instances_->draw_instanced();
    }
    if (view.toggles.tools && view.targets != nullptr) {
        for (std::uint32_t i = 0; i < view.targets->count && i < frame.tool_count && i < layout.tools.size(); ++i) {
            const Eigen::Vector3d target = point(view.targets->target[i].position_m);
            if ((target - point(frame.tools[i].pose.position_m)).norm() < 2e-3) continue;
            draw_shape(*sphere_, affine(1.5 * layout.tools[i].radius_m * Eigen::Matrix3d::Identity(), target),
                       make(linear(0.40f, 0.52f, 0.70f), 0.3f, 30.0f, 0.0f, 0, 0.4f));
        }
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

}  // namespace viewer
