// SPDX-License-Identifier: Apache-2.0
// The OBJ reader (lib/scene/obj_reader.cpp, mesh_readers.h): the geometry of every corner
// form, negative indices, polygons fanned, the statements that carry no geometry skipped,
// numbers read exactly as strtod reads them. Its refusals: tests/unit/scene/test_mesh_file.cpp.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "scene/mesh_readers.h"

namespace enteron::scene {
namespace {

using Indices = std::pmr::vector<uint32_t>;

TEST(ObjReader, EveryCornerFormNamesTheSameVertices) {
    const std::string head = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
    for (const char* face : {"f 1 2 3", "f 1/1 2/1 3/1", "f 1//1 2//1 3//1", "f 1/1/1 2/1/1 3/1/1", "f -4 -3 -2",
                             "f 1 -3/1 3//1"}) {
        const collision::TriangleMesh mesh = read_obj(head + face + "\n").finish(1.0);
        EXPECT_EQ(mesh.indices, (Indices{0, 1, 2})) << face;
        EXPECT_EQ(mesh.vertex_count(), 4u) << "unreferenced vertices stay";
    }
}

TEST(ObjReader, APolygonIsAFanFromItsFirstCorner) {
    const collision::TriangleMesh mesh =
        read_obj("v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\n").finish(1.0);
    EXPECT_EQ(mesh.indices, (Indices{0, 1, 2, 0, 2, 3, 0, 3, 4}));
}

TEST(ObjReader, NegativeIndicesCountBackFromTheVerticesDefinedSoFar) {
    // The second face's -1 is vertex 6 (the last one then), not the file's last.
    const collision::TriangleMesh mesh =
        read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 0 0 1\nv 1 0 1\nv 0 1 1\nf -3 -2 -1\nv 9 9 9\n").finish(1.0);
    EXPECT_EQ(mesh.indices, (Indices{0, 1, 2, 3, 4, 5}));
}

TEST(ObjReader, StatementsWithoutGeometryCommentsAndLineEndsAreSkipped) {
    const std::string text =
        "# exported\r\nmtllib organ.mtl\r\no liver\r\ng lobe\r\nusemtl tissue\r\ns off\r\n"
        "v 0 0 0 1.0\r\nv 1 0 0 0.5 0.5 0.5\r\n\r\n   v\t0 1 0   # a comment\r\nvp 0.5\r\nl 1 2\r\n"
        "f 1 2 3 # the only face\r\n";
    const collision::TriangleMesh mesh = read_obj(text).finish(1.0);
    EXPECT_EQ(mesh.vertex_count(), 3u);
    EXPECT_EQ(mesh.indices, (Indices{0, 1, 2}));
    EXPECT_EQ(mesh.vertices[7], 1.0);  // the y of the vertex after the blank line
}

TEST(ObjReader, NumbersAreReadExactlyAsStrtodReadsThem) {
    const char* const numbers[] = {"0.1", "-2.5e-3", "+7", "1e-320", "123456789.123456789", "3.0000000000000004"};
    std::string text;
    for (const char* n : numbers) text += std::string("v ") + n + " " + n + " " + n + "\n";
    text += "f 1 2 3\n";
    const collision::TriangleMesh mesh = read_obj(text).finish(1.0);
    for (std::size_t i = 0; i < std::size(numbers); ++i)
        EXPECT_EQ(mesh.vertices[3 * i], std::strtod(numbers[i], nullptr)) << numbers[i];
}

}  // namespace
}  // namespace enteron::scene
