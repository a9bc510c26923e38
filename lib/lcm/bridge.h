// SPDX-License-Identifier: Apache-2.0
// A scene served over LCM (enteron_lcm.h, docs/lcm.md): the scene, the LCM instance, the
// tick, and the threads around it. Every exchange between the tick and the other threads
// goes through a preallocated wait-free queue or mailbox:
//
//   receive thread --CommandReceiver (mailbox per tool)--> tick
//   tick --feedback_ (SpscQueue)--> publish thread          (woken by notify())
//   tick --journal_, step_us_ (SpscQueue), summary_ (mailbox), log lines--> report thread
//   mesh thread: reads the scene's published snapshot through ent_skin_update
#pragma once

#include <lcm/lcm.h>
#include <lcmtypes/enteron_tool_feedback_t.h>
#include <lcmtypes/enteron_tool_state_t.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <future>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "lcm/bridge_counters.h"
#include "lcm/bridge_settings.h"
#include "lcm/clock.h"
#include "lcm/command_receiver.h"
#include "lcm/host_callbacks.h"
#include "lcm/journal_format.h"
#include "lcm/journal_writer.h"
#include "lcm/latest_mailbox.h"
#include "lcm/scene_facts.h"
#include "lcm/spsc_queue.h"
#include "lcm/tool_safety.h"
#include "lcm/wakeup.h"

namespace enteron::lcm {

// What the report thread needs of the last tick to publish a scene_state_t.
struct TickSummary {
    int64_t tick = 0;
    int64_t state_digest = 0;
    ent_stats stats{};
    std::vector<double> control_points;       // 3 per point, the exact doubles the digest hashes
    std::vector<enteron_tool_state_t> tools;
};

class Bridge {
public:
    // Throws enteron::Error; nothing is left running or open then.
    explicit Bridge(BridgeSettings settings);
    ~Bridge();
    Bridge(const Bridge&) = delete;
    Bridge& operator=(const Bridge&) = delete;

    ent_scene* scene() { return scene_; }
    lcm_t* lcm() { return lcm_; }
    const BridgeCounters& counters() const { return counters_; }
    std::size_t tool_count() const { return tools_.size(); }

    // The driving thread. Returns ENT_OK, or ENT_ERROR_INTERNAL when the scene refused a
    // call the bridge checked beforehand.
    ent_status tick(int64_t now_ns);
    void notify() { publisher_wakeup_.notify(); }
    bool started() const { return physics_running_.load(std::memory_order_acquire); }
    void start();  // throws Error(internal) when the thread cannot be made
    void stop();

    Rejection feed(const void* bytes, std::size_t size, int64_t received_ns, char* detail, std::size_t detail_size) {
        return receiver_->feed(bytes, size, received_ns, detail, detail_size);
    }
    // The driving thread: the last feedback of a tool, or null before the first tick.
    const enteron_tool_feedback_t* last_feedback(std::size_t tool) const {
        return tick_ > 0 ? &tools_[tool].feedback : nullptr;
    }

private:
    struct Tool {
        Tool(const ToolFacts& facts, const SafetyLimits& limits, const WorkspaceMapping& mapping)
            : facts(facts), safety(limits, mapping, facts.initial_pose) {}
        ToolFacts facts;
        ToolSafety safety;
        enteron_tool_feedback_t feedback{};
    };

    void make_scene();
    void open_lcm();
    void start_threads();
    void stop_threads();
    void release();
    std::vector<uint8_t> encoded_session(int64_t utime) const;
    std::string channel(const char* name) const { return name + settings_.channel_suffix; }

    // Tick parts.
    bool plan_tool(std::size_t index, int64_t now_ns, int64_t utime);
    bool render_tool(std::size_t index, int64_t now_ns, int64_t utime, bool step_ok, const ent_stats& stats,
                     TickSummary& summary);
    template <class Fill>
    void queue_journal(Fill&& fill);

    // Threads.
    void receive_loop();
    bool use_realtime_priority(int priority, const char* thread);
    void publish_loop();
    void publish_feedback();
    void report_loop();
    void report_once_a_second(std::vector<int32_t>& step_us);
    void publish_state(const TickSummary& summary);
    void publish(const char* name, const std::vector<uint8_t>& bytes);
    void publish_status();
    void publish_session();
    void write_journal();
    void mesh_loop();
    void physics_loop();
    bool wait_or_stop(int64_t timeout_ns);  // report and mesh threads: true when stopping

    BridgeSettings settings_;
    BridgeCounters counters_;
    HostCallbacks callbacks_;
    SceneFacts facts_;
    ent_scene* scene_ = nullptr;
    lcm_t* lcm_ = nullptr;
    std::unique_ptr<JournalWriter> journal_writer_;
    std::unique_ptr<CommandReceiver> receiver_;
    std::vector<Tool> tools_;
    UtimeFromMonotonic utime_;
    const int64_t created_ns_ = monotonic_ns();
    const std::string feedback_channel_ = channel("ENTERON_TOOL_FEEDBACK");
    std::promise<std::string> subscribed_;  // the receive thread's verdict on its subscription

    // Driving thread only.
    int64_t tick_ = 0;
    std::vector<double> tool_digest_values_;  // what each tool was given this tick (state_digest.h)
    bool journal_open_ = false;  // false once an entry could not be queued: the journal stops there

    // Between the tick and the other threads.
    SpscQueue<enteron_tool_feedback_t> feedback_{1024};
    SpscQueue<JournalRecord> journal_{16384};
    SpscQueue<int32_t> step_us_{4096};
    std::unique_ptr<LatestMailbox<TickSummary>> summary_;
    std::atomic<bool> journal_failed_{false};  // the report thread could not write: the journal ends
    Wakeup publisher_wakeup_;

    // Report thread only.
    enteron_journal_step_t last_journal_step_{};
    int64_t watchdog_trips_logged_ = 0;

    std::atomic<bool> stopping_{false};
    std::mutex stop_mutex_;
    std::condition_variable stop_signal_;
    std::atomic<bool> physics_running_{false};
    std::atomic<bool> physics_stop_{false};
    bool tick_failure_logged_ = false;  // physics thread
    std::thread physics_thread_;
    std::thread receive_thread_, publish_thread_, report_thread_, mesh_thread_;
};

}  // namespace enteron::lcm
