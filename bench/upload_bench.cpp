// SPDX-License-Identifier: Apache-2.0
// What stable topology saves a renderer per frame (docs/skinning.md, "A mesh a GPU can
// keep"), in time: the tube and the convolution skins of the settled demo pile
// (bench/skin_piles.h), at their default resolution (16 segments, rings every R / 2) and
// four times finer (32, R / 4), uploaded to real OpenGL buffers every frame, at 60 Hz of
// simulated time (the scene steps 1 ms at a time between frames, the skins update untimed),
// three ways, each timed from its first GL call to the return of glFinish:
//   full            every array re-specified with glBufferData (GL_STREAM_DRAW): positions,
//                   normals, tangents, axis_u, around_v and the indices, as a renderer
//                   must when the vertex count and the indices may change every frame;
//   stable          glBufferSubData of positions, normals and tangents into buffers sized
//                   once; axis_u, around_v and the indices only when topology_changed
//                   (column "topology changes"), as docs/skinning.md says;
//   stable_orphan   the same arrays re-specified with glBufferData (buffer orphaning);
//   memcpy_full / memcpy_stable: the same bytes copied into host memory, for reference.
// Every frame runs the variants in a rotated order, on buffers of their own. Medians and
// 99th percentiles over the frames; the load average before and after is printed.
//
// On Mesa's llvmpipe (EGL's surfaceless platform, no GPU: examples/egl_offscreen_context.h)
// a buffer is host memory: an upload is the driver's copy and bookkeeping, with no PCIe
// transfer. The figures bound the driver's work, not a GPU's transfer time. Nothing draws
// from the buffers, so no upload waits for a draw still reading one.
//
// Reported, not asserted. Run:
//   build/bench/enteron_upload_bench [--frames N]   (default 600: 10 s at 60 Hz)
#include <enteron/enteron.h>

#include <epoxy/gl.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <unistd.h>

#include "egl_offscreen_context.h"
#include "skin_piles.h"
#include "step_timing.h"

namespace {

using namespace enteron::bench;
using Clock = std::chrono::steady_clock;

constexpr int kStepsPerSecond = 1000;  // 1 ms steps
constexpr int kFramesPerSecond = 60;

// The arrays of one mesh as a renderer holds them, in the order they are uploaded.
enum Array { kPositions, kNormals, kTangents, kAxisU, kAroundV, kIndices, kArrayCount };

struct ArrayBytes {
    const void* data[kArrayCount];
    std::size_t size[kArrayCount];
};

ArrayBytes arrays_of(const ent_mesh_view& view) {
    const std::size_t vertices = view.vertex_count, corners = 3 * std::size_t(view.triangle_count);
    return {{view.positions_xyz_m, view.normals_xyz, view.tangents_xyz, view.axis_u, view.around_v, view.indices},
            {3 * vertices * sizeof(float), 3 * vertices * sizeof(float), 3 * vertices * sizeof(float),
             vertices * sizeof(float), vertices * sizeof(float), corners * sizeof(uint32_t)}};
}

// The arrays that change on every update (the rest only with the topology).
bool every_frame(int array) { return array <= kTangents; }

// One renderer's GL buffers for a mesh: a vertex array object holding a buffer per array.
class GlMeshBuffers {
public:
    GlMeshBuffers() {
        glGenVertexArrays(1, &vao_);
        glGenBuffers(kArrayCount, buffers_);
    }
    ~GlMeshBuffers() {
        glDeleteBuffers(kArrayCount, buffers_);
        glDeleteVertexArrays(1, &vao_);
    }
    GlMeshBuffers(const GlMeshBuffers&) = delete;
    GlMeshBuffers& operator=(const GlMeshBuffers&) = delete;

