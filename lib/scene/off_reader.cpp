// SPDX-License-Identifier: Apache-2.0
// Object File Format (mesh_readers.h; the format: segeval.cs.princeton.edu/public/off_format.html
// and Geomview's OFF manual). The keyword "OFF", with the prefixes that add per-vertex data
// (ST texture coordinates, C colour, N normal: COFF, NOFF, STCNOFF...), then the vertex,
// face and edge counts, one vertex per line (x y z first) and one face per line ("n" then
// n vertex indices from 0, a colour after them). "#" starts a comment. The 4-dimensional
// and n-dimensional variants and binary OFF are refused.
#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "scene/mesh_readers.h"
#include "scene/mesh_text.h"

namespace enteron::scene {

namespace {

// The next line with a word on it, or a refusal saying what was expected.
void next_content_line(MeshText& in, const char* expected) {
    bool line = in.next_line();
    while (line && in.at_end()) line = in.next_line();
    if (!line) refuse_mesh(MeshPlace::line(in.line() + 1), std::string("the file ends before ") + expected);
}

// "OFF" with its optional prefixes ST, C, N (in that order).
bool is_off_keyword(std::string_view keyword) {
    for (std::string_view prefix : {"ST", "C", "N"})
        if (keyword.substr(0, prefix.size()) == prefix) keyword.remove_prefix(prefix.size());
    return keyword == "OFF";
}

}  // namespace

MeshSoup read_off(std::string_view text) {
    MeshText in(text, 1, '#');
    next_content_line(in, "the \"OFF\" keyword");
    const std::string_view keyword = in.word();
    if (!is_off_keyword(keyword)) {
        const bool dimensions = keyword.size() >= 3 && keyword.substr(keyword.size() - 3) == "OFF";
        in.refuse(dimensions ? "the 4-dimensional and n-dimensional OFF variants (" + MeshText::shown(keyword) +
                                   ") are not read: give 3-dimensional vertices"
                             : "not an OFF file: it must start with \"OFF\" (or COFF, NOFF...), found " +
                                   MeshText::shown(keyword));
    }
    // The counts follow the keyword on its line or on the next.
    MeshText ahead = in;
    const std::string_view after_keyword = ahead.word();
    if (after_keyword == "BINARY") in.refuse("binary OFF is not read: write the file as text");
    if (after_keyword.empty()) next_content_line(in, "the vertex, face and edge counts");
    constexpr int64_t kMostVertices = std::numeric_limits<uint32_t>::max();
    const int64_t vertices = in.integer("the vertex count", 0, kMostVertices);
    const int64_t faces = in.integer("the face count", 0, std::numeric_limits<int64_t>::max());
    if (!in.at_end()) in.integer("the edge count", 0, std::numeric_limits<int64_t>::max());
    // A vertex line takes at least 6 bytes, a face line 8.
    MeshSoup soup;
    soup.reserve(std::min<uint64_t>(vertices, text.size() / 6), std::min<uint64_t>(faces, text.size() / 8));
    for (int64_t v = 0; v < vertices; ++v) {
        next_content_line(in, ("vertex " + std::to_string(v) + " (the file declares " + std::to_string(vertices) + ")").c_str());
        const double x = in.number("the vertex's x");
        const double y = in.number("the vertex's y");
        const double z = in.number("the vertex's z");
        soup.add_vertex(x, y, z);  // normals, colours, texture coordinates after them are skipped
    }
    std::vector<uint32_t> corners;
    for (int64_t f = 0; f < faces; ++f) {
        next_content_line(in, ("face " + std::to_string(f) + " (the file declares " + std::to_string(faces) + ")").c_str());
        const int64_t count = in.integer("the face's corner count", 0, std::numeric_limits<int32_t>::max());
        corners.clear();
        for (int64_t k = 0; k < count; ++k)
            corners.push_back(static_cast<uint32_t>(in.integer("a vertex index", 0, kMostVertices)));
        soup.add_polygon(corners.data(), corners.size(), in.place());  // a colour after them is skipped
    }
    return soup;
}

}  // namespace enteron::scene
