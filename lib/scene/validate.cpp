// SPDX-License-Identifier: Apache-2.0
#include "scene/validate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mechanics/clamped_ends.h"
#include "scene/checked_value.h"
#include "scene/pin_spans.h"
#include "scene/plausible_ranges.h"
#include "scene/points_length.h"
#include "scene/scene_table.h"
#include "scene/shape_builder.h"
#include "spline/length_profile.h"

namespace enteron::scene {
namespace {

std::string format(const Vec3& v) {
    return "[" + format_number(v[0]) + ", " + format_number(v[1]) + ", " + format_number(v[2]) + "]";
}

// "0-11, 40, 52-239": the indices (ascending) as ranges, at most a few of them.
std::string index_ranges(const std::vector<std::size_t>& indices) {
    constexpr std::size_t kMaxRanges = 6;
    std::string text;
    std::size_t ranges = 0;
    for (std::size_t i = 0; i < indices.size();) {
        std::size_t j = i;
        while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
        if (ranges == kMaxRanges) return text + ", ...";
        text += (text.empty() ? "" : ", ") + std::to_string(indices[i]);
        if (j > i) text += "-" + std::to_string(indices[j]);
        ++ranges;
        i = j + 1;
    }
    return text;
}

// The JSON name of an obstacle's type ("box_inside"), from the table.
const char* obstacle_kind_name(collision::ObstacleKind kind) {
    const Choices& kinds = std::get<Choice>(obstacle_block().kind->value).choices;
    for (std::size_t i = 0; i < kinds.count; ++i)
        if (kinds.names[i].value == static_cast<int32_t>(kind)) return kinds.names[i].name;
    return "?";
}

// Refuses an obstacle with control points so far beyond its surface that their contacts
// would throw them out faster than the guard allows (StartClearance): every step of such a
// scene would fail.
void check_clearance(const collision::Obstacle& o, const std::string& name, ErrorCode code, const double* points,
                     std::size_t count, const StartClearance& clearance) {
    const mechanics::FramePlacement frame = mechanics::placement_at(o.pose);
    std::vector<std::size_t> stuck;
    double deepest = 0.0, escape = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const double depth = collision::beyond_surface(o, frame.to_local(point_at(points, i)));
        // Beyond deepest_possible the escape speed passes max_speed.
        if (depth > 0.0 && depth > clearance.deepest_possible(i)) {
            stuck.push_back(i);
            deepest = std::max(deepest, depth);
            escape = std::max(escape, (depth + clearance.radius_of(i)) * clearance.escape_rate_of(i));
        }
    }
    if (stuck.empty()) return;
    const bool organ = o.kind == collision::ObstacleKind::sphere || o.kind == collision::ObstacleKind::capsule ||
                       (o.kind == collision::ObstacleKind::mesh && !o.field->outside_is_solid());
    const char* where = organ ? "inside it" : o.kind == collision::ObstacleKind::plane ? "behind it" : "outside it";
    throw Error(code, name + " (" + obstacle_kind_name(o.kind) + ") has control points " + index_ranges(stuck) +
                          " (" + std::to_string(stuck.size()) + " of " + std::to_string(count) + ") " + where +
                          ", up to " + format_rounded(deepest) + " m beyond its surface: its contacts would throw them "
                          "out at up to " + format_rounded(escape) + " m/s, past the guard's max_speed (" +
                          format_number(clearance.max_speed) + " m/s), so the scene cannot start. Move the obstacle "
                          "or the bowel's shape so that the bowel starts " +
                          (organ ? "outside every organ" : "within the cavity"));
}

// Where the walk is: the part a block describes, its JSON path and the prefix of its C
// names, inside the scope of the object around it (null at the top).
struct Scope {
    const Scope* outer;
    const Block& block;
    void* part;
    std::string path;
    std::string prefix;
};

// A field found from a scope (Agreement::other, Limits::high_field), with its part and names.
struct Located {
    const Field* field = nullptr;
    const void* part = nullptr;
    std::string path;    // of its part
    std::string prefix;
};

// The value of a number or a count, as a double.
double value_of(const Field& field, const void* part) {
    if (const Number* number = std::get_if<Number>(&field.value)) return number->get(part);
    return static_cast<double>(std::get<Count>(field.value).get(part));
}

// Walks a description's table over a config, checking each field by its row, then the rules
// between a block's fields. Obstacle indices are checked in a second pass, once the
// environment they index is known to be valid.
class Validator {
public:
    enum class Pass { values, obstacle_indices };

    Validator(const FieldNames& names, const FieldSet& given, std::size_t obstacles)
        : names_(names), given_(given), obstacles_(obstacles) {}

    void walk(const Scope& scope, Pass pass) const;

