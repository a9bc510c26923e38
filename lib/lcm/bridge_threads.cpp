// SPDX-License-Identifier: Apache-2.0
// The bridge's threads: receive, publish, report, mesh, and the physics thread of
// ent_lcm_bridge_start. None of them ever waits for the tick; the tick never waits for them.
#include <lcmtypes/enteron_mesh_t.h>
#include <lcmtypes/enteron_scene_state_t.h>
#include <lcmtypes/enteron_server_status_t.h>

#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cstring>
#include <future>

#include "base/error.h"
#include "lcm/bridge.h"

namespace enteron::lcm {

namespace {

constexpr int64_t kSecond_ns = 1000000000;
constexpr int64_t kMillisecond_ns = 1000000;
constexpr int kReceiveTimeout_ms = 20;     // the receive thread notices a stop within this
constexpr int64_t kReportPeriod_ns = 2 * kMillisecond_ns;

// Sleeping threads wake this close to when they asked (the default slack is 50 us).
void tighten_timer_slack() { prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL); }

void sleep_until(int64_t monotonic_ns) {
    const timespec when{static_cast<time_t>(monotonic_ns / kSecond_ns), static_cast<long>(monotonic_ns % kSecond_ns)};
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &when, nullptr) == EINTR) {
    }
}

template <class Message>
void encode_into(std::vector<uint8_t>& bytes, const Message& message, int (*size_of)(const Message*),
                 int (*encode)(void*, int, int, const Message*)) {
    bytes.resize(static_cast<std::size_t>(size_of(&message)));
    encode(bytes.data(), 0, static_cast<int>(bytes.size()), &message);
}

// lcm-gen's C types hold a variable array of rows (float x[n][3]) as n row pointers: points
// them at the rows of a contiguous buffer, without copying.
template <class T>
T** rows_of(std::vector<T*>& rows, T* data, std::size_t count) {
    rows.resize(count);
    for (std::size_t i = 0; i < count; ++i) rows[i] = data + 3 * i;
    return rows.data();
}

}  // namespace

// The real-time priority of the threads on the feedback's path: the physics thread at the
// desc's priority, the receive and publishing threads (which run microseconds per message)
// just below it. false with a warning when not permitted.
bool Bridge::use_realtime_priority(int priority, const char* thread) {
    if (settings_.desc.realtime_priority <= 0) return true;
    sched_param parameter{};
    parameter.sched_priority = std::max(1, priority);
    const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &parameter);
    if (error == 0) return true;
    callbacks_.log(LogLevel::warning, "enteron_lcm: realtime_priority %d: the %s thread cannot use SCHED_FIFO (%s); "
                   "normal scheduling", settings_.desc.realtime_priority, thread, std::strerror(error));
    return false;
}

void Bridge::start_threads() {
    report_thread_ = std::thread([this] { report_loop(); });
    if (!settings_.network) return;
    // The receive thread subscribes itself, so that the thread LCM starts to read the
    // socket inherits its priority; its verdict comes back here (the promise is a member:
    // it outlives the receive thread's set_value).
    std::future<std::string> verdict = subscribed_.get_future();
    receive_thread_ = std::thread([this] { receive_loop(); });
    const std::string problem = verdict.get();
    if (!problem.empty()) throw Error(ErrorCode::invalid_argument, problem);
    publish_thread_ = std::thread([this] { publish_loop(); });
    if (settings_.desc.mesh_hz > 0.0) mesh_thread_ = std::thread([this] { mesh_loop(); });
}

void Bridge::stop_threads() {
    {
        std::lock_guard<std::mutex> lock(stop_mutex_);
        stopping_.store(true);
    }
    stop_signal_.notify_all();
    publisher_wakeup_.notify();
    for (std::thread* thread : {&receive_thread_, &publish_thread_, &mesh_thread_, &report_thread_})
        if (thread->joinable()) thread->join();
}

bool Bridge::wait_or_stop(int64_t timeout_ns) {
    std::unique_lock<std::mutex> lock(stop_mutex_);
    return stop_signal_.wait_for(lock, std::chrono::nanoseconds(timeout_ns), [this] { return stopping_.load(); });
}

void Bridge::publish(const char* name, const std::vector<uint8_t>& bytes) {
    if (lcm_ == nullptr) return;
    lcm_publish(lcm_, channel(name).c_str(), bytes.data(), static_cast<unsigned>(bytes.size()));
}

// ---- receive ---------------------------------------------------------------------------------

