// SPDX-License-Identifier: Apache-2.0
// The scene of the bridge's tests, the fuzzer and the probe (also
// examples/lcm/scenes/short_bowel.json, which the server tests load): a 0.4 m bowel along x
// on the floor of a box (z = 0), a tool with max_force 5 N starting 6 cm above its middle.
#pragma once

inline constexpr char kShortBowelScene[] =
    "{\"intestine\": {\"length\": 0.4, \"control_points\": 17, \"stretch_stiffness\": 100,"
    " \"bend_stiffness\": 2.5e-3, \"shape\": {\"kind\": \"line\", \"center\": [-0.2, 0, 0.0125]}},"
    " \"gravity\": [0, 0, -9.81], \"damping\": {},"
    " \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0.1], \"half_extents\": [0.25, 0.15, 0.1]}],"
    " \"tools\": [{\"radius\": 0.005, \"length\": 0.3, \"max_force\": 5, \"position\": [0, 0.06, 0.06]}]}";
inline constexpr double kShortBowelMaxForce_N = 5.0;
