// SPDX-License-Identifier: Apache-2.0
// The bridge's life: creation, the tick and destruction. Its threads are in bridge_threads.cpp.
#include "lcm/bridge.h"

#include <lcmtypes/enteron_session_t.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "base/error.h"
#include "lcm/message_check.h"
#include "lcm/scene_calls.h"
#include "lcm/state_digest.h"

namespace enteron::lcm {

namespace {

int64_t random_session_id() {
    std::random_device device;
    return static_cast<int64_t>((static_cast<uint64_t>(device()) << 32) | device());
}

int32_t clamp_to_int32(int64_t value) {
    return static_cast<int32_t>(std::clamp<int64_t>(value, std::numeric_limits<int32_t>::min(),
                                                    std::numeric_limits<int32_t>::max()));
}

void copy3(const Eigen::Vector3d& from, double to[3]) {
    for (int i = 0; i < 3; ++i) to[i] = from[i];
}
void copy_wxyz(const Eigen::Quaterniond& from, double to[4]) {
    to[0] = from.w(), to[1] = from.x(), to[2] = from.y(), to[3] = from.z();
}

}  // namespace

Bridge::Bridge(BridgeSettings settings)
    : settings_(std::move(settings)),
      callbacks_(settings_.has_callbacks ? &settings_.callbacks : nullptr, counters_) {
    counters_.session_id = random_session_id();
    prepare_message_types();
    try {
        make_scene();
        receiver_ = std::make_unique<CommandReceiver>(tools_.size(), settings_.mapping, settings_.limits().watchdog_ns,
                                                      counters_, callbacks_);
        if (!settings_.journal_path.empty()) {
            journal_writer_ = std::make_unique<JournalWriter>(settings_.journal_path);
            if (!journal_writer_->write_session(encoded_session(realtime_us()), realtime_us()))
                throw Error(ErrorCode::invalid_argument,
                            "journal_path: cannot write to \"" + settings_.journal_path + "\"");
            journal_open_ = true;
        }
        open_lcm();
        start_threads();
        publish_session();
    } catch (...) {
        stop_threads();
        release();
        throw;
    }
}

Bridge::~Bridge() {
    stop();
    stop_threads();
    release();
}

void Bridge::make_scene() {
    const ent_status status = ent_scene_create_json_with(settings_.scene_json.data(), settings_.scene_json.size(),
                                                         &callbacks_.scene_callbacks(), &scene_);
    if (status != ENT_OK) throw Error(static_cast<ErrorCode>(status), std::string("scene_json: ") + ent_last_error());
    facts_ = read_scene_facts(scene_);
    tools_.reserve(facts_.tools.size());
    for (const ToolFacts& tool : facts_.tools) {
        SafetyLimits limits = settings_.limits();
        limits.tool_max_force_N = tool.max_force_N;
        tools_.emplace_back(tool, limits, settings_.mapping);
    }
    uint32_t points = 0;
    ent_scene_control_points(scene_, 0, nullptr, &points);
    TickSummary initial;
    initial.control_points.assign(3 * static_cast<std::size_t>(points), 0.0);
    initial.tools.assign(tools_.size(), enteron_tool_state_t{});
    summary_ = std::make_unique<LatestMailbox<TickSummary>>(initial);
    tool_digest_values_.assign(kToolDigestValues * tools_.size(), 0.0);
}

void Bridge::open_lcm() {
    if (!settings_.network) return;
    lcm_ = lcm_create(settings_.lcm_url.c_str());
    if (lcm_ == nullptr)
        throw Error(ErrorCode::invalid_argument,
                    "lcm_url: LCM cannot open \"" + settings_.lcm_url + "\" (liblcm wrote why on stderr)");
}

void Bridge::release() {
    journal_writer_.reset();
    if (lcm_ != nullptr) lcm_destroy(lcm_);
    lcm_ = nullptr;
    if (scene_ != nullptr) ent_scene_destroy(scene_);
    scene_ = nullptr;
}

std::vector<uint8_t> Bridge::encoded_session(int64_t utime) const {
    const ent_lcm_bridge_desc& d = settings_.desc;
    enteron_session_t m{};
    m.utime = utime;
    m.session_id = counters_.session_id;
    m.library_version = static_cast<int32_t>(ent_version());
    m.bridge_version = static_cast<int32_t>(ENT_VERSION);
    m.num_tools = static_cast<int32_t>(tools_.size());
    m.start_tick = 0;
    m.tick_s = d.tick_s;
    m.watchdog_s = d.watchdog_s;
    m.state_hz = d.state_hz;
    m.mesh_hz = d.mesh_hz;
    m.mesh_skin_method = d.mesh_skin_method;
    m.state_axis_points = static_cast<int32_t>(d.state_axis_points);
    m.force_ramp_s = d.force_ramp_s;
    m.max_tool_speed_m_per_s = d.max_tool_speed_m_per_s;
    m.max_tool_angular_speed_rad_per_s = d.max_tool_angular_speed_rad_per_s;
    m.device_max_force = d.device_max_force;
    m.max_force_change_per_tick = d.max_force_change_per_tick;
    m.workspace_scale = d.workspace_scale;
    std::copy(d.workspace_rotation_wxyz, d.workspace_rotation_wxyz + 4, m.workspace_rotation_wxyz);
    std::copy(d.workspace_offset_m, d.workspace_offset_m + 3, m.workspace_offset_m);
    m.force_scale = d.force_scale;
    std::string json = settings_.scene_json;
    m.scene_json = json.data();
    std::vector<uint8_t> bytes(static_cast<std::size_t>(enteron_session_t_encoded_size(&m)));
    enteron_session_t_encode(bytes.data(), 0, static_cast<int>(bytes.size()), &m);
    return bytes;
}

// ---- the tick ------------------------------------------------------------------------------

template <class Fill>
void Bridge::queue_journal(Fill&& fill) {
    if (!journal_open_) return;
    if (journal_failed_.load(std::memory_order_relaxed)) {
        journal_open_ = false;
        return;
    }
    JournalRecord* record = journal_.claim();
    if (record == nullptr) {  // the report thread fell behind: the journal ends here
        journal_open_ = false;
        return;
    }
    fill(*record);
    journal_.commit();
}

bool Bridge::plan_tool(std::size_t index, int64_t now_ns, int64_t utime) {
    Tool& tool = tools_[index];
    LatestMailbox<AcceptedCommand>& mailbox = receiver_->mailbox(index);
    const AcceptedCommand* fresh = mailbox.take() ? &mailbox.front() : nullptr;
    const ToolSafety::Plan plan = tool.safety.plan(fresh, now_ns);
    if (plan.watchdog_tripped) BridgeCounters::add(counters_.watchdog_trips);

    const Pose& pose = tool.safety.applied_pose();
    double position[3], orientation[4];
    copy3(pose.position, position);
    copy_wxyz(pose.orientation, orientation);
    const int32_t id = static_cast<int32_t>(index);
    const bool given = give_tool(scene_, id, position, orientation, plan.grasp_action,
                                 &tool_digest_values_[kToolDigestValues * index]) == ENT_OK;
    queue_journal([&](JournalRecord& record) {
        record.kind = JournalRecord::Kind::tool;
        enteron_journal_tool_t& entry = record.tool;
        entry.utime = utime;
        entry.tick = tick_;
        entry.tool = id;
        std::copy(position, position + 3, entry.position_m);
        std::copy(orientation, orientation + 4, entry.orientation_wxyz);
        entry.grasp_action = static_cast<int8_t>(plan.grasp_action);
        entry.grasp = tool.safety.jaws_closed() ? 1 : 0;
        entry.force_enable = tool.safety.live() && tool.safety.latest().force_enable ? 1 : 0;
        entry.command_seq = tool.safety.live() ? tool.safety.latest().seq : -1;
    });
    return given;
}

bool Bridge::render_tool(std::size_t index, int64_t now_ns, int64_t utime, bool step_ok, const ent_stats& stats,
                         TickSummary& summary) {
    Tool& tool = tools_[index];
    const int32_t id = static_cast<int32_t>(index);
    // The wrench and the grasp of the step just published, from one snapshot.
    ent_tool_feedback output{};
    output.struct_size = sizeof output;
    const bool read = ent_tool_read_feedback(scene_, id, &output) == ENT_OK;
    const int32_t grasping = read ? output.grasping : 0;
    const Eigen::Vector3d scene_force(output.force_N[0], output.force_N[1], output.force_N[2]);
    const Eigen::Vector3d scene_torque(output.torque_Nm[0], output.torque_Nm[1], output.torque_Nm[2]);
    // dF/dx of that force with respect to the tip (ent_tool_stiffness), scene frame, from
    // the same snapshot.
    const Eigen::Matrix3d scene_stiffness =
        read ? Eigen::Matrix3d(Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(output.stiffness_N_per_m))
             : Eigen::Matrix3d::Zero();
    ToolSafety& safety = tool.safety;
    safety.render(scene_force, scene_torque, scene_stiffness, read && output.saturated != 0, step_ok && read);
    // A device locked out (another sender keeps the sequence, a command the checks refuse)
    // hears it here: the safety's bits and the last rejection of the watchdog time.
    const int32_t status =
        safety.status() | rejection_status(receiver_->recent_rejection(index, now_ns, settings_.limits().watchdog_ns));

    enteron_tool_feedback_t& feedback = tool.feedback;
    feedback.utime = utime;
    feedback.tick = tick_;
    feedback.sim_time_s = stats.time_s;
    feedback.tool = id;
    feedback.command_seq = safety.live() ? safety.latest().seq : -1;
    feedback.command_utime = safety.live() ? safety.latest().utime : 0;
    feedback.command_age_us = safety.live() ? clamp_to_int32(safety.command_age_ns() / 1000) : 0;
    copy3(safety.device_force(), feedback.force_N);
    copy3(safety.device_torque(), feedback.torque_Nm);
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(feedback.stiffness_N_per_m) = safety.device_stiffness();
    const Pose device_pose = settings_.mapping.to_device(safety.applied_pose());
    copy3(device_pose.position, feedback.applied_position_m);
    copy_wxyz(device_pose.orientation, feedback.applied_orientation_wxyz);
    feedback.grasping = static_cast<int8_t>(grasping);
    feedback.status = status;
    feedback.step_us = clamp_to_int32(static_cast<int64_t>(stats.last_step_ns / 1000));
    if (settings_.network && !feedback_.push(feedback)) BridgeCounters::add(counters_.feedback_dropped);

    enteron_tool_state_t& state = summary.tools[index];
    state.tool = id;
    state.radius_m = tool.facts.radius_m;
    state.length_m = tool.facts.length_m;
    state.max_force_N = tool.facts.max_force_N;
    copy3(safety.commanded_pose().position, state.commanded_position_m);
    copy_wxyz(safety.commanded_pose().orientation, state.commanded_orientation_wxyz);
    copy3(safety.applied_pose().position, state.applied_position_m);
    copy_wxyz(safety.applied_pose().orientation, state.applied_orientation_wxyz);
    copy3(scene_force, state.force_N);
    copy3(scene_torque, state.torque_Nm);
    copy3(safety.rendered_scene_force(), state.rendered_force_N);
    state.grasping = static_cast<int8_t>(grasping);
    state.jaws_closed = safety.jaws_closed() ? 1 : 0;
    state.status = status;
    state.command_seq = feedback.command_seq;
    return read;
}

ent_status Bridge::tick(int64_t now_ns) {
    callbacks_.enter_tick();
    ++tick_;
    const int64_t utime = utime_(now_ns);
    bool calls_ok = true;
    for (std::size_t i = 0; i < tools_.size(); ++i) calls_ok = plan_tool(i, now_ns, utime) && calls_ok;

    TickSummary& summary = summary_->back();
    const double dt = settings_.desc.tick_s;
    const ent_status step =
        step_and_digest(scene_, dt, tool_digest_values_, summary.control_points, summary.stats, summary.state_digest);
    const bool step_ok = step == ENT_OK;
    if (!step_ok) BridgeCounters::add(counters_.step_failures);
    calls_ok = step != ENT_ERROR_INTERNAL && calls_ok;
    summary.tick = tick_;

    for (std::size_t i = 0; i < tools_.size(); ++i)
        calls_ok = render_tool(i, now_ns, utime, step_ok, summary.stats, summary) && calls_ok;
    queue_journal([&](JournalRecord& record) {
        record.kind = JournalRecord::Kind::step;
        enteron_journal_step_t& entry = record.step;
        entry.utime = utime;
        entry.tick = tick_;
        entry.dt_s = dt;
        entry.step_status = step;
        entry.sim_time_s = summary.stats.time_s;
        entry.state_digest = summary.state_digest;
    });
    if (journal_writer_ != nullptr && !journal_open_) BridgeCounters::add(counters_.journal_dropped);
    summary_->publish();
    step_us_.push(clamp_to_int32(static_cast<int64_t>(summary.stats.last_step_ns / 1000)));
    counters_.sim_time_s.store(summary.stats.time_s, std::memory_order_relaxed);
    counters_.ticks.store(tick_, std::memory_order_relaxed);
    callbacks_.leave_tick();
    return calls_ok ? ENT_OK : ENT_ERROR_INTERNAL;
}

}  // namespace enteron::lcm
