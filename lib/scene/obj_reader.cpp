// SPDX-License-Identifier: Apache-2.0
// Wavefront OBJ (mesh_readers.h): a statement per line, "#" starts a comment. Only "v" and
// "f" carry the geometry; the other statements of the format (texture coordinates, normals,
// groups, materials, free-form surfaces) are skipped, and anything else is refused with its
// line, so that a file of another format named .obj says so at its first line.
#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "scene/mesh_readers.h"
#include "scene/mesh_text.h"

namespace enteron::scene {

namespace {

// The statements of the OBJ format that hold no triangle geometry.
constexpr std::string_view kSkipped[] = {
    "vt", "vn", "vp", "o", "g", "s", "mg", "usemtl", "mtllib", "usemap", "maplib", "l", "p", "cstype", "deg",
    "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con", "lod",
    "shadow_obj", "trace_obj", "ctech", "stech", "bevel", "c_interp", "d_interp"};

// A face's corner "i", "i/t", "i//n" or "i/t/n": its vertex index i as written (from 1, or
// negative from the end), checked to be a whole number; the texture and normal indices
// are skipped but must be numbers too.
int64_t corner_index(std::string_view corner, MeshText& in) {
    const std::size_t slash = corner.find('/');
    const std::string_view vertex = corner.substr(0, slash);
    int64_t index = 0;
    bool ok = MeshText::parse(vertex, index);
    if (ok && slash != std::string_view::npos) {
        const std::string_view rest = corner.substr(slash + 1);
        const std::size_t second = rest.find('/');
        const std::string_view texture = rest.substr(0, second);
        int64_t ignored = 0;
        ok = texture.empty() ? second != std::string_view::npos : MeshText::parse(texture, ignored);
        if (ok && second != std::string_view::npos) ok = MeshText::parse(rest.substr(second + 1), ignored);
    }
    if (!ok)
        in.refuse("a face's corner " + MeshText::shown(corner) +
                  " is not a vertex index (i, i/t, i//n or i/t/n, whole numbers)");
    return index;
}

}  // namespace

MeshSoup read_obj(std::string_view text) {
    MeshSoup soup(1);
    // About 30 bytes per vertex and per face line; two faces per vertex in a closed mesh.
    soup.reserve(text.size() / 90, text.size() / 45);
    MeshText in(text, 1, '#');
    std::vector<uint32_t> corners;
    while (in.next_line()) {
        const std::string_view statement = in.word();
        if (statement.empty()) continue;
        if (statement == "v") {
            const double x = in.number("the vertex's x");
            const double y = in.number("the vertex's y");
            const double z = in.number("the vertex's z");
            soup.add_vertex(x, y, z);  // a w or a colour after them is skipped
        } else if (statement == "f") {
            corners.clear();
            for (std::string_view corner = in.word(); !corner.empty(); corner = in.word()) {
                const int64_t index = corner_index(corner, in);
                const int64_t defined = static_cast<int64_t>(soup.vertex_count());
                if (index == 0) in.refuse("a face refers to vertex 0 (OBJ counts vertices from 1)");
                if (index < 0 && -index > defined)
                    in.refuse("a face refers to vertex " + std::to_string(index) + " (counted back from the last), but " +
                              std::to_string(defined) + " vertices precede it");
                if (index > int64_t{std::numeric_limits<uint32_t>::max()})
                    in.refuse("a face refers to vertex " + std::to_string(index) + ", beyond any mesh");
                corners.push_back(static_cast<uint32_t>(index > 0 ? index - 1 : defined + index));
            }
            soup.add_polygon(corners.data(), corners.size(), in.place());
        } else if (std::find(std::begin(kSkipped), std::end(kSkipped), statement) == std::end(kSkipped)) {
            in.refuse(MeshText::shown(statement) + " is not an OBJ statement (v, f, vt, vn, g, o, usemtl, ...)");
        }
    }
    return soup;
}

}  // namespace enteron::scene
