// SPDX-License-Identifier: Apache-2.0
#include "lcm/journal_replay.h"

#include <lcmtypes/enteron_session_t.h>

#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "base/error.h"
#include "lcm/journal_format.h"
#include "lcm/journal_reader.h"
#include "lcm/message_check.h"
#include "lcm/scene_calls.h"
#include "lcm/state_digest.h"

namespace enteron::lcm {

namespace {

struct SceneDeleter {
    void operator()(ent_scene* scene) const { ent_scene_destroy(scene); }
};
using ScenePtr = std::unique_ptr<ent_scene, SceneDeleter>;

// Reads the session entry and makes its scene.
ScenePtr scene_of_session(const LogEvent& event, const ent_callbacks* callbacks, int64_t& start_tick,
                          int32_t& tools, std::string& note) {
    char problem[200];
    if (event.channel != kJournalSessionChannel ||
        check_message(ENT_LCM_SESSION, event.data.data(), event.data.size(), problem, sizeof problem) !=
            MessageFault::none)
        throw Error(ErrorCode::invalid_argument, "not a journal: its first entry is not a session_t on " +
                                                     std::string(kJournalSessionChannel) + " (" + event.channel + ")");
    enteron_session_t session;
    if (enteron_session_t_decode(event.data.data(), 0, static_cast<int>(event.data.size()), &session) < 0)
        throw Error(ErrorCode::invalid_argument, "not a journal: its session_t does not decode");
    const std::string json = session.scene_json;
    start_tick = session.start_tick;
    tools = session.num_tools;
    if (static_cast<uint32_t>(session.library_version) != ent_version()) {
        char line[160];
        std::snprintf(line, sizeof line, " (recorded with libenteron %d.%d.%d, replayed with %u.%u.%u)",
                      session.library_version >> 16, (session.library_version >> 8) & 0xff,
                      session.library_version & 0xff, ent_version() >> 16, (ent_version() >> 8) & 0xff,
                      ent_version() & 0xff);
        note = line;
    }
    enteron_session_t_decode_cleanup(&session);
    ent_scene* scene = nullptr;
    const ent_status status = ent_scene_create_json_with(json.data(), json.size(), callbacks, &scene);
    if (status != ENT_OK)
        throw Error(static_cast<ErrorCode>(status), std::string("the journal's scene: ") + ent_last_error());
    return ScenePtr(scene);
}

class Replay {
public:
    explicit Replay(ent_lcm_replay_result& out) : out_(out) {}

    void run(const char* path, const ent_callbacks* callbacks) {
        JournalReader reader(path);
        LogEvent event;
        std::string problem;
        if (reader.next(event, problem) != JournalReader::Next::event)
            throw Error(ErrorCode::invalid_argument, std::string("not a journal: \"") + path + "\" holds no entry" +
                                                         (problem.empty() ? "" : ": " + problem));
        int32_t tools = 0;
        scene_ = scene_of_session(event, callbacks, tick_, tools, note_);
        tools_ = tools;
        uint32_t points = 0;
        ent_scene_control_points(scene_.get(), 0, nullptr, &points);
        control_points_.assign(3 * static_cast<std::size_t>(points), 0.0);
        tool_digest_values_.assign(kToolDigestValues * static_cast<std::size_t>(tools_), 0.0);
        ++tick_;  // the first tick to come

        std::string cut;
        for (;;) {
            const JournalReader::Next next = reader.next(event, problem);
            if (next == JournalReader::Next::end) break;
            if (next == JournalReader::Next::truncated) {
                cut = " (" + problem + ")";
                break;
            }
            if (next == JournalReader::Next::damaged) return damaged(problem);
            if (event.channel == kJournalToolChannel) {
                if (!apply_tool(event)) return;
            } else if (event.channel == kJournalStepChannel) {
                if (!apply_step(event)) return;
            } else if (event.channel == kJournalEndChannel) {
                out_.complete = 1;
                break;
            } else {
                return damaged("an entry on channel \"" + event.channel + "\", which a journal does not have");
            }
        }
        out_.identical = 1;
        std::snprintf(out_.message, sizeof out_.message, "bit-identical over %" PRId64 " ticks%s%s%s", out_.ticks,
                      out_.complete ? "" : "; the journal has no end record (the session did not stop cleanly)",
                      cut.c_str(), note_.c_str());
    }

private:
    void damaged(const std::string& what) {
        out_.first_difference_tick = tick_;
        std::snprintf(out_.message, sizeof out_.message, "tick %" PRId64 ": damaged journal entry: %s%s", tick_,
                      what.c_str(), note_.c_str());
    }

