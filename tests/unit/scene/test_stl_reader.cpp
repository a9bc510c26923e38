// SPDX-License-Identifier: Apache-2.0
// The STL reader (lib/scene/stl_reader.cpp, mesh_readers.h): ASCII and binary (also a binary
// file whose header starts with "solid") read the same mesh; the vertices every triangle
// repeats are welded into one, numbered as they first appear, so the triangles share their
// edges. Its refusals: tests/unit/scene/test_mesh_file.cpp.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "scene/mesh_readers.h"

namespace enteron::scene {
namespace {

using Indices = std::pmr::vector<uint32_t>;

// A tetrahedron, normals out.
const float kCorners[4][3][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}},
                                 {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
                                 {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                 {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

std::string ascii_tetrahedron() {
    std::string out = "solid tetrahedron\n";
    for (const auto& t : kCorners) {
        out += "  facet normal 0 0 0\n    outer loop\n";
        for (const auto& v : t)
            out += "      vertex " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
        out += "    endloop\n  endfacet\n";
    }
    return out + "endsolid tetrahedron\n";
}

std::string binary_tetrahedron(const std::string& header) {
    std::string out = header;
    out.resize(80, '\0');
    const uint32_t count = 4;
    out.append(reinterpret_cast<const char*>(&count), 4);
    for (const auto& t : kCorners) {
        const float normal[3] = {0, 0, 0};
        out.append(reinterpret_cast<const char*>(normal), sizeof normal);
        out.append(reinterpret_cast<const char*>(t), 36);
        out.append(2, '\0');
    }
    return out;
}

void expect_tetrahedron(const collision::TriangleMesh& mesh, const char* what) {
    // Welded: 4 vertices in the order they first appear (0,0,0), (0,1,0), (1,0,0), (0,0,1).
    EXPECT_EQ(mesh.vertices, (std::pmr::vector<double>{0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1})) << what;
    EXPECT_EQ(mesh.indices, (Indices{0, 1, 2, 0, 2, 3, 0, 3, 1, 2, 1, 3})) << what;
}

TEST(StlReader, AsciiAndBinaryReadTheSameWeldedMesh) {
    expect_tetrahedron(read_stl(ascii_tetrahedron()).finish(1.0), "ASCII");
    expect_tetrahedron(read_stl(binary_tetrahedron("made by a test")).finish(1.0), "binary");
    expect_tetrahedron(read_stl(binary_tetrahedron("solid but binary")).finish(1.0), "binary, header 'solid'");
}

TEST(StlReader, MinusZeroAndZeroAreOneVertex) {
    std::string text = ascii_tetrahedron();
    const std::size_t first = text.find("vertex 0.000000 0.000000 0.000000");
    text.replace(first, 33, "vertex -0.0 0.000000 -0");
    expect_tetrahedron(read_stl(text).finish(1.0), "-0");
}

}  // namespace
}  // namespace enteron::scene
