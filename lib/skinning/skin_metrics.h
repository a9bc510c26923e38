// SPDX-License-Identifier: Apache-2.0
// Accuracy of a skin's mesh against the ideal tube of radius R around the same axis.
// Used by ent_skin_metrics, the tests and the benchmarks, the same for every method.
//
// Each vertex is compared with its own axis point A(u), u being its axis parameter:
//   radius error      | |v - A(u)| - R | / R                         (RMS and max)
//   normal deviation  angle between the vertex normal and (v - A(u)) / |v - A(u)|, rad
//   inverted triangle a triangle whose normal points towards the axis as seen from the
//                     axis point of each of its three corners: the fold-over of a tube
//                     ring at a bend tighter than R
//   facet error       | |c - axis| - R | / R for each triangle's centroid c, its distance
//                     to the axis near its corners' axis points (RMS and max): how far the
//                     flat triangles depart from the tube between the vertices (the chord
//                     error of rings too far apart at a bend, or of too few segments)
//   unwanted blending a vertex within kBlendBand R of a non-neighbouring part of the
//                     axis (more than kNeighbourWindow R away in arc length): it has been
//                     pulled into the blend band of another fold (with legs 2.2 R apart a
//                     correct vertex stays >= 1.2 R from the other leg's axis)
//   watertight        every edge is shared by exactly two triangles
//   volume error      (V - pi R^2 L) / (pi R^2 L), V by the divergence theorem. Rounded
//                     ends add 4 R / (3 L) to it.
//
// Where folds meet ("another fold": the axis more than kOtherFoldArc R away along it, the
// mechanics' neighbour window; contact_profile.h):
//   overlap           how deep a vertex lies inside another fold's part of the mesh (its
//                     signed distance to the nearest of that fold's triangles, signed by
//                     the angle-weighted pseudo-normal, Baerentzen and Aanaes 2005), and the
//                     area of the triangles whose corners all lie deeper than
//                     kOverlapFloor R: surfaces passing through each other
//   tube overlap      the same inside another fold's ideal tube (radius R around its axis):
//                     how hard the folds are pressed together
//   contact gap       for a vertex inside another fold's ideal tube but outside its skin,
//                     its distance to that skin: two surfaces that should meet and do not
//   shape volume      (V - V_tube) / V_tube, V_tube the volume of the same triangles with
//                     every vertex moved onto the ideal tube (R from its own axis point, in
//                     its own direction): the volume the skin's shape adds or loses
//                     (contacts, bulges, radius error), without the facets' and caps' share
//   free radius error the radius error of the vertices where nothing may deform the tube:
//                     farther than (1 + kMaxBulgeReach) R from any other fold's axis, on a
//                     stretch of axis (R either way) bending with a radius above R
// Motion since the previous update (popping):
//   vertex motion     how far each vertex moved (with the same vertices: the same vertex;
//                     otherwise its distance to the previous mesh), and by how much that
//                     exceeds the motion of its own axis point A(u), in R
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "skinning/mesh.h"
#include "skinning/tube_radius.h"
#include "spline/arc_length.h"

namespace enteron::skinning {

constexpr double kNeighbourWindow = 4.0;  // in R: arc length beyond which axis points are another fold
constexpr double kBlendBand = 1.1;        // in R: a vertex this close to another fold's axis is blended
constexpr double kOtherFoldArc = 3.14159265358979323846;  // in R: farther along the axis, another fold (contacts)
constexpr double kOverlapFloor = 0.01;    // in R: overlap area counts triangles deeper than this

struct SkinMetrics {
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    double radius_error_rms = 0.0;  // relative to R
    double radius_error_max = 0.0;
    double facet_error_rms = 0.0;   // relative to R
    double facet_error_max = 0.0;
    std::size_t blended_vertices = 0;
    std::size_t inverted_triangles = 0;
    bool watertight = false;
    std::size_t open_edges = 0;         // edges of one triangle only
    std::size_t nonmanifold_edges = 0;  // edges of three or more triangles
    double normal_deviation_rms = 0.0;  // rad
    double normal_deviation_max = 0.0;  // rad
    double volume = 0.0;                // m^3
    double volume_error = 0.0;          // relative to pi R^2 L
    double axis_length = 0.0;           // L, m
    // Where folds meet.
    double overlap_depth_max = 0.0;       // in R, inside another fold's skin
    double overlap_area = 0.0;            // m^2
    double tube_overlap_depth_max = 0.0;  // in R, inside another fold's ideal tube
    double tube_overlap_area = 0.0;       // m^2
    double contact_gap_max = 0.0;         // in R
    double shape_volume_error = 0.0;      // relative to V_tube
    double free_radius_error_rms = 0.0;   // relative to R
    std::size_t free_vertices = 0;
    // Since the previous update (0 without one).
    double vertex_motion_max = 0.0;         // in R
    double vertex_excess_motion_max = 0.0;  // in R
};

// The mesh and the axis of the update before (for the motion measures).
struct PreviousFrame {
    const Mesh* mesh = nullptr;
    const double* points_xyz = nullptr;
    std::size_t count = 0;
    const spline::ArcLengthTable* table = nullptr;
};

// Measures `mesh` around the spline of `count` control points with arc-length table
// `table` (built on those points), and its motion since `previous` when given. Allocates
// its own work space.
SkinMetrics measure_skin(const Mesh& mesh, const double* points_xyz, std::size_t count,
                         const spline::ArcLengthTable& table, double radius, const PreviousFrame* previous = nullptr);
// The same against a tube whose radius varies `along` the axis (tube_radius.h; `radius` its
// largest): each vertex's radius error, its ideal tube point, each facet's error and the
// other folds' tubes take the radius at their own place, relative to it; the volume error
// is against pi times the integral of r^2 along the axis. The measures in R (overlaps,
// motion) and the search windows stay in the largest radius.
SkinMetrics measure_skin(const Mesh& mesh, const double* points_xyz, std::size_t count,
                         const spline::ArcLengthTable& table, double radius, const TubeRadius& along,
                         const PreviousFrame* previous = nullptr);

}  // namespace enteron::skinning