    // Uploads the arrays chosen: into their storage (glBufferSubData) when `in_place` and
    // the size is the one specified before, else re-specifying it (glBufferData, which also
    // orphans the old storage).
    template <class Choose>
    void upload(const ArrayBytes& a, Choose&& chosen, bool in_place) {
        glBindVertexArray(vao_);
        for (int i = 0; i < kArrayCount; ++i) {
            if (!chosen(i)) continue;
            const GLenum target = i == kIndices ? GL_ELEMENT_ARRAY_BUFFER : GL_ARRAY_BUFFER;
            glBindBuffer(target, buffers_[i]);
            if (in_place && specified_[i] == a.size[i]) {
                glBufferSubData(target, 0, GLsizeiptr(a.size[i]), a.data[i]);
            } else {
                glBufferData(target, GLsizeiptr(a.size[i]), a.data[i], GL_STREAM_DRAW);
                specified_[i] = a.size[i];
            }
        }
    }

private:
    GLuint vao_ = 0;
    GLuint buffers_[kArrayCount] = {};
    std::size_t specified_[kArrayCount] = {};
};

// The same bytes into host memory (buffers grown untimed beforehand).
struct HostCopy {
    std::vector<unsigned char> arrays[kArrayCount];
    template <class Choose>
    void reserve(const ArrayBytes& a, Choose&& chosen) {
        for (int i = 0; i < kArrayCount; ++i)
            if (chosen(i) && arrays[i].size() < a.size[i]) arrays[i].resize(a.size[i]);
    }
    template <class Choose>
    void copy(const ArrayBytes& a, Choose&& chosen) {
        for (int i = 0; i < kArrayCount; ++i)
            if (chosen(i)) std::memcpy(arrays[i].data(), a.data[i], a.size[i]);
    }
};

enum Variant { kFull, kStable, kStableOrphan, kMemcpyFull, kMemcpyStable, kVariantCount };
const char* const kVariantNames[kVariantCount] = {"full", "stable", "stable_orphan", "memcpy_full",
                                                  "memcpy_stable"};

struct SkinUnderTest {
    const char* name;
    int32_t method;
    uint32_t segments;
    double ring_spacing_radii;
    ent_skin* skin = nullptr;
    GlMeshBuffers gl[3];  // full, stable, stable_orphan
    HostCopy host[2];     // memcpy_full, memcpy_stable
    std::vector<double> samples_us[kVariantCount];
    double bytes_sum[kVariantCount] = {};
    uint64_t serial_first = 0, serial_last = 0;
    uint32_t vertices = 0, triangles = 0;
};

double seconds_between(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

// One frame of one variant: the upload (or copy), then glFinish; returns the bytes moved.
double upload(SkinUnderTest& s, int variant, const ent_mesh_view& view) {
    const ArrayBytes a = arrays_of(view);
    const bool topology = view.topology_changed != 0;
    auto all = [](int) { return true; };
    auto stable = [topology](int i) { return topology || every_frame(i); };
    if (variant == kMemcpyFull) s.host[0].reserve(a, all);
    if (variant == kMemcpyStable) s.host[1].reserve(a, stable);
    glFinish();  // nothing of an earlier upload left to finish in this one's time
    const auto start = Clock::now();
    switch (variant) {
        case kFull: s.gl[0].upload(a, all, false); break;
        case kStable: s.gl[1].upload(a, stable, true); break;
        case kStableOrphan: s.gl[2].upload(a, stable, false); break;
        case kMemcpyFull: s.host[0].copy(a, all); break;
        case kMemcpyStable: s.host[1].copy(a, stable); break;
    }
    if (variant == kFull || variant == kStable || variant == kStableOrphan) glFinish();
    const auto stop = Clock::now();
    s.samples_us[variant].push_back(1e6 * seconds_between(start, stop));
    double bytes = 0.0;
    for (int i = 0; i < kArrayCount; ++i)
        if (variant == kFull || variant == kMemcpyFull || stable(i)) bytes += double(a.size[i]);
    return bytes;
}

// The load averages over 1, 5 and 15 minutes, as uptime prints them.
std::string load_average() {
    std::string text = "?";
    if (FILE* f = std::fopen("/proc/loadavg", "r")) {
        double one = 0.0, five = 0.0, fifteen = 0.0;
        if (std::fscanf(f, "%lf %lf %lf", &one, &five, &fifteen) == 3) {
            char line[64];
            std::snprintf(line, sizeof line, "%.2f, %.2f, %.2f", one, five, fifteen);
            text = line;
        }
        std::fclose(f);
    }
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 600;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
            frames = std::atoi(argv[++i]);
        } else {
            std::fprintf(stderr, "usage: %s [--frames N]  (N >= 10, default 600)\n", argv[0]);
            return 2;
        }
    }
    if (frames < 10) {
        std::fprintf(stderr, "enteron_upload_bench: --frames must be at least 10\n");
        return 2;
    }

    enteron_examples::EglOffscreenContext context;
    std::string error;
    if (!context.create(error)) {
        std::fprintf(stderr, "enteron_upload_bench: no OpenGL context: %s\n", error.c_str());
        return 1;
    }
    const std::string load_before = load_average();
    ent_scene* scene = settle_pile(kDemoPile);
    if (scene == nullptr) {
        std::fprintf(stderr, "enteron_upload_bench: the demo pile: %s\n", ent_last_error());
        return 1;
    }

