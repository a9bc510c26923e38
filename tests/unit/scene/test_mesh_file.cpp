// SPDX-License-Identifier: Apache-2.0
// Reading a mesh file (lib/scene/mesh_file.h): every broken file of the table below is
// refused with the scene's name for it, its path, and the line (in binary data the byte
// offset) and what is wrong there, each message checked whole; the files a scene names
// are read whatever the case of their extension.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "base/error.h"
#include "refusal.h"
#include "scene/mesh_file.h"

namespace enteron::scene {
namespace {

// Binary data: `count` values of type T in little-endian order appended to `out`.
template <class T>
void put(std::string& out, std::initializer_list<T> values) {
    for (T v : values) {
        char raw[sizeof(T)];
        std::memcpy(raw, &v, sizeof(T));
        out.append(raw, sizeof(T));
    }
}

std::string write_file(const std::string& name, const std::string& bytes) {
    const std::string path = ::testing::TempDir() + "enteron_mesh_file_" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

// The message read_mesh_file gives for the file `name` holding `bytes`.
std::string refusal(const std::string& name, const std::string& bytes, std::string* path_out) {
    const std::string path = write_file(name, bytes);
    *path_out = path;
    return unit_test::refusal([&] { read_mesh_file(path, 1.0, "environment[3].file", ErrorCode::invalid_scene); },
                              ErrorCode::invalid_scene);
}

const std::string kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
const std::string kPlyHead = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string kPlyVertices = "0 0 0\n1 0 0\n0 1 0\n";

// A binary PLY of three vertices (float x y z) and one face (uchar count, int indices).
std::string binary_ply(float y1, std::initializer_list<int32_t> face, uint8_t corners = 3, bool cut = false) {
    std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    put<float>(out, {0, 0, 0, 1, y1, 0, 0, 1, 0});
    if (cut) return out.substr(0, out.size() - 6);
    put<uint8_t>(out, {corners});
    for (int32_t i : face) put<int32_t>(out, {i});
    return out;
}
// The byte where binary_ply's data starts.
std::size_t binary_ply_body() { return binary_ply(0, {}).size() - 9 * 4 - 1; }

// A binary STL of one triangle whose header claims `count`.
std::string binary_stl(uint32_t count, float x = 0.0f) {
    std::string out(80, ' ');
    put<uint32_t>(out, {count});
    put<float>(out, {0, 0, 1, x, 0, 0, 1, 0, 0, 0, 1, 0});
    out.append(2, '\0');
    return out;
}

struct Broken {
    const char* name;  // the file's name (its extension picks the reader)
    std::string bytes;
    std::string why;   // what follows `environment[3].file "<path>": `
};

TEST(MeshFile, EveryBrokenFileIsRefusedNamingItsLineAndWhatIsWrong) {
    const std::size_t body = binary_ply_body();
    const std::vector<Broken> table = {
        // OBJ
        {"face_beyond.obj", kTriangleObj + "f 1 2 4\n",
         "line 4: a face refers to vertex 4, but the file has 3 vertices (numbered from 1)"},
        {"face_before.obj", "f 1 2 9\n" + kTriangleObj + "f 1 2 3\n",
         "line 1: a face refers to vertex 9, but the file has 3 vertices (numbered from 1)"},
        {"short_vertex.obj", "v 0 0 0\nv 1 0\n", "line 2: expected the vertex's z, found the end of the line"},
        {"word_vertex.obj", "# a comment\n\nv 0 0 zero\n",
         "line 3: expected the vertex's z, a finite number, found \"zero\""},
        {"nan_vertex.obj", "v nan 0 0\n", "line 1: expected the vertex's x, a finite number, found \"nan\""},
        {"huge_vertex.obj", "v 0 1e999 0\n", "line 1: expected the vertex's y, a finite number, found \"1e999\""},
        {"zero_index.obj", kTriangleObj + "f 0 1 2\n", "line 4: a face refers to vertex 0 (OBJ counts vertices from 1)"},
        {"back_too_far.obj", kTriangleObj + "f -1 -2 -4\n",
         "line 4: a face refers to vertex -4 (counted back from the last), but 3 vertices precede it"},
        {"two_corners.obj", kTriangleObj + "f 1 2\r\n", "line 4: a face of 2 corners (a face needs at least 3)"},
        {"bad_corner.obj", kTriangleObj + "f 1/x/2 2 3\n",
         "line 4: a face's corner \"1/x/2\" is not a vertex index (i, i/t, i//n or i/t/n, whole numbers)"},
        {"half_corner.obj", kTriangleObj + "f 1/ 2 3\n",
         "line 4: a face's corner \"1/\" is not a vertex index (i, i/t, i//n or i/t/n, whole numbers)"},
        {"ply_named.obj", kPlyHead + kPlyVertices + "3 0 1 2\n",
         "line 1: \"ply\" is not an OBJ statement (v, f, vt, vn, g, o, usemtl, ...)"},
        {"binary.obj", std::string("\x01\x02\x7f", 3) + "\n",
         "line 1: \"\\x01\\x02\\x7f\" is not an OBJ statement (v, f, vt, vn, g, o, usemtl, ...)"},
        {"points.obj", "# vertices only\n" + kTriangleObj, "holds no triangle"},
        {"empty.obj", "", "holds no triangle"},
        // PLY, the header
        {"not.ply", "plyx\n", "line 1: not a PLY file: its first line must be \"ply\""},
        {"version.ply", "ply\nformat ascii 2.0\n", "line 2: only version 1.0 of the PLY format is read"},
        {"encoding.ply", "ply\nformat utf8 1.0\n",
         "line 2: the format \"utf8\" is not ascii, binary_little_endian or binary_big_endian"},
        {"type.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty flaot x\n",
         "line 4: \"flaot\" is not a PLY type (char, uchar, short, ushort, int, uint, float, double)"},
        {"orphan.ply", "ply\nformat ascii 1.0\nproperty float x\n", "line 3: a property before any element"},
        {"keyword.ply", "ply\nformat ascii 1.0\nelemnt vertex 3\n",
         "line 3: \"elemnt\" is not a PLY header line (format, element, property, comment, end_header)"},
        {"count.ply", "ply\nformat ascii 1.0\nelement vertex many\n",
         "line 3: expected the element's count, a whole number, found \"many\""},
        {"unended.ply", "ply\nformat ascii 1.0\nelement vertex 3\n",
         "line 3: the header ends without an \"end_header\" line"},
        {"no_format.ply", "ply\nelement vertex 0\nend_header\n", "line 3: the header has no \"format\" line"},
        {"cloud.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                      "end_header\n0 0 0\n",
         "line 7: the header ends without declaring a \"face\" element (a point cloud is not a mesh)"},
        {"no_z.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nelement face 0\n"
                     "property list uchar int vertex_indices\nend_header\n",
         "line 3: the vertex element has no scalar property \"z\""},
        {"no_indices.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 0\nproperty list uchar int vertex_list\nend_header\n",
         "line 7: the face element has no list property \"vertex_indices\" (or \"vertex_index\")"},
        {"float_indices.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                              "property float z\nelement face 0\nproperty list uchar float vertex_indices\nend_header\n",
         "line 7: the face element's vertex indices must have an integer type"},
        // PLY, ASCII data (kPlyHead ends on line 9)
        {"short_line.ply", kPlyHead + "0 0 0\n1 0\n", "line 11: expected the vertex's z, found the end of the line"},
        {"long_line.ply", kPlyHead + "0 0 0 5\n", "line 10: more values than the 3 properties of a vertex"},
        {"word.ply", kPlyHead + "0 0 0\n1 zero 0\n",
         "line 11: expected the vertex's y, a finite number, found \"zero\""},
        {"ends.ply", kPlyHead + kPlyVertices, "line 13: the file ends before face 0 (it declares 1)"},
        {"beyond.ply", kPlyHead + kPlyVertices + "3 0 1 7\n",
         "line 13: a face refers to vertex 7, but the file has 3 vertices (numbered from 0)"},
        {"negative.ply", kPlyHead + kPlyVertices + "3 0 -1 2\n",
         "line 13: a face refers to vertex -1, which no mesh has"},
        {"two.ply", kPlyHead + kPlyVertices + "2 0 1\n", "line 13: a face of 2 corners (a face needs at least 3)"},
        {"list_short.ply", kPlyHead + kPlyVertices + "4 0 1 2\n",
         "line 13: expected a vertex index, found the end of the line"},
        // PLY, binary data: byte offsets
        {"cut.ply", binary_ply(0, {0, 1, 2}, 3, true),
         "byte " + std::to_string(body + 24) + ": the file ends inside vertex 2 (it declares 3)"},
        {"nan.ply", binary_ply(std::nanf(""), {0, 1, 2}),
         "byte " + std::to_string(body + 16) + ": the vertex's y of vertex 1 is not a finite number"},
        {"beyond_binary.ply", binary_ply(0, {0, 1, 9}),
         "byte " + std::to_string(body + 36) + ": a face refers to vertex 9, but the file has 3 vertices (numbered from 0)"},
        {"negative_binary.ply", binary_ply(0, {0, -5, 1}),
         "byte " + std::to_string(body + 41) + ": a face refers to vertex -5, which no mesh has"},
        {"long_list.ply", binary_ply(0, {0, 1, 2}, 200),
         "byte " + std::to_string(body + 36) + ": a list of face 0 has 200 items, past the end of the file"},
        {"one_corner.ply", binary_ply(0, {0}, 1),
         "byte " + std::to_string(body + 36) + ": a face of 1 corner (a face needs at least 3)"},
        // OFF
        {"not.off", "OFX\n", "line 1: not an OFF file: it must start with \"OFF\" (or COFF, NOFF...), found \"OFX\""},
        {"four.off", "4OFF\n1 1 0\n",
         "line 1: the 4-dimensional and n-dimensional OFF variants (\"4OFF\") are not read: give 3-dimensional vertices"},
        {"binary.off", "OFF BINARY\n", "line 1: binary OFF is not read: write the file as text"},
        {"counts.off", "OFF\n# counts next\n3\n", "line 3: expected the face count, found the end of the line"},
        {"vertices.off", "OFF 3 1 0\n0 0 0\n1 0 0\n", "line 4: the file ends before vertex 2 (the file declares 3)"},
        {"beyond.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
         "line 6: a face refers to vertex 3, but the file has 3 vertices (numbered from 0)"},
        {"negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
         "line 6: a vertex index is -1, not in [0, 4294967295]"},
        // STL
        {"short.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\n",
         "line 5: expected a coordinate, found the end of the line"},
        {"no_endloop.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendfacet\n",
         "line 7: expected \"endloop\", found \"endfacet\""},
        {"no_endsolid.stl", "solid x\n\n", "line 3: the file ends without \"endsolid\""},
        {"facet.stl", "solid x\nfacte normal 0 0 1\n", "line 2: expected \"facet\" or \"endsolid\", found \"facte\""},
        {"empty.stl", "solid x\nendsolid x\n", "holds no triangle"},
        {"count.stl", binary_stl(3),
         "byte 80: binary STL counts 3 triangles, which take 234 bytes, but the file has 134"},
        {"tiny.stl", "12345",
         "byte 0: neither ASCII STL (starting with \"solid\") nor binary STL (5 bytes, shorter than the 84-byte header)"},
        {"nan.stl", binary_stl(1, std::nanf("")), "byte 96: a coordinate of triangle 0 is not a finite number"},
        // Any format
        {"model.dae", "<COLLADA/>", "unknown mesh format \".dae\" (expected .obj or .ply; .off and .stl also work)"},
    };
    for (const Broken& b : table) {
        std::string path;
        const std::string message = refusal(b.name, b.bytes, &path);
        EXPECT_EQ(message, "environment[3].file \"" + path + "\": " + b.why) << b.name;
        std::remove(path.c_str());
    }
}

TEST(MeshFile, AMissingFileADirectoryAndAPipeAreNamed) {
    const std::string missing = ::testing::TempDir() + "enteron_mesh_file_no_such.obj";
    EXPECT_EQ(unit_test::refusal([&] { read_mesh_file(missing, 1.0, "liver", ErrorCode::invalid_argument); }),
              "liver \"" + missing + "\": cannot be opened (no such file, or not readable)");
    const std::string directory = ::testing::TempDir() + "enteron_mesh_file_dir.obj";
    ASSERT_EQ(std::system(("mkdir -p " + directory).c_str()), 0);
    EXPECT_EQ(unit_test::refusal([&] { read_mesh_file(directory, 1.0, "liver", ErrorCode::invalid_argument); }),
              "liver \"" + directory + "\": is a directory, not a mesh file");
    const std::string pipe = ::testing::TempDir() + "enteron_mesh_file_pipe.obj";
    std::remove(pipe.c_str());
    ASSERT_EQ(std::system(("mkfifo " + pipe).c_str()), 0);
    EXPECT_EQ(unit_test::refusal([&] { read_mesh_file(pipe, 1.0, "liver", ErrorCode::invalid_argument); }),
              "liver \"" + pipe + "\": is not a regular file (a pipe or a device?)")
        << "refused, not waited on";
    std::remove(pipe.c_str());
}

TEST(MeshFile, TheExtensionPicksTheReaderWhateverItsCaseAndTheScaleApplies) {
    const std::string path = write_file("upper.OBJ", kTriangleObj + "f 1 2 3\n");
    const collision::TriangleMesh mesh = read_mesh_file(path, 0.001, "organ", ErrorCode::invalid_scene);
    ASSERT_EQ(mesh.vertex_count(), 3u);
    EXPECT_DOUBLE_EQ(mesh.vertices[3], 0.001);
    EXPECT_EQ(mesh.indices, (std::pmr::vector<uint32_t>{0, 1, 2}));
    std::remove(path.c_str());
    MeshFormat format = MeshFormat::obj;
    EXPECT_TRUE(mesh_format_of("a/b.Ply", format));
    EXPECT_EQ(format, MeshFormat::ply);
    EXPECT_TRUE(mesh_format_of("x.STL", format));
    EXPECT_EQ(format, MeshFormat::stl);
    EXPECT_TRUE(mesh_format_of("x.off", format));
    EXPECT_EQ(format, MeshFormat::off);
    EXPECT_FALSE(mesh_format_of("organs.d/liver", format));  // the dot is the directory's
    EXPECT_FALSE(mesh_format_of("liver", format));
}

}  // namespace
}  // namespace enteron::scene
