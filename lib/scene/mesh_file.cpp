#include "scene/mesh_file.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <vector>

namespace enteron::scene {

namespace {
using Point = CGAL::Simple_cartesian<double>::Point_3;

std::string extension_of(const std::string& path) {
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return "";
    std::string extension = path.substr(dot + 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}
}  // namespace

collision::TriangleMesh read_mesh_file(const std::string& path, double scale, const std::string& name,
                                       ErrorCode code) {
    const auto fail = [&](const std::string& why) { throw Error(code, name + " \"" + path + "\": " + why); };
    const std::string extension = extension_of(path);
    if (extension != "obj" && extension != "ply" && extension != "off" && extension != "stl")
        fail("unknown mesh format \"." + extension + "\" (expected .obj or .ply; .off and .stl also work)");
    if (!std::ifstream(path).good()) fail("cannot be opened (no such file, or not readable)");
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    bool read = false;
    try {
        read = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
    } catch (const std::exception& error) {
        fail(std::string("is not a readable mesh (") + error.what() + ")");
    }
    if (!read) fail("is not a readable " + extension + " mesh");
    collision::TriangleMesh mesh;
    mesh.vertices.reserve(3 * points.size());
    for (const Point& p : points)
        for (int c = 0; c < 3; ++c) mesh.vertices.push_back(scale * p[c]);
    for (const std::vector<std::size_t>& polygon : polygons) {
        for (std::size_t k = 0; k < polygon.size(); ++k)
            if (polygon[k] >= points.size()) fail("a face refers to vertex " + std::to_string(polygon[k]) +
                                                  " of " + std::to_string(points.size()));
        for (std::size_t k = 2; k < polygon.size(); ++k)
            for (std::size_t corner : {polygon[0], polygon[k - 1], polygon[k]})
                mesh.indices.push_back(static_cast<uint32_t>(corner));
    }
    if (mesh.indices.empty()) fail("holds no triangle");
    return mesh;
}

}  // namespace enteron::scene
