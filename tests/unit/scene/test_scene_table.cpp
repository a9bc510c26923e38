// SPDX-License-Identifier: Apache-2.0
// The scene description's table (lib/scene/scene_table.h): each key once in its object, each
// C name once in its description and found again by it, every field another row names
// (an agreement, a bound) found from that row, and the accessors reaching the members the
// rows say, nested and optional ones too.
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "scene/scene_config.h"
#include "scene/scene_table.h"

namespace enteron::scene {
namespace {

// Every block of a table with its path ("intestine.shape") and the blocks around it.
struct Place {
    const Block* block;
    std::string path;
    std::vector<const Block*> around;  // innermost last
};

void collect(const Block& block, const std::string& path, std::vector<const Block*> around, std::vector<Place>& out) {
    out.push_back({&block, path, around});
    around.push_back(&block);
    for (const Field& field : block) {
        const std::string inner = path.empty() ? field.key : path + "." + field.key;
        if (const Object* object = std::get_if<Object>(&field.value)) collect(*object->block, inner, around, out);
        if (const List* list = std::get_if<List>(&field.value)) collect(*list->block, inner, around, out);
    }
}

std::vector<Place> every_block() {
    std::vector<Place> places;
    collect(scene_block(), "", {}, places);
    return places;
}

TEST(SceneTable, EachKeyOnceInItsObject) {
    for (const Place& place : every_block()) {
        std::set<std::string> keys;
        for (const Field& field : *place.block) {
            ASSERT_NE(field.key, nullptr);
            EXPECT_GT(std::strlen(field.key), 0u) << place.path;
            EXPECT_TRUE(keys.insert(field.key).second) << place.path << "." << field.key << " twice";
        }
    }
}

TEST(SceneTable, EachCNameOnceAndFoundByIt) {
    for (const Block* top : {&scene_block(), &tool_block()}) {
        std::set<std::string> names;
        std::vector<Place> places;
        collect(*top, "", {}, places);
        for (const Place& place : places) {
            if (place.block == &obstacle_block() || (top == &scene_block() && place.block == &tool_block())) continue;
            for (const Field& field : *place.block) {
                if (field.c_name == nullptr || std::holds_alternative<List>(field.value)) continue;
                EXPECT_TRUE(names.insert(field.c_name).second) << field.c_name << " twice";
                const FieldPath found = find_c_name(*top, field.c_name);
                EXPECT_EQ(found.field, &field) << field.c_name;
            }
        }
    }
    EXPECT_FALSE(find_c_name(scene_block(), "no_such_field_m"));
}

TEST(SceneTable, EveryFieldARowNamesIsFoundFromIt) {
    // As the validation looks them up: in the row's block or one around it, the first that has it.
    const auto found_from = [](const Place& place, const char* key) {
        if (find_path(*place.block, key)) return true;
        for (auto block = place.around.rbegin(); block != place.around.rend(); ++block)
            if (find_path(**block, key)) return true;
        return false;
    };
    std::size_t named = 0;
    for (const Place& place : every_block()) {
        for (const Field& field : *place.block) {
            if (field.agreement.other != nullptr) {
                ++named;
                EXPECT_TRUE(found_from(place, field.agreement.other)) << field.key << " names " << field.agreement.other;
            }
            if (field.limits.high_field != nullptr) {
                ++named;
                EXPECT_TRUE(found_from(place, field.limits.high_field))
                    << field.key << " names " << field.limits.high_field;
            }
        }
    }
    EXPECT_GE(named, 5u);  // radius < length, two shape spacings >= 2 radius, spacing <= radius, a pin's index
}

TEST(SceneTable, PathsFindTheirRowsAndTheAccessorsReachTheMembers) {
    SceneConfig config;
    const FieldPath pitch = find_path(scene_block(), "intestine.shape.helix_pitch");
    ASSERT_TRUE(pitch);
    std::get<Number>(pitch.field->value).set(pitch.make_part(&config), 0.07);
    EXPECT_EQ(config.intestine.shape.helix_pitch, 0.07);

    // A member of a member: collision.stiffness is contact.stiffness.
    const FieldPath stiffness = find_path(scene_block(), "collision.stiffness");
    ASSERT_TRUE(stiffness);
    std::get<Number>(stiffness.field->value).set(stiffness.make_part(&config), 321.0);
    EXPECT_EQ(config.collision.contact.stiffness, 321.0);

    // An optional part: absent until made, and then with its defaults.
    const FieldPath drag = find_path(scene_block(), "damping.drag");
    ASSERT_TRUE(drag);
    EXPECT_EQ(drag.part(&config), nullptr);
    EXPECT_EQ(std::get<Number>(drag.field->value).get(drag.make_part(&config)), DampingConfig{}.drag);
    ASSERT_TRUE(config.damping);

    // An optional value: gravity is absent until set.
    const FieldPath gravity = find_path(scene_block(), "gravity");
    ASSERT_TRUE(gravity);
    ASSERT_NE(gravity.field->present, nullptr);
    EXPECT_FALSE(gravity.field->present(&config));
    std::get<Point>(gravity.field->value).set(&config, Vec3(0.0, 0.0, -1.0));
    ASSERT_TRUE(config.gravity);
    EXPECT_EQ((*config.gravity)[2], -1.0);

    // An enum as its int32_t, a count of uint32_t as a size_t.
    const FieldPath clamped = find_path(scene_block(), "pinned.clamped");
    std::get<Choice>(clamped.field->value).set(clamped.make_part(&config), pin_both);
    EXPECT_EQ(config.pinned->clamped, pin_both);
    const Block& pin_block = *std::get<List>(find_path(scene_block(), "pinned.attached").field->value).block;
    PinAttachment pin;
    std::get<Count>(pin_block.find("control_point")->value).set(&pin, 17);
    EXPECT_EQ(pin.point, 17u);

    EXPECT_FALSE(find_path(scene_block(), "intestine.no_such_key"));
    EXPECT_FALSE(find_path(scene_block(), "no_such_object.radius"));
}

TEST(SceneTable, AFieldOfAnotherKindDoesNotApply) {
    ShapeConfig shape;
    const Block& block = *std::get<Object>(find_path(scene_block(), "intestine.shape").field->value).block;
    shape.kind = ShapeKind::line;
    EXPECT_TRUE(block.applies(*block.find("direction"), &shape));
    EXPECT_FALSE(block.applies(*block.find("helix_pitch"), &shape));
    shape.kind = static_cast<ShapeKind>(1000);  // out of range: nothing but the kind applies
    EXPECT_FALSE(block.applies(*block.find("center"), &shape));
    EXPECT_TRUE(block.applies(*block.kind, &shape));
}

}  // namespace
}  // namespace enteron::scene