void Bridge::receive_loop() {
    use_realtime_priority(settings_.desc.realtime_priority - 1, "receive");
    // Commands are checked in the handler (CommandReceiver::feed), on this thread.
    const auto on_command = [](const lcm_recv_buf_t* buffer, const char*, void* self) {
        static_cast<Bridge*>(self)->feed(buffer->data, buffer->data_size, monotonic_ns(), nullptr, 0);
    };
    if (lcm_subscribe(lcm_, channel("ENTERON_TOOL_COMMAND").c_str(), on_command, this) == nullptr) {
        subscribed_.set_value("lcm_url: cannot subscribe to " + channel("ENTERON_TOOL_COMMAND") + " on \"" +
                              settings_.lcm_url + "\"");
        return;
    }
    subscribed_.set_value("");
    while (!stopping_.load(std::memory_order_relaxed))
        if (lcm_handle_timeout(lcm_, kReceiveTimeout_ms) < 0) {
            callbacks_.log(LogLevel::error, "enteron_lcm: LCM cannot receive on \"%s\"; the receive thread stops",
                           settings_.lcm_url.c_str());
            return;
        }
}

// ---- publish: the feedback, as soon as the tick queued it -------------------------------------

void Bridge::publish_feedback() {
    static thread_local std::vector<uint8_t> bytes;
    for (const enteron_tool_feedback_t* queued = feedback_.front(); queued != nullptr; queued = feedback_.front()) {
        enteron_tool_feedback_t feedback = *queued;
        feedback_.release();
        feedback.utime = realtime_us();  // "server clock at publication"
        encode_into(bytes, feedback, enteron_tool_feedback_t_encoded_size, enteron_tool_feedback_t_encode);
        if (lcm_publish(lcm_, feedback_channel_.c_str(), bytes.data(), static_cast<unsigned>(bytes.size())) == 0)
            BridgeCounters::add(counters_.feedback_published);
    }
}

void Bridge::publish_loop() {
    tighten_timer_slack();
    use_realtime_priority(settings_.desc.realtime_priority - 1, "publishing");
    while (!stopping_.load(std::memory_order_relaxed)) {
        publisher_wakeup_.wait(kMillisecond_ns, [this] { return !feedback_.empty() || stopping_.load(); });
        publish_feedback();
    }
    publish_feedback();
}

// ---- report: state, session, status, journal, log lines -----------------------------------------

void Bridge::publish_state(const TickSummary& summary) {
    static thread_local std::vector<float> control_points, axis;
    static thread_local std::vector<double> axis_m;
    static thread_local std::vector<uint8_t> bytes;
    static thread_local std::vector<float*> control_point_rows, axis_rows;
    const uint32_t axis_points = settings_.desc.state_axis_points;
    control_points.assign(summary.control_points.begin(), summary.control_points.end());
    axis_m.resize(3 * static_cast<std::size_t>(axis_points));
    // The axis comes from the scene's newest published state, at most a tick newer.
    if (ent_scene_axis(scene_, axis_points, axis_m.data()) != ENT_OK) return;
    axis.assign(axis_m.begin(), axis_m.end());

    enteron_scene_state_t m{};
    m.utime = realtime_us();
    m.tick = summary.tick;
    m.sim_time_s = summary.stats.time_s;
    m.state_digest = summary.state_digest;
    m.radius_m = facts_.radius_m;
    m.kinetic_energy_J = summary.stats.kinetic_energy_J;
    m.potential_energy_J = summary.stats.potential_energy_J;
    m.contacts = static_cast<int32_t>(summary.stats.contacts);
    m.max_penetration_m = summary.stats.max_penetration_m;
    m.steps = static_cast<int64_t>(summary.stats.steps);
    m.substeps = static_cast<int64_t>(summary.stats.substeps);
    m.rollbacks = static_cast<int64_t>(summary.stats.rollbacks);
    m.step_us = static_cast<int32_t>(std::min<uint64_t>(summary.stats.last_step_ns / 1000, INT32_MAX));
    m.num_control_points = static_cast<int32_t>(control_points.size() / 3);
    m.num_axis_points = static_cast<int32_t>(axis_points);
    m.num_tools = static_cast<int32_t>(summary.tools.size());
    m.control_points_m = rows_of(control_point_rows, control_points.data(), control_points.size() / 3);
    m.axis_m = rows_of(axis_rows, axis.data(), axis_points);
    m.tools = const_cast<enteron_tool_state_t*>(summary.tools.data());
    encode_into(bytes, m, enteron_scene_state_t_encoded_size, enteron_scene_state_t_encode);
    publish("ENTERON_STATE", bytes);
}

void Bridge::publish_session() { publish("ENTERON_SESSION", encoded_session(realtime_us())); }

