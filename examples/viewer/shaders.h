// SPDX-License-Identifier: Apache-2.0
// The GLSL 3.30 core programs: lit surfaces (with the key light's shadow), flat lines, and
// the shadow map's depth pass. Colours are linear; the fragment shaders
// write sRGB.
#pragma once

namespace viewer::shaders {

// Every mesh: model space, then an optional instance offset and scale (spheres).
inline const char* const kSurfaceVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in float axis_u;
layout(location = 3) in vec4 instance;  // centre xyz, scale w
uniform mat4 model;
uniform mat3 normal_matrix;
uniform mat4 view_projection;
uniform mat4 light_view_projection;
uniform float axis_length;      // m: the bowel's tint changes slowly along it
out vec3 world_position;
out vec3 world_normal;
out float s;                    // arc length along the bowel, m
out vec3 tint;
out vec4 light_space;
void main() {
    vec4 p = model * vec4(instance.xyz + instance.w * position, 1.0);
    world_position = p.xyz;
    world_normal = normal_matrix * normal;
    s = axis_u * axis_length;
    tint = vec3(1.0, 0.90 + 0.10 * sin(s * 1.7), 0.92 + 0.08 * cos(s * 2.3));
    light_space = light_view_projection * p;
    gl_Position = view_projection * p;
}
)";

// Lighting as in a laparoscope: the main light sits at the camera (a headlight, which
// gives tissue its wet highlights), a key light from above casts the shadows that show
// how high the tool is, and a sky/ground ambient term keeps the shadows from going black.
// Tissue gets "wrap" diffuse lighting: light bleeding past the terminator, as in
// translucent flesh. Through the laparoscope (scope = 1) its light at the tip is the only
// one: it falls off with the square of the distance and away from the optics' axis, and
// the image is the scope's round field, black outside it.
inline const char* const kSurfaceFragment = R"(#version 330 core
in vec3 world_position;
in vec3 world_normal;
in float s;
in vec3 tint;
in vec4 light_space;
uniform vec3 eye;
uniform vec3 key_direction;     // unit, toward the key light
uniform vec3 base_color;        // linear
uniform float alpha;
uniform float specular;
uniform float shininess;
uniform float wrap;             // 0: hard terminator; 0.5: soft, tissue-like
uniform int pattern;            // 0 none, 1 the bowel's faint vessels and tint, 2 a 5 cm grid
uniform int shadows;
uniform sampler2DShadow shadow_map;
uniform int scope;              // 1: seen through the laparoscope
uniform vec3 view_direction;    // scope: unit, the optics' axis (the light's beam)
uniform vec3 scope_circle;      // scope: the round field's centre x, y and radius, pixels
out vec4 color;

// Schlick's cheap stand-in for pow(x, shininess): a software renderer's pow is slow.
float highlight(float x) {
    x = max(x, 0.0);
    return x / (shininess - shininess * x + x);
}

float lit_fraction(vec3 n) {
    if (shadows == 0) return 1.0;
    vec3 p = light_space.xyz / light_space.w * 0.5 + 0.5;
    if (p.z > 1.0 || p.x < 0.0 || p.y < 0.0 || p.x > 1.0 || p.y > 1.0) return 1.0;
    float bias = 0.0008 + 0.002 * (1.0 - max(dot(n, key_direction), 0.0));
    vec2 texel = 1.0 / vec2(textureSize(shadow_map, 0));
    // Four bilinear comparisons (each of four texels): a soft edge for little work.
    float sum = 0.0;
    for (int x = 0; x <= 1; ++x)
        for (int y = 0; y <= 1; ++y) sum += texture(shadow_map, vec3(p.xy + (vec2(x, y) - 0.5) * texel, p.z - bias));
    return 0.25 * sum;
}

void main() {
    vec3 n = normalize(world_normal);
    vec3 v = normalize(eye - world_position);
    if (!gl_FrontFacing) n = -n;
    vec3 albedo = base_color;
    if (pattern == 1) {
        // Thin darker rings about every 1.5 cm, like the small vessels that wrap a real
        // bowel, and a slow change of tint along it: sliding and twisting show.
        float vessel = 1.0 - min(abs(fract(s * 66.7) - 0.5) * 12.0, 1.0);
        albedo *= mix(vec3(1.0), vec3(0.85, 0.60, 0.66), 0.35 * vessel) * tint;
    } else if (pattern == 2) {
        // Lines where a coordinate in the surface's plane is a multiple of 5 cm, about a
        // pixel wide; the coordinate along the normal is constant and left out.
        vec3 cell = world_position / 0.05;
        vec3 d = abs(fract(cell - 0.5) - 0.5) / max(fwidth(cell), vec3(1e-6)) + 1e3 * step(0.9, abs(n));
        float line = 1.0 - min(min(min(d.x, d.y), d.z), 1.0);
        albedo *= 1.0 - 0.35 * line;
    }
    if (scope == 1) {
        float d = length(eye - world_position);
        float beam = mix(0.3, 1.0, smoothstep(0.55, 0.97, dot(-v, view_direction)));
        float light = beam * min(3.0, 0.0064 / (d * d));  // 1 at 8 cm
        float lit = max((dot(n, v) + wrap) / (1.0 + wrap), 0.0);
        vec3 dim = mix(vec3(0.02, 0.015, 0.015), vec3(0.03, 0.03, 0.035), 0.5 + 0.5 * n.z);
        vec3 c = albedo * (1.25 * lit * light + dim) + vec3(specular * highlight(dot(n, v)) * light);
        float edge = length(gl_FragCoord.xy - scope_circle.xy) - scope_circle.z;
        c *= 1.0 - smoothstep(-4.0, 0.0, edge);
        color = vec4(sqrt(clamp(c, 0.0, 1.0)), edge > 0.0 ? 1.0 : alpha);
        return;
    }
    float shadow = lit_fraction(n);
    float key = max((dot(n, key_direction) + wrap) / (1.0 + wrap), 0.0) * shadow;
    float head = max((dot(n, v) + wrap) / (1.0 + wrap), 0.0);
    vec3 ambient = mix(vec3(0.05, 0.04, 0.035), vec3(0.09, 0.10, 0.12), 0.5 + 0.5 * n.z);
    vec3 h = normalize(key_direction + v);
    float gloss = specular * (highlight(dot(n, v)) + 0.6 * shadow * highlight(dot(n, h)));
    vec3 c = albedo * (0.85 * key + 0.45 * head + ambient) + vec3(gloss);
    color = vec4(sqrt(clamp(c, 0.0, 1.0)), alpha);  // gamma 2, near enough to sRGB
}
)";

inline const char* const kFlatVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 view_projection;
void main() { gl_Position = view_projection * vec4(position, 1.0); }
)";

inline const char* const kFlatFragment = R"(#version 330 core
uniform vec4 flat_color;  // sRGB, alpha
out vec4 color;
void main() { color = flat_color; }
)";

inline const char* const kDepthFragment = R"(#version 330 core
void main() {}
)";

}  // namespace viewer::shaders
