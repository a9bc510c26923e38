// SPDX-License-Identifier: Apache-2.0
// The guard of the driving calls (ent_scene_step, ent_scene_add_obstacle, ent_tool_add,
// ent_scene_save_state, ent_scene_restore_state and the anatomy's changes between steps,
// enteron.h lists them):
// one atomic exchange detects a driving call on the same scene that is still running on
// another thread, and the call then fails with ENT_ERROR_BUSY before it touches anything.
// Two threads stepping one scene at once used to hang in the near-pair search or publish
// garbage; now the second gets an error and the first goes on.
#pragma once

#include <atomic>
#include <string>

#include "base/error.h"
#include "capi/scene_handle.h"

namespace enteron::capi {

// Holds an atomic flag for the length of one call: a call that finds it held throws
// ENT_ERROR_BUSY with busy_message() and touches nothing. The message is made only then, so
// holding the flag allocates nothing (the step's guard).
class ExclusiveCall {
public:
    template <class Message>
    ExclusiveCall(std::atomic<bool>& flag, Message&& busy_message) : flag_(flag) {
        if (flag_.exchange(true, std::memory_order_acquire)) throw Error(ErrorCode::busy, busy_message());
    }
    ~ExclusiveCall() { flag_.store(false, std::memory_order_release); }
    ExclusiveCall(const ExclusiveCall&) = delete;
    ExclusiveCall& operator=(const ExclusiveCall&) = delete;

private:
    std::atomic<bool>& flag_;
};

class DrivingCall : ExclusiveCall {
public:
    // `call` names the entry point ("ent_scene_step"), for the message.
    DrivingCall(SceneHandle& handle, const char* call)
        : ExclusiveCall(handle.driving, [call] {
              return std::string(call) +
                     ": another thread is in a driving call on this scene (ent_scene_step, "
                     "ent_scene_add_obstacle, ent_tool_add, ent_scene_save_state, "
                     "ent_scene_restore_state or a change of the anatomy between steps); "
                     "driving calls on one scene must not overlap. Nothing was done: call "
                     "again once it has returned";
          }) {}
};

}  // namespace enteron::capi