    std::string name(const Field& field, const Scope& scope) const {
        return names_.of(field, scope.path, scope.prefix);
    }
    std::string name(const Located& at) const { return names_.of(*at.field, at.path, at.prefix); }
    [[noreturn]] void fail(const std::string& name, const std::string& message) const {
        throw Error(names_.code, name + " " + message);
    }
    // The field `key` ("radius", "intestine.radius") seen from scope: in its block, or in one
    // around it. Throws Error(internal) if the table names a field it does not have.
    Located locate(const Scope& scope, const char* key) const;

private:
    void field(const Field& field, const Scope& scope, Pass pass) const;
    template <typename T>
    void limits(const Checked<T>& value, const Field& field, const Scope& scope) const;
    void agree(double value, const Field& field, const Scope& scope) const;
    void point(const Point& point, const Field& field, const Scope& scope) const;
    void custom(const Custom& special, const Field& field, const Scope& scope) const;
    void block_rules(const Scope& scope) const;
    void shape_points(const Field& field, const Scope& scope) const;
    void pinned_points(const Field& field, const Scope& scope) const;
    void length_profile(const Custom& profile, const Field& field, const Scope& scope) const;
    void root_polyline(const Custom& polyline, const Field& field, const Scope& scope) const;
    void root_mapping(const Custom& mapping, const Field& field, const Scope& scope) const;
    // Pairs (s, value) of a profile or a mapping: at least 2, finite, s increasing along `what`.
    void check_pairs(const std::vector<double>& pairs, const std::string& own, const char* pair_looks,
                     const char* what) const;
    // Entry `part` (0: s, 1: the value) of pair k: JSON own[k][part], C own[2 k + part].
    std::string pair_entry(const std::string& own, std::size_t k, std::size_t part) const {
        return !names_.c_names ? index_path(index_path(own, k), part) : index_path(own, 2 * k + part);
    }
    // The name of a list's element (pinned.spans[0], C pinned_spans_m[0]).
    std::string element_name(const Scope& scope) const {
        return names_.c_names ? scope.prefix.substr(0, scope.prefix.size() - 1) : scope.path;
    }
    void pin_span(const Scope& scope) const;
    void mesh(const collision::TriangleMesh& mesh, const Scope& scope) const;
    std::string virtual_name(const Scope& scope, const char* key) const {
        return names_.c_names ? scope.prefix + key : join_path(scope.path, key);
    }

