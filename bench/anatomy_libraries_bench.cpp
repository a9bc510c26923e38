// SPDX-License-Identifier: Apache-2.0
// The candidate libraries for organ meshes (issue 20, docs/anatomy.md "Library"), measured
// against each other on the same closed ellipsoid organ (20 x 14 x 10 cm) of 10k, 100k and
// 1M triangles, one thread each:
//  - closest-point structures: Embree's BVH with a point query (what libenteron uses,
//    collision/triangle_bvh.h), CGAL's AABB tree (closest_point_and_primitive), and
//    OpenVDB's mesh-to-level-set (a narrow-band signed distance grid, read by trilinear
//    sampling; it answers only within its band). Next to them, the library's own field
//    (collision/mesh_distance_field.h, built with Embree's queries): what a step reads.
//    Build time (wall and CPU), memory (heap growth during the build, glibc's count), and
//    query time for points near the surface (within 1 cm) and far from it (10-30 cm).
//  - mesh files: tinyobjloader (OBJ only), assimp (OBJ, PLY), CGAL's polygon soup readers
//    (OBJ, PLY; what libenteron used, LGPL-3.0-or-later) and libenteron's own readers
//    (scene/mesh_readers.h) reading the same mesh written as an ASCII OBJ, an ASCII PLY
//    and a binary PLY: CPU time, the median of several rounds that alternate the readers.
// What each adds to libenteron.so's dependencies is measured outside this program
// (bench/results/anatomy_libraries.md gives the command). Built only when every candidate is
// installed (scripts/install-deps installs them). Reported, not asserted. Run:
//   build/bench/enteron_anatomy_libraries_bench [--quick]
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <malloc.h>
#include <tiny_obj_loader.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>
#include <assimp/Importer.hpp>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/MeshToVolume.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <memory_resource>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#include "collision/mesh_distance_field.h"
#include "collision/mesh_topology.h"
#include "collision/triangle_bvh.h"
#include "scene/mesh_file.h"

namespace {

using enteron::Vec3;
using enteron::collision::TriangleMesh;

constexpr double kRadius = 0.0125;           // m, the bowel's R
constexpr double kVoxel = kRadius / 4.0;     // the field's default voxel
constexpr double kBand = kRadius + 2 * kVoxel;  // the field's exact band (mesh_distance_field.h)

// A closed ellipsoid, semi-axes a, normals out: 2 segments (rings - 1) triangles.
TriangleMesh ellipsoid(const double a[3], uint32_t rings, uint32_t segments) {
    TriangleMesh m;
    auto vertex = [&](double x, double y, double z) { m.vertices.insert(m.vertices.end(), {x, y, z}); };
    vertex(0, 0, -a[2]);
    for (uint32_t i = 1; i < rings; ++i) {
        const double theta = M_PI * i / rings;
        for (uint32_t j = 0; j < segments; ++j) {
            const double phi = 2.0 * M_PI * j / segments;
            vertex(a[0] * std::sin(theta) * std::cos(phi), a[1] * std::sin(theta) * std::sin(phi), -a[2] * std::cos(theta));
        }
    }
    vertex(0, 0, a[2]);
    const uint32_t north = static_cast<uint32_t>(m.vertex_count() - 1);
    auto at = [&](uint32_t ring, uint32_t j) { return 1 + (ring - 1) * segments + j % segments; };
    auto triangle = [&](uint32_t x, uint32_t y, uint32_t z) { m.indices.insert(m.indices.end(), {x, y, z}); };
    for (uint32_t j = 0; j < segments; ++j) triangle(0, at(1, j + 1), at(1, j));
    for (uint32_t i = 1; i + 1 < rings; ++i)
        for (uint32_t j = 0; j < segments; ++j) {
            triangle(at(i, j), at(i, j + 1), at(i + 1, j + 1));
            triangle(at(i, j), at(i + 1, j + 1), at(i + 1, j));
        }
    for (uint32_t j = 0; j < segments; ++j) triangle(north, at(rings - 1, j), at(rings - 1, j + 1));
    return m;
}

// Query points: on rays from the centre, `near`: within 1 cm of the surface (either side);
// far: 10 to 30 cm outside it.
std::vector<Vec3> query_points(const double a[3], bool near, std::size_t count) {
    std::mt19937_64 random(near ? 1 : 2);
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < count; ++i) {
        Vec3 d(gauss(random), gauss(random), gauss(random));
        d.normalize();
        // The surface point along d: d scaled so that sum (d_k / a_k)^2 = 1.
        const double s = 1.0 / std::sqrt(std::pow(d.x() / a[0], 2) + std::pow(d.y() / a[1], 2) + std::pow(d.z() / a[2], 2));
        const double offset = near ? 0.02 * uniform(random) - 0.01 : 0.1 + 0.2 * uniform(random);
        points.push_back((s + offset) * d);
    }
    return points;
}

