// SPDX-License-Identifier: Apache-2.0
// The marching cubes case table (Lorensen and Cline 1987), generated once rather than typed
// in, with one fixed rule for the ambiguous faces: on a face whose inside corners are
// diagonal, the iso-line cuts off each inside corner (the inside corners stay separate).
// The rule depends only on the face's own four corners, so the two cells sharing a face
// always cut it the same way and the surface has no cracks. The segments on each face are
// chained into loops and each loop is triangulated without a diagonal between two vertices
// of one face that the face's segments leave apart: the neighbouring cell sees those two
// vertices on the same face and might draw the same diagonal, which would then belong to
// four triangles (a plain fan from the first vertex did so in 18 cases, where two folds of
// the bowel touch). So every mesh edge belongs to exactly two triangles.
//
// Corner c of a cell is at (c & 1, (c >> 1) & 1, (c >> 2) & 1). Edge e joins corners
// kEdgeCorners[e][0] -> [1] along axis e / 4. A corner is inside when its field exceeds the
// iso-value; triangles are wound counter-clockwise seen from outside.
#pragma once

#include <array>
#include <cstdint>

namespace enteron::skinning {

struct MarchingCubesCase {
    uint8_t triangle_count = 0;
    std::array<uint8_t, 36> edges{};  // 3 edges per triangle
};

// The 12 edges: first and second corner (the second differs in bit e / 4).
extern const std::array<std::array<uint8_t, 2>, 12> kEdgeCorners;

// The table, indexed by the mask of inside corners (bit c set: corner c inside).
// Throws enteron::Error(internal) on first use if the generated table is inconsistent.
const std::array<MarchingCubesCase, 256>& marching_cubes_table();

}  // namespace enteron::skinning
