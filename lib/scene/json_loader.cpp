// SPDX-License-Identifier: Apache-2.0
#include "scene/json_loader.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/error.h"
#include "scene/mesh_file.h"
#include "scene/points_length.h"
#include "scene/scene_table.h"
#include "scene/validate.h"

namespace enteron::scene {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& message) {
    throw Error(ErrorCode::invalid_scene, message);
}

// Cuts long text for a message, never inside a UTF-8 sequence.
std::string shorten(std::string text) {
    constexpr std::size_t kMaxChars = 60;
    if (text.size() <= kMaxChars) return text;
    std::size_t cut = kMaxChars;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    return text.substr(0, cut) + "...";
}

std::string quote(const std::string& text) { return json(shorten(text)).dump(); }

// A value as a message shows it. Containers are only described, so a huge or deeply
// nested value cannot blow up the message (or the stack, through dump()).
std::string describe(const json& value) {
    if (value.is_object()) return "an object";
    if (value.is_array()) {
        return "an array of " + std::to_string(value.size()) + (value.size() == 1 ? " element" : " elements");
    }
    if (value.is_string()) return quote(value.get<std::string>());
    return value.dump();  // a number, true, false or null: short
}

std::string place(const std::string& path) {
    return path.empty() ? "at the top level" : "in " + path;
}

// ---- values ------------------------------------------------------------------------

double read_number(const json& value, const std::string& path) {
    if (!value.is_number()) fail(path + " must be a number, got " + describe(value));
    return value.get<double>();
}

// A count or index. JSON has one number type, so 1e5, 240.0 and -0 are integers too.
std::uint64_t read_count(const json& value, const std::string& path,
                         std::uint64_t max = std::numeric_limits<std::size_t>::max()) {
    std::uint64_t count = 0;
    if (value.is_number_unsigned()) {
        count = value.get<std::uint64_t>();
    } else {
        if (!value.is_number() || std::floor(value.get<double>()) != value.get<double>()) {
            fail(path + " must be an integer, got " + describe(value));
        }
        const double number = value.get<double>();
        if (number < 0.0) fail(path + " must be a non-negative integer, got " + describe(value));
        constexpr double kTwoTo64 = 18446744073709551616.0;
        if (number >= kTwoTo64) fail(path + " must be <= " + std::to_string(max) + ", got " + describe(value));
        count = static_cast<std::uint64_t>(number);
    }
    if (count > max) fail(path + " must be <= " + std::to_string(max) + ", got " + describe(value));
    return count;
}

bool read_bool(const json& value, const std::string& path) {
    if (!value.is_boolean()) fail(path + " must be true or false, got " + describe(value));
    return value.get<bool>();
}

Vec3 read_vec3(const json& value, const std::string& path) {
    if (!value.is_array() || value.size() != 3) {
        fail(path + " must be an array of 3 numbers [x, y, z], got " + describe(value));
    }
    return {read_number(value[0], index_path(path, 0)), read_number(value[1], index_path(path, 1)),
            read_number(value[2], index_path(path, 2))};
}

std::array<double, 4> read_quaternion(const json& value, const std::string& path) {
    if (!value.is_array() || value.size() != 4)
        fail(path + " must be an array of 4 numbers [w, x, y, z], got " + describe(value));
    return {read_number(value[0], index_path(path, 0)), read_number(value[1], index_path(path, 1)),
            read_number(value[2], index_path(path, 2)), read_number(value[3], index_path(path, 3))};
}

int32_t read_choice(const json& value, const std::string& path, const Choices& choices) {
    if (value.is_string()) {
        for (std::size_t i = 0; i < choices.count; ++i)
            if (value.get<std::string>() == choices.names[i].name) return choices.names[i].value;
    }
    std::string names;
    for (std::size_t i = 0; i < choices.count; ++i)
        names += (names.empty() ? "\"" : ", \"") + std::string(choices.names[i].name) + "\"";
    fail(path + " must be one of " + names + ", got " + describe(value));
}

const char* choice_name(const Choices& choices, int32_t value) {
    for (std::size_t i = 0; i < choices.count; ++i)
        if (choices.names[i].value == value) return choices.names[i].name;
    return "?";
}

// ---- objects -----------------------------------------------------------------------

// Reads a document into a config by the scene's table (scene_table.h): each key of an
// object is a row of its block, read by the row's type into the part the block describes.
class Reader {
public:
    explicit Reader(const std::string& base_directory) : base_directory_(base_directory) {}

    // The object `value` at `path` into `part`, described by `block`.
    void read_block(const json& value, const std::string& path, const Block& block, void* part);

