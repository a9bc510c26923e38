// SPDX-License-Identifier: Apache-2.0
// ent_lcm_check_message's rule (message_check.h): bytes encoded by lcm-gen's own encoders
// pass, whatever their counts; any other size, a negative count, a string without its NUL
// or another type's fingerprint do not. And the layout it relies on: counts last among the
// fixed fields, arrays after them in the same order.
#include <gtest/gtest.h>

#include <lcmtypes/enteron_journal_step_t.h>
#include <lcmtypes/enteron_mesh_t.h>
#include <lcmtypes/enteron_scene_state_t.h>
#include <lcmtypes/enteron_session_t.h>
#include <lcmtypes/enteron_tool_command_t.h>
#include <lcmtypes/enteron_tool_feedback_t.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "enteron/enteron_lcm.h"
#include "lcm/message_check.h"

namespace enteron::lcm {
namespace {

template <class Message>
std::vector<uint8_t> message_check_encode(const Message& m, int (*size_of)(const Message*),
                            int (*encoder)(void*, int, int, const Message*)) {
    std::vector<uint8_t> bytes(static_cast<std::size_t>(size_of(&m)));
    EXPECT_EQ(encoder(bytes.data(), 0, static_cast<int>(bytes.size()), &m), static_cast<int>(bytes.size()));
    return bytes;
}

MessageFault check(int32_t type, const std::vector<uint8_t>& bytes) {
    return check_message(type, bytes.data(), bytes.size(), nullptr, 0);
}

void write_int32(std::vector<uint8_t>& bytes, std::size_t offset, int32_t value) {
    for (int i = 0; i < 4; ++i) bytes[offset + i] = static_cast<uint8_t>(static_cast<uint32_t>(value) >> (24 - 8 * i));
}

// scene_state_t with n control points, m axis points and t tools, as the server would send it.
std::vector<uint8_t> scene_state(int n, int m, int t) {
    std::vector<float> control(3 * n, 0.5f), axis(3 * m, 0.25f);
    std::vector<float*> control_rows(n), axis_rows(m);
    for (int i = 0; i < n; ++i) control_rows[i] = &control[3 * i];
    for (int i = 0; i < m; ++i) axis_rows[i] = &axis[3 * i];
    std::vector<enteron_tool_state_t> tools(t);
    enteron_scene_state_t message{};
    message.num_control_points = n;
    message.num_axis_points = m;
    message.num_tools = t;
    message.control_points_m = control_rows.data();
    message.axis_m = axis_rows.data();
    message.tools = tools.data();
    return message_check_encode(message, enteron_scene_state_t_encoded_size, enteron_scene_state_t_encode);
}

TEST(MessageCheck, FixedSizeMessagesMustBeExact) {
    enteron_tool_command_t command{};
    const std::vector<uint8_t> bytes = message_check_encode(command, enteron_tool_command_t_encoded_size, enteron_tool_command_t_encode);
    EXPECT_EQ(bytes.size(), tool_command_size());
    EXPECT_EQ(check(ENT_LCM_TOOL_COMMAND, bytes), MessageFault::none);
    std::vector<uint8_t> longer = bytes;
    longer.push_back(0);
    EXPECT_EQ(check(ENT_LCM_TOOL_COMMAND, longer), MessageFault::size);
    EXPECT_EQ(check(ENT_LCM_TOOL_COMMAND, std::vector<uint8_t>(bytes.begin(), bytes.end() - 1)), MessageFault::size);
    EXPECT_EQ(check(ENT_LCM_TOOL_COMMAND, {}), MessageFault::size);
    std::vector<uint8_t> other = bytes;
    other[3] ^= 1;
    EXPECT_EQ(check(ENT_LCM_TOOL_COMMAND, other), MessageFault::fingerprint);
    // Another type's bytes, padded to the command's size, are still not a command.
    enteron_journal_step_t step{};
    std::vector<uint8_t> step_bytes = message_check_encode(step, enteron_journal_step_t_encoded_size, enteron_journal_step_t_encode);
    step_bytes.resize(bytes.size());
    EXPECT_EQ(check(ENT_LCM_TOOL_COMMAND, step_bytes), MessageFault::fingerprint);
}

TEST(MessageCheck, ArraysPassAtAnyCountTheEncoderWrites) {
    std::mt19937 random(7);
    for (int trial = 0; trial < 20; ++trial) {
        const int n = static_cast<int>(random() % 300), m = static_cast<int>(random() % 300),
                  t = static_cast<int>(random() % 4);
        const std::vector<uint8_t> bytes = scene_state(n, m, t);
        ASSERT_EQ(check(ENT_LCM_SCENE_STATE, bytes), MessageFault::none) << n << " " << m << " " << t;
    }
}

TEST(MessageCheck, HostileCountsAreRefusedBeforeAnyDecoding) {
    const std::vector<uint8_t> good = scene_state(4, 5, 1);
    enteron_scene_state_t empty{};
    const std::size_t counts = static_cast<std::size_t>(enteron_scene_state_t_encoded_size(&empty)) - 12;
    for (int field = 0; field < 3; ++field) {
        for (int32_t count : {-1, -2147483647 - 1, 2147483647, 6}) {
            std::vector<uint8_t> bytes = good;
            write_int32(bytes, counts + 4 * field, count);
            const MessageFault fault = check(ENT_LCM_SCENE_STATE, bytes);
            EXPECT_NE(fault, MessageFault::none) << "field " << field << " count " << count;
            EXPECT_EQ(fault, count < 0 ? MessageFault::count : MessageFault::size);
        }
    }
}

TEST(MessageCheck, MeshCountsAgreeWithItsArrays) {
    const int vertices = 7, triangles = 3;
    std::vector<float> positions(3 * vertices, 1.0f), normals(3 * vertices, 0.0f), u(vertices, 0.5f);
    std::vector<int32_t> indices(3 * triangles, 0);
    std::vector<float*> position_rows(vertices), normal_rows(vertices);
    std::vector<int32_t*> triangle_rows(triangles);
    for (int i = 0; i < vertices; ++i) position_rows[i] = &positions[3 * i], normal_rows[i] = &normals[3 * i];
    for (int i = 0; i < triangles; ++i) triangle_rows[i] = &indices[3 * i];
    enteron_mesh_t mesh{};
    mesh.num_vertices = vertices;
    mesh.num_triangles = triangles;
    mesh.positions_m = position_rows.data();
    mesh.normals = normal_rows.data();
    mesh.axis_u = u.data();
    mesh.triangles = triangle_rows.data();
    std::vector<uint8_t> bytes = message_check_encode(mesh, enteron_mesh_t_encoded_size, enteron_mesh_t_encode);
    EXPECT_EQ(check(ENT_LCM_MESH, bytes), MessageFault::none);
    bytes.resize(bytes.size() - 12);  // one triangle short
    EXPECT_EQ(check(ENT_LCM_MESH, bytes), MessageFault::size);
}

TEST(MessageCheck, TheSessionStringMustFillTheRestAndEndWithItsNul) {
    std::string json = "{\"intestine\": {}}";
    enteron_session_t session{};
    session.scene_json = json.data();
    std::vector<uint8_t> bytes = message_check_encode(session, enteron_session_t_encoded_size, enteron_session_t_encode);
    EXPECT_EQ(check(ENT_LCM_SESSION, bytes), MessageFault::none);
    std::vector<uint8_t> no_nul = bytes;
    no_nul.back() = '}';
    EXPECT_EQ(check(ENT_LCM_SESSION, no_nul), MessageFault::count);
    std::vector<uint8_t> huge = bytes;
    write_int32(huge, huge.size() - json.size() - 1 - 4, 2147483647);
    EXPECT_EQ(check(ENT_LCM_SESSION, huge), MessageFault::size);
    write_int32(huge, huge.size() - json.size() - 1 - 4, 0);
    EXPECT_EQ(check(ENT_LCM_SESSION, huge), MessageFault::count);
}

TEST(MessageCheck, UnknownTypesAreNamed) {
    char detail[128] = "";
    EXPECT_EQ(check_message(99, "", 0, detail, sizeof detail), MessageFault::fingerprint);
    EXPECT_STREQ(detail, "unknown message type 99");
    EXPECT_FALSE(known_message_type(8));
    EXPECT_TRUE(known_message_type(ENT_LCM_JOURNAL_STEP));
}

}  // namespace
}  // namespace enteron::lcm
