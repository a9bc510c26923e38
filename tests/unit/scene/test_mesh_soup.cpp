// SPDX-License-Identifier: Apache-2.0
// What the mesh readers collect (lib/scene/mesh_soup.h): polygons fanned into triangles from
// their first corner; a face of fewer than three corners refused where it is; a corner
// beyond the last vertex refused at the first face naming the largest one, in the file's
// numbering; no triangle at all refused; the scale applied; places said as "line N" or
// "byte N".
#include <gtest/gtest.h>

#include <string>

#include "base/error.h"
#include "refusal.h"
#include "scene/mesh_soup.h"

namespace enteron::scene {
namespace {

using unit_test::refusal;

TEST(MeshSoup, PolygonsAreFannedAndTheScaleApplied) {
    MeshSoup soup;
    for (int i = 0; i < 5; ++i) soup.add_vertex(i, 2 * i, 3 * i);
    const uint32_t pentagon[5] = {4, 0, 1, 2, 3};
    soup.add_polygon(pentagon, 5, MeshPlace::line(1));
    const collision::TriangleMesh mesh = soup.finish(0.5);
    EXPECT_EQ(mesh.indices, (std::pmr::vector<uint32_t>{4, 0, 1, 4, 1, 2, 4, 2, 3}));
    EXPECT_EQ(mesh.vertices[3 * 4 + 2], 6.0);
}

TEST(MeshSoup, BadFacesAreRefusedWhereTheyAre) {
    EXPECT_EQ(refusal([] {
                  MeshSoup soup;
                  const uint32_t two[2] = {0, 1};
                  soup.add_polygon(two, 2, MeshPlace::byte(96));
              }),
              "byte 96: a face of 2 corners (a face needs at least 3)");
    // The first face with the largest corner is named, in the file's numbering.
    EXPECT_EQ(refusal([] {
                  MeshSoup soup(1);
                  for (int i = 0; i < 3; ++i) soup.add_vertex(0, 0, i);
                  const uint32_t a[3] = {0, 1, 5}, b[3] = {5, 1, 2}, c[3] = {0, 1, 2};
                  soup.add_polygon(a, 3, MeshPlace::line(7));
                  soup.add_polygon(b, 3, MeshPlace::line(8));
                  soup.add_polygon(c, 3, MeshPlace::line(9));
                  soup.finish(1.0);
              }),
              "line 7: a face refers to vertex 6, but the file has 3 vertices (numbered from 1)");
    EXPECT_EQ(refusal([] {
                  MeshSoup soup;
                  soup.add_vertex(0, 0, 0);
                  soup.finish(1.0);
              }),
              "holds no triangle");
}

TEST(MeshSoup, AMeshBeyondTheLargestAllowedIsRefusedBeforeItIsMade) {
    MeshSoup soup;
    std::vector<uint32_t> fan(collision::kMaxMeshTriangles + 3, 0);
    EXPECT_EQ(refusal([&] { soup.add_polygon(fan.data(), fan.size(), MeshPlace::line(2)); }),
              "line 2: more than the 16777216 triangles a mesh obstacle may have");
}

}  // namespace
}  // namespace enteron::scene