    const FieldNames& names_;
    const FieldSet& given_;
    std::size_t obstacles_;
};

Located Validator::locate(const Scope& scope, const char* key) const {
    for (const Scope* s = &scope; s != nullptr; s = s->outer) {
        const FieldPath found = find_path(s->block, key);
        if (!found) continue;
        Located at{found.field, found.part(s->part), s->path, s->prefix};
        for (std::size_t i = 0; i < found.depth; ++i) at.path = join_path(at.path, found.objects[i]->key);
        return at;
    }
    throw Error(ErrorCode::internal, std::string("the scene table names no field \"") + key + "\"");
}

void Validator::walk(const Scope& scope, Pass pass) const {
    for (const Field& f : scope.block) {
        if (!scope.block.applies(f, scope.part)) continue;
        if (f.present != nullptr && !f.present(scope.part)) continue;
        field(f, scope, pass);
    }
    // An attached pin is checked whole once its obstacle is known to exist.
    const bool last_pass = scope.block.check == Block::Check::attached_pin;
    if (pass == (last_pass ? Pass::obstacle_indices : Pass::values)) block_rules(scope);
}

void Validator::field(const Field& f, const Scope& scope, Pass pass) const {
    void* part = scope.part;
    if (const Object* object = std::get_if<Object>(&f.value)) {
        if (void* inner = const_cast<void*>(object->find(part)))
            walk(Scope{&scope, *object->block, inner, join_path(scope.path, f.key), scope.prefix}, pass);
        return;
    }
    if (const List* list = std::get_if<List>(&f.value)) {
        for (std::size_t i = 0; i < list->size(part); ++i)
            walk(Scope{&scope, *list->block, list->element(part, i), index_path(join_path(scope.path, f.key), i),
                       names_.element_prefix(f, scope.prefix, i)},
                 pass);
        return;
    }
    // The values: an obstacle's index once the obstacles are checked, the others before.
    if (f.obstacle_index != (pass == Pass::obstacle_indices)) return;
    if (const Number* number = std::get_if<Number>(&f.value)) {
        const double value = number->get(part);
        limits(Checked<double>(value, name(f, scope), names_.code), f, scope);
        if (f.agreement.relation != Agreement::Relation::none) agree(value, f, scope);
    } else if (const Count* count = std::get_if<Count>(&f.value)) {
        const Checked<std::size_t> value(count->get(part), name(f, scope), names_.code);
        limits(value, f, scope);
        if (f.obstacle_index) value.below(obstacles_, "the number of obstacles");
    } else if (const Choice* choice = std::get_if<Choice>(&f.value)) {
        int32_t low = choice->choices.names[0].value, high = low;
        for (std::size_t i = 1; i < choice->choices.count; ++i) {
            low = std::min(low, choice->choices.names[i].value);
            high = std::max(high, choice->choices.names[i].value);
        }
        Checked<int32_t>(choice->get(part), name(f, scope), names_.code).at_least(low).at_most(high);
    } else if (const Point* p = std::get_if<Point>(&f.value)) {
        point(*p, f, scope);
    } else if (const Rotation* rotation = std::get_if<Rotation>(&f.value)) {
        rotation->set(part, unit_quaternion(rotation->get(part), [&] { return name(f, scope); }, names_.code));
    } else if (const Custom* special = std::get_if<Custom>(&f.value)) {
        custom(*special, f, scope);
    }
}

template <typename T>
void Validator::limits(const Checked<T>& value, const Field& field, const Scope& scope) const {
    const Limits& l = field.limits;
    if (l.low == Limits::Low::above) value.above(static_cast<T>(l.low_value));
    if (l.low == Limits::Low::at_least) value.at_least(static_cast<T>(l.low_value));
    if (l.high_field != nullptr) {
        const Located other = locate(scope, l.high_field);
        value.below(static_cast<T>(value_of(*other.field, other.part)), name(other));
    } else if (l.high == Limits::High::below) {
        value.below(static_cast<T>(l.high_value));
    } else if (l.high == Limits::High::at_most) {
        value.at_most(static_cast<T>(l.high_value));
    }
}

// value (field) must be below / at most / at least factor x other. The message names what
// the caller wrote: when field still has its default but the other was given, it is the
// other that does not fit.
void Validator::agree(double value, const Field& field, const Scope& scope) const {
    using Relation = Agreement::Relation;
    const Agreement& a = field.agreement;
    const Located at = locate(scope, a.other);
    const double other = value_of(*at.field, at.part);
    const double bound = a.factor * other;
    const bool ok = a.relation == Relation::below     ? value < bound
                    : a.relation == Relation::at_most ? value <= bound
                                                      : value >= bound;
    if (ok) return;
    const char* op = a.relation == Relation::below ? "<" : a.relation == Relation::at_most ? "<=" : ">=";
    const std::string own = name(field, scope), other_name = name(at);
    const bool own_given = given_.has(join_path(scope.path, field.key));
    const bool other_given = given_.has(join_path(at.path, at.field->key));
    const std::string scaled = a.factor == 1.0 ? other_name : format_number(a.factor) + " x " + other_name;
    if (!own_given && other_given) {
        std::string message = other_name + " (" + format_number(other) + ") does not fit the default " + own + " (" +
                              format_number(value) + "), which must be " + op + " " + scaled + ": give " + own +
                              " too, or check " + other_name;
        if (at.field->plausible != nullptr) {
            const std::string unlikely = implausibility(*at.field->plausible, other);
            if (!unlikely.empty()) message += ": " + unlikely;
        }
        throw Error(names_.code, message);
    }
    std::string bound_text = scaled + " (" + format_number(bound);
    if (!other_given) bound_text += a.factor == 1.0 ? ", the default" : ", from its default " + format_number(other);
    bound_text += ")";
    throw Error(names_.code, own + " must be " + op + " " + bound_text + ", got " + format_number(value));
}

void Validator::point(const Point& p, const Field& field, const Scope& scope) const {
    const Vec3 v = p.get(scope.part);
    const std::string base = name(field, scope);
    for (std::size_t k = 0; k < 3; ++k) limits(Checked<double>(v[k], index_path(base, k), names_.code), field, scope);
    if (!p.direction) return;
    // Normalising needs a length that is neither zero nor overflowing.
    if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0) fail(base, "must be non-zero, got " + format(v));
    const double squared_length = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if (!(squared_length > 0.0) || !std::isfinite(squared_length))
        fail(base, "must have a length between 1e-150 and 1e150, got " + format(v));
}

void Validator::custom(const Custom& special, const Field& field, const Scope& scope) const {
    switch (special.special) {
        case Special::shape_points: shape_points(field, scope); break;
        case Special::length_profile: length_profile(special, field, scope); break;
        case Special::pinned_points: pinned_points(field, scope); break;
        case Special::root_polyline: root_polyline(special, field, scope); break;
        case Special::root_mapping: root_mapping(special, field, scope); break;
        // Checked when read (the version), or as the obstacle's mesh (block_rules).
        default: break;
    }
}

void Validator::shape_points(const Field& field, const Scope& scope) const {
    const ShapeConfig& shape = *static_cast<const ShapeConfig*>(scope.part);
    const Located control_points = locate(scope, "control_points");
    const auto n = static_cast<std::size_t>(value_of(*control_points.field, control_points.part));
    const std::string points = name(field, scope);
    const bool nested = !names_.c_names;
    if (shape.points.size() != 3 * n && nested)
        fail(points, "must hold " + format_number(n) + " points (" + name(control_points) + "), got " +
                         format_number(shape.points.size() / 3));
    if (shape.points.size() != 3 * n)
        fail(points, "must hold " + format_number(3 * n) + " values (" + name(control_points) + " x 3), got " +
                         format_number(shape.points.size()));
    for (std::size_t i = 0; i < shape.points.size(); ++i)
        Checked<double>(shape.points[i], nested ? index_path(index_path(points, i / 3), i % 3) : index_path(points, i),
                        names_.code);
}

