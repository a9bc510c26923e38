// SPDX-License-Identifier: Apache-2.0
// Stanford PLY (mesh_readers.h; the format: paulbourke.net/dataformats/ply). A text header
// declares the elements in the order their data follows, each with a count and properties
// (scalars, or lists: a count then that many items); the data is text, one element per
// line, or binary, packed, in either byte order. The "vertex" element's x, y and z and the
// "face" element's vertex_indices (or vertex_index) are kept; everything else is read past.
// Values are read as the header types them (a float property is a float, as in the file),
// then widened to double.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "scene/mesh_readers.h"
#include "scene/mesh_text.h"

namespace enteron::scene {

namespace {

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

struct TypeName {
    std::string_view name;
    PlyType type;
};
// The type names of the format, and the sized aliases most writers use.
constexpr TypeName kTypeNames[] = {
    {"char", PlyType::int8},     {"uchar", PlyType::uint8},    {"short", PlyType::int16},
    {"ushort", PlyType::uint16}, {"int", PlyType::int32},      {"uint", PlyType::uint32},
    {"float", PlyType::float32}, {"double", PlyType::float64}, {"int8", PlyType::int8},
    {"uint8", PlyType::uint8},   {"int16", PlyType::int16},    {"uint16", PlyType::uint16},
    {"int32", PlyType::int32},   {"uint32", PlyType::uint32},  {"float32", PlyType::float32},
    {"float64", PlyType::float64}};

std::size_t size_of(PlyType type) {
    switch (type) {
        case PlyType::int8:
        case PlyType::uint8: return 1;
        case PlyType::int16:
        case PlyType::uint16: return 2;
        case PlyType::int32:
        case PlyType::uint32:
        case PlyType::float32: return 4;
        case PlyType::float64: return 8;
    }
    return 0;
}
bool is_integer(PlyType type) { return type != PlyType::float32 && type != PlyType::float64; }

// What a property is to the mesh.
enum class Role { skipped, x, y, z, corners };

struct Property {
    std::string name;
    PlyType type = PlyType::float32;  // of a scalar, or of a list's items
    bool list = false;
    PlyType count_type = PlyType::uint8;
    Role role = Role::skipped;
    std::string what;  // its name in a refusal: "the property \"red\""
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
    std::size_t line = 0;  // of its declaration
};

enum class Encoding { ascii, little_endian, big_endian };

struct Header {
    Encoding encoding = Encoding::ascii;
    std::vector<Element> elements;
    const Element* vertex = nullptr;  // the elements that hold the mesh (assign_roles)
    const Element* face = nullptr;
    std::size_t body = 0;       // byte offset of the data
    std::size_t body_line = 0;  // its first line (ASCII)
};

constexpr const char* kAxisWhat[3] = {"the vertex's x", "the vertex's y", "the vertex's z"};

PlyType type_named(std::string_view name, MeshText& in) {
    for (const TypeName& t : kTypeNames)
        if (t.name == name) return t.type;
    in.refuse(MeshText::shown(name) + " is not a PLY type (char, uchar, short, ushort, int, uint, float, double)");
}

Header read_header(std::string_view bytes) {
    Header header;
    MeshText in(bytes);
    if (!in.next_line() || in.word() != "ply" || !in.at_end())
        in.refuse("not a PLY file: its first line must be \"ply\"");
    bool format_given = false;
    while (true) {
        if (!in.next_line()) in.refuse("the header ends without an \"end_header\" line");
        const std::string_view keyword = in.word();
        if (keyword == "end_header") break;
        if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) continue;
        if (keyword == "format") {
            const std::string_view encoding = in.word();
            if (encoding == "ascii") header.encoding = Encoding::ascii;
            else if (encoding == "binary_little_endian") header.encoding = Encoding::little_endian;
            else if (encoding == "binary_big_endian") header.encoding = Encoding::big_endian;
            else in.refuse("the format " + MeshText::shown(encoding) +
                           " is not ascii, binary_little_endian or binary_big_endian");
            if (in.word() != "1.0") in.refuse("only version 1.0 of the PLY format is read");
            format_given = true;
        } else if (keyword == "element") {
            Element element;
            element.name = std::string(in.word());
            if (element.name.empty()) in.refuse("an element without a name");
            element.count = static_cast<uint64_t>(in.integer("the element's count", 0, std::numeric_limits<int64_t>::max()));
            element.line = in.line();
            header.elements.push_back(std::move(element));
        } else if (keyword == "property") {
            if (header.elements.empty()) in.refuse("a property before any element");
            Property property;
            std::string_view type = in.word();
            if (type == "list") {
                property.list = true;
                property.count_type = type_named(in.word(), in);
                if (!is_integer(property.count_type)) in.refuse("a list's count must have an integer type");
                type = in.word();
            }
            property.type = type_named(type, in);
            property.name = std::string(in.word());
            if (property.name.empty()) in.refuse("a property without a name");
            property.what = "the property \"" + property.name + "\"";
            header.elements.back().properties.push_back(std::move(property));
        } else {
            in.refuse(MeshText::shown(keyword) + " is not a PLY header line (format, element, property, comment, "
                      "end_header)");
        }
        if (!in.at_end()) in.refuse("more words than a \"" + std::string(keyword) + "\" line has");
    }
    if (!format_given) in.refuse("the header has no \"format\" line");
    header.body = in.consumed();
    header.body_line = in.line() + 1;
    return header;
}

// The vertex and face elements, their properties given their roles. Refuses a header
// without them.
void assign_roles(Header& header) {
    const auto refuse = [](std::size_t line, const std::string& why) { refuse_mesh(MeshPlace::line(line), why); };
    const std::size_t end_header = header.body_line - 1;
    Element* vertex = nullptr;
    Element* face = nullptr;
    for (Element& e : header.elements) {
        if (e.name == "vertex" && vertex == nullptr) vertex = &e;
        if (e.name == "face" && face == nullptr) face = &e;
    }
    if (vertex == nullptr) refuse(end_header, "the header ends without declaring a \"vertex\" element");
    if (face == nullptr)
        refuse(end_header, "the header ends without declaring a \"face\" element (a point cloud is not a mesh)");
    const Role axes[3] = {Role::x, Role::y, Role::z};
    const char* const axis_names[3] = {"x", "y", "z"};
    for (int c = 0; c < 3; ++c) {
        Property* found = nullptr;
        for (Property& p : vertex->properties)
            if (p.name == axis_names[c] && found == nullptr) found = &p;
        if (found == nullptr || found->list)
            refuse(vertex->line, std::string("the vertex element has no scalar property \"") + axis_names[c] + "\"");
        found->role = axes[c];
    }
    Property* corners = nullptr;
    for (Property& p : face->properties)
        if ((p.name == "vertex_indices" || p.name == "vertex_index") && corners == nullptr) corners = &p;
    if (corners == nullptr || !corners->list)
        refuse(face->line, "the face element has no list property \"vertex_indices\" (or \"vertex_index\")");
    if (!is_integer(corners->type)) refuse(face->line, "the face element's vertex indices must have an integer type");
    corners->role = Role::corners;
    header.vertex = vertex;
    header.face = face;
}

// A face's corner as a vertex index of the mesh, or a refusal.
uint32_t corner_of(int64_t index, const MeshPlace& place) {
    if (index < 0 || index > int64_t{std::numeric_limits<uint32_t>::max()})
        refuse_mesh(place, "a face refers to vertex " + std::to_string(index) + ", which no mesh has");
    return static_cast<uint32_t>(index);
}

// ---- ASCII data: an element per line -----------------------------------------------------

void read_ascii(std::string_view bytes, const Header& header, MeshSoup& soup) {
    MeshText in(bytes.substr(header.body), header.body_line);
    std::vector<uint32_t> corners;
    constexpr int64_t kLeast = std::numeric_limits<int64_t>::min(), kMost = std::numeric_limits<int64_t>::max();
    for (const Element& e : header.elements) {
        for (uint64_t item = 0; item < e.count; ++item) {
            bool line = in.next_line();
            while (line && in.at_end()) line = in.next_line();  // blank lines
            if (!line)
                refuse_mesh(MeshPlace::line(in.line() + 1), "the file ends before " + e.name + " " +
                                                                std::to_string(item) + " (it declares " +
                                                                std::to_string(e.count) + ")");
            double xyz[3] = {0, 0, 0};
            corners.clear();
            for (const Property& p : e.properties) {
                if (p.list) {
                    const int64_t count = in.integer("a list's count", 0, std::numeric_limits<int32_t>::max());
                    for (int64_t k = 0; k < count; ++k) {
                        if (p.role == Role::corners)
                            corners.push_back(corner_of(in.integer("a vertex index", kLeast, kMost), in.place()));
                        else
                            in.number(p.what.c_str());
                    }
                } else if (p.role == Role::skipped) {
                    in.number(p.what.c_str());
                } else {
                    const int axis = static_cast<int>(p.role) - static_cast<int>(Role::x);
                    const char* const what = kAxisWhat[axis];
                    xyz[axis] = p.type == PlyType::float32   ? double(in.number<float>(what))
                                : p.type == PlyType::float64 ? in.number<double>(what)
                                                             : double(in.integer(what, kLeast, kMost));
                }
            }
            if (!in.at_end())
                in.refuse("more values than the " + std::to_string(e.properties.size()) + " properties of a " + e.name);
            if (&e == header.vertex) soup.add_vertex(xyz[0], xyz[1], xyz[2]);
            if (&e == header.face) soup.add_polygon(corners.data(), corners.size(), in.place());
        }
    }
}

// ---- binary data: packed values, in the header's byte order -------------------------------

class BinaryData {
public:
    BinaryData(std::string_view bytes, std::size_t at, bool swap) : bytes_(bytes), at_(at), swap_(swap) {}

