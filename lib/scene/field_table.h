// SPDX-License-Identifier: Apache-2.0
// The vocabulary of a description table (scene_table.h). A Field is one key of a JSON
// object: where its value goes in the config, the rule the value obeys, its plausible range
// and its name in C. A Block is the fields of one object. The JSON loader, the validation,
// the plausibility warnings, the C descriptions and the documentation test all walk the
// tables, so a new setting is one row:
//
//     number<&SolverConfig::max_speed>("max_speed", "max_speed_m_per_s").above(0.0),
//
// A value lives in a part (the object its block describes: a SolverConfig, a ToolConfig),
// reached through accessors made from the member pointers of the row, so one walk serves
// every part; the accessors convert each member to one of a few value types (a count of any
// integer type is a std::size_t, an enum an int32_t, a position a Vec3), and an optional
// member makes an optional field (absent: not checked).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <variant>
#include <vector>

#include "base/geometry.h"

namespace enteron::scene {

struct Block;
struct PlausibleRange;

// value > low (above) or >= low (at_least); value < high (below) or <= high (at_most).
// A bound may be another field instead of a number (`high_field`, found as Agreement::other
// is), for an index into something the description sizes: "< intestine.control_points (80)".
struct Limits {
    enum class Low : uint8_t { none, above, at_least };
    enum class High : uint8_t { none, below, at_most };
    Low low = Low::none;
    High high = High::none;
    double low_value = 0.0;
    double high_value = 0.0;
    const char* high_field = nullptr;
};

// A value that must agree with another field: value <, <= or >= factor x other. The other is
// named by its key, found in the field's own block or in a block around it ("radius" from
// intestine.shape is intestine.radius), or by its path from the top ("intestine.radius").
// The validation's message blames what the caller wrote (validate.h).
struct Agreement {
    enum class Relation : uint8_t { none, below, at_most, at_least };
    Relation relation = Relation::none;
    double factor = 1.0;
    const char* other = nullptr;
};

// The JSON names of an enum's values ("helix", "bdf2", "both").
struct ChoiceName {
    const char* name;
    int32_t value;
};
struct Choices {
    const ChoiceName* names = nullptr;
    std::size_t count = 0;
};

// How a value of type T is read from and written to its part.
template <typename T>
struct Access {
    T (*get)(const void* part) = nullptr;
    void (*set)(void* part, const T& value) = nullptr;
};

// The types a value can have. Numbers must be finite; a count is a JSON integer.
struct Number : Access<double> {};
struct Count : Access<std::size_t> {
    std::uint64_t max = std::numeric_limits<std::size_t>::max();  // the largest JSON accepts
};
struct Choice : Access<int32_t> {
    Choices choices;
};
struct Point : Access<Vec3> {
    bool direction = false;  // also non-zero, with a length that can be normalised
};
struct Rotation : Access<std::array<double, 4>> {};  // a quaternion w x y z, normalised
struct Flag : Access<bool> {};
// An object with the keys of `block`. find: the part it describes, or null when it is absent
// (an effect the description leaves off); make: that part, made if absent (a JSON object
// turns its effect on).
struct Object {
    const void* (*find)(const void* part) = nullptr;
    void* (*make)(void* part) = nullptr;
    const Block* block = nullptr;
};
// An array of objects of `block` (tools, obstacles). `what` says what the array holds in a
// message: "must be an array of tools".
struct List {
    std::size_t (*size)(const void* part) = nullptr;
    void* (*element)(void* part, std::size_t index) = nullptr;
    void (*resize)(void* part, std::size_t size) = nullptr;
    const Block* block = nullptr;
    const char* what = nullptr;
};
// A value with a shape of its own, read and checked by code that knows it (json_loader.cpp,
// validate.cpp). A new one is rare: most settings are one of the types above.
enum class Special : uint8_t {
    version,         // "version": 1
    shape_points,    // intestine.shape.points: [[x, y, z], ...] into control_points x 3 numbers
    pinned_points,   // pinned.control_points: indices of control points
    mesh_file,       // an obstacle's mesh, from an OBJ or PLY file
    mesh_vertices,   // an obstacle's mesh given inline
    mesh_triangles,
    mesh_scale,      // the mesh's unit, applied once every key is read
    length_profile,  // intestine.radius_profile, ...: [[s, value], ...] into pairs (Custom::profile)
    root_polyline,   // mesentery.root: [[x, y, z], ...], two or more, into coordinates (Custom::profile)
    root_mapping,    // mesentery.root_mapping: [[s, t], ...] into pairs (Custom::profile)
};
struct Custom {
    Special special;
    // length_profile, root_polyline, root_mapping: its numbers in the part; length_profile:
    // the key of the constant it replaces.
    std::vector<double>& (*profile)(void* part) = nullptr;
    const char* replaces = nullptr;
};

using Value = std::variant<Number, Count, Choice, Point, Rotation, Flag, Object, List, Custom>;

// One key of a JSON object (and its C field). Made by the factories below, then refined:
//   number<&IntestineConfig::radius>("radius", "radius_m").above(0.0).below("length")
struct Field {
    const char* key = nullptr;     // the JSON key in its object
    const char* c_name = nullptr;  // the ent_*_desc field, when C names it otherwise than its key
    Value value;
    Limits limits;
    Agreement agreement;
    const PlausibleRange* plausible = nullptr;  // a value outside is likely a unit mistake (plausible_ranges.h)
    bool zero_is_off = false;                   // 0 turns the effect off: not a mistake to warn about
    bool plausible_magnitude = false;           // the range is of a point's length (gravity's), not of each coordinate
    uint32_t kinds = ~0u;                       // the kinds of its block it belongs to (Block::kind)
    bool obstacle_index = false;                // an obstacle's index: checked once the environment is
    bool (*present)(const void* part) = nullptr;  // an optional value: whether the part has it