void Bridge::publish_status() {
    ent_lcm_stats stats{};
    counters_.fill(stats);
    enteron_server_status_t m{};
    m.utime = realtime_us();
    m.session_id = stats.session_id;
    m.tick = stats.ticks;
    m.sim_time_s = stats.sim_time_s;
    m.wall_time_s = 1e-9 * static_cast<double>(monotonic_ns() - created_ns_);
    m.missed_deadlines = stats.missed_deadlines;
    m.commands_received = stats.commands_received;
    m.commands_accepted = stats.commands_accepted;
    m.commands_coalesced = stats.commands_coalesced;
    m.rejected_size = stats.rejected_size;
    m.rejected_fingerprint = stats.rejected_fingerprint;
    m.rejected_not_finite = stats.rejected_not_finite;
    m.rejected_zero_quaternion = stats.rejected_zero_quaternion;
    m.rejected_unknown_tool = stats.rejected_unknown_tool;
    m.rejected_sequence = stats.rejected_sequence;
    m.rejected_out_of_range = stats.rejected_out_of_range;
    m.sequence_gaps = stats.sequence_gaps;
    m.commands_missed = stats.commands_missed;
    m.watchdog_trips = stats.watchdog_trips;
    m.step_failures = stats.step_failures;
    m.step_us_median = stats.step_us_median;
    m.step_us_max = stats.step_us_max;
    m.tick_us_max = stats.tick_us_max;
    m.feedback_published = stats.feedback_published;
    m.feedback_dropped = stats.feedback_dropped;
    m.journal_entries = stats.journal_entries;
    m.journal_dropped = stats.journal_dropped;
    static thread_local std::vector<uint8_t> bytes;
    encode_into(bytes, m, enteron_server_status_t_encoded_size, enteron_server_status_t_encode);
    publish("ENTERON_STATUS", bytes);
}

void Bridge::write_journal() {
    for (const JournalRecord* record = journal_.front(); record != nullptr; record = journal_.front()) {
        if (!journal_failed_.load(std::memory_order_relaxed)) {
            if (!journal_writer_->write(*record)) {
                journal_failed_.store(true, std::memory_order_relaxed);
                callbacks_.log(LogLevel::error, "enteron_lcm: cannot write the journal \"%s\" (%s); it ends at tick %" PRId64,
                               journal_writer_->path().c_str(), std::strerror(errno), last_journal_step_.tick);
            } else if (record->kind == JournalRecord::Kind::step) {
                last_journal_step_ = record->step;
                BridgeCounters::add(counters_.journal_entries);
            }
        }
        journal_.release();
    }
}

void Bridge::report_once_a_second(std::vector<int32_t>& step_us) {
    step_us.clear();
    for (int32_t sample; step_us_.pop(sample);) step_us.push_back(sample);
    if (!step_us.empty()) {
        auto middle = step_us.begin() + static_cast<std::ptrdiff_t>(step_us.size() / 2);
        std::nth_element(step_us.begin(), middle, step_us.end());
        counters_.step_us_median.store(*middle, std::memory_order_relaxed);
        counters_.step_us_max.store(*std::max_element(step_us.begin(), step_us.end()), std::memory_order_relaxed);
    }
    counters_.tick_us_max.store(static_cast<int32_t>(counters_.tick_ns_max_window.exchange(0) / 1000),
                                std::memory_order_relaxed);
    publish_session();
    publish_status();
    receiver_->log_summary(1.0);
    const int64_t trips = BridgeCounters::get(counters_.watchdog_trips);
    if (trips > watchdog_trips_logged_) {
        callbacks_.log(LogLevel::warning,
                       "enteron_lcm: watchdog: %" PRId64 " time(s) a tool had no command for %.0f ms: zero force, tool held",
                       trips - watchdog_trips_logged_, 1e3 * settings_.desc.watchdog_s);
        watchdog_trips_logged_ = trips;
    }
    if (journal_writer_ != nullptr && !journal_failed_.load()) journal_writer_->flush();
}

void Bridge::report_loop() {
    std::vector<int32_t> step_us;
    step_us.reserve(step_us_.capacity());
    const double state_hz = settings_.desc.state_hz;
    const int64_t state_period_ns = state_hz > 0.0 ? static_cast<int64_t>(1e9 / state_hz) : 0;
    int64_t next_state_ns = monotonic_ns();
    int64_t next_second_ns = monotonic_ns() + kSecond_ns;
    bool have_summary = false;
    while (!wait_or_stop(kReportPeriod_ns)) {
        callbacks_.drain();
        if (journal_writer_ != nullptr) write_journal();
        have_summary = summary_->take() || have_summary;
        const int64_t now = monotonic_ns();
        if (settings_.network && state_period_ns > 0 && have_summary && now >= next_state_ns) {
            publish_state(summary_->front());
            next_state_ns = std::max(next_state_ns + state_period_ns, now);
        }
        if (now >= next_second_ns) {
            report_once_a_second(step_us);
            next_second_ns = std::max(next_second_ns + kSecond_ns, now);
        }
    }
    // Stopping: the physics thread has stopped (destroy stops it first); write what is left.
    callbacks_.drain();
    if (journal_writer_ != nullptr) {
        write_journal();
        if (!journal_failed_.load() && last_journal_step_.tick > 0 &&
            last_journal_step_.tick == BridgeCounters::get(counters_.ticks) &&
            BridgeCounters::get(counters_.journal_dropped) == 0)
            journal_writer_->write_end(last_journal_step_);
        journal_writer_->flush();
    }
    publish_status();
}