void Validator::pinned_points(const Field& field, const Scope& scope) const {
    const PinnedConfig& pinned = *static_cast<const PinnedConfig*>(scope.part);
    const Located control_points = locate(scope, "intestine.control_points");
    const auto n = static_cast<std::size_t>(value_of(*control_points.field, control_points.part));
    const std::string clamped = name(*scope.block.find("clamped"), scope);
    for (std::size_t i = 0; i < pinned.points.size(); ++i) {
        const std::size_t point = pinned.points[i];
        Checked<std::size_t>(point, index_path(name(field, scope), i), names_.code).below(n, name(control_points));
        const mechanics::ClampedEnd end = mechanics::clamped_end_neighbour(
            point, n, (pinned.clamped & pin_first) != 0, (pinned.clamped & pin_last) != 0);
        if (end != mechanics::ClampedEnd::none)
            fail(index_path(name(field, scope), i),
                 "is " + std::to_string(point) + ", a control point whose motion the clamped " +
                     (end == mechanics::ClampedEnd::first ? "first" : "last") + " end already constrains (" + clamped +
                     "): a point pin there would fight the clamp; remove it");
    }
}

// A property along the length: pairs (s, value) with s increasing from 0 (or before) to the
// length (or past it), every value > 0, in place of its constant, which takes the largest.
void Validator::length_profile(const Custom& profile, const Field& field, const Scope& scope) const {
    const std::vector<double>& pairs = profile.profile(scope.part);
    if (pairs.empty()) return;
    const std::string own = name(field, scope);
    const Located constant = locate(scope, profile.replaces);
    const Located length = locate(scope, "length");
    const auto entry = [&](std::size_t k, std::size_t part) { return pair_entry(own, k, part); };
    if (!(value_of(*constant.field, constant.part) != 0.0))
        fail(own, "is given, but " + name(constant) + " is 0, which turns its effect off: give one of them");
    if (given_.has(join_path(constant.path, constant.field->key)))
        fail(own, "and " + name(constant) + " are both given: a profile replaces the constant, give one of them");
    check_pairs(pairs, own, "[s, value] (from s = 0 to the length)", "the profile");
    const std::size_t count = pairs.size() / 2;
    for (std::size_t k = 0; k < count; ++k)
        if (!(pairs[2 * k + 1] > 0.0)) fail(entry(k, 1), "must be > 0, got " + format_number(pairs[2 * k + 1]));
    const double total = value_of(*length.field, length.part);
    if (!(pairs[0] <= 0.0))
        fail(entry(0, 0), "must be <= 0: the profile must cover the bowel from its first end (s = 0), got " +
                              format_number(pairs[0]));
    // A hair of rounding spared: a points shape's length is the spline's, computed.
    if (!(pairs[2 * count - 2] >= total * (1.0 - 1e-9)))
        fail(entry(count - 1, 0), "must be >= " + name(length) + " (" + format_number(total) +
                                      "): the profile must cover the bowel to its last end, got " +
                                      format_number(pairs[2 * count - 2]));
    double largest = 0.0;
    for (std::size_t k = 0; k < count; ++k) largest = std::max(largest, pairs[2 * k + 1]);
    std::get<Number>(constant.field->value).set(const_cast<void*>(constant.part), largest);
    this->field(*constant.field, scope, Pass::values);  // its rules, for the largest value
}

void Validator::check_pairs(const std::vector<double>& pairs, const std::string& own, const char* pair_looks,
                            const char* what) const {
    const std::size_t count = pairs.size() / 2;
    if (count < 2) fail(own, std::string("must have at least 2 pairs ") + pair_looks + ", got " + std::to_string(count));
    for (std::size_t i = 0; i < pairs.size(); ++i) Checked<double>(pairs[i], pair_entry(own, i / 2, i % 2), names_.code);
    for (std::size_t k = 1; k < count; ++k)
        if (!(pairs[2 * k] > pairs[2 * k - 2]))
            fail(pair_entry(own, k, 0), "must be greater than the s before it (" + format_number(pairs[2 * k - 2]) +
                                            "): s must increase along " + what + ", got " + format_number(pairs[2 * k]));
}

