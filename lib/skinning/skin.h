// SPDX-License-Identifier: Apache-2.0
// One interface, three methods: a skin turns the axis (spline control points) into a
// closed triangle mesh of radius R around it, for rendering. update() keeps its own copy of
// the axis it was built from, so metrics and exports describe exactly that mesh.
//
// Topology: the vertex count and the triangle indices. The tube and the convolution skins
// keep them while the axis moves when settings.stable_topology is set: their rings (a
// fixed grid of vertices, ring_grid.h) are as many as the axis' length at the first
// update holds at the ring spacing, spread evenly over the current length, so a renderer uploads the indices once and
// then only the vertex data (and u and v, fixed per vertex, only with the indices). With
// levels of detail (ring_chord_error) the ring count moves in discrete steps, with
// hysteresis (ring_placement.h). The point skeleton's marching cubes make new triangles
// every update: its topology changes every time, and it says so.
#pragma once

#include <cstddef>
#include <cstdint>
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
    // Whether the last update changed the vertex count or the indices (the first one does).
    bool topology_changed() const { return topology_changed_; }
    // Updates that changed the topology so far: equal numbers, the same indices.
    uint64_t topology_changes() const { return topology_changes_; }
    // Whether this skin keeps its topology while the axis moves (see above).
    virtual bool stable_topology() const { return settings_.stable_topology; }
    // Whether every update rebuilds every buffer of the mesh, indices included (marching
    // cubes); the ring skins rewrite the positions every update and the rest with the
    // topology.
    virtual bool rebuilds_whole_mesh() const { return false; }
    // The axis of the last update.
    const double* axis_points() const { return points_.data(); }
    std::size_t axis_count() const { return points_.size() / 3; }
    const spline::ArcLengthTable& arc_length() const { return table_; }

    // The update before the last (for the motion metrics), once there were two: its mesh
    // (positions always; indices and u as they were) and its axis. The ring skins copy
    // only the positions each update (the indices and u when they change); a skin that
    // rebuilds its whole mesh every update keeps the old one by swapping buffers.
    bool has_previous() const { return has_previous_; }
    const Mesh& previous_mesh() const { return previous_mesh_; }
    const double* previous_axis_points() const { return previous_points_.data(); }
    std::size_t previous_axis_count() const { return previous_points_.size() / 3; }
    const spline::ArcLengthTable& previous_arc_length() const { return previous_table_; }
    // Whether vertex i of the previous mesh is vertex i of this one (no topology change).
    bool same_vertices_as_previous() const { return has_previous_ && !topology_changed_; }

protected:
    // Fills mesh_ from points_ / table_, and sets topology_changed_.
    virtual void rebuild() = 0;
    // Intervals between evenly spaced rings of settings_.ring_spacing along `length` (m):
    // with stable_topology, fixed by the length of the first update;
    // otherwise as many as the current length holds.
    std::size_t ring_intervals(double length) const;

    SkinSettings settings_;
    Mesh mesh_;
    bool topology_changed_ = false;
    std::vector<double> points_;
    spline::ArcLengthTable table_;

private:
    // Keeps the mesh and axis of the last update as the previous frame.
    void keep_previous();

    uint64_t topology_changes_ = 0;
    double reference_length_ = 0.0;
    Mesh previous_mesh_;
    std::vector<double> previous_points_;
    spline::ArcLengthTable previous_table_;
    uint64_t previous_indices_of_ = ~uint64_t{0};  // topology_changes_ when previous_mesh_'s indices were copied
    bool has_previous_ = false;
};

// Makes the skin of settings.method. The settings must have been validated.
std::unique_ptr<Skin> make_skin(const SkinSettings& settings);

}  // namespace enteron::skinning
