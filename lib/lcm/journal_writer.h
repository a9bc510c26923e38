// SPDX-License-Identifier: Apache-2.0
// Writes the journal (journal_format.h) with LCM's lcm_eventlog API, on the report thread.
#pragma once

#include <lcm/eventlog.h>

#include <cstdint>
#include <string>
#include <vector>

#include "lcm/journal_format.h"

namespace enteron::lcm {

class JournalWriter {
public:
    // Throws Error(invalid_argument) naming the path when the file cannot be created.
    explicit JournalWriter(const std::string& path);
    ~JournalWriter();
    JournalWriter(const JournalWriter&) = delete;
    JournalWriter& operator=(const JournalWriter&) = delete;

    // Each returns false when the file could not be written (disk full): the caller stops journaling.
    bool write_session(const std::vector<uint8_t>& encoded_session, int64_t utime);
    bool write(const JournalRecord& record);
    bool write_end(const enteron_journal_step_t& last_step);
    void flush();

    const std::string& path() const { return path_; }

private:
    bool write_event(const char* channel, int64_t utime, const void* data, int size);

    std::string path_;
    lcm_eventlog_t* log_ = nullptr;
    std::vector<uint8_t> buffer_;
};

}  // namespace enteron::lcm
