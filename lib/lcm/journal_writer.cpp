// SPDX-License-Identifier: Apache-2.0
#include "lcm/journal_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "base/error.h"

namespace enteron::lcm {

JournalWriter::JournalWriter(const std::string& path) : path_(path) {
    errno = 0;
    log_ = lcm_eventlog_create(path.c_str(), "w");
    if (log_ == nullptr)
        throw Error(ErrorCode::invalid_argument, "journal_path: cannot create \"" + path + "\": " +
                                                     (errno != 0 ? std::strerror(errno) : "unknown error"));
    buffer_.resize(1024);
}

JournalWriter::~JournalWriter() {
    if (log_ != nullptr) lcm_eventlog_destroy(log_);
}

bool JournalWriter::write_event(const char* channel, int64_t utime, const void* data, int size) {
    lcm_eventlog_event_t event{};
    event.timestamp = utime;
    event.channellen = static_cast<int32_t>(std::strlen(channel));
    event.datalen = size;
    event.channel = const_cast<char*>(channel);
    event.data = const_cast<void*>(data);  // lcm_eventlog_write_event only reads it
    return lcm_eventlog_write_event(log_, &event) == 0;
}

bool JournalWriter::write_session(const std::vector<uint8_t>& encoded_session, int64_t utime) {
    return write_event(kJournalSessionChannel, utime, encoded_session.data(), static_cast<int>(encoded_session.size()));
}

bool JournalWriter::write(const JournalRecord& record) {
    if (record.kind == JournalRecord::Kind::tool) {
        const int size = enteron_journal_tool_t_encode(buffer_.data(), 0, static_cast<int>(buffer_.size()), &record.tool);
        return size > 0 && write_event(kJournalToolChannel, record.tool.utime, buffer_.data(), size);
    }
    const int size = enteron_journal_step_t_encode(buffer_.data(), 0, static_cast<int>(buffer_.size()), &record.step);
    return size > 0 && write_event(kJournalStepChannel, record.step.utime, buffer_.data(), size);
}

bool JournalWriter::write_end(const enteron_journal_step_t& last_step) {
    const int size = enteron_journal_step_t_encode(buffer_.data(), 0, static_cast<int>(buffer_.size()), &last_step);
    const bool written = size > 0 && write_event(kJournalEndChannel, last_step.utime, buffer_.data(), size);
    flush();
    return written;
}

void JournalWriter::flush() { std::fflush(log_->f); }

}  // namespace enteron::lcm
