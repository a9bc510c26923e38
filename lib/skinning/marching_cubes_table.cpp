// SPDX-License-Identifier: Apache-2.0
#include "skinning/marching_cubes_table.h"

#include <string>

#include "base/error.h"
#include "base/geometry.h"

namespace enteron::skinning {

namespace {

std::array<std::array<uint8_t, 2>, 12> make_edges() {
    std::array<std::array<uint8_t, 2>, 12> edges{};
    for (int e = 0; e < 12; ++e) {
        const int axis = e / 4, combo = e % 4, p = (axis + 1) % 3, q = (axis + 2) % 3;
        const int c0 = ((combo & 1) << p) | (((combo >> 1) & 1) << q);
        edges[e] = {uint8_t(c0), uint8_t(c0 | (1 << axis))};
    }
    return edges;
}

Vec3 corner_position(int c) { return {double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1)}; }

}  // namespace

const std::array<std::array<uint8_t, 2>, 12> kEdgeCorners = make_edges();

namespace {

int edge_between(int a, int b) {
    for (int e = 0; e < 12; ++e)
        if ((kEdgeCorners[e][0] == a && kEdgeCorners[e][1] == b) || (kEdgeCorners[e][0] == b && kEdgeCorners[e][1] == a))
            return e;
    return -1;
}

Vec3 edge_midpoint(int e) { return 0.5 * (corner_position(kEdgeCorners[e][0]) + corner_position(kEdgeCorners[e][1])); }

// True if edges a and b both lie on one face of the cell.
bool share_face(int a, int b) {
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            auto on = [&](int e) {
                return ((kEdgeCorners[e][0] >> axis) & 1) == side && ((kEdgeCorners[e][1] >> axis) & 1) == side;
            };
            if (on(a) && on(b)) return true;
        }
    return false;
}

// Triangulates the polygon loop[first..last] (indices into loop, first < last), in which
// (loop[first], loop[last]) is already an edge, with no diagonal between two vertices on a
// common cell face. Such a diagonal crosses that face, and the cell on the other side of the
// face (which sees the same two vertices, unjoined, on the same face) may draw it too: the
// mesh edge would then belong to four triangles. Appends the triangles; false if impossible.
bool triangulate_range(const int* loop, int first, int last, MarchingCubesCase& out) {
    if (last - first < 2) return true;
    const uint8_t saved = out.triangle_count;
    for (int k = first + 1; k < last; ++k) {
        // Triangle (first, k, last); its sides (first, k) and (k, last) are diagonals unless
        // they join neighbours of the loop.
        if (k - first > 1 && share_face(loop[first], loop[k])) continue;
        if (last - k > 1 && share_face(loop[k], loop[last])) continue;
        if (out.triangle_count >= 12) throw Error(ErrorCode::internal, "marching cubes table: too many triangles");
        uint8_t* t = &out.edges[3 * out.triangle_count++];
        t[0] = uint8_t(loop[first]);
        t[1] = uint8_t(loop[k]);
        t[2] = uint8_t(loop[last]);
        if (triangulate_range(loop, first, k, out) && triangulate_range(loop, k, last, out)) return true;
        out.triangle_count = saved;
    }
    return false;
}

// Triangulates a closed loop of edges (wound as the segments were), trying each start
// vertex in turn so that a fan from loop[0] is kept whenever it is allowed.
bool triangulate(const int* loop, int length, MarchingCubesCase& out) {
    for (int start = 0; start < length; ++start) {
        int rotated[12];
        for (int i = 0; i < length; ++i) rotated[i] = loop[(start + i) % length];
        if (triangulate_range(rotated, 0, length - 1, out)) return true;
    }
    return false;
}

std::array<MarchingCubesCase, 256> generate() {
    std::array<MarchingCubesCase, 256> table{};
    for (int mask = 0; mask < 256; ++mask) {
        auto inside = [&](int c) { return ((mask >> c) & 1) != 0; };
        int next[12];
        int incoming[12] = {};
        for (int& n : next) n = -1;
        auto add_segment = [&](int from, int to, Vec3 towards_outside, Vec3 face_normal) {
            // Oriented along g x N: then the triangle through this segment faces outside.
            const Vec3 want = towards_outside.cross(face_normal);
            if ((edge_midpoint(to) - edge_midpoint(from)).dot(want) < 0.0) std::swap(from, to);
            if (next[from] != -1) throw Error(ErrorCode::internal, "marching cubes table: edge used twice");
            next[from] = to;
            ++incoming[to];
        };
        for (int axis = 0; axis < 3; ++axis) {
            for (int side = 0; side < 2; ++side) {
                const int p = (axis + 1) % 3, q = (axis + 2) % 3, base = side << axis;
                const int cycle[4] = {base, base | (1 << p), base | (1 << p) | (1 << q), base | (1 << q)};
                Vec3 normal = Vec3::Zero();
                (axis == 0 ? normal.x() : axis == 1 ? normal.y() : normal.z()) = side ? 1.0 : -1.0;
                int crossing[4], crossings = 0, inside_count = 0;
                Vec3 in_sum = Vec3::Zero(), out_sum = Vec3::Zero();
                for (int i = 0; i < 4; ++i) {
                    const int a = cycle[i], b = cycle[(i + 1) % 4];
                    if (inside(a) != inside(b)) crossing[crossings++] = edge_between(a, b);
                    if (inside(a)) {
                        in_sum = in_sum + corner_position(a);
                        ++inside_count;
                    } else {
                        out_sum = out_sum + corner_position(a);
                    }
                }
                if (crossings == 2) {
                    const Vec3 g = (1.0 / (4 - inside_count)) * out_sum - (1.0 / inside_count) * in_sum;
                    add_segment(crossing[0], crossing[1], g, normal);
                } else if (crossings == 4) {
                    // Ambiguous face: cut off each inside corner on its own.
                    Vec3 centre = Vec3::Zero();
                    for (int c : cycle) centre = centre + 0.25 * corner_position(c);
                    for (int i = 0; i < 4; ++i) {
                        if (!inside(cycle[i])) continue;
                        const int before = edge_between(cycle[(i + 3) % 4], cycle[i]);
                        const int after = edge_between(cycle[i], cycle[(i + 1) % 4]);
                        add_segment(before, after, centre - corner_position(cycle[i]), normal);
                    }
                }
            }
        }
        // Chain the segments into loops and fan each loop.
        bool visited[12] = {};
        MarchingCubesCase& out = table[std::size_t(mask)];
        for (int start = 0; start < 12; ++start) {
            if (next[start] == -1 || visited[start]) continue;
            if (incoming[start] != 1) throw Error(ErrorCode::internal, "marching cubes table: open loop");
            int loop[12], length = 0;
            for (int e = start; !visited[e]; e = next[e]) {
                if (next[e] == -1) throw Error(ErrorCode::internal, "marching cubes table: open loop");
                visited[e] = true;
                loop[length++] = e;
            }
            if (!triangulate(loop, length, out))
                throw Error(ErrorCode::internal, "marching cubes table: a loop has no triangulation without face diagonals");
        }
    }
    return table;
}

}  // namespace

const std::array<MarchingCubesCase, 256>& marching_cubes_table() {
    static const std::array<MarchingCubesCase, 256> table = generate();
    return table;
}

}  // namespace enteron::skinning