// The root as a polyline of two or more finite points, in place of the segment root_start,
// root_end; consecutive points apart (each segment has a direction) when there are more
// than two. The segment then reads as the polyline's ends (two points: it is the segment).
void Validator::root_polyline(const Custom& polyline, const Field& field, const Scope& scope) const {
    std::vector<double>& xyz = polyline.profile(scope.part);
    if (xyz.empty()) return;
    const std::string own = name(field, scope);
    for (const char* end : {"root_start", "root_end"})
        if (given_.has(join_path(scope.path, end)))
            fail(own, "and " + name(*scope.block.find(end), scope) +
                          " are both given: the root is a polyline or the segment from its start to its end, give "
                          "one of them");
    const bool nested = !names_.c_names;
    const std::size_t count = xyz.size() / 3;
    if (count < 2) fail(own, "must have at least 2 points (the root's ends), got " + std::to_string(count));
    for (std::size_t i = 0; i < xyz.size(); ++i)
        Checked<double>(xyz[i], nested ? index_path(index_path(own, i / 3), i % 3) : index_path(own, i), names_.code);
    const auto point = [&](std::size_t k) { return Vec3(point_at(xyz.data(), k)); };
    for (std::size_t k = 1; k < count && count > 2; ++k)
        if (point(k) == point(k - 1))
            fail(nested ? index_path(own, k) : index_path(own, 3 * k),
                 "is the point before it again, " + format(point(k)) +
                     ": each segment of a root of more than 2 points needs a length");
    MesenteryConfig& mesentery = *static_cast<MesenteryConfig*>(scope.part);
    mesentery.root_start = point(0);
    mesentery.root_end = point(count - 1);
    if (count == 2) xyz.clear();
}

// Pairs (s, t): s along the bowel, increasing; t a fraction of the root's length, in [0, 1]
// and never decreasing (the bowel's order along the root does not turn back).
void Validator::root_mapping(const Custom& mapping, const Field& field, const Scope& scope) const {
    const std::vector<double>& pairs = mapping.profile(scope.part);
    if (pairs.empty()) return;
    const std::string own = name(field, scope);
    check_pairs(pairs, own, "[s, t] (s along the bowel in m, t the fraction of the root's length)", "the mapping");
    for (std::size_t k = 0; k < pairs.size() / 2; ++k) {
        const double t = pairs[2 * k + 1];
        if (!(t >= 0.0 && t <= 1.0))
            fail(pair_entry(own, k, 1), "must be in [0, 1], a fraction of the root's length, got " + format_number(t));
        if (k > 0 && !(t >= pairs[2 * k - 1]))
            fail(pair_entry(own, k, 1), "must be >= the t before it (" + format_number(pairs[2 * k - 1]) +
                                            "): the bowel's order along the root must not turn back, got " +
                                            format_number(t));
    }
}

// A pinned span: from <= to <= the length, holding at least one control point, none of them
// a point a clamped end constrains (the clamp's own end point only when pinned in the world).
void Validator::pin_span(const Scope& scope) const {
    const PinSpan& span = *static_cast<const PinSpan*>(scope.part);
    const std::string from = name(*scope.block.find("from"), scope), to = name(*scope.block.find("to"), scope);
    const Located length = locate(scope, "intestine.length");
    const Located control_points = locate(scope, "intestine.control_points");
    const double total = value_of(*length.field, length.part);
    const auto n = static_cast<std::size_t>(value_of(*control_points.field, control_points.part));
    if (!(span.to >= span.from))
        fail(to, "must be >= " + from + " (" + format_number(span.from) + "), got " + format_number(span.to));
    // A hair of rounding spared: a points shape's length is the spline's, computed.
    if (!(span.to <= total * (1.0 + 1e-9)))
        fail(to, "must be <= " + name(length) + " (" + format_number(total) + "): a span lies along the bowel, got " +
                     format_number(span.to));
    const std::string own = element_name(scope);
    const ControlPointRange points = control_points_in(span, n, total);
    if (points.empty())
        fail(own, "holds no control point: they lie every " + format_rounded(total / double(n - 1)) +
                      " m along the bowel at rest, and none in [" + format_number(span.from) + ", " +
                      format_number(span.to) + "]; widen the span");
    const PinnedConfig& pinned = *static_cast<const PinnedConfig*>(scope.outer->part);
    const bool first = (pinned.clamped & pin_first) != 0, last = (pinned.clamped & pin_last) != 0;
    const std::string clamped = name(*scope.outer->block.find("clamped"), *scope.outer);
    for (uint32_t i = points.first; i <= points.last; ++i) {
        const mechanics::ClampedEnd neighbour = mechanics::clamped_end_neighbour(i, n, first, last);
        const mechanics::ClampedEnd end = mechanics::clamped_end_point(i, n, first, last);
        const mechanics::ClampedEnd conflict = neighbour != mechanics::ClampedEnd::none ? neighbour
                                               : span.obstacle ? end
                                                               : mechanics::ClampedEnd::none;
        if (conflict == mechanics::ClampedEnd::none) continue;
        fail(own, "holds control point " + std::to_string(i) + ", which the clamped " +
                      (conflict == mechanics::ClampedEnd::first ? "first" : "last") + " end (" + clamped +
                      ") already moves: a pin there would fight the clamp; end the span before it" +
                      (neighbour == mechanics::ClampedEnd::none ? " (or attach the clamped end with clamped_attached)"
                                                                : ""));
    }
}

