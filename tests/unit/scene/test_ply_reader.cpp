// SPDX-License-Identifier: Apache-2.0
// The PLY reader (lib/scene/ply_reader.cpp, mesh_readers.h): the same mesh written as ASCII,
// binary little-endian and binary big-endian, with the coordinates as float and as double,
// with properties and elements the mesh does not use between the ones it does, reads the
// same; float properties are floats; a face element before the vertex element works. Its
// refusals: tests/unit/scene/test_mesh_file.cpp.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "base/error.h"
#include "scene/mesh_readers.h"

namespace enteron::scene {
namespace {

using Indices = std::pmr::vector<uint32_t>;

// A pyramid: a square base (one quad) and four triangles.
const double kVertices[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0.7}};
const std::vector<std::vector<int>> kFaces = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};

template <class T>
void ply_reader_put(std::string& out, T value, bool big_endian) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (big_endian)
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    out.append(raw, sizeof(T));
}

// The pyramid as PLY: `format` ascii, binary_little_endian or binary_big_endian; `real` the
// coordinates' type (float or double). Each vertex has a colour between y and z, each face
// a quality after its list, and an "edge" element lies between the two.
std::string pyramid(const std::string& format, const std::string& real, bool faces_first = false) {
    std::string vertex_decl = "element vertex 5\nproperty " + real + " x\nproperty " + real +
                              " y\nproperty uchar red\nproperty " + real + " z\n";
    std::string face_decl = "element face 5\nproperty list uchar int vertex_indices\nproperty float quality\n";
    const std::string edge_decl = "element edge 1\nproperty int vertex1\nproperty list uchar int more\n";
    std::string out = "ply\nformat " + format + " 1.0\ncomment made by a test\nobj_info nothing\n" +
                      (faces_first ? face_decl + edge_decl + vertex_decl : vertex_decl + edge_decl + face_decl) +
                      "end_header\n";
    std::string vertices, faces, edges;
    const bool binary = format != "ascii", big = format == "binary_big_endian";
    for (const auto& v : kVertices) {
        if (!binary) {
            vertices += std::to_string(v[0]) + " " + std::to_string(v[1]) + " 255 " + std::to_string(v[2]) + "\n";
        } else if (real == "float") {
            ply_reader_put<float>(vertices, float(v[0]), big), ply_reader_put<float>(vertices, float(v[1]), big);
            ply_reader_put<uint8_t>(vertices, 255, big), ply_reader_put<float>(vertices, float(v[2]), big);
        } else {
            ply_reader_put<double>(vertices, v[0], big), ply_reader_put<double>(vertices, v[1], big);
            ply_reader_put<uint8_t>(vertices, 255, big), ply_reader_put<double>(vertices, v[2], big);
        }
    }
    for (const auto& f : kFaces) {
        if (!binary) {
            faces += std::to_string(f.size());
            for (int i : f) faces += " " + std::to_string(i);
            faces += " 0.5\n";
        } else {
            ply_reader_put<uint8_t>(faces, uint8_t(f.size()), big);
            for (int i : f) ply_reader_put<int32_t>(faces, i, big);
            ply_reader_put<float>(faces, 0.5f, big);
        }
    }
    if (!binary) edges = "0 2 1 2\n";
    else ply_reader_put<int32_t>(edges, 0, big), ply_reader_put<uint8_t>(edges, 2, big), ply_reader_put<int32_t>(edges, 1, big), ply_reader_put<int32_t>(edges, 2, big);
    return out + (faces_first ? faces + edges + vertices : vertices + edges + faces);
}

void expect_pyramid(const collision::TriangleMesh& mesh, const std::string& what) {
    ASSERT_EQ(mesh.vertex_count(), 5u) << what;
    for (std::size_t i = 0; i < 5; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(mesh.vertices[3 * i + c], kVertices[i][c], 1e-6) << what;
    EXPECT_EQ(mesh.indices, (Indices{0, 3, 2, 0, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4})) << what;
}

TEST(PlyReader, AsciiAndBinaryInEitherByteOrderReadTheSameMesh) {
    for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"})
        for (const char* real : {"float", "double"}) {
            expect_pyramid(read_ply(pyramid(format, real)).finish(1.0), std::string(format) + " " + real);
            expect_pyramid(read_ply(pyramid(format, real, true)).finish(1.0), std::string(format) + " faces first");
        }
}

TEST(PlyReader, AFloatPropertyIsAFloatAndADoubleADouble) {
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty TYPE x\nproperty TYPE y\n"
                             "property TYPE z\nelement face 1\nproperty list uchar uint vertex_index\nend_header\n";
    const std::string body = "0.1 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    for (const std::string type : {"float", "float32", "double", "float64", "int"}) {
        std::string text = head;
        for (std::size_t at = text.find("TYPE"); at != std::string::npos; at = text.find("TYPE")) text.replace(at, 4, type);
        if (type == "int") {
            EXPECT_THROW(read_ply(text + body), Error) << "0.1 is not an int";
            continue;
        }
        const double x = read_ply(text + body).finish(1.0).vertices[0];
        EXPECT_EQ(x, type.rfind("float", 0) == 0 && type != "float64" ? double(0.1f) : 0.1) << type;
    }
}

TEST(PlyReader, BlankLinesAndWindowsLineEndsAreRead) {
    std::string text = pyramid("ascii", "double");
    std::string crlf;
    for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    expect_pyramid(read_ply(crlf).finish(1.0), "CRLF");
}

}  // namespace
}  // namespace enteron::scene
