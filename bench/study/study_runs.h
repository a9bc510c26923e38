// SPDX-License-Identifier: Apache-2.0
// The study split in two, so that its error part can run anywhere (docs/accuracy.md,
// "The distributed study"): the runs of the error part are named, computed one at a time
// (enteron_study --run NAME, on any machine: the library is deterministic) and stored as
// run records; the assembly then reads them (--runs DIR) and measures only the timings,
// serially, on a quiet core.
//
// A run record is text, one "key value..." line per field, doubles with %.17g (they read
// back to the same bits), a saved scene state in hex. Its name says what it computes:
// "mechanics swing rk4 240 2e-05", "collision 0.00625 500", "tool 0.00625 500".
#pragma once

#include "study_common.h"

#include <map>
#include <string>
#include <vector>

namespace study {

class RunRecord {
public:
    void put(const std::string& key, double value);
    void put(const std::string& key, const std::string& value);  // one line, no newline
    void put(const std::string& key, const std::vector<double>& values);
    void put_bytes(const std::string& key, const std::vector<unsigned char>& bytes);

    double number(const std::string& key) const;
    std::string text(const std::string& key) const;
    std::vector<double> numbers(const std::string& key) const;
    std::vector<unsigned char> bytes(const std::string& key) const;

    std::string serialize() const;
    static RunRecord parse(const std::string& text, const std::string& what);

private:
    const std::string& field(const std::string& key) const;
    std::map<std::string, std::string> fields_;
    std::string what_;  // for messages: the run's name or file
};

// What the parts of the study do with one of their runs, by Options: list its name
// (--list-runs), compute it alone and print its record (--run NAME), or read its record
// from --runs DIR. The parts that take no part in this (skins, effects, peers) run as before.
enum class RunMode { inline_timing, list, compute_one, from_records };
RunMode run_mode(const Options& options);

// The path of a part's CSV file, or /dev/null while only listing the runs.
std::string csv_path(const Options& options, const std::string& file);

// --list-runs: the name goes to stdout.
void list_run(const std::string& name);
// --runs DIR: the record of a run computed elsewhere; throws naming the run and DIR if absent.
RunRecord load_run(const Options& options, const std::string& name);
// A file name for a run's record: the name with spaces as '+'.
std::string run_file_name(const std::string& name);

// A double written so that it reads back to the same bits, and as short as that allows.
std::string exact(double value);
// The words of a run's name.
std::vector<std::string> name_words(const std::string& name);

// Saved scene state (ent_scene_save_state) and its restore, for the timing pass.
std::vector<unsigned char> save_state(ent_scene* scene);
void restore_state(ent_scene* scene, const std::vector<unsigned char>& state);

}  // namespace study
