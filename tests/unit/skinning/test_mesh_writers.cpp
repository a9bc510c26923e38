// SPDX-License-Identifier: Apache-2.0
// The OBJ and PLY writers (lib/skinning/mesh_writers.h) describe the mesh.
#include "skinning/mesh_writers.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>
#include <string>

#include "skinning/skin.h"
#include "skinning/skin_axes.h"
#include "skinning/skin_fixtures.h"

namespace {

using namespace skin_test;
using namespace enteron::skinning;

TEST(MeshWriters, ObjAndPlyDescribeTheMesh) {
    auto skin = make_skin(defaults(SkinMethod::tube));
    const auto q = skin_test::straight_axis(5, 0.025);
    skin->update(q.data(), q.size() / 3);
    const Mesh& mesh = skin->mesh();

    std::ostringstream obj;
    ASSERT_TRUE(write_obj(mesh, obj));
    std::istringstream lines(obj.str());
    std::string line;
    std::size_t v = 0, f = 0;
    double last_x = 0.0;
    while (std::getline(lines, line)) {
        if (line.rfind("v ", 0) == 0) {
            ++v;
            last_x = std::stod(line.substr(2));
        }
        if (line.rfind("f ", 0) == 0) ++f;
    }
    EXPECT_EQ(v, mesh.vertex_count());
    EXPECT_EQ(f, mesh.triangle_count());
    EXPECT_FLOAT_EQ(float(last_x), mesh.positions[3 * (mesh.vertex_count() - 1)]);

    std::ostringstream ply;
    ASSERT_TRUE(write_ply(mesh, ply));
    const std::string text = ply.str();
    const std::size_t header = text.find("end_header\n") + std::strlen("end_header\n");
    EXPECT_NE(text.find("element vertex " + std::to_string(mesh.vertex_count())), std::string::npos);
    EXPECT_EQ(text.size() - header, mesh.vertex_count() * 7 * 4 + mesh.triangle_count() * (1 + 3 * 4));
    float x0;
    std::memcpy(&x0, text.data() + header, 4);
    EXPECT_EQ(x0, mesh.positions[0]);
}

}  // namespace
