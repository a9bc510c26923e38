// SPDX-License-Identifier: Apache-2.0
#include "skinning/mesh_writers.h"

#include <cstdint>
#include <cstring>

namespace enteron::skinning {

namespace {

template <class T>
void put_le(std::ostream& out, T value) {
    // x86-64 and aarch64 Linux are little-endian; write byte by byte to stay correct elsewhere.
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    const uint16_t probe = 1;
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    if (first == 1) {
        out.write(reinterpret_cast<const char*>(bytes), sizeof(T));
    } else {
        for (std::size_t i = sizeof(T); i-- > 0;) out.put(static_cast<char>(bytes[i]));
    }
}

}  // namespace

bool write_obj(const Mesh& mesh, std::ostream& out) {
    const std::size_t n = mesh.vertex_count();
    out << "# Enteron skin: " << n << " vertices, " << mesh.triangle_count() << " triangles, m\n";
    out.precision(9);
    for (std::size_t i = 0; i < n; ++i)
        out << "v " << mesh.positions[3 * i] << ' ' << mesh.positions[3 * i + 1] << ' ' << mesh.positions[3 * i + 2]
            << '\n';
    for (std::size_t i = 0; i < n; ++i)
        out << "vn " << mesh.normals[3 * i] << ' ' << mesh.normals[3 * i + 1] << ' ' << mesh.normals[3 * i + 2] << '\n';
    for (std::size_t i = 0; i < n; ++i) out << "vt " << mesh.u[i] << " 0\n";
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        out << 'f';
        for (int c = 0; c < 3; ++c) {
            const uint64_t index = uint64_t(mesh.indices[3 * t + c]) + 1;
            out << ' ' << index << '/' << index << '/' << index;
        }
        out << '\n';
    }
    return bool(out);
}

bool write_ply(const Mesh& mesh, std::ostream& out) {
    const std::size_t n = mesh.vertex_count();
    out << "ply\nformat binary_little_endian 1.0\ncomment Enteron skin, positions in m, u = axis parameter\n"
        << "element vertex " << n << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "property float nx\nproperty float ny\nproperty float nz\nproperty float u\n"
        << "element face " << mesh.triangle_count() << "\nproperty list uchar uint vertex_indices\nend_header\n";
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) put_le(out, mesh.positions[3 * i + c]);
        for (int c = 0; c < 3; ++c) put_le(out, mesh.normals[3 * i + c]);
        put_le(out, mesh.u[i]);
    }
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        put_le(out, uint8_t(3));
        for (int c = 0; c < 3; ++c) put_le(out, mesh.indices[3 * t + c]);
    }
    return bool(out);
}

}  // namespace enteron::skinning