    Field above(double bound) const { return low(Limits::Low::above, bound); }
    Field at_least(double bound) const { return low(Limits::Low::at_least, bound); }
    Field below(double bound) const { return high(Limits::High::below, bound); }
    Field at_most(double bound) const { return high(Limits::High::at_most, bound); }
    // An index below the value of another field ("intestine.control_points").
    Field below(const char* other) const {
        Field f = high(Limits::High::below, 0.0);
        f.limits.high_field = other;
        return f;
    }
    // value < / <= / >= factor x other (Agreement).
    Field must_be(Agreement::Relation relation, double factor, const char* other) const {
        Field f = *this;
        f.agreement = {relation, factor, other};
        return f;
    }
    Field plausible_in(const PlausibleRange& range, bool zero_turns_off = false) const {
        Field f = *this;
        f.plausible = &range;
        f.zero_is_off = zero_turns_off;
        return f;
    }
    // Only for these kinds (a bit per kind: kind_bit) of its block's kind field.
    Field plausible_length_in(const PlausibleRange& range) const {
        Field f = plausible_in(range, true);
        f.plausible_magnitude = true;
        return f;
    }
    Field for_kinds(uint32_t bits) const {
        Field f = *this;
        f.kinds = bits;
        return f;
    }
    Field indexing_obstacles() const {
        Field f = *this;
        f.obstacle_index = true;
        return f;
    }

private:
    Field low(Limits::Low kind, double bound) const {
        Field f = *this;
        f.limits.low = kind;
        f.limits.low_value = bound;
        return f;
    }
    Field high(Limits::High kind, double bound) const {
        Field f = *this;
        f.limits.high = kind;
        f.limits.high_value = bound;
        return f;
    }
};

template <typename Kind>
constexpr uint32_t kind_bit(Kind kind) {
    return 1u << static_cast<uint32_t>(kind);
}

// The fields of one JSON object (and of the part it describes). When `kind` is set, that
// field's choice selects which of the others apply (Field::kinds): a helix has no
// leg_length. `typed`: the kind comes first and alone picks the keys ("type" of an
// obstacle: a key of another type is unknown); otherwise a key of another kind "does not
// apply" (a shape's).
struct Block {
    const Field* fields = nullptr;
    std::size_t count = 0;
    const Field* kind = nullptr;
    bool typed = false;
    // typed: the part as that kind starts, before its keys are read (the defaults of its kind).
    void (*start)(void* part, int32_t kind) = nullptr;
    // What a JSON object of this block looks like, for a message: "{"first": k, "last": k}
    // naming obstacles" ("must be an object {...}"); null: "an object".
    const char* looks_like = nullptr;
    bool every_key_required = false;  // JSON: an object without one of its keys (not optional ones) is refused
    // Rules between the block's fields beyond their rows', in validate.cpp, run after them.
    enum class Check : uint8_t { none, pinned, attached_pin, clamped_attached, pin_span, obstacle } check = Check::none;

