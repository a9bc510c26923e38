// SPDX-License-Identifier: Apache-2.0
// The OFF reader (lib/scene/off_reader.cpp, mesh_readers.h): the keyword's variants, the
// counts on the keyword's line or the next, comments and blank lines, per-vertex and
// per-face data after the geometry skipped. Its refusals: tests/unit/scene/test_mesh_file.cpp.
#include <gtest/gtest.h>

#include <string>

#include "scene/mesh_readers.h"

namespace enteron::scene {
namespace {

using Indices = std::pmr::vector<uint32_t>;

TEST(OffReader, TheKeywordsVariantsAndWhereTheCountsAre) {
    const std::string body = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";  // one quad
    for (const std::string head : {"OFF\n4 1 0\n", "OFF 4 1 0\n", "OFF\n# counts\n\n4 1\n", "COFF\n4 1 0\n",
                                   "NOFF\n4 1 0\n", "STCNOFF\n4 1 0\n"}) {
        const collision::TriangleMesh mesh = read_off(head + body).finish(1.0);
        EXPECT_EQ(mesh.vertex_count(), 4u) << head;
        EXPECT_EQ(mesh.indices, (Indices{0, 1, 2, 0, 2, 3})) << head;
    }
}

TEST(OffReader, ColoursAndNormalsAfterTheGeometryAreSkipped) {
    const std::string text = "CNOFF\n3 1 3\n0 0 0  0 0 1  255 0 0 255\n1 0 0 0 0 1 0 255 0 255  # a comment\n"
                             "0 1 0 0 0 1 0 0 255 255\n3 0 1 2  0.5 0.5 0.5 1\n";
    const collision::TriangleMesh mesh = read_off(text).finish(2.0);
    EXPECT_EQ(mesh.indices, (Indices{0, 1, 2}));
    EXPECT_EQ(mesh.vertices, (std::pmr::vector<double>{0, 0, 0, 2, 0, 0, 0, 2, 0}));
}

}  // namespace
}  // namespace enteron::scene