// The rules between the fields of a block, beyond each field's own.
void Validator::block_rules(const Scope& scope) const {
    switch (scope.block.check) {
        case Block::Check::none: break;
        case Block::Check::pinned: {
            // The two clamps' constraints (mechanics/clamped_ends.h) must not share a control point.
            constexpr std::size_t kBothClampedPoints = 6;
            const PinnedConfig& pinned = *static_cast<const PinnedConfig*>(scope.part);
            const Located control_points = locate(scope, "intestine.control_points");
            const double n = value_of(*control_points.field, control_points.part);
            if (pinned.clamped == pin_both && n < kBothClampedPoints)
                fail(name(*scope.block.find("clamped"), scope),
                     "clamps both ends, which needs at least " + std::to_string(kBothClampedPoints) +
                         " control points (" + name(control_points) + " is " + format_number(n) + ")");
            break;
        }
        case Block::Check::attached_pin: {
            // A clamped end's point moves with its clamp: pinned alone, the clamp would be half
            // attached (the end point on the organ, its direction in the world). Only JSON
            // attaches pins in the description (C pins with ent_scene_pin_point).
            const PinAttachment& pin = *static_cast<const PinAttachment*>(scope.part);
            const Scope& pins = *scope.outer;
            const PinnedConfig& pinned = *static_cast<const PinnedConfig*>(pins.part);
            const Located control_points = locate(scope, "intestine.control_points");
            const auto n = static_cast<std::size_t>(value_of(*control_points.field, control_points.part));
            const mechanics::ClampedEnd end = mechanics::clamped_end_point(
                pin.point, n, (pinned.clamped & pin_first) != 0, (pinned.clamped & pin_last) != 0);
            if (end != mechanics::ClampedEnd::none) {
                const bool first = end == mechanics::ClampedEnd::first;
                fail(name(*scope.block.find("control_point"), scope),
                     "is " + std::to_string(pin.point) + ", the point of the clamped " + (first ? "first" : "last") +
                         " end (" + name(*pins.block.find("clamped"), pins) + "): attach the clamped end with " +
                         name(*pins.block.find("clamped_attached"), pins));
            }
            break;
        }
        case Block::Check::pin_span: pin_span(scope); break;
        case Block::Check::clamped_attached: {
            // Its keys are fields of the pinned part (object_here), around it.
            const PinnedConfig& pinned = *static_cast<const PinnedConfig*>(scope.part);
            const Scope& pins = *scope.outer;
            for (const bool first : {true, false})
                if (pinned.clamped_obstacle[first ? 0 : 1] && (pinned.clamped & (first ? pin_first : pin_last)) == 0)
                    fail(name(*scope.block.find(first ? "first" : "last"), scope),
                         std::string("attaches the ") + (first ? "first" : "last") + " end, which " +
                             name(*pins.block.find("clamped"), pins) + " does not clamp: clamp it or remove the key");
            break;
        }
        case Block::Check::obstacle: {
            const collision::Obstacle& o = *static_cast<const collision::Obstacle*>(scope.part);
            if (o.kind != collision::ObstacleKind::mesh) break;
            if (!o.mesh && !o.field) fail(virtual_name(scope, "mesh"), "must be given for a mesh obstacle");
            if (o.mesh) mesh(*o.mesh, scope);
            break;
        }
    }
}

void Validator::mesh(const collision::TriangleMesh& m, const Scope& scope) const {
    const std::size_t triangles = m.triangle_count();
    const std::string mesh = virtual_name(scope, "mesh");
    if (m.indices.size() % 3 != 0 || m.vertices.size() % 3 != 0)
        fail(mesh, "must have 3 coordinates per vertex and 3 indices per triangle");
    if (triangles == 0) fail(mesh, "must have at least one triangle, got 0");
    if (triangles > collision::kMaxMeshTriangles)
        fail(mesh, "has " + std::to_string(triangles) + " triangles, more than the " +
                       std::to_string(collision::kMaxMeshTriangles) + " a mesh obstacle may have");
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
        if (!std::isfinite(m.vertices[i]))
            fail(index_path(virtual_name(scope, "vertices"), i / 3),
                 "must be finite, got " + format_number(m.vertices[i]) + " for coordinate " + std::to_string(i % 3));
    const std::size_t vertices = m.vertex_count();
    for (std::size_t i = 0; i < m.indices.size(); ++i)
        if (m.indices[i] >= vertices)
            fail(index_path(virtual_name(scope, "triangles"), i / 3),
                 "refers to vertex " + std::to_string(m.indices[i]) + ", but the mesh has " + std::to_string(vertices) +
                     " vertices (indices count from 0)");
    bool some_area = false;
    for (std::size_t t = 0; t < triangles && !some_area; ++t)
        some_area = (m.corner(t, 1) - m.corner(t, 0)).cross(m.corner(t, 2) - m.corner(t, 0)).squaredNorm() > 0.0;
    if (!some_area) fail(virtual_name(scope, "triangles"), "are all of zero area: nothing to collide with");
}