// ---- mesh --------------------------------------------------------------------------------------

void Bridge::mesh_loop() {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    desc.method = settings_.desc.mesh_skin_method;
    ent_skin* skin = nullptr;
    if (ent_skin_create(scene_, &desc, &skin) != ENT_OK) {
        callbacks_.log(LogLevel::error, "enteron_lcm: no mesh: ent_skin_create: %s", ent_last_error());
        return;
    }
    const int64_t period_ns = static_cast<int64_t>(1e9 / settings_.desc.mesh_hz);
    std::vector<uint8_t> bytes;
    std::vector<float*> position_rows, normal_rows;
    std::vector<int32_t*> triangle_rows;
    while (!wait_or_stop(period_ns)) {
        ent_mesh_view view{};
        view.struct_size = sizeof view;
        if (ent_skin_update(skin) != ENT_OK || ent_skin_mesh(skin, &view) != ENT_OK) continue;
        enteron_mesh_t m{};
        m.utime = realtime_us();
        m.tick = BridgeCounters::get(counters_.ticks);
        m.sim_time_s = view.time_s;
        m.skin_method = desc.method;
        m.num_vertices = static_cast<int32_t>(view.vertex_count);
        m.num_triangles = static_cast<int32_t>(view.triangle_count);
        // The view's rows are the messages' rows: x y z floats, three indices (each < 2^31).
        m.positions_m = rows_of(position_rows, const_cast<float*>(view.positions_xyz_m), view.vertex_count);
        m.normals = rows_of(normal_rows, const_cast<float*>(view.normals_xyz), view.vertex_count);
        m.axis_u = const_cast<float*>(view.axis_u);
        m.triangles = rows_of(triangle_rows, reinterpret_cast<int32_t*>(const_cast<uint32_t*>(view.indices)),
                              view.triangle_count);
        encode_into(bytes, m, enteron_mesh_t_encoded_size, enteron_mesh_t_encode);
        publish("ENTERON_MESH", bytes);
    }
    ent_skin_destroy(skin);
}

// ---- physics: one tick per period on an absolute-deadline clock ---------------------------------

void Bridge::start() {
    if (physics_running_.load()) throw Error(ErrorCode::invalid_argument, "the bridge is already started");
    physics_stop_.store(false);
    physics_running_.store(true, std::memory_order_release);
    try {
        physics_thread_ = std::thread([this] { physics_loop(); });
    } catch (const std::exception& error) {
        physics_running_.store(false);
        throw Error(ErrorCode::internal, std::string("cannot start the physics thread: ") + error.what());
    }
}

void Bridge::stop() {
    physics_stop_.store(true);
    if (physics_thread_.joinable()) physics_thread_.join();
    physics_running_.store(false, std::memory_order_release);
}

void Bridge::physics_loop() {
    tighten_timer_slack();
    use_realtime_priority(settings_.desc.realtime_priority, "physics");
    const int64_t period_ns = static_cast<int64_t>(std::llround(settings_.desc.tick_s * 1e9));
    int64_t due_ns = monotonic_ns();
    while (!physics_stop_.load(std::memory_order_relaxed)) {
        const int64_t started_ns = monotonic_ns();
        if (tick(started_ns) != ENT_OK && !tick_failure_logged_) {
            tick_failure_logged_ = true;
            callbacks_.log(LogLevel::error, "enteron_lcm: the scene refused a call of the tick: %s", ent_last_error());
        }
        notify();
        const int64_t finished_ns = monotonic_ns();
        const int64_t took_ns = finished_ns - started_ns;
        int64_t largest = counters_.tick_ns_max_window.load(std::memory_order_relaxed);
        while (took_ns > largest && !counters_.tick_ns_max_window.compare_exchange_weak(largest, took_ns)) {
        }
        // This tick was due at due_ns and had to be done one period later.
        const int64_t deadline_ns = due_ns + period_ns;
        if (finished_ns > deadline_ns) {
            BridgeCounters::add(counters_.missed_deadlines);
            due_ns = finished_ns;  // restart the schedule: no burst of late ticks
        } else {
            due_ns = deadline_ns;
        }
        sleep_until(due_ns);
    }
}

}  // namespace enteron::lcm
