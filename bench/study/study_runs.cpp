// SPDX-License-Identifier: Apache-2.0
#include "study_runs.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace study {

void RunRecord::put(const std::string& key, double value) { fields_[key] = exact(value); }

void RunRecord::put(const std::string& key, const std::string& value) {
    std::string line = value;
    for (char& c : line)
        if (c == '\n' || c == '\r') c = ' ';
    fields_[key] = line;
}

void RunRecord::put(const std::string& key, const std::vector<double>& values) {
    std::string line;
    for (std::size_t i = 0; i < values.size(); ++i) line += (i ? " " : "") + exact(values[i]);
    fields_[key] = line;
}

void RunRecord::put_bytes(const std::string& key, const std::vector<unsigned char>& bytes) {
    static const char digits[] = "0123456789abcdef";
    std::string hex;
    hex.reserve(2 * bytes.size());
    for (unsigned char b : bytes) {
        hex += digits[b >> 4];
        hex += digits[b & 15];
    }
    fields_[key] = hex;
}

const std::string& RunRecord::field(const std::string& key) const {
    const auto found = fields_.find(key);
    if (found == fields_.end()) throw std::runtime_error(what_ + ": the run record has no " + key);
    return found->second;
}

double RunRecord::number(const std::string& key) const {
    const std::vector<double> values = numbers(key);
    if (values.size() != 1) throw std::runtime_error(what_ + ": " + key + " is not one number");
    return values[0];
}

std::string RunRecord::text(const std::string& key) const { return field(key); }

std::vector<double> RunRecord::numbers(const std::string& key) const {
    std::vector<double> values;
    const std::string& line = field(key);
    const char* p = line.c_str();
    while (*p != '\0') {
        char* end = nullptr;
        errno = 0;
        const double value = std::strtod(p, &end);
        if (end == p) throw std::runtime_error(what_ + ": " + key + " holds something that is not a number");
        values.push_back(value);
        p = end;
        while (*p == ' ') ++p;
    }
    return values;
}

std::vector<unsigned char> RunRecord::bytes(const std::string& key) const {
    const std::string& hex = field(key);
    if (hex.size() % 2 != 0) throw std::runtime_error(what_ + ": " + key + " is not hex");
    std::vector<unsigned char> out(hex.size() / 2);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<unsigned char>(std::stoi(hex.substr(2 * i, 2), nullptr, 16));
    return out;
}

std::string RunRecord::serialize() const {
    std::string out;
    for (const auto& [key, value] : fields_) out += key + " " + value + "\n";
    return out;
}

RunRecord RunRecord::parse(const std::string& text, const std::string& what) {
    RunRecord record;
    record.what_ = what;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.empty()) continue;
        const auto space = line.find(' ');
        record.fields_[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
    }
    return record;
}

RunMode run_mode(const Options& options) {
    if (options.list_runs) return RunMode::list;
    if (!options.run.empty()) return RunMode::compute_one;
    if (!options.runs_dir.empty()) return RunMode::from_records;
    return RunMode::inline_timing;
}

std::string csv_path(const Options& options, const std::string& file) {
    return options.list_runs ? std::string("/dev/null") : options.out_dir + "/" + file;
}

void list_run(const std::string& name) {
    std::printf("%s\n", name.c_str());
    std::fflush(stdout);
}

std::string run_file_name(const std::string& name) {
    std::string file = name;
    for (char& c : file)
        if (c == ' ') c = '+';
    return file + ".run";
}

RunRecord load_run(const Options& options, const std::string& name) {
    const std::string path = options.runs_dir + "/" + run_file_name(name);
    std::ifstream file(path, std::ios::binary);
    if (!file)
        throw std::runtime_error("the run \"" + name + "\" is not in " + options.runs_dir +
                                 " (compute the error part first: bench/study/distributed_study.py)");
    std::ostringstream text;
    text << file.rdbuf();
    return RunRecord::parse(text.str(), path);
}

std::string exact(double value) {
    if (std::isnan(value)) return "nan";
    for (int digits = 6; digits < 17; ++digits) {
        const std::string text = format("%.*g", digits, value);
        if (std::strtod(text.c_str(), nullptr) == value) return text;
    }
    return format("%.17g", value);
}

std::vector<std::string> name_words(const std::string& name) {
    std::vector<std::string> words;
    std::istringstream in(name);
    std::string word;
    while (in >> word) words.push_back(word);
    return words;
}

std::vector<unsigned char> save_state(ent_scene* scene) {
    size_t size = 0;
    check(ent_scene_save_state(scene, nullptr, 0, &size), "ent_scene_save_state");
    std::vector<unsigned char> state(size);
    check(ent_scene_save_state(scene, state.data(), state.size(), &size), "ent_scene_save_state");
    state.resize(size);
    return state;
}

void restore_state(ent_scene* scene, const std::vector<unsigned char>& state) {
    check(ent_scene_restore_state(scene, state.data(), state.size()), "ent_scene_restore_state");
}

}  // namespace study
