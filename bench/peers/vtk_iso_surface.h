// SPDX-License-Identifier: Apache-2.0
// VTK's iso-surface filters as peers of our marching cubes, on the same scalar field and
// grid: vtkFlyingEdges3D (Schroeder, Maynard and Geveci 2015, VTK's fastest) and
// vtkMarchingCubes (Lorensen and Cline's). Each runs on one thread (vtkSMPTools set to 1),
// without normals, gradients or scalars on its output, so that it does what ours does:
// triangles with vertices interpolated on the lattice edges.
//
// Built only when Debian's libvtk9-dev is found (ENTERON_BENCH_VTK,
// `scripts/install-deps --with-peers`).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace enteron::peers {

// A scalar field on a dense lattice: value of corner (i, j, k) at
// values[i + nx * (j + ny * k)], at origin + spacing * (i, j, k).
struct DenseField {
    int nx = 0, ny = 0, nz = 0;
    double origin[3] = {0.0, 0.0, 0.0};
    double spacing = 1.0;  // m
    std::vector<float> values;
    std::size_t cells() const { return std::size_t(nx - 1) * std::size_t(ny - 1) * std::size_t(nz - 1); }
};

enum class VtkFilter { flying_edges, marching_cubes };
const char* vtk_filter_name(VtkFilter filter);

class VtkIsoSurface {
public:
    // Wraps `field` (not copied: it must outlive this object) for the filter.
    VtkIsoSurface(const DenseField& field, double iso, VtkFilter filter);
    ~VtkIsoSurface();
    VtkIsoSurface(const VtkIsoSurface&) = delete;
    VtkIsoSurface& operator=(const VtkIsoSurface&) = delete;

    // Runs the filter once on the field; returns the number of triangles made.
    std::size_t run();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace enteron::peers
