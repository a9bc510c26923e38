// Rigid shapes around the bowel: the abdominal cavity (inside of a box) and other organs
// (planes, spheres, capsules). Each reports, for a sphere of radius R, the contacts it
// makes: depth of penetration and the unit normal pushing the sphere out.
#pragma once

#include <array>
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace enteron::collision {

using Vec3 = std::array<double, 3>;

// The numbers are those of ENT_OBSTACLE_* in enteron.h.
enum class ObstacleKind : int32_t { box_inside = 0, plane = 1, sphere = 2, capsule = 3 };

struct Obstacle {
    ObstacleKind kind = ObstacleKind::box_inside;
    Vec3 center{};        // box_inside, sphere: centre; plane: a point of it; capsule: axis start
    Vec3 extent{};        // box_inside: half extents; plane: normal (unit); capsule: axis end
    double radius = 0.0;  // sphere, capsule
};

struct ObstacleContact {
    double depth;     // m, > 0
    double normal[3]; // unit, out of the obstacle
};

// Calls on_contact(const ObstacleContact&) for each contact of a sphere (centre p,
// radius r) with the obstacle: up to three for a box corner, at most one otherwise.
// Always inlined: the environment calls it for every sphere and obstacle, and the call
// cost more than a box's six wall tests.
template <class OnContact>
[[gnu::always_inline]] inline void for_each_contact(const Obstacle& o, const double p[3], double r, OnContact&& on_contact) {
    switch (o.kind) {
        case ObstacleKind::box_inside: {
            // Each wall is a plane facing inward. Most spheres touch none: one test for all
            // six walls first, without a branch per wall.
            double low[3], high[3];
            bool touching = false;
            for (int c = 0; c < 3; ++c) {
                low[c] = (o.center[c] - o.extent[c]) - (p[c] - r);
                high[c] = (p[c] + r) - (o.center[c] + o.extent[c]);
                touching = touching | (low[c] > 0.0) | (high[c] > 0.0);
            }
            if (!touching) return;
            for (int c = 0; c < 3; ++c) {
                if (low[c] > 0.0) {
                    ObstacleContact contact{low[c], {0.0, 0.0, 0.0}};
                    contact.normal[c] = 1.0;
                    on_contact(contact);
                }
                if (high[c] > 0.0) {
                    ObstacleContact contact{high[c], {0.0, 0.0, 0.0}};
                    contact.normal[c] = -1.0;
                    on_contact(contact);
                }
            }
            return;
        }
        case ObstacleKind::plane: {
            const double* n = o.extent.data();
            const double distance = (p[0] - o.center[0]) * n[0] + (p[1] - o.center[1]) * n[1] + (p[2] - o.center[2]) * n[2];
            if (distance < r) on_contact(ObstacleContact{r - distance, {n[0], n[1], n[2]}});
            return;
        }
        case ObstacleKind::sphere:
        case ObstacleKind::capsule: {
            // Closest point of the sphere's centre or the capsule's axis segment.
            double closest[3] = {o.center[0], o.center[1], o.center[2]};
            if (o.kind == ObstacleKind::capsule) {
                double axis[3], rel[3], axis2 = 0.0, dot = 0.0;
                for (int c = 0; c < 3; ++c) {
                    axis[c] = o.extent[c] - o.center[c];
                    rel[c] = p[c] - o.center[c];
                    axis2 += axis[c] * axis[c];
                    dot += axis[c] * rel[c];
                }
                const double t = axis2 > 0.0 ? std::min(1.0, std::max(0.0, dot / axis2)) : 0.0;
                for (int c = 0; c < 3; ++c) closest[c] += t * axis[c];
            }
            const double d[3] = {p[0] - closest[0], p[1] - closest[1], p[2] - closest[2]};
            const double distance = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            const double depth = o.radius + r - distance;
            if (!(depth > 0.0)) return;
            // A centre exactly on the axis has no direction: push up, any direction will do.
            if (distance > 1e-12) on_contact(ObstacleContact{depth, {d[0] / distance, d[1] / distance, d[2] / distance}});
            else on_contact(ObstacleContact{depth, {0.0, 0.0, 1.0}});
            return;
        }
    }
}

}  // namespace enteron::collision