double cpu_s() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
double wall_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
// Heap in use (glibc: small blocks plus mmapped ones), bytes.
double heap_bytes() {
    const struct mallinfo2 info = mallinfo2();
    return double(info.uordblks) + double(info.hblkhd);
}

struct Build {
    double wall_ms, cpu_ms, heap_mb;
};
// Times `make` (which builds and keeps its structure) and the heap it grew by.
Build measure_build(const std::function<void()>& make) {
    malloc_trim(0);
    const double heap = heap_bytes(), cpu = cpu_s(), wall = wall_s();
    make();
    return {1e3 * (wall_s() - wall), 1e3 * (cpu_s() - cpu), (heap_bytes() - heap) / 1048576.0};
}
// Nanoseconds per query; `sink` keeps the answers alive.
double measure_queries(const std::vector<Vec3>& points, const std::function<double(const Vec3&)>& query) {
    volatile double sink = 0.0;
    const double start = wall_s();
    for (const Vec3& p : points) sink = sink + query(p);
    return 1e9 * (wall_s() - start) / double(points.size());
}

void row(const char* library, std::size_t triangles, const Build& b, const char* near, const char* far) {
    std::printf("| %s | %zu | %.0f | %.0f | %.1f | %s | %s |\n", library, triangles, b.wall_ms, b.cpu_ms, b.heap_mb, near,
                far);
}
std::string ns(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f", value);
    return text;
}

void structures(const TriangleMesh& mesh, const double a[3], std::size_t queries) {
    const std::vector<Vec3> near = query_points(a, true, queries), far = query_points(a, false, queries);
    const std::size_t triangles = mesh.triangle_count();
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();

    {  // Embree (with the topology the library builds anyway for the signs: not counted)
        const enteron::collision::MeshTopology topology(mesh, memory);
        std::unique_ptr<enteron::collision::TriangleBvh> bvh;
        const Build b = measure_build([&] { bvh = std::make_unique<enteron::collision::TriangleBvh>(mesh, topology); });
        const auto closest = [&](const Vec3& p) { return bvh->closest(p, std::numeric_limits<double>::infinity()).distance; };
        row("Embree 3.13 BVH, closest point", triangles, b, ns(measure_queries(near, closest)).c_str(),
            ns(measure_queries(far, closest)).c_str());
    }
    {  // CGAL
        using K = CGAL::Simple_cartesian<double>;
        using Iterator = std::vector<K::Triangle_3>::const_iterator;
        using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Iterator>>>;
        std::vector<K::Triangle_3> soup;
        std::unique_ptr<Tree> tree;
        const Build b = measure_build([&] {
            soup.reserve(triangles);
            for (std::size_t t = 0; t < triangles; ++t) {
                const Vec3 p = mesh.corner(t, 0), q = mesh.corner(t, 1), r = mesh.corner(t, 2);
                soup.emplace_back(K::Point_3(p.x(), p.y(), p.z()), K::Point_3(q.x(), q.y(), q.z()),
                                  K::Point_3(r.x(), r.y(), r.z()));
            }
            tree = std::make_unique<Tree>(soup.cbegin(), soup.cend());
            tree->build();
            tree->accelerate_distance_queries();
        });
        const auto closest = [&](const Vec3& p) {
            const K::Point_3 x(p.x(), p.y(), p.z());
            return CGAL::squared_distance(tree->closest_point_and_primitive(x).first, x);
        };
        row("CGAL 5.5 AABB tree, closest point", triangles, b, ns(measure_queries(near, closest)).c_str(),
            ns(measure_queries(far, closest)).c_str());
    }
    {  // OpenVDB: a narrow band as wide as the library's exact band
        openvdb::FloatGrid::Ptr grid;
        const Build b = measure_build([&] {
            std::vector<openvdb::Vec3s> points;
            std::vector<openvdb::Vec3I> faces;
            for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
                const Vec3 p = mesh.vertex(v);
                points.emplace_back(float(p.x()), float(p.y()), float(p.z()));
            }
            for (std::size_t t = 0; t < triangles; ++t)
                faces.emplace_back(mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
            const auto transform = openvdb::math::Transform::createLinearTransform(kVoxel);
            grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points, faces,
                                                                      float(std::ceil(kBand / kVoxel)));
        });
        const openvdb::FloatGrid::ConstAccessor accessor = grid->getConstAccessor();
        const openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler> sampler(
            accessor, grid->transform());
        const auto sample = [&](const Vec3& p) { return double(sampler.wsSample(openvdb::Vec3R(p.x(), p.y(), p.z()))); };
        const std::string far_ns = ns(measure_queries(far, sample)) + " (no answer: beyond the band)";
        char library[96];
        std::snprintf(library, sizeof library, "OpenVDB %s meshToLevelSet, trilinear sample (%.1f MB in its grid)",
                      openvdb::getLibraryVersionString(), double(grid->memUsage()) / 1048576.0);
        row(library, triangles, b, ns(measure_queries(near, sample)).c_str(), far_ns.c_str());
    }
    {  // The library's field (Embree inside), as ent_scene_add_obstacle builds it
        std::unique_ptr<enteron::collision::MeshDistanceField> field;
        const enteron::collision::DistanceFieldSettings settings{kVoxel, kBand, false};
        const Build b = measure_build(
            [&] { field = std::make_unique<enteron::collision::MeshDistanceField>(mesh, settings, memory); });
        const auto sample = [&](const Vec3& p) { return field->distance(p); };
        row("libenteron's field (Embree queries), trilinear sample", triangles, b, ns(measure_queries(near, sample)).c_str(),
            ns(measure_queries(far, sample)).c_str());
    }
}