    std::size_t at() const { return at_; }
    // Whether `size` more bytes are there.
    bool has(std::size_t size) const { return size <= bytes_.size() - at_; }

    // The next value of type `type` as a double (has() checked by the caller), or, for the
    // integer types the header allows where it asks for one (counts, indices), as an int64.
    double real(PlyType type) { return next<double>(type); }
    int64_t whole(PlyType type) { return next<int64_t>(type); }
    void skip(std::size_t size) { at_ += size; }

private:
    template <class Out>
    Out next(PlyType type) {
        switch (type) {
            case PlyType::int8: return static_cast<Out>(take<int8_t>());
            case PlyType::uint8: return static_cast<Out>(take<uint8_t>());
            case PlyType::int16: return static_cast<Out>(take<int16_t>());
            case PlyType::uint16: return static_cast<Out>(take<uint16_t>());
            case PlyType::int32: return static_cast<Out>(take<int32_t>());
            case PlyType::uint32: return static_cast<Out>(take<uint32_t>());
            case PlyType::float32: return static_cast<Out>(take<float>());
            case PlyType::float64: return static_cast<Out>(take<double>());
        }
        return Out{};
    }
    template <class T>
    T take() {
        unsigned char raw[sizeof(T)];
        std::memcpy(raw, bytes_.data() + at_, sizeof(T));
        if (swap_)
            for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
        T value;
        std::memcpy(&value, raw, sizeof(T));
        at_ += sizeof(T);
        return value;
    }