    // The paths of the keys the document gives ("intestine.radius").
    const FieldSet& given() const { return given_; }

private:
    void read_field(const Field& field, const json& value, const std::string& path, void* part);
    void read_custom(const Custom& custom, const json& value, const std::string& path, void* part);
    // An obstacle's own rules: a mesh from a file or inline, its scale, a friction >= 0.
    void check_mesh_keys(const json& value, const std::string& path) const;
    void finish_obstacle(const json& value, const std::string& path, collision::Obstacle& obstacle) const;

    const std::string& base_directory_;
    FieldSet given_ = FieldSet::none();
    double mesh_scale_ = 1.0;
};

// The keys a block accepts for its part (a typed block: those of the part's kind), in the
// order of its rows, each once.
std::string expected_keys(const Block& block, const void* part) {
    std::string keys;
    for (const Field& field : block) {
        if (block.typed && (&field == block.kind || !block.applies(field, part))) continue;
        keys += (keys.empty() ? "" : ", ") + std::string(field.key);
    }
    return keys;
}

void Reader::read_block(const json& value, const std::string& path, const Block& block, void* part) {
    const bool obstacle = &block == &obstacle_block();
    if (block.every_key_required) {
        bool complete = value.is_object();
        std::string keys;
        for (const Field& field : block) {
            if (field.present != nullptr) continue;  // an optional key
            complete = complete && value.contains(field.key);
            keys += (keys.empty() ? "\"" : "\" and \"") + std::string(field.key);
        }
        if (!complete) fail(path + " must be an object with " + keys + "\", got " + describe(value));
    }
    if (block.typed) {
        const char* kind = block.kind->key;
        if (!value.is_object() || !value.contains(kind))
            fail(path + " must be an object with a \"" + kind + "\", got " + describe(value));
        const Choice& choice = std::get<Choice>(block.kind->value);
        block.start(part, read_choice(value.at(kind), join_path(path, kind), choice.choices));
        if (obstacle) {
            check_mesh_keys(value, path);
            mesh_scale_ = 1.0;
        }
    }
    if (!value.is_object()) {
        const std::string subject = path.empty() ? "the scene" : path;
        fail(subject + " must be an object" + (block.looks_like ? std::string(" ") + block.looks_like : "") +
             ", got " + describe(value));
    }
    for (const auto& [key, item] : value.items()) {
        if (block.typed && key == block.kind->key) continue;
        const Field* field = block.find(key.c_str());
        if (field == nullptr || (block.typed && !block.applies(*field, part)))
            fail("unknown key " + quote(key) + " " + place(path) + " (expected one of: " +
                 expected_keys(block, part) + ")");
        given_.add(join_path(path, key));
        read_field(*field, item, join_path(path, key), part);
    }
    // A key of another kind is a mistake worth reporting (typed blocks refused it as unknown).
    if (block.kind != nullptr && !block.typed) {
        for (const Field& field : block) {
            if (value.contains(field.key) && !block.applies(field, part)) {
                const Choice& choice = std::get<Choice>(block.kind->value);
                fail(join_path(path, field.key) + " does not apply to kind \"" +
                     choice_name(choice.choices, choice.get(part)) + "\"");
            }
        }
    }
    if (obstacle) finish_obstacle(value, path, *static_cast<collision::Obstacle*>(part));
}

void Reader::read_field(const Field& field, const json& value, const std::string& path, void* part) {
    if (const Number* number = std::get_if<Number>(&field.value)) {
        number->set(part, read_number(value, path));
    } else if (const Count* count = std::get_if<Count>(&field.value)) {
        count->set(part, static_cast<std::size_t>(read_count(value, path, count->max)));
    } else if (const Choice* choice = std::get_if<Choice>(&field.value)) {
        choice->set(part, read_choice(value, path, choice->choices));
    } else if (const Point* point = std::get_if<Point>(&field.value)) {
        point->set(part, read_vec3(value, path));
    } else if (const Rotation* rotation = std::get_if<Rotation>(&field.value)) {
        // Normalised (and checked for zero) by the validation.
        rotation->set(part, read_quaternion(value, path));
    } else if (const Flag* flag = std::get_if<Flag>(&field.value)) {
        flag->set(part, read_bool(value, path));
    } else if (const Object* object = std::get_if<Object>(&field.value)) {
        // A present object turns its effect on, starting from its defaults.
        read_block(value, path, *object->block, object->make(part));
    } else if (const List* list = std::get_if<List>(&field.value)) {
        if (!value.is_array()) fail(path + " must be an array of " + list->what + ", got " + describe(value));
        list->resize(part, value.size());
        for (std::size_t i = 0; i < value.size(); ++i)
            read_block(value[i], index_path(path, i), *list->block, list->element(part, i));
    } else {
        read_custom(std::get<Custom>(field.value), value, path, part);
    }
}

