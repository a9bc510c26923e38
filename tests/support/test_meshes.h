// SPDX-License-Identifier: Apache-2.0
// Closed organ-like meshes with known shapes, shared by the tests that compare a mesh
// obstacle with the analytic shape it approximates: the C API's (tests/capi/test_anatomy.cpp)
// and the collision layer's unit tests (tests/unit/collision). Plain arrays: x y z per
// vertex, three indices per triangle, counter-clockwise seen from outside (normals out)
// unless a cavity is asked for.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace test_meshes {

struct Mesh {
    std::vector<double> vertices;
    std::vector<uint32_t> triangles;
};

// A sphere of radius r about c: an icosahedron subdivided `levels` times, pushed onto it.
inline Mesh icosphere(const double c[3], double r, int levels) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<std::array<double, 3>> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<std::array<uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> middle;
        auto mid = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = middle.find(key);
            if (it != middle.end()) return it->second;
            v.push_back({(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2});
            return middle[key] = uint32_t(v.size() - 1);
        };
        std::vector<std::array<uint32_t, 3>> next;
        for (const auto& tri : f) {
            const uint32_t ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
            next.insert(next.end(), {{tri[0], ab, ca}, {tri[1], bc, ab}, {tri[2], ca, bc}, {ab, bc, ca}});
        }
        f = next;
    }
    Mesh m;
    for (const auto& p : v) {
        const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int k = 0; k < 3; ++k) m.vertices.push_back(c[k] + r * p[k] / n);
    }
    for (const auto& tri : f) m.triangles.insert(m.triangles.end(), tri.begin(), tri.end());
    return m;
}

// An axis-aligned box about c with half extents h; normals out, or in (a cavity).
inline Mesh box(const double c[3], const double h[3], bool inward) {
    Mesh m;
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k) m.vertices.push_back(c[k] + ((i >> k) & 1 ? h[k] : -h[k]));
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        const uint32_t a[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
        for (int k = 0; k < 6; k += 3) {
            if (inward)
                m.triangles.insert(m.triangles.end(), {a[k], a[k + 2], a[k + 1]});
            else
                m.triangles.insert(m.triangles.end(), {a[k], a[k + 1], a[k + 2]});
        }
    }
    return m;
}

// A capsule from (0,0,z0) to (0,0,z1) of radius r: rings of a sphere split at the equator.
inline Mesh capsule(double z0, double z1, double r, int segments) {
    Mesh m;
    const int rings = segments / 2;  // per hemisphere, pole excluded
    auto ring = [&](double z, double radius) {
        for (int j = 0; j < segments; ++j) {
            const double a = 2.0 * M_PI * j / segments;
            m.vertices.insert(m.vertices.end(), {radius * std::cos(a), radius * std::sin(a), z});
        }
    };
    m.vertices.insert(m.vertices.end(), {0.0, 0.0, z0 - r});
    for (int i = 1; i <= rings; ++i) {
        const double th = M_PI / 2 * i / rings;
        ring(z0 - r * std::cos(th), r * std::sin(th));
    }
    for (int i = rings; i >= 1; --i) {
        const double th = M_PI / 2 * i / rings;
        ring(z1 + r * std::cos(th), r * std::sin(th));
    }
    m.vertices.insert(m.vertices.end(), {0.0, 0.0, z1 + r});
    const uint32_t last = uint32_t(m.vertices.size() / 3 - 1), ring_count = uint32_t(2 * rings);
    auto id = [&](uint32_t i, int j) { return 1 + i * segments + uint32_t((j + segments) % segments); };
    for (int j = 0; j < segments; ++j) m.triangles.insert(m.triangles.end(), {0, id(0, j + 1), id(0, j)});
    for (uint32_t i = 0; i + 1 < ring_count; ++i)
        for (int j = 0; j < segments; ++j)
            m.triangles.insert(m.triangles.end(),
                               {id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    for (int j = 0; j < segments; ++j) m.triangles.insert(m.triangles.end(), {last, id(ring_count - 1, j), id(ring_count - 1, j + 1)});
    return m;
}

}  // namespace test_meshes