// Every clamped end needs a direction to hold: its tangent in the initial shape.
void check_clamped_tangents(const SceneConfig& config, const FieldNames& names) {
    const int32_t clamped = config.pinned->clamped;
    const std::size_t n = config.intestine.control_points;
    for (const bool first : {true, false}) {
        if ((clamped & (first ? pin_first : pin_last)) == 0) continue;
        if (mechanics::clamped_end_is_degenerate(config.start_points.data(), n, first))
            throw Error(names.code, names.at("pinned.clamped") + " clamps the " + (first ? "first" : "last") +
                                        " end, but the initial shape gives it no direction to hold: its tangent " +
                                        (first ? "4 q1 - 3 q0 - q2" : "3 q[n-1] - 4 q[n-2] + q[n-3]") +
                                        " is zero (the end folds back on itself); change the shape's " +
                                        (first ? "first" : "last") + " three points");
    }
}

// What every field of a part is compared with, in the walk of fields_apart_from_defaults.
void mark_apart(const Block& block, const void* part, const void* defaults, const std::string& path, FieldSet& apart) {
    for (const Field& f : block) {
        if (f.present != nullptr && !f.present(part)) continue;
        const std::string at = join_path(path, f.key);
        bool differs = false;
        if (const Object* object = std::get_if<Object>(&f.value)) {
            const void* inner = object->find(part);
            const void* inner_defaults = object->find(defaults);
            if (inner != nullptr && inner_defaults != nullptr) mark_apart(*object->block, inner, inner_defaults, at, apart);
            continue;
        }
        if (f.present != nullptr && !f.present(defaults)) {
            differs = true;
        } else if (const Number* number = std::get_if<Number>(&f.value)) {
            differs = number->get(part) != number->get(defaults);
        } else if (const Count* count = std::get_if<Count>(&f.value)) {
            differs = count->get(part) != count->get(defaults);
        } else if (const Choice* choice = std::get_if<Choice>(&f.value)) {
            differs = choice->get(part) != choice->get(defaults);
        } else if (const Point* point = std::get_if<Point>(&f.value)) {
            differs = point->get(part) != point->get(defaults);
        }
        if (differs) apart.add(at);
    }
}

}  // namespace

std::string FieldNames::of(const Field& field, const std::string& path, const std::string& prefix) const {
    if (c_names && field.c_name != nullptr) return prefix + field.c_name;
    return c_names ? prefix + field.key : join_path(path, field.key);
}

std::string FieldNames::element_prefix(const Field& field, const std::string& prefix, std::size_t index) const {
    return index_path(prefix + (field.c_name != nullptr ? field.c_name : field.key), index) + ".";
}

std::string FieldNames::at(const std::string& path) const {
    const std::size_t dot = path.rfind('.');
    return of(*find_path(scene_block(), path).field, dot == std::string::npos ? "" : path.substr(0, dot));
}

std::string FieldNames::obstacle(std::size_t index) const {
    const Field& environment = *scene_block().find("environment");
    return index_path(c_names ? environment.c_name : environment.key, index);
}

const FieldNames& json_field_names() {
    static const FieldNames names{ErrorCode::invalid_scene, false};
    return names;
}

const FieldNames& c_field_names() {
    static const FieldNames names{ErrorCode::invalid_argument, true};
    return names;
}

SceneConfig validate(SceneConfig config, const FieldNames& names, const FieldSet& given) {
    const Validator validator(names, given, config.environment.size());
    // A points shape starts at rest: its length 0 (JSON: no length) is the length of the
    // spline through the points (points_length.h), once they are seen to be valid.
    if (config.intestine.shape.kind == ShapeKind::points && config.intestine.length == kLengthOfThePoints) {
        SceneConfig placeholder = config;
        placeholder.intestine.length = IntestineConfig().length;
        for (std::vector<double>* profile :
             {&placeholder.intestine.radius_profile, &placeholder.intestine.linear_density_profile,
              &placeholder.intestine.stretch_stiffness_profile, &placeholder.intestine.bend_stiffness_profile})
            profile->clear();
        if (placeholder.pinned) placeholder.pinned->spans.clear();  // checked against the length
        validator.walk(Scope{nullptr, scene_block(), &placeholder, "", ""}, Validator::Pass::values);
        config.intestine.length = points_spline_length(config);
        if (!(config.intestine.length > config.intestine.radius))
            throw Error(names.code, names.at("intestine.shape.points") +
                                        " must spread along the bowel: the spline through them is " +
                                        format_number(config.intestine.length) + " m long, not longer than " +
                                        names.at("intestine.radius") + " (" + format_number(config.intestine.radius) +
                                        " m), and a points shape without a length takes the spline's");
    }
    const Scope top{nullptr, scene_block(), &config, "", ""};
    validator.walk(top, Validator::Pass::values);
    validator.walk(top, Validator::Pass::obstacle_indices);

    const std::size_t n = config.intestine.control_points;
    config.start_points.assign(3 * n, 0.0);
    build_shape(config.intestine.shape, config.intestine.length, n, config.start_points.data());
    if (config.pinned) check_clamped_tangents(config, names);
    const StartClearance clearance = start_clearance(config);
    // A mesh is checked by the scene, once its distance field is built.
    for (std::size_t i = 0; i < config.environment.size(); ++i)
        if (config.environment[i].kind != collision::ObstacleKind::mesh)
            check_clearance(config.environment[i], names.obstacle(i), names.code, config.start_points.data(), n,
                            clearance);
    return config;
}