// A mesh given inline: [[x, y, z], ...] and [[a, b, c], ...].
collision::TriangleMesh& inline_mesh(collision::Obstacle& o) {
    if (!o.mesh) o.mesh = std::make_shared<collision::TriangleMesh>();
    return const_cast<collision::TriangleMesh&>(*o.mesh);
}

// [[x, y, z], ...] into x, y, z of each point (a vector of doubles of any allocator).
template <class Numbers>
void read_json_points(const json& value, const std::string& path, Numbers& points) {
    if (!value.is_array()) fail(path + " must be an array of [x, y, z] points, got " + describe(value));
    points.clear();
    points.reserve(3 * value.size());
    for (std::size_t i = 0; i < value.size(); ++i) {
        const Vec3 point = read_vec3(value[i], index_path(path, i));
        points.insert(points.end(), point.begin(), point.end());
    }
}

// [[a, b], ...] into a, b of each pair; `pair` is how one looks ("[s, t]"), `meaning` what
// its numbers are.
void read_json_pairs(const json& value, const std::string& path, const char* pair, const char* meaning,
                std::vector<double>& pairs) {
    if (!value.is_array())
        fail(path + " must be an array of " + pair + " pairs (" + meaning + "), got " + describe(value));
    pairs.clear();
    pairs.reserve(2 * value.size());
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string at = index_path(path, i);
        if (!value[i].is_array() || value[i].size() != 2) fail(at + " must be a pair " + pair + ", got " + describe(value[i]));
        pairs.push_back(read_number(value[i][0], index_path(at, 0)));
        pairs.push_back(read_number(value[i][1], index_path(at, 1)));
    }
}

void Reader::read_custom(const Custom& custom, const json& value, const std::string& path, void* part) {
    switch (custom.special) {
        case Special::version:
            if (!value.is_number() || value.get<double>() != 1.0) fail(path + " must be 1, got " + describe(value));
            break;
        case Special::shape_points: read_json_points(value, path, static_cast<ShapeConfig*>(part)->points); break;
        case Special::root_polyline: read_json_points(value, path, custom.profile(part)); break;
        case Special::length_profile:
            read_json_pairs(value, path, "[s, value]", "s the arc length from the first end, m", custom.profile(part));
            break;
        case Special::root_mapping:
            read_json_pairs(value, path, "[s, t]",
                       "s the arc length along the bowel from its first end, m; t the fraction of the root's length",
                       custom.profile(part));
            break;
        case Special::pinned_points: {
            if (!value.is_array()) fail(path + " must be an array of control point indices, got " + describe(value));
            std::vector<uint32_t>& points = static_cast<PinnedConfig*>(part)->points;
            points.clear();
            for (std::size_t i = 0; i < value.size(); ++i)
                points.push_back(static_cast<uint32_t>(
                    read_count(value[i], index_path(path, i), std::numeric_limits<uint32_t>::max())));
            break;
        }
        case Special::mesh_file: {
            // Read at once, relative to the scene file's directory.
            if (!value.is_string() || value.get<std::string>().empty())
                fail(path + " must be the path of an OBJ or PLY file, got " + describe(value));
            std::string file = value.get<std::string>();
            if (file.front() != '/' && !base_directory_.empty()) file = base_directory_ + "/" + file;
            static_cast<collision::Obstacle*>(part)->mesh = std::make_shared<collision::TriangleMesh>(
                read_mesh_file(file, 1.0, path, ErrorCode::invalid_scene));
            break;
        }
        case Special::mesh_vertices:
            read_json_points(value, path, inline_mesh(*static_cast<collision::Obstacle*>(part)).vertices);
            break;
        case Special::mesh_triangles: {
            if (!value.is_array())
                fail(path + " must be an array of [a, b, c] vertex indices, got " + describe(value));
            collision::TriangleMesh& mesh = inline_mesh(*static_cast<collision::Obstacle*>(part));
            mesh.indices.clear();
            for (std::size_t i = 0; i < value.size(); ++i) {
                const std::string at = index_path(path, i);
                if (!value[i].is_array() || value[i].size() != 3)
                    fail(at + " must be an array of 3 vertex indices [a, b, c], got " + describe(value[i]));
                for (std::size_t k = 0; k < 3; ++k)
                    mesh.indices.push_back(static_cast<uint32_t>(
                        read_count(value[i][k], index_path(at, k), std::numeric_limits<uint32_t>::max())));
            }
            break;
        }
        case Special::mesh_scale:
            // A CT mesh in millimetres: 0.001, applied once every key of the obstacle is read,
            // whatever their order.
            mesh_scale_ = read_number(value, path);
            if (!(mesh_scale_ > 0.0) || !std::isfinite(mesh_scale_)) fail(path + " must be > 0, got " + describe(value));
            break;
    }
}