void write_obj(const TriangleMesh& m, const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    for (std::size_t v = 0; v < m.vertex_count(); ++v)
        std::fprintf(f, "v %.9g %.9g %.9g\n", m.vertices[3 * v], m.vertices[3 * v + 1], m.vertices[3 * v + 2]);
    for (std::size_t t = 0; t < m.triangle_count(); ++t)
        std::fprintf(f, "f %u %u %u\n", m.indices[3 * t] + 1, m.indices[3 * t + 1] + 1, m.indices[3 * t + 2] + 1);
    std::fclose(f);
}

void write_ply(const TriangleMesh& m, const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fprintf(f, "ply\nformat ascii 1.0\nelement vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face %zu\nproperty list uchar int vertex_indices\nend_header\n",
                 m.vertex_count(), m.triangle_count());
    for (std::size_t v = 0; v < m.vertex_count(); ++v)
        std::fprintf(f, "%.9g %.9g %.9g\n", m.vertices[3 * v], m.vertices[3 * v + 1], m.vertices[3 * v + 2]);
    for (std::size_t t = 0; t < m.triangle_count(); ++t)
        std::fprintf(f, "3 %u %u %u\n", m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]);
    std::fclose(f);
}

// The same as binary little-endian PLY (float coordinates, int indices), as scanners and
// CAD tools write it.
void write_binary_ply(const TriangleMesh& m, const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    std::fprintf(f, "ply\nformat binary_little_endian 1.0\nelement vertex %zu\nproperty float x\nproperty float y\n"
                    "property float z\nelement face %zu\nproperty list uchar int vertex_indices\nend_header\n",
                 m.vertex_count(), m.triangle_count());
    for (double coordinate : m.vertices) {
        const float value = static_cast<float>(coordinate);
        std::fwrite(&value, sizeof value, 1, f);
    }
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const unsigned char corners = 3;
        const int32_t index[3] = {int32_t(m.indices[3 * t]), int32_t(m.indices[3 * t + 1]), int32_t(m.indices[3 * t + 2])};
        std::fwrite(&corners, 1, 1, f);
        std::fwrite(index, sizeof index, 1, f);
    }
    std::fclose(f);
}

// One way of reading a file: the triangles it found (0: it failed or cannot read it).
struct Reader {
    const char* name;
    std::function<std::size_t(const std::string& path)> read;
    bool reads_ply;
};

