// SPDX-License-Identifier: Apache-2.0
#include "scene/mesh_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "scene/mesh_readers.h"

namespace enteron::scene {

namespace {

std::string extension_of(const std::string& path) {
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return "";
    std::string extension = path.substr(dot + 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace

bool mesh_format_of(const std::string& path, MeshFormat& format) {
    const std::string extension = extension_of(path);
    if (extension == "obj") format = MeshFormat::obj;
    else if (extension == "ply") format = MeshFormat::ply;
    else if (extension == "off") format = MeshFormat::off;
    else if (extension == "stl") format = MeshFormat::stl;
    else return false;
    return true;
}

collision::TriangleMesh parse_mesh(std::string_view bytes, MeshFormat format, double scale) {
    switch (format) {
        case MeshFormat::obj: return read_obj(bytes).finish(scale);
        case MeshFormat::ply: return read_ply(bytes).finish(scale);
        case MeshFormat::off: return read_off(bytes).finish(scale);
        case MeshFormat::stl: return read_stl(bytes).finish(scale);
    }
    throw Error(ErrorCode::internal, "unknown mesh format");
}

collision::TriangleMesh read_mesh_file(const std::string& path, double scale, const std::string& name,
                                       ErrorCode code) {
    const auto fail = [&](const std::string& why) { throw Error(code, name + " \"" + path + "\": " + why); };
    MeshFormat format = MeshFormat::obj;
    if (!mesh_format_of(path, format))
        fail("unknown mesh format \"." + extension_of(path) + "\" (expected .obj or .ply; .off and .stl also work)");
    std::error_code ignored;
    const std::filesystem::file_status status = std::filesystem::status(path, ignored);
    if (std::filesystem::is_directory(status)) fail("is a directory, not a mesh file");
    // A pipe or a device would block or never end: only files are read.
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        fail("is not a regular file (a pipe or a device?)");
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file.good()) fail("cannot be opened (no such file, or not readable)");
    const std::streamoff size = file.tellg();
    if (size < 0) fail("cannot be read (not a regular file)");
    std::string bytes(static_cast<std::size_t>(size), '\0');
    file.seekg(0);
    if (!file.read(bytes.data(), static_cast<std::streamsize>(bytes.size()))) fail("cannot be read");
    try {
        return parse_mesh(bytes, format, scale);
    } catch (const Error& error) {
        fail(error.what());
    }
    throw Error(ErrorCode::internal, "unreachable");
}

}  // namespace enteron::scene
