// SPDX-License-Identifier: Apache-2.0
// A C description struct (ent_scene_desc, ent_tool_desc) bound to its description's table
// (scene/scene_table.h): each field of the struct is listed once, by its name, which is the
// C name of a row of the table; the row says where the value goes in the config, how it is
// checked and how it is named. The list fills the struct's defaults from a default config,
// a config from a caller's struct, and a struct from a scene's config (read back).
//
//     ENTERON_DESC_FIELD(ent_scene_desc, radius_m),
//
// Fields that are not values of a row (struct_size, effects, pointers and their counts) are
// handled by the code around the list.
#pragma once

#include <cstdint>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "base/error.h"
#include "scene/scene_table.h"

namespace enteron::capi {

template <typename Desc>
struct DescField {
    const char* name;
    std::variant<double Desc::*, uint32_t Desc::*, int32_t Desc::*, double (Desc::*)[3], double (Desc::*)[4]> member;
};

// A field of Desc, named as the table's row names it.
#define ENTERON_DESC_FIELD(Desc, field) ::enteron::capi::DescField<Desc>{#field, &Desc::field}

template <typename Desc>
class DescBinding {
public:
    // Finds each field's row in `top` (and its table). A name without a row, or a row whose
    // value the field's type cannot hold, is a bug of the list: Error(internal) names it.
    template <std::size_t N>
    DescBinding(const scene::Block& top, const DescField<Desc> (&fields)[N]) {
        for (const DescField<Desc>& field : fields) {
            const scene::FieldPath path = scene::find_c_name(top, field.name);
            if (!path || !fits(field, *path.field))
                throw Error(ErrorCode::internal, std::string("no row of the description's table holds the C field ") +
                                                     field.name);
            bound_.push_back({field, path});
        }
    }

    // desc's fields from the config at `top` (a SceneConfig, a ToolConfig); a field whose
    // part is absent there (an effect left off) is left as it is.
    void write(const void* top, Desc& desc) const {
        for (const Bound& b : bound_) {
            const void* part = b.path.part(top);
            const scene::Field& row = *b.path.field;
            if (part == nullptr || (row.present != nullptr && !row.present(part))) continue;
            std::visit([&](auto member) { put(row, part, desc.*member); }, b.field.member);
        }
    }

    // The config at `top` from desc's fields, for the parts and optional values present.
    // Throws Error(invalid_argument) for a C value the row's type cannot take (a flag that is
    // neither 0 nor 1); the validation checks the rest.
    void read(const Desc& desc, void* top) const {
        for (const Bound& b : bound_) {
            const scene::Field& row = *b.path.field;
            void* part = const_cast<void*>(b.path.part(top));
            if (part == nullptr || (row.present != nullptr && !row.present(part))) continue;
            std::visit([&](auto member) { take(row, b.field.name, desc.*member, part); }, b.field.member);
        }
    }

private:
    struct Bound {
        DescField<Desc> field;
        scene::FieldPath path;
    };

    static bool fits(const DescField<Desc>& field, const scene::Field& row) {
        const std::size_t type = field.member.index();
        return std::visit(
            [&](const auto& value) {
                using V = std::decay_t<decltype(value)>;
                if constexpr (std::is_same_v<V, scene::Number>) return type == 0;
                if constexpr (std::is_same_v<V, scene::Count>) return type == 1;
                if constexpr (std::is_same_v<V, scene::Choice> || std::is_same_v<V, scene::Flag>) return type == 2;
                if constexpr (std::is_same_v<V, scene::Point>) return type == 3;
                if constexpr (std::is_same_v<V, scene::Rotation>) return type == 4;
                return false;
            },
            row.value);
    }

    static void put(const scene::Field& row, const void* part, double& out) {
        out = std::get<scene::Number>(row.value).get(part);
    }
    static void put(const scene::Field& row, const void* part, uint32_t& out) {
        out = static_cast<uint32_t>(std::get<scene::Count>(row.value).get(part));
    }
    static void put(const scene::Field& row, const void* part, int32_t& out) {
        if (const scene::Flag* flag = std::get_if<scene::Flag>(&row.value)) {
            out = flag->get(part) ? 1 : 0;
        } else {
            out = std::get<scene::Choice>(row.value).get(part);
        }
    }
    static void put(const scene::Field& row, const void* part, double (&out)[3]) {
        const Vec3 v = std::get<scene::Point>(row.value).get(part);
        for (int c = 0; c < 3; ++c) out[c] = v[c];
    }
    static void put(const scene::Field& row, const void* part, double (&out)[4]) {
        const std::array<double, 4> q = std::get<scene::Rotation>(row.value).get(part);
        for (int c = 0; c < 4; ++c) out[c] = q[c];
    }

    static void take(const scene::Field& row, const char*, double in, void* part) {
        std::get<scene::Number>(row.value).set(part, in);
    }
    static void take(const scene::Field& row, const char*, uint32_t in, void* part) {
        std::get<scene::Count>(row.value).set(part, in);
    }
    static void take(const scene::Field& row, const char* name, int32_t in, void* part) {
        if (const scene::Flag* flag = std::get_if<scene::Flag>(&row.value)) {
            if (in != 0 && in != 1)
                throw Error(ErrorCode::invalid_argument,
                            std::string(name) + " must be 0 or 1, got " + std::to_string(in));
            flag->set(part, in == 1);
        } else {
            std::get<scene::Choice>(row.value).set(part, in);
        }
    }
    static void take(const scene::Field& row, const char*, const double (&in)[3], void* part) {
        std::get<scene::Point>(row.value).set(part, Vec3(in[0], in[1], in[2]));
    }
    static void take(const scene::Field& row, const char*, const double (&in)[4], void* part) {
        std::get<scene::Rotation>(row.value).set(part, {in[0], in[1], in[2], in[3]});
    }

    std::vector<Bound> bound_;
};

}  // namespace enteron::capi