// CPU ms of each reader on each file, the median of `rounds` rounds; each round reads every
// file with every reader in turn, so that the machine's load falls on all of them alike.
void readers(const TriangleMesh& mesh, const std::string& directory, int rounds) {
    const std::string obj = directory + "/organ.obj", ply = directory + "/organ.ply", binary = directory + "/organ_binary.ply";
    write_obj(mesh, obj);
    write_ply(mesh, ply);
    write_binary_ply(mesh, binary);
    const auto tinyobj_read = [](const std::string& path) {
        tinyobj::attrib_t attrib;
        std::vector<tinyobj::shape_t> shapes;
        std::vector<tinyobj::material_t> materials;
        std::string warning, error;
        if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, path.c_str(), nullptr, true)) return std::size_t{0};
        std::size_t count = 0;
        for (const tinyobj::shape_t& s : shapes) count += s.mesh.num_face_vertices.size();
        return count;
    };
    const auto assimp_read = [](const std::string& path) {
        Assimp::Importer importer;
        const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate);
        if (scene == nullptr) return std::size_t{0};
        std::size_t count = 0;
        for (unsigned i = 0; i < scene->mNumMeshes; ++i) count += scene->mMeshes[i]->mNumFaces;
        return count;
    };
    const auto cgal_read = [](const std::string& path) {
        std::vector<CGAL::Simple_cartesian<double>::Point_3> points;
        std::vector<std::vector<std::size_t>> polygons;
        if (!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false))) return std::size_t{0};
        return polygons.size();
    };
    const auto enteron_read = [](const std::string& path) {
        return enteron::scene::read_mesh_file(path, 1.0, "organ", enteron::ErrorCode::invalid_argument).triangle_count();
    };
    const Reader readers[] = {{"tinyobjloader 2.0rc10", tinyobj_read, false},
                              {"assimp 5.2", assimp_read, true},
                              {"CGAL 5.5 polygon soup (what libenteron used)", cgal_read, true},
                              {"libenteron's own readers (scene/mesh_readers.h)", enteron_read, true}};
    const std::string files[] = {obj, ply, binary};
    constexpr std::size_t kReaders = std::size(readers), kFiles = std::size(files);
    std::vector<double> cpu_ms[kReaders][kFiles];
    std::size_t found[kReaders][kFiles] = {};
    for (int round = 0; round < rounds; ++round)
        for (std::size_t f = 0; f < kFiles; ++f)
            for (std::size_t r = 0; r < kReaders; ++r) {
                if (f > 0 && !readers[r].reads_ply) continue;
                const double start = cpu_s();
                found[r][f] = readers[r].read(files[f]);
                cpu_ms[r][f].push_back(1e3 * (cpu_s() - start));
            }
    for (std::size_t r = 0; r < kReaders; ++r) {
        std::printf("| %s | %zu |", readers[r].name, mesh.triangle_count());
        for (std::size_t f = 0; f < kFiles; ++f) {
            std::vector<double>& times = cpu_ms[r][f];
            if (times.empty()) {
                std::printf(" cannot |");
                continue;
            }
            std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
            std::printf(" %.1f (%zu) |", times[times.size() / 2], found[r][f]);
        }
        std::printf("\n");
    }
    for (const std::string& file : files) std::remove(file.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    openvdb::initialize();
    // One thread for every candidate (OpenVDB and TBB would take every core; libenteron's
    // Embree device has one): the same work, compared on equal terms.
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const double a[3] = {0.1, 0.07, 0.05};
    struct Size {
        uint32_t rings, segments;
    };
    const Size sizes[] = {{51, 100}, {201, 250}, {501, 1000}};  // 10k, 100k, 1M triangles
    const std::size_t queries = quick ? 2000 : 20000;
    std::printf("Closest point / signed distance, one thread; voxel %.3g mm, band %.3g mm; %zu queries each:\n\n",
                1e3 * kVoxel, 1e3 * kBand, queries);
    std::printf("| structure | triangles | build wall ms | build CPU ms | heap MB | near ns/query | far ns/query |\n"
                "|---|---:|---:|---:|---:|---:|---:|\n");
    for (const Size& size : sizes) {
        if (quick && size.rings > 201) break;
        structures(ellipsoid(a, size.rings, size.segments), a, queries);
    }
    char directory[] = "/tmp/enteron_anatomy_libraries_XXXXXX";
    if (mkdtemp(directory) == nullptr) return 1;
    const int rounds = quick ? 3 : 7;
    std::printf("\nReading the mesh from a file, CPU ms, median of %d rounds (triangles read):\n\n"
                "| reader | triangles | ASCII OBJ | ASCII PLY | binary PLY |\n|---|---:|---:|---:|---:|\n",
                rounds);
    for (const Size& size : sizes) {
        if (quick && size.rings > 201) break;
        readers(ellipsoid(a, size.rings, size.segments), directory, rounds);
    }
    rmdir(directory);
    return 0;
}