    const Field* begin() const { return fields; }
    const Field* end() const { return fields + count; }
    // The field of that key, or null.
    const Field* find(const char* key) const;
    // Whether `field` applies to the part's kind.
    bool applies(const Field& field, const void* part) const;
};

template <std::size_t N>
Block block_of(const Field (&fields)[N]) {
    return Block{fields, N};
}

// ---- accessors from member pointers ---------------------------------------------------

namespace access {

// The part type a path starts from: the class of a member pointer, or the argument of an
// accessor function (for what a member pointer cannot reach: an array's element).
template <typename M>
struct Owner;
template <typename C, typename T>
struct Owner<T C::*> {
    using type = C;
};
template <typename C, typename T>
struct Owner<T& (*)(C&)> {
    using type = C;
};

template <typename T>
struct IsOptional : std::false_type {};
template <typename T>
struct IsOptional<std::optional<T>> : std::true_type {};

// The member a path of member pointers (or accessor functions) reaches from a part:
// Reach<&CollisionConfig::contact, &ContactParameters::stiffness> is part.contact.stiffness.
template <auto... Steps>
struct Reach;
template <>
struct Reach<> {
    template <typename T>
    static T& reach(T& t) {
        return t;
    }
};
template <auto Step, auto... Rest>
struct Reach<Step, Rest...> {
    template <typename T>
    static auto& reach(T& t) {
        if constexpr (std::is_member_pointer_v<decltype(Step)>) {
            return Reach<Rest...>::reach(t.*Step);
        } else {
            return Reach<Rest...>::reach(Step(t));
        }
    }
};

template <auto First, auto... Rest>
auto& member(void* part) {
    using Part = typename Owner<decltype(First)>::type;
    return Reach<First, Rest...>::reach(*static_cast<Part*>(part));
}
template <auto... Path>
const auto& member(const void* part) {
    return member<Path...>(const_cast<void*>(part));
}

// A member of type T as the value type V.
template <typename V, typename T>
struct Convert {
    static V get(const T& t) { return static_cast<V>(t); }
    static void set(T& t, const V& v) { t = static_cast<T>(v); }
};
template <>
struct Convert<std::array<double, 4>, Eigen::Quaterniond> {
    static std::array<double, 4> get(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }
    static void set(Eigen::Quaterniond& q, const std::array<double, 4>& v) { q.coeffs() << v[1], v[2], v[3], v[0]; }
};
template <typename V, typename T>
struct Convert<V, std::optional<T>> {
    static V get(const std::optional<T>& t) { return Convert<V, T>::get(*t); }
    static void set(std::optional<T>& t, const V& v) { Convert<V, T>::set(t.emplace(), v); }
};

template <typename V, auto... Path>
V get(const void* part) {
    const auto& m = member<Path...>(part);
    return Convert<V, std::decay_t<decltype(m)>>::get(m);
}
template <typename V, auto... Path>
void set(void* part, const V& value) {
    auto& m = member<Path...>(part);
    Convert<V, std::decay_t<decltype(m)>>::set(m, value);
}
template <auto... Path>
bool has(const void* part) {
    return member<Path...>(part).has_value();
}

template <typename V, auto... Path>
Access<V> of() {
    return {&get<V, Path...>, &set<V, Path...>};
}

template <auto... Path>
using MemberType = std::decay_t<decltype(member<Path...>(static_cast<void*>(nullptr)))>;

template <auto... Path>
Field field(const char* key, const char* c_name, Value value) {
    Field f;
    f.key = key;
    f.c_name = c_name;
    f.value = value;
    if constexpr (IsOptional<MemberType<Path...>>::value) f.present = &has<Path...>;
    return f;
}

template <auto... Path>
const void* find(const void* part) {
    const auto& m = member<Path...>(part);
    if constexpr (IsOptional<std::decay_t<decltype(m)>>::value) {
        return m ? static_cast<const void*>(&*m) : nullptr;
    } else {
        return &m;
    }
}
template <auto... Path>
void* make(void* part) {
    auto& m = member<Path...>(part);
    if constexpr (IsOptional<std::decay_t<decltype(m)>>::value) {
        return &m.emplace();
    } else {
        return &m;
    }
}

// An object that only switches a flag on (self_collision: {}): the part itself when on.
template <auto... Path>
const void* find_switched(const void* part) {
    return member<Path...>(part) ? part : nullptr;
}
template <auto... Path>
void* make_switched(void* part) {
    member<Path...>(part) = true;
    return part;
}
// An object whose keys fill the part it is in (pinned.clamped_attached fills the pinned part).
inline const void* find_here(const void* part) { return part; }
inline void* make_here(void* part) { return part; }

template <auto... Path>
std::size_t size(const void* part) {
    return member<Path...>(part).size();
}
template <auto... Path>
void* element(void* part, std::size_t index) {
    return &member<Path...>(part)[index];
}
template <auto... Path>
void resize(void* part, std::size_t size) {
    member<Path...>(part).assign(size, {});
}

}  // namespace access

// ---- the factories of the rows --------------------------------------------------------

template <auto... Path>
Field number(const char* key, const char* c_name = nullptr) {
    return access::field<Path...>(key, c_name, Number{access::of<double, Path...>()});
}
template <auto... Path>
Field count(const char* key, const char* c_name = nullptr,
            std::uint64_t max = std::numeric_limits<std::size_t>::max()) {
    return access::field<Path...>(key, c_name, Count{access::of<std::size_t, Path...>(), max});
}
template <auto... Path, std::size_t N>
Field choice(const char* key, const char* c_name, const ChoiceName (&names)[N]) {
    return access::field<Path...>(key, c_name, Choice{access::of<int32_t, Path...>(), Choices{names, N}});
}
template <auto... Path>
Field point(const char* key, const char* c_name = nullptr) {
    return access::field<Path...>(key, c_name, Point{access::of<Vec3, Path...>(), false});
}
// A direction: a point that must be non-zero and normalisable.
template <auto... Path>
Field direction(const char* key, const char* c_name = nullptr) {
    return access::field<Path...>(key, c_name, Point{access::of<Vec3, Path...>(), true});
}
template <auto... Path>
Field rotation(const char* key, const char* c_name = nullptr) {
    return access::field<Path...>(key, c_name, Rotation{access::of<std::array<double, 4>, Path...>()});
}
template <auto... Path>
Field flag(const char* key, const char* c_name = nullptr) {
    return access::field<Path...>(key, c_name, Flag{access::of<bool, Path...>()});
}
// An object member (or an optional one: absent, its effect is off).
template <auto... Path>
Field object(const char* key, const Block& block) {
    Field f;
    f.key = key;
    f.value = Object{&access::find<Path...>, &access::make<Path...>, &block};
    return f;
}
// An object whose presence switches a flag (self_collision).
template <auto... Path>
Field switch_object(const char* key, const Block& block) {
    Field f;
    f.key = key;
    f.value = Object{&access::find_switched<Path...>, &access::make_switched<Path...>, &block};
    return f;
}
// An object whose keys are fields of the part around it.
inline Field object_here(const char* key, const Block& block) {
    Field f;
    f.key = key;
    f.value = Object{&access::find_here, &access::make_here, &block};
    return f;
}
template <auto... Path>
Field list(const char* key, const Block& block, const char* what, const char* c_name = nullptr) {
    Field f;
    f.key = key;
    f.c_name = c_name;
    f.value = List{&access::size<Path...>, &access::element<Path...>, &access::resize<Path...>, &block, what};
    return f;
}
// A property along the length (Special::length_profile) in place of the constant `replaces`.
template <auto Member>
Field length_profile(const char* key, const char* c_name, const char* replaces) {
    Field f;
    f.key = key;
    f.c_name = c_name;
    f.value = Custom{Special::length_profile,
                     [](void* part) -> std::vector<double>& { return access::member<Member>(part); }, replaces};
    return f;
}
// Numbers of a special shape kept in a vector of the part (Special::root_polyline, root_mapping).
template <auto Member>
Field numbers(const char* key, const char* c_name, Special special) {
    Field f;
    f.key = key;
    f.c_name = c_name;
    f.value = Custom{special, [](void* part) -> std::vector<double>& { return access::member<Member>(part); }};
    return f;
}
inline Field custom(const char* key, Special special, const char* c_name = nullptr) {
    Field f;
    f.key = key;
    f.c_name = c_name;
    f.value = Custom{special};
    return f;
}

}  // namespace enteron::scene
