// SPDX-License-Identifier: Apache-2.0
// The journal: an LCM log file (lcm_eventlog format, readable by lcm-logplayer, lcm-spy
// and bindings/lcm/python/log.py) holding a session_t first, then for every tick one
// journal_tool_t per tool (what the tool was given before the step) and one
// journal_step_t (the step and the state digest it reached), and, when the bridge stops
// cleanly, a journal_step_t on the end channel repeating the last tick. Its channels carry
// no suffix.
#pragma once

#include <lcmtypes/enteron_journal_step_t.h>
#include <lcmtypes/enteron_journal_tool_t.h>

#include <cstdint>

namespace enteron::lcm {

inline constexpr const char* kJournalSessionChannel = "ENTERON_SESSION";
inline constexpr const char* kJournalToolChannel = "ENTERON_JOURNAL_TOOL";
inline constexpr const char* kJournalStepChannel = "ENTERON_JOURNAL_STEP";
inline constexpr const char* kJournalEndChannel = "ENTERON_JOURNAL_END";

// One entry as the tick queues it for the report thread.
struct JournalRecord {
    enum class Kind : uint8_t { tool, step } kind = Kind::step;
    enteron_journal_tool_t tool{};
    enteron_journal_step_t step{};
};

}  // namespace enteron::lcm
