// SPDX-License-Identifier: Apache-2.0
// The knobs of a skin, in the library's own units: lengths in metres (the C API converts
// its radius-relative knobs). One struct for the three methods; each reads only its own.
#pragma once

#include <cstdint>

#include "skinning/tube_radius.h"

namespace enteron::skinning {

enum class SkinMethod : int32_t { tube = 0, point_skeleton = 1, convolution = 2 };

struct SkinSettings {
    SkinMethod method = SkinMethod::convolution;
    double radius = 0.0125;          // R, m: the largest with a radius profile; the knobs below scale with it
    // The radius along the axis (tube_radius.h): each ring, skeleton point and vertex takes
    // its own; constant (radius) unless given.
    TubeRadius radius_along;
    uint32_t segments = 16;          // vertices around a ring (tube, convolution)
    double ring_spacing = 0.00625;   // arc length between rings, m (tube, convolution); the largest if adaptive
    double ring_chord_error = 0.0;   // convolution: > 0 places rings closer at bends, chord error tolerance, m
    uint32_t cap_rings = 4;          // rings of each hemispherical end cap (tube, convolution)
    double skeleton_spacing = 0.003125;  // arc length between skeleton samples, m (the largest if adaptive)
    double skeleton_chord_error = 0.0;   // > 0: skeleton samples closer where the axis bends, chord sag tolerance, m
    double voxel_size = 0.0041667;   // marching-cubes cell edge, m (point_skeleton)
    double window = 0.0125;          // half-width of the local blending window in arc length, m
    // Tube, convolution: keep the vertex count and the triangle indices while the axis moves
    // (skin.h). Point_skeleton: ignored (its topology follows the surface).
    bool stable_topology = true;
    // Folds that touch meet on contact surfaces, with a bulge that keeps the volume
    // (contact_profile.h); false: their surfaces pass through each other.
    bool contact_surfaces = true;
};

}  // namespace enteron::skinning
