// SPDX-License-Identifier: Apache-2.0
// Draws one frame of the scene with OpenGL 3.3 core: the bowel's skin shaded with its
// normals, the obstacles where they are now (organ meshes translucent, so that the bowel
// under them shows; a cavity's wall seen from inside), the tools' capsules, the force on
// each tool as an arrow, and on request the axis, the control points, the collision
// spheres, the mesentery and a wireframe. Needs a current context; every call on the
// render thread.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <string>

#include "camera.h"
#include "gl_mesh.h"
#include "gl_program.h"
#include "scene_layout.h"
#include "session.h"

namespace viewer {

struct DrawToggles {
    bool skin = true;
    bool wireframe = false;
    bool axis = false;
    bool control_points = false;
    bool spheres = false;          // the collision spheres
    bool mesentery = false;
    bool obstacles = true;
    bool tools = true;
    bool force_arrows = true;
    bool shadows = true;
};

// The box around a skin's vertices (empty for an empty mesh).
Eigen::AlignedBox3d mesh_bounds(const ent_mesh_view& mesh);

// How a surface looks (linear colour, lit by the shader in shaders.h).
struct Material {
    Eigen::Vector3f color = Eigen::Vector3f::Ones();
    float alpha = 1.0f;
    float specular = 0.2f;
    float shininess = 40.0f;
    float wrap = 0.0f;   // light past the terminator: 0 hard, 0.5 soft like tissue
    int pattern = 0;     // 0 plain, 1 the bowel's rings along its axis, 2 a 5 cm grid
};

// Everything one frame draws.
struct SceneView {
    const SceneLayout* layout = nullptr;
    const FrameState* frame = nullptr;
    const ToolCommands* targets = nullptr;  // where the mouse wants the tools
    DrawToggles toggles;
    double force_scale_m_per_N = 0.02;     // arrow length per newton
};

class Renderer {
public:
    Renderer();
    ~Renderer();
    // Compiles the programs and makes the shapes. False with the reason.
    bool init(std::string& error);
    void draw(const SceneView& view, const Camera& camera, int width_px, int height_px);

private:
    void upload_frame(const SceneView& view);
    void draw_casters(const SceneView& view, bool colour_pass);
    // pass: shadow (what casts: solid organs), opaque (the rest but translucent organs),
    // translucent (the solid organ meshes, after everything they may cover).
    enum class ObstaclePass { shadow, opaque, translucent };
    void draw_obstacles(const SceneView& view, ObstaclePass pass);
    const GlMesh* organ_buffer(std::size_t obstacle, const std::shared_ptr<const OrganMesh>& mesh);
    void draw_tools(const SceneView& view, bool colour_pass);
    void draw_capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius, const Material& material);
    void draw_arrow(const Eigen::Vector3d& from, const Eigen::Vector3d& vector, double radius, const Material& material);
    void draw_shape(const GlMesh& mesh, const Eigen::Matrix4f& model, const Material& material);
    void draw_overlays(const SceneView& view);
    void set_material(const Material& material);
    void prepare_shadow_map(const SceneView& view);

    GlProgram surface_, depth_, flat_;
    std::unique_ptr<GlMesh> bowel_, sphere_, sphere_instances_, cylinder_, cone_, box_, square_, lines_;
    // The mesh obstacles' triangles on the GPU, by obstacle, uploaded once per mesh (the
    // mesh is kept so that a new scene's mesh at the same address is not taken for it).
    struct OrganBuffer {
        std::shared_ptr<const OrganMesh> mesh;
        std::unique_ptr<GlMesh> buffer;
    };
    std::vector<OrganBuffer> organs_;
    GLuint shadow_fbo_ = 0, shadow_texture_ = 0;
    int shadow_size_ = 1024;

    // Per frame.
    const GlProgram* active_ = nullptr;      // surface_ (colour pass) or depth_ (shadow pass)
    Eigen::Matrix4f view_projection_, light_view_projection_;
    Eigen::Vector3f eye_, key_direction_;
    Eigen::AlignedBox3d bounds_;              // of what is drawn, for the shadow map
    std::vector<float> scratch_;              // instance and line data
};

}  // namespace viewer
