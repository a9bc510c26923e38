// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: arbitrary bytes as a mesh file (lib/scene/mesh_readers.h). The first
// byte picks the format (% 4: OBJ, PLY, OFF, STL), the rest is the file. Every input must be
// read into a mesh whose indices name its vertices and whose coordinates are finite, or be
// refused with a message that says where ("line N: ", "byte N: ") or "holds no triangle";
// never a crash, a hang, a leak or an allocation the file's size does not justify.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "base/error.h"
#include "scene/mesh_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using enteron::scene::MeshFormat;
    if (size == 0) return 0;
    const MeshFormat formats[] = {MeshFormat::obj, MeshFormat::ply, MeshFormat::off, MeshFormat::stl};
    const MeshFormat format = formats[data[0] % 4];
    const std::string_view file(reinterpret_cast<const char*>(data) + 1, size - 1);
    try {
        const enteron::collision::TriangleMesh mesh = enteron::scene::parse_mesh(file, format, 1.0);
        if (mesh.triangle_count() == 0 || mesh.triangle_count() > enteron::collision::kMaxMeshTriangles) std::abort();
        for (uint32_t index : mesh.indices)
            if (index >= mesh.vertex_count()) std::abort();
        for (double coordinate : mesh.vertices)
            if (!std::isfinite(coordinate)) std::abort();
    } catch (const enteron::Error& error) {
        const std::string message = error.what();
        if (error.code() != enteron::ErrorCode::invalid_argument) std::abort();
        if (message.rfind("line ", 0) != 0 && message.rfind("byte ", 0) != 0 && message != "holds no triangle")
            std::abort();  // a refusal says where
    }
    return 0;
}