    template <class Message>
    bool decode(int32_t type, const LogEvent& event, int (*decoder)(const void*, int, int, Message*), Message& message) {
        char problem[200];
        if (check_message(type, event.data.data(), event.data.size(), problem, sizeof problem) != MessageFault::none) {
            damaged(problem);
            return false;
        }
        decoder(event.data.data(), 0, static_cast<int>(event.data.size()), &message);
        if (message_tick(message) != tick_) {
            damaged("an entry for tick " + std::to_string(message_tick(message)));
            return false;
        }
        return true;
    }
    static int64_t message_tick(const enteron_journal_tool_t& m) { return m.tick; }
    static int64_t message_tick(const enteron_journal_step_t& m) { return m.tick; }

    bool apply_tool(const LogEvent& event) {
        enteron_journal_tool_t entry;
        if (!decode(ENT_LCM_JOURNAL_TOOL, event, enteron_journal_tool_t_decode, entry)) return false;
        if (entry.tool < 0 || entry.tool >= tools_ || entry.grasp_action < 0 || entry.grasp_action > 2) {
            damaged("tool " + std::to_string(entry.tool) + ", grasp action " + std::to_string(entry.grasp_action));
            return false;
        }
        if (give_tool(scene_.get(), entry.tool, entry.position_m, entry.orientation_wxyz,
                      static_cast<GraspAction>(entry.grasp_action),
                      &tool_digest_values_[kToolDigestValues * static_cast<std::size_t>(entry.tool)]) != ENT_OK) {
            damaged(std::string("the scene refused the tool's pose: ") + ent_last_error());
            return false;
        }
        return true;
    }

    bool apply_step(const LogEvent& event) {
        enteron_journal_step_t entry;
        if (!decode(ENT_LCM_JOURNAL_STEP, event, enteron_journal_step_t_decode, entry)) return false;
        int64_t digest = 0;
        ent_stats stats{};
        const ent_status status =
            step_and_digest(scene_.get(), entry.dt_s, tool_digest_values_, control_points_, stats, digest);
        if (status != entry.step_status || digest != entry.state_digest) {
            out_.first_difference_tick = tick_;
            out_.journal_digest = entry.state_digest;
            out_.replay_digest = digest;
            std::snprintf(out_.message, sizeof out_.message,
                          "tick %" PRId64 " differs: state digest 0x%016" PRIx64 " (step status %d) in the journal, "
                          "0x%016" PRIx64 " (status %d) replayed, after %" PRId64 " identical ticks%s",
                          tick_, static_cast<uint64_t>(entry.state_digest), entry.step_status,
                          static_cast<uint64_t>(digest), status, out_.ticks, note_.c_str());
            return false;
        }
        ++out_.ticks;
        ++tick_;
        return true;
    }

    ent_lcm_replay_result& out_;
    ScenePtr scene_;
    int32_t tools_ = 0;
    int64_t tick_ = 0;
    std::vector<double> control_points_;
    std::vector<double> tool_digest_values_;
    std::string note_;
};

}  // namespace

void replay_journal(const char* path, const ent_callbacks* callbacks, ent_lcm_replay_result& out) {
    std::memset(&out, 0, sizeof out);
    out.struct_size = sizeof out;
    out.first_difference_tick = -1;
    Replay(out).run(path, callbacks);
}

}  // namespace enteron::lcm
