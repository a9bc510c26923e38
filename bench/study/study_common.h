// SPDX-License-Identifier: Apache-2.0
// Shared pieces of the accuracy study (bench/study): options, scenes from JSON through the
// public C API, stepping with per-step timing, axis sampling and CSV output.
// Like a simulator vendor, the study uses nothing but include/enteron/enteron.h.
#pragma once

#include <enteron/enteron.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace study {

struct Options {
    bool fast = false;       // small grid for ctest; full: the committed results
    bool tiny = false;       // the smallest grid (seconds; fast where a part has no tiny one)
    std::string out_dir;     // CSV files go here
    std::vector<std::string> parts;  // empty: all parts
    bool wants(const std::string& part) const;
    // The distributed study (study_runs.h): --list-runs, --run NAME, --runs DIR, and the
    // outer steps of a mechanics run timed by the timing pass (--timing-steps).
    bool list_runs = false;
    std::string run;
    std::string runs_dir;
    long timing_steps = 200;
};

// Formats like printf into a std::string.
std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

// A failing C API call, with the library's message.
struct ApiError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
void check(ent_status status, const char* call);

struct SceneDeleter {
    void operator()(ent_scene* scene) const { ent_scene_destroy(scene); }
};
using ScenePtr = std::unique_ptr<ent_scene, SceneDeleter>;
struct SkinDeleter {
    void operator()(ent_skin* skin) const { ent_skin_destroy(skin); }
};
using SkinPtr = std::unique_ptr<ent_skin, SkinDeleter>;

ScenePtr make_scene(const std::string& json);

ent_stats scene_stats(const ent_scene* scene);
ent_effect_stats effect_stats(const ent_scene* scene, int32_t effect);

// count points evenly spaced in arc length (x y z each).
std::vector<double> sample_axis(const ent_scene* scene, uint32_t count);
// RMS distance between two axes sampled at the same arc-length fractions.
double rms_distance(const std::vector<double>& a, const std::vector<double>& b);

double now_s();
double median(std::vector<double> values);
// Least-squares slope of log(y) against log(x): the observed order when y = C x^p.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

const char* integrator_name(int32_t integrator);
extern const int32_t kIntegrators[4];

// A CSV file with a fixed header; every row must have as many fields.
class Csv {
public:
    Csv(const std::string& path, const std::vector<std::string>& columns);
    ~Csv();
    Csv(const Csv&) = delete;
    Csv& operator=(const Csv&) = delete;
    void row(const std::vector<std::string>& fields);
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::FILE* file_;
    std::size_t columns_;
};

std::string num(double value);  // %.6g, "nan" for NaN
std::string num(uint64_t value);
std::string num(int value);
std::string num(uint32_t value);

// A progress line on stderr (stdout stays free for the caller).
void progress(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

}  // namespace study
