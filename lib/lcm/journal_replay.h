// SPDX-License-Identifier: Apache-2.0
// enteron-lcm-replay's work (ent_lcm_replay_journal): re-creates the scene of a journal
// from its session entry and gives it, tick by tick, exactly what the journal says the
// bridge gave it (journal_format.h), comparing the state digest after every step. Stops
// at the first tick that differs or whose entries are damaged.
#pragma once

#include "enteron/enteron_lcm.h"

namespace enteron::lcm {

// Fills every field of `out` (the caller copies what its struct_size allows). Throws
// Error for a file that is not a journal or a scene that cannot be made.
void replay_journal(const char* path, const ent_callbacks* callbacks, ent_lcm_replay_result& out);

}  // namespace enteron::lcm
