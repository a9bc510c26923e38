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
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "skinning/mesh.h"
#include "spline/arc_length.h"

namespace enteron::skinning {

constexpr double kNeighbourWindow = 4.0;  // in R: arc length beyond which axis points are another fold
constexpr double kBlendBand = 1.1;        // in R: a vertex this close to another fold's axis is blended

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
};

// Measures `mesh` around the spline of `count` control points with arc-length table
// `table` (built on those points). Allocates its own work space.
SkinMetrics measure_skin(const Mesh& mesh, const double* points_xyz, std::size_t count,
                         const spline::ArcLengthTable& table, double radius);

}  // namespace enteron::skinning
