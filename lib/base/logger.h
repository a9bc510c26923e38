// SPDX-License-Identifier: Apache-2.0
// Log lines go to the scene's callback only; without one the library is silent.
// Formatting uses a stack buffer, so logging from the step allocates nothing.
#pragma once

#include <cstdarg>
#include <cstdint>
#include <cstdio>

namespace enteron {

enum class LogLevel : int32_t { debug = 0, info = 1, warning = 2, error = 3 };

class Logger {
public:
    using Callback = void (*)(void* user, int32_t level, const char* message);

    Logger() = default;
    Logger(Callback callback, void* user) : callback_(callback), user_(user) {}

    bool enabled() const { return callback_ != nullptr; }

#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    void log(LogLevel level, const char* format, ...) const {
        if (callback_ == nullptr) return;
        char line[512];
        va_list args;
        va_start(args, format);
        std::vsnprintf(line, sizeof line, format, args);
        va_end(args);
        callback_(user_, static_cast<int32_t>(level), line);
    }

private:
    Callback callback_ = nullptr;
    void* user_ = nullptr;
};

}  // namespace enteron
