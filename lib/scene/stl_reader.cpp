// SPDX-License-Identifier: Apache-2.0
// STL (mesh_readers.h). Binary: an 80-byte header, a little-endian uint32 triangle count,
// then per triangle a normal and three vertices (12 float32) and a 2-byte attribute. ASCII:
// "solid name", then per triangle "facet normal nx ny nz", "outer loop", three "vertex x y
// z", "endloop", "endfacet", and "endsolid". A file is binary when its size is the one its
// count gives (some binary headers start with "solid" too), ASCII when it starts with
// "solid". The normals are skipped (the winding gives the side). Every triangle repeats its
// vertices: equal coordinates are welded into one vertex, numbered in the order they first
// appear, so that the mesh's triangles share their edges.
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <string>
#include <unordered_map>

#include "scene/mesh_readers.h"
#include "scene/mesh_text.h"

namespace enteron::scene {

namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kTriangleBytes = 50;

// The welded vertices: coordinates to their index (+0 and -0 are one coordinate).
class Welder {
public:
    explicit Welder(MeshSoup& soup) : soup_(soup) {}
    uint32_t index_of(double x, double y, double z) {
        const Key key{x + 0.0, y + 0.0, z + 0.0};
        const auto [at, added] = index_.try_emplace(key, static_cast<uint32_t>(soup_.vertex_count()));
        if (added) soup_.add_vertex(key.x, key.y, key.z);
        return at->second;
    }
    void reserve(std::size_t triangles) { index_.reserve(triangles / 2 + 3); }

private:
    struct Key {
        double x, y, z;
        bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
    };
    struct Hash {
        std::size_t operator()(const Key& k) const {
            uint64_t bits[3];
            std::memcpy(bits, &k, sizeof bits);
            uint64_t h = 0xcbf29ce484222325ull;
            for (uint64_t b : bits) h = (h ^ b) * 0x100000001b3ull;
            return static_cast<std::size_t>(h ^ (h >> 32));
        }
    };
    MeshSoup& soup_;
    std::unordered_map<Key, uint32_t, Hash> index_;
};

uint32_t little_u32(const char* at) {
    const auto* b = reinterpret_cast<const unsigned char*>(at);
    return uint32_t{b[0]} | uint32_t{b[1]} << 8 | uint32_t{b[2]} << 16 | uint32_t{b[3]} << 24;
}
float little_f32(const char* at) {
    const uint32_t bits = little_u32(at);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

void stl_reader_read_binary(std::string_view bytes, uint64_t triangles, MeshSoup& soup) {
    Welder welder(soup);
    welder.reserve(triangles);
    soup.reserve(triangles / 2 + 3, triangles);
    for (uint64_t t = 0; t < triangles; ++t) {
        const std::size_t start = kHeaderBytes + 4 + t * kTriangleBytes;
        uint32_t corners[3];
        for (int k = 0; k < 3; ++k) {
            const std::size_t at = start + 12 + 12 * k;  // after the normal
            double xyz[3];
            for (int c = 0; c < 3; ++c) {
                xyz[c] = little_f32(bytes.data() + at + 4 * c);
                if (!std::isfinite(xyz[c]))
                    refuse_mesh(MeshPlace::byte(at + 4 * c),
                                "a coordinate of triangle " + std::to_string(t) + " is not a finite number");
            }
            corners[k] = welder.index_of(xyz[0], xyz[1], xyz[2]);
        }
        soup.add_polygon(corners, 3, MeshPlace::byte(start));
    }
}

// The next line's words must be `expected` (a word "*" stands for a number, read into
// `numbers`); blank lines are skipped.
void expect_line(MeshText& in, std::initializer_list<std::string_view> expected, double* numbers = nullptr) {
    bool line = in.next_line();
    while (line && in.at_end()) line = in.next_line();
    std::string wanted;
    for (std::string_view w : expected) wanted += (wanted.empty() ? "" : " ") + std::string(w == "*" ? "<number>" : w);
    if (!line) refuse_mesh(MeshPlace::line(in.line() + 1), "the file ends where \"" + wanted + "\" should be");
    for (std::string_view w : expected) {
        if (w == "*") {
            *numbers++ = in.number("a coordinate");
            continue;
        }
        const std::string_view found = in.word();
        if (found != w) in.refuse("expected \"" + wanted + "\", found " + MeshText::shown(found));
    }
    if (!in.at_end()) in.refuse("more words than \"" + wanted + "\"");
}

void stl_reader_read_ascii(std::string_view text, MeshSoup& soup) {
    Welder welder(soup);
    MeshText in(text);
    in.next_line();  // "solid name"
    while (true) {
        bool line = in.next_line();
        while (line && in.at_end()) line = in.next_line();
        if (!line) refuse_mesh(MeshPlace::line(in.line() + 1), "the file ends without \"endsolid\"");
        const std::string_view keyword = in.word();
        if (keyword == "endsolid") break;  // the solid's name may follow
        if (keyword != "facet") in.refuse("expected \"facet\" or \"endsolid\", found " + MeshText::shown(keyword));
        if (in.word() != "normal") in.refuse("expected \"facet normal <nx> <ny> <nz>\"");
        for (int c = 0; c < 3; ++c) in.number("the facet's normal");
        if (!in.at_end()) in.refuse("more words than \"facet normal <nx> <ny> <nz>\"");
        expect_line(in, {"outer", "loop"});
        uint32_t corners[3];
        std::size_t face_line = in.line();
        for (uint32_t& corner : corners) {
            double xyz[3];
            expect_line(in, {"vertex", "*", "*", "*"}, xyz);
            corner = welder.index_of(xyz[0], xyz[1], xyz[2]);
            face_line = in.line();
        }
        expect_line(in, {"endloop"});
        expect_line(in, {"endfacet"});
        soup.add_polygon(corners, 3, MeshPlace::line(face_line));
    }
}

}  // namespace

MeshSoup read_stl(std::string_view bytes) {
    MeshSoup soup;
    if (bytes.size() >= kHeaderBytes + 4) {
        const uint64_t triangles = little_u32(bytes.data() + kHeaderBytes);
        if (bytes.size() == kHeaderBytes + 4 + triangles * kTriangleBytes) {
            stl_reader_read_binary(bytes, triangles, soup);
            return soup;
        }
    }
    MeshText first(bytes);
    if (first.next_line() && first.word() == "solid") {
        stl_reader_read_ascii(bytes, soup);
        return soup;
    }
    if (bytes.size() < kHeaderBytes + 4)
        refuse_mesh(MeshPlace::byte(0), "neither ASCII STL (starting with \"solid\") nor binary STL (" +
                                            std::to_string(bytes.size()) + " bytes, shorter than the 84-byte header)");
    const uint64_t triangles = little_u32(bytes.data() + kHeaderBytes);
    refuse_mesh(MeshPlace::byte(kHeaderBytes),
                "binary STL counts " + std::to_string(triangles) + " triangles, which take " +
                    std::to_string(kHeaderBytes + 4 + triangles * kTriangleBytes) + " bytes, but the file has " +
                    std::to_string(bytes.size()));
}

}  // namespace enteron::scene