    // At the defaults (16 segments, rings every R / 2) and four times finer.
    SkinUnderTest skins[4];
    for (int i = 0; i < 4; ++i) {
        skins[i].name = i % 2 == 0 ? "tube" : "convolution";
        skins[i].method = i % 2 == 0 ? ENT_SKIN_TUBE : ENT_SKIN_CONVOLUTION;
        skins[i].segments = i < 2 ? 16 : 32;
        skins[i].ring_spacing_radii = i < 2 ? 0.5 : 0.25;
    }
    for (SkinUnderTest& s : skins) {
        ent_skin_desc desc;
        ent_skin_desc_default(&desc);  // stable_topology 1
        desc.method = s.method;
        desc.segments = s.segments;
        desc.ring_spacing_radii = s.ring_spacing_radii;
        if (ent_skin_create(scene, &desc, &s.skin) != ENT_OK || ent_skin_update(s.skin) != ENT_OK) {
            std::fprintf(stderr, "enteron_upload_bench: the %s skin: %s\n", s.name, ent_last_error());
            return 1;
        }
        // The first update's topology goes to every variant's buffers untimed, as a
        // renderer's first frame would.
        const ent_mesh_view view = mesh_of(s.skin);
        for (int v = 0; v < kVariantCount; ++v) upload(s, v, view);
        for (auto& samples : s.samples_us) samples.clear();
        s.serial_first = view.topology_serial;
    }

    long steps_done = 0;
    for (int frame = 0; frame < frames; ++frame) {
        // Step to this frame's time (1000 / 60 ms: 16 or 17 steps).
        const long steps_due = long(frame + 1) * kStepsPerSecond / kFramesPerSecond;
        for (; steps_done < steps_due; ++steps_done) {
            if (ent_scene_step(scene, 1.0 / kStepsPerSecond) != ENT_OK) {
                std::fprintf(stderr, "enteron_upload_bench: step: %s\n", ent_last_error());
                return 1;
            }
        }
        for (SkinUnderTest& s : skins) {
            if (ent_skin_update(s.skin) != ENT_OK) {
                std::fprintf(stderr, "enteron_upload_bench: %s update: %s\n", s.name, ent_last_error());
                return 1;
            }
            const ent_mesh_view view = mesh_of(s.skin);
            for (int k = 0; k < kVariantCount; ++k) {
                const int variant = (frame + k) % kVariantCount;
                s.bytes_sum[variant] += upload(s, variant, view);
            }
            const GLenum gl_error = glGetError();
            if (gl_error != GL_NO_ERROR) {
                std::fprintf(stderr, "enteron_upload_bench: OpenGL error 0x%x\n", unsigned(gl_error));
                return 1;
            }
            s.serial_last = view.topology_serial;
            s.vertices = view.vertex_count;
            s.triangles = view.triangle_count;
        }
    }
    const std::string load_after = load_average();

    std::printf("## Uploading a skin's mesh per frame: stable topology against a full re-upload\n\n");
    std::printf("OpenGL: %s, %s (EGL, no window). Demo pile settled %.0f s, then %d frames at %d Hz of "
                "simulated time; skins with stable_topology 1 (the default).\n",
                context.renderer().c_str(), reinterpret_cast<const char*>(glGetString(GL_VERSION)), kDemoPile.settle_s,
                frames, kFramesPerSecond);
    std::printf("Load average (1, 5, 15 min) before: %s; after: %s (on %ld cores).\n\n", load_before.c_str(),
                load_after.c_str(), sysconf(_SC_NPROCESSORS_ONLN));
    std::printf("| skin | segments, ring spacing | vertices | triangles | topology changes | variant | kB per frame | "
                "median us | p99 us | GB/s at median |\n|---|---|---:|---:|---:|---|---:|---:|---:|---:|\n");
    for (SkinUnderTest& s : skins) {
        for (int v = 0; v < kVariantCount; ++v) {
            const double kilobytes = s.bytes_sum[v] / frames / 1e3;
            const StepTimeSummary t = summarize(s.samples_us[v]);
            std::printf("| %s | %u, %.2g R | %u | %u | %llu | %s | %.0f | %.1f | %.1f | %.2f |\n", s.name, s.segments,
                        s.ring_spacing_radii, s.vertices, s.triangles,
                        static_cast<unsigned long long>(s.serial_last - s.serial_first), kVariantNames[v], kilobytes,
                        t.median_us, t.p99_us, t.median_us > 0.0 ? kilobytes * 1e3 / (t.median_us * 1e3) : 0.0);
        }
    }
    std::printf("\nSaved per frame by stable topology (median of full - median of stable):");
    for (SkinUnderTest& s : skins) {
        std::vector<double> full = s.samples_us[kFull], stable = s.samples_us[kStable];
        const double saved = summarize(full).median_us - summarize(stable).median_us;
        std::printf("\n- %s (%u segments, rings every %.2g R): %.1f us (%.0f kB)", s.name, s.segments,
                    s.ring_spacing_radii, saved, (s.bytes_sum[kFull] - s.bytes_sum[kStable]) / frames / 1e3);
    }
    std::printf("\n");
    for (SkinUnderTest& s : skins) ent_skin_destroy(s.skin);
    ent_scene_destroy(scene);
    return 0;
}
