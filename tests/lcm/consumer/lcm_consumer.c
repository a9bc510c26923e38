/* SPDX-License-Identifier: Apache-2.0 */
/* A program built against an installed libenteron_lcm: makes a bridge without a network,
 * feeds it one command, ticks it, reads the feedback back. Exit 0 when all of it works. */
#include <enteron/enteron_lcm.h>

#include <stdio.h>
#include <string.h>

static const char scene[] = "{\"intestine\": {\"length\": 0.4, \"control_points\": 9},"
                            " \"tools\": [{\"position\": [0, 0, 0.1]}]}";

int main(void) {
    ent_lcm_bridge_desc desc;
    ent_lcm_bridge* bridge = NULL;
    unsigned char feedback[512];
    size_t size = 0;
    ent_lcm_bridge_desc_default(&desc);
    desc.scene_json = scene;
    desc.scene_json_length = strlen(scene);
    desc.lcm_url = "";
    if (ent_lcm_bridge_create(&desc, &bridge) != ENT_OK || ent_lcm_bridge_tick(bridge, ent_lcm_monotonic_ns()) != ENT_OK ||
        ent_lcm_bridge_feedback(bridge, 0, feedback, sizeof feedback, &size) != ENT_OK ||
        ent_lcm_check_message(ENT_LCM_TOOL_FEEDBACK, feedback, size) != ENT_OK) {
        fprintf(stderr, "lcm_consumer: %s\n", ent_lcm_last_error());
        ent_lcm_bridge_destroy(bridge);
        return 1;
    }
    ent_lcm_bridge_destroy(bridge);
    printf("lcm_consumer: libenteron_lcm %u.%u.%u, one tick, a %zu-byte tool_feedback_t\n", ent_lcm_version() >> 16,
           (ent_lcm_version() >> 8) & 0xff, ent_lcm_version() & 0xff, size);
    return 0;
}
