// SPDX-License-Identifier: Apache-2.0
#include "study_common.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstring>

namespace study {

const int32_t kIntegrators[4] = {ENT_INTEGRATOR_RK4, ENT_INTEGRATOR_SYMPLECTIC_EULER,
                                 ENT_INTEGRATOR_IMPLICIT_EULER, ENT_INTEGRATOR_BDF2};

bool Options::wants(const std::string& part) const {
    return parts.empty() || std::find(parts.begin(), parts.end(), part) != parts.end();
}

std::string format(const char* fmt, ...) {
    va_list args;
    va_start(args, fmt);
    va_list copy;
    va_copy(copy, args);
    const int size = std::vsnprintf(nullptr, 0, fmt, copy);
    va_end(copy);
    std::string out(static_cast<std::size_t>(std::max(size, 0)) + 1, '\0');
    std::vsnprintf(out.data(), out.size(), fmt, args);
    va_end(args);
    out.resize(out.size() - 1);
    return out;
}

void check(ent_status status, const char* call) {
    if (status != ENT_OK)
        throw ApiError(format("%s: %s: %s", call, ent_status_string(status), ent_last_error()));
}

ScenePtr make_scene(const std::string& json) {
    ent_scene* scene = nullptr;
    check(ent_scene_create_json(json.data(), json.size(), &scene), "ent_scene_create_json");
    return ScenePtr(scene);
}

ent_stats scene_stats(const ent_scene* scene) {
    ent_stats stats;
    std::memset(&stats, 0, sizeof stats);
    stats.struct_size = sizeof stats;
    check(ent_scene_stats(scene, &stats), "ent_scene_stats");
    return stats;
}

ent_effect_stats effect_stats(const ent_scene* scene, int32_t effect) {
    ent_effect_stats stats;
    std::memset(&stats, 0, sizeof stats);
    stats.struct_size = sizeof stats;
    check(ent_scene_effect_stats(scene, effect, &stats), "ent_scene_effect_stats");
    return stats;
}

std::vector<double> sample_axis(const ent_scene* scene, uint32_t count) {
    std::vector<double> points(3 * static_cast<std::size_t>(count));
    check(ent_scene_axis(scene, count, points.data()), "ent_scene_axis");
    return points;
}

double rms_distance(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size() || a.empty()) return std::nan("");
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(sum / static_cast<double>(a.size() / 3));
}

double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> values) {
    if (values.empty()) return std::nan("");
    const std::size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle), values.end());
    const double upper = values[middle];
    if (values.size() % 2 == 1) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle));
    return 0.5 * (lower + upper);
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (!(x[i] > 0.0) || !(y[i] > 0.0)) continue;
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        ++n;
    }
    if (n < 2) return std::nan("");
    const double dn = static_cast<double>(n);
    return (dn * sxy - sx * sy) / (dn * sxx - sx * sx);
}

const char* integrator_name(int32_t integrator) {
    switch (integrator) {
        case ENT_INTEGRATOR_RK4: return "rk4";
        case ENT_INTEGRATOR_SYMPLECTIC_EULER: return "symplectic_euler";
        case ENT_INTEGRATOR_IMPLICIT_EULER: return "implicit_euler";
        case ENT_INTEGRATOR_BDF2: return "bdf2";
        default: return "unknown";
    }
}

Csv::Csv(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), file_(std::fopen(path.c_str(), "w")), columns_(columns.size()) {
    if (file_ == nullptr) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    for (std::size_t i = 0; i < columns.size(); ++i)
        std::fprintf(file_, "%s%s", i ? "," : "", columns[i].c_str());
    std::fprintf(file_, "\n");
    std::fflush(file_);
}

Csv::~Csv() {
    if (file_ != nullptr) std::fclose(file_);
}

void Csv::row(const std::vector<std::string>& fields) {
    if (fields.size() != columns_)
        throw std::logic_error(format("%s: a row of %zu fields for %zu columns", path_.c_str(), fields.size(), columns_));
    for (std::size_t i = 0; i < fields.size(); ++i) std::fprintf(file_, "%s%s", i ? "," : "", fields[i].c_str());
    std::fprintf(file_, "\n");
    std::fflush(file_);  // a long run that dies keeps what it measured
}

std::string num(double value) { return std::isnan(value) ? std::string("nan") : format("%.6g", value); }
std::string num(uint64_t value) { return format("%llu", static_cast<unsigned long long>(value)); }
std::string num(int value) { return format("%d", value); }
std::string num(uint32_t value) { return format("%u", value); }

void progress(const char* fmt, ...) {
    va_list args;
    va_start(args, fmt);
    std::fprintf(stderr, "study: ");
    std::vfprintf(stderr, fmt, args);
    std::fprintf(stderr, "\n");
    va_end(args);
    std::fflush(stderr);
}

}  // namespace study
