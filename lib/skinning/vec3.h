// A minimal double 3-vector for the skinning hot loops (no Eigen dependency in lib/skinning).
#pragma once

#include <cmath>

namespace enteron::skinning {

struct Vec3 {
    double x = 0.0, y = 0.0, z = 0.0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalized(Vec3 a, Vec3 fallback) {
    const double n = norm(a);
    return n > 1e-300 ? (1.0 / n) * a : fallback;
}
inline Vec3 load(const double* p) { return {p[0], p[1], p[2]}; }

}  // namespace enteron::skinning