void Reader::check_mesh_keys(const json& value, const std::string& path) const {
    if (value.at(obstacle_block().kind->key) != "mesh") return;
    if (value.contains("file") == (value.contains("vertices") || value.contains("triangles")))
        fail(path + " (mesh) must have either \"file\" or both \"vertices\" and \"triangles\"");
    if (value.contains("vertices") != value.contains("triangles"))
        fail(path + " (mesh) must have both \"vertices\" and \"triangles\"");
}

void Reader::finish_obstacle(const json& value, const std::string& path, collision::Obstacle& obstacle) const {
    // JSON's friction is a coefficient; C also takes a negative one, the scene's.
    if (value.contains("friction") && !(obstacle.friction >= 0.0))
        fail(join_path(path, "friction") + " must be >= 0, got " + describe(value.at("friction")));
    if (obstacle.kind == collision::ObstacleKind::mesh)
        for (double& coordinate : inline_mesh(obstacle).vertices) coordinate *= mesh_scale_;
}

// ---- parsing -----------------------------------------------------------------------

// nlohmann silently keeps the last of two equal keys; a scene that says "radius" twice is a
// mistake to report. Follows the parser's events to know which object holds the key.
class DuplicateKeyCheck {
public:
    void on_event(json::parse_event_t event, const json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start: open_.push_back({false, 0, {}, {}}); break;
            case json::parse_event_t::array_start: open_.push_back({true, 0, {}, {}}); break;
            case json::parse_event_t::key: {
                Container& object = open_.back();
                object.key = parsed.get<std::string>();
                if (!object.keys.insert(object.key).second) {
                    fail("duplicate key " + quote(object.key) + " " + place(shorten(innermost_path())));
                }
                break;
            }
            case json::parse_event_t::value: count_element(); break;
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                open_.pop_back();
                count_element();
                break;
        }
    }

private:
    struct Container {
        bool is_array;
        std::size_t elements;        // arrays: elements completed so far
        std::string key;             // objects: the key being read
        std::set<std::string> keys;  // objects: keys seen
    };

    void count_element() {
        if (!open_.empty() && open_.back().is_array) ++open_.back().elements;
    }

    std::string innermost_path() const {
        std::string path;
        for (std::size_t i = 0; i + 1 < open_.size(); ++i) {
            path = open_[i].is_array ? index_path(path, open_[i].elements) : join_path(path, open_[i].key);
        }
        return path;
    }

    std::vector<Container> open_;
};

// nlohmann's what() reads "[json.exception.parse_error.101] parse error at line 1,
// column 2: <detail>"; keep the location and the detail.
[[noreturn]] void fail_parse(const json::parse_error& error) {
    const std::string what = error.what();
    const std::string marker = "parse error at ";
    const std::size_t at = what.find(marker);
    const std::size_t colon = at == std::string::npos ? at : what.find(": ", at);
    std::string message = "JSON parse error at byte " + std::to_string(error.byte);
    if (colon != std::string::npos) {
        const std::size_t location = at + marker.size();
        message += " (" + what.substr(location, colon - location) + "): " + what.substr(colon + 2);
    } else {
        message += ": " + what;
    }
    throw Error(ErrorCode::parse, message);
}

json parse(const char* text, std::size_t length) {
    DuplicateKeyCheck duplicates;
    try {
        return json::parse(text, text + length, [&duplicates](int, json::parse_event_t event, json& parsed) {
            duplicates.on_event(event, parsed);
            return true;
        });
    } catch (const json::parse_error& error) {
        fail_parse(error);
    } catch (const json::exception& error) {  // e.g. out_of_range 406: a number that overflows a double
        const std::string what = error.what();
        const std::size_t prefix_end = what.find("] ");
        const std::string detail = prefix_end == std::string::npos ? what : what.substr(prefix_end + 2);
        throw Error(ErrorCode::parse, "JSON parse error: " + detail);
    }
}

}  // namespace

SceneConfig load_scene_json(const char* text, std::size_t length, const std::string& base_directory) {
    if (text == nullptr && length != 0) throw Error(ErrorCode::invalid_argument, "json is NULL");
    static const char kEmpty[] = "";
    const json document = parse(text != nullptr ? text : kEmpty, length);
    SceneConfig config;
    Reader reader(base_directory);
    reader.read_block(document, "", scene_block(), &config);
    // Explicit points set the control point count unless it is given too, and the length:
    // the spline's through them (points_length.h).
    IntestineConfig& intestine = config.intestine;
    if (intestine.shape.kind == ShapeKind::points && !reader.given().has("intestine.control_points"))
        intestine.control_points = intestine.shape.points.size() / 3;
    if (intestine.shape.kind == ShapeKind::points && !reader.given().has("intestine.length"))
        intestine.length = kLengthOfThePoints;
    return validate(std::move(config), json_field_names(), reader.given());
}

}  // namespace enteron::scene
