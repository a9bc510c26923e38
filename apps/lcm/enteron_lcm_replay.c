/* SPDX-License-Identifier: Apache-2.0 */
/*
 * enteron-lcm-replay: replays a journal written by enteron-lcm-server --journal (or any
 * bridge with a journal_path) and checks that the scene reaches, bit for bit, the state
 * digest the journal recorded after every tick (docs/lcm.md, "Journal and replay").
 *
 *   enteron-lcm-replay FILE
 *
 * Prints "bit-identical over N ticks" and exits 0, or prints the first tick that differs
 * (or whose entry is damaged) and exits 1. Exits 2 when FILE is not a journal.
 */
#include <enteron/enteron_lcm.h>

#include <stdio.h>
#include <string.h>

int main(int argc, char** argv) {
    ent_lcm_replay_result result;
    if (argc != 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        fprintf(argc == 2 ? stdout : stderr, "usage: enteron-lcm-replay FILE\n"
                                             "Replays a journal of enteron-lcm-server and compares every tick's state.\n");
        return argc == 2 ? 0 : 2;
    }
    memset(&result, 0, sizeof result);
    result.struct_size = sizeof result;
    if (ent_lcm_replay_journal(argv[1], NULL, &result) != ENT_OK) {
        fprintf(stderr, "enteron-lcm-replay: %s: %s\n", argv[1], ent_lcm_last_error());
        return 2;
    }
    printf("enteron-lcm-replay: %s: %s\n", argv[1], result.message);
    return result.identical ? 0 : 1;
}
