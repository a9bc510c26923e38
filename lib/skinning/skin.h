// One interface, three methods: a skin turns the axis (spline control points) into a
// closed triangle mesh of radius R around it, for rendering. update() keeps its own copy of
// the axis it was built from, so metrics and exports describe exactly that mesh.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "skinning/mesh.h"
#include "skinning/skin_settings.h"
#include "spline/arc_length.h"

namespace enteron::skinning {

class Skin {
public:
    explicit Skin(const SkinSettings& settings) : settings_(settings) {}
    virtual ~Skin() = default;
    Skin(const Skin&) = delete;
    Skin& operator=(const Skin&) = delete;

    // Rebuilds the mesh around the spline of `count` (>= 4) control points, x y z each.
    // Reuses every buffer: no allocation once the largest mesh has been seen.
    void update(const double* points_xyz, std::size_t count);

    const Mesh& mesh() const { return mesh_; }
    const SkinSettings& settings() const { return settings_; }
    // The axis of the last update.
    const double* axis_points() const { return points_.data(); }
    std::size_t axis_count() const { return points_.size() / 3; }
    const spline::ArcLengthTable& arc_length() const { return table_; }

protected:
    // Fills mesh_ from points_ / table_.
    virtual void rebuild() = 0;

    SkinSettings settings_;
    Mesh mesh_;
    std::vector<double> points_;
    spline::ArcLengthTable table_;
};

// Makes the skin of settings.method. The settings must have been validated.
std::unique_ptr<Skin> make_skin(const SkinSettings& settings);

}  // namespace enteron::skinning
