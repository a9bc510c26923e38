// SPDX-License-Identifier: Apache-2.0
#include "lcm/journal_reader.h"

#include <cerrno>
#include <cstring>

#include "base/error.h"

namespace enteron::lcm {

namespace {

constexpr uint32_t kMagic = 0xEDA1DA01u;
constexpr int64_t kHeaderBytes = 4 + 8 + 8 + 4 + 4;
constexpr int32_t kLongestChannel = 255;

int64_t big_endian(const unsigned char* p, int bytes) {
    uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | p[i];
    return bytes == 4 ? static_cast<int32_t>(static_cast<uint32_t>(value)) : static_cast<int64_t>(value);
}

}  // namespace

JournalReader::JournalReader(const std::string& path) {
    file_ = std::fopen(path.c_str(), "rb");
    if (file_ == nullptr)
        throw Error(ErrorCode::invalid_argument, "cannot open the journal \"" + path + "\": " + std::strerror(errno));
    if (std::fseek(file_, 0, SEEK_END) == 0) size_ = std::ftell(file_);
    std::fseek(file_, 0, SEEK_SET);
}

JournalReader::~JournalReader() {
    if (file_ != nullptr) std::fclose(file_);
}

JournalReader::Next JournalReader::next(LogEvent& event, std::string& problem) {
    if (offset_ == size_) return Next::end;
    unsigned char header[kHeaderBytes];
    const auto fail = [&](Next kind, const std::string& what) {
        problem = "byte " + std::to_string(offset_) + ": " + what;
        return kind;
    };
    if (size_ - offset_ < kHeaderBytes || std::fread(header, 1, sizeof header, file_) != sizeof header)
        return fail(Next::truncated, "the file ends inside an event header");
    if (static_cast<uint32_t>(big_endian(header, 4)) != kMagic)
        return fail(Next::damaged, "no event starts here (bad magic)");
    const int64_t channel_length = big_endian(header + 20, 4);
    const int64_t data_length = big_endian(header + 24, 4);
    if (channel_length < 1 || channel_length > kLongestChannel || data_length < 0)
        return fail(Next::damaged, "channel length " + std::to_string(channel_length) + ", data length " +
                                       std::to_string(data_length));
    if (data_length > size_ - offset_ - kHeaderBytes - channel_length)
        return fail(Next::truncated, "the file ends inside an event of " + std::to_string(data_length) + " bytes");
    event.number = big_endian(header + 4, 8);
    event.timestamp_us = big_endian(header + 12, 8);
    event.channel.resize(static_cast<std::size_t>(channel_length));
    event.data.resize(static_cast<std::size_t>(data_length));
    if (std::fread(event.channel.data(), 1, event.channel.size(), file_) != event.channel.size() ||
        std::fread(event.data.data(), 1, event.data.size(), file_) != event.data.size())
        return fail(Next::truncated, "the file ends inside an event");
    offset_ += kHeaderBytes + channel_length + data_length;
    return Next::event;
}

}  // namespace enteron::lcm