StartClearance start_clearance(const SceneConfig& config, std::pmr::memory_resource* memory) {
    const IntestineConfig& tube = config.intestine;
    const double radius = tube.radius, spacing = resting_sphere_spacing(config.collision, radius);
    const double k = config.collision.contact.stiffness;
    StartClearance clearance{radius, std::sqrt(k / (tube.linear_density * spacing)), config.solver.max_speed,
                             std::pmr::vector<double>(memory), std::pmr::vector<double>(memory)};
    if (tube.radius_profile.empty() && tube.linear_density_profile.empty()) return clearance;
    // Each control point at its rest arc length s = i l0: its radius, and a sphere there of
    // the spacing x R(s) / R_max (collision_spheres.h) and the density at s.
    const spline::LengthProfile radii(tube.radius_profile, std::pmr::get_default_resource());
    const spline::LengthProfile densities(tube.linear_density_profile, std::pmr::get_default_resource());
    const std::size_t n = tube.control_points;
    const double l0 = tube.length / static_cast<double>(n - 1);
    clearance.radius_at.resize(n);
    clearance.escape_rate_at.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double s = l0 * static_cast<double>(i);
        const double r = radii.empty() ? radius : radii.at(s);
        const double density = densities.empty() ? tube.linear_density : densities.at(s);
        clearance.radius_at[i] = r;
        clearance.escape_rate_at[i] = std::sqrt(k / (density * spacing * r / radius));
    }
    return clearance;
}

FieldSet fields_apart_from_defaults(const SceneConfig& config) {
    // The defaults of a C description: every effect's own, gravity the Earth's.
    SceneConfig defaults;
    defaults.gravity = kStandardGravity;
    defaults.damping.emplace();
    defaults.mesentery.emplace();
    defaults.pinned.emplace();
    FieldSet apart = FieldSet::none();
    mark_apart(scene_block(), &config, &defaults, "", apart);
    return apart;
}

collision::Obstacle validate_obstacle(const collision::Obstacle& obstacle, const std::string& name,
                                     const FieldNames& names, const double* control_points, std::size_t count,
                                     const StartClearance* clearance) {
    collision::Obstacle valid = obstacle;
    const FieldSet all;
    const Validator validator(names, all, 0);
    validator.walk(Scope{nullptr, obstacle_block(), &valid, name, name + "."}, Validator::Pass::values);
    const bool unprepared_mesh = valid.kind == collision::ObstacleKind::mesh && !valid.field;
    if (control_points != nullptr && clearance != nullptr && !unprepared_mesh)
        check_clearance(valid, name, names.code, control_points, count, *clearance);
    return valid;
}

collision::ToolConfig validate_tool(const collision::ToolConfig& tool, const std::string& prefix,
                                    const FieldNames& names) {
    collision::ToolConfig valid = tool;
    const FieldSet all;
    const std::string path = prefix.empty() ? prefix : prefix.substr(0, prefix.size() - 1);
    Validator(names, all, 0).walk(Scope{nullptr, tool_block(), &valid, path, prefix}, Validator::Pass::values);
    return valid;
}

collision::ToolPose validate_tool_pose(const collision::ToolPose& pose, const std::string& prefix,
                                       const FieldNames& names) {
    static const Field& position = *tool_block().find("position");
    static const Field& orientation = *tool_block().find("orientation");
    const std::string path = prefix.empty() ? prefix : prefix.substr(0, prefix.size() - 1);
    for (std::size_t c = 0; c < 3; ++c)
        if (!std::isfinite(pose.position[c]))
            Checked<double>(pose.position[c], index_path(names.of(position, path, prefix), c), names.code);
    collision::ToolPose unit = pose;
    unit.orientation = unit_quaternion(pose.orientation, [&] { return names.of(orientation, path, prefix); }, names.code);
    return unit;
}

std::string join_path(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

std::string index_path(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

}  // namespace enteron::scene