    std::string_view bytes_;
    std::size_t at_;
    bool swap_;
};

bool little_endian_machine() {
    const uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

void read_binary(std::string_view bytes, const Header& header, MeshSoup& soup) {
    const bool file_little = header.encoding == Encoding::little_endian;
    BinaryData in(bytes, header.body, file_little != little_endian_machine());
    std::vector<uint32_t> corners;
    for (const Element& e : header.elements) {
        for (uint64_t item = 0; item < e.count; ++item) {
            const std::size_t item_at = in.at();
            const auto ends = [&](std::size_t size) {
                if (!in.has(size))
                    refuse_mesh(MeshPlace::byte(item_at), "the file ends inside " + e.name + " " + std::to_string(item) +
                                                              " (it declares " + std::to_string(e.count) + ")");
            };
            double xyz[3] = {0, 0, 0};
            corners.clear();
            for (const Property& p : e.properties) {
                if (!p.list) {
                    ends(size_of(p.type));
                    if (p.role == Role::skipped) {
                        in.skip(size_of(p.type));
                        continue;
                    }
                    const int axis = static_cast<int>(p.role) - static_cast<int>(Role::x);
                    const std::size_t at = in.at();
                    xyz[axis] = in.real(p.type);
                    if (!std::isfinite(xyz[axis]))
                        refuse_mesh(MeshPlace::byte(at), std::string(kAxisWhat[axis]) + " of vertex " + std::to_string(item) +
                                                             " is not a finite number");
                    continue;
                }
                ends(size_of(p.count_type));
                const std::size_t count_at = in.at();
                const int64_t count = in.whole(p.count_type);
                if (count < 0)
                    refuse_mesh(MeshPlace::byte(count_at), "a list of " + e.name + " " + std::to_string(item) +
                                                               " has " + std::to_string(count) + " items");
                if (!in.has(static_cast<uint64_t>(count) * size_of(p.type)) ||
                    static_cast<uint64_t>(count) > bytes.size())
                    refuse_mesh(MeshPlace::byte(count_at), "a list of " + e.name + " " + std::to_string(item) + " has " +
                                                               std::to_string(count) + " items, past the end of the file");
                if (p.role != Role::corners) {
                    in.skip(static_cast<std::size_t>(count) * size_of(p.type));
                    continue;
                }
                for (int64_t k = 0; k < count; ++k) {
                    const std::size_t at = in.at();
                    corners.push_back(corner_of(in.whole(p.type), MeshPlace::byte(at)));
                }
            }
            if (&e == header.vertex) soup.add_vertex(xyz[0], xyz[1], xyz[2]);
            if (&e == header.face) soup.add_polygon(corners.data(), corners.size(), MeshPlace::byte(item_at));
        }
    }
}

}  // namespace

MeshSoup read_ply(std::string_view bytes) {
    Header header = read_header(bytes);
    assign_roles(header);
    MeshSoup soup;
    // Room for what the header announces, as far as the file's size can hold it (a vertex
    // takes at least 3 bytes of data, a face 4).
    soup.reserve(std::min<uint64_t>(header.vertex->count, bytes.size() / 3),
                 std::min<uint64_t>(header.face->count, bytes.size() / 4));
    if (header.encoding == Encoding::ascii) read_ascii(bytes, header, soup);
    else read_binary(bytes, header, soup);
    return soup;
}

}  // namespace enteron::scene
