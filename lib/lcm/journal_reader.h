// SPDX-License-Identifier: Apache-2.0
// Reads an LCM log file event by event, for the replay. LCM's own reader
// (lcm_eventlog_read_next_event) prints to stderr on a damaged file and allocates whatever
// size a damaged header claims; this one never prints, and refuses a header whose sizes
// run past the end of the file.
//
// The format (lcm_eventlog): per event, big-endian, the int32 magic 0xEDA1DA01, int64 event
// number, int64 timestamp (us), int32 channel length, int32 data length, the channel's
// bytes, the data's bytes.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace enteron::lcm {

struct LogEvent {
    int64_t number = 0;
    int64_t timestamp_us = 0;
    std::string channel;
    std::vector<uint8_t> data;
};

class JournalReader {
public:
    // Throws Error(invalid_argument) naming the path when it cannot be opened.
    explicit JournalReader(const std::string& path);
    ~JournalReader();
    JournalReader(const JournalReader&) = delete;
    JournalReader& operator=(const JournalReader&) = delete;

    enum class Next { event, end, truncated, damaged };
    // The next event. `truncated`: the file ends inside an event (a writer that stopped
    // mid-write); `damaged`: something else is wrong. For both, `problem` says what and where.
    Next next(LogEvent& event, std::string& problem);

private:
    std::FILE* file_ = nullptr;
    int64_t size_ = 0;
    int64_t offset_ = 0;
};

}  // namespace enteron::lcm
