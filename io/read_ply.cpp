// PLY reader of our own (ASCII, binary little and big endian). vcglib 2020.09's plylib is not
// safe on untrusted files: it skips unread binary lists through a 512-byte stack buffer whatever
// their length, reads int-counted index lists into a fixed 512-entry array, and calls atoi on a
// missing element count; and ImporterPLY leaves some polygon indices unchecked.
#include "errors.h"
#include "formats.h"
#include "io_detail.h"
#include "text_scan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>

namespace fieldcvt::io_detail {

namespace {

//! A vertex index read as a double, for an error message: as an integer where it is one a long
//! long holds (converting a larger or fractional value would be undefined or misleading).
std::string indexText(double v)
{
    if (std::isfinite(v) && std::fabs(v) < 9.0e18 && v == std::floor(v)) return std::to_string(static_cast<long long>(v));
    std::ostringstream s;
    s << v;
    return s.str();
}

enum class Encoding { Ascii, LittleEndian, BigEndian };

struct Property {
    std::string name;
    int size = 0;  //!< bytes of the value (of each item, for a list)
    bool isFloat = false;
    bool isSigned = false;
    int countSize = 0;  //!< > 0: a list, with a count of this many bytes
    bool countSigned = false;
};

struct Element {
    std::string name;
    long long count = 0;
    std::vector<Property> properties;
};

//! Size and kind of a PLY scalar type name; size 0 if unknown.
Property scalarType(const std::string& type)
{
    static const std::map<std::string, Property> types = {
        {"char", {"", 1, false, true}},    {"int8", {"", 1, false, true}},    {"uchar", {"", 1, false, false}},
        {"uint8", {"", 1, false, false}},  {"short", {"", 2, false, true}},   {"int16", {"", 2, false, true}},
        {"ushort", {"", 2, false, false}}, {"uint16", {"", 2, false, false}}, {"int", {"", 4, false, true}},
        {"int32", {"", 4, false, true}},   {"uint", {"", 4, false, false}},   {"uint32", {"", 4, false, false}},
        {"float", {"", 4, true, true}},    {"float32", {"", 4, true, true}},  {"double", {"", 8, true, true}},
        {"float64", {"", 8, true, true}}};
    const auto it = types.find(type);
    return it == types.end() ? Property{} : it->second;
}

//! Reads values from the body in the file's encoding, failing cleanly at the end of the data.
class BodyReader {
public:
    BodyReader(const std::string& path, const std::string& bytes, std::size_t start, Encoding encoding)
        : path_(path), bytes_(bytes), pos_(start), encoding_(encoding)
    {
    }

    double value(int size, bool isFloat, bool isSigned)
    {
        if (encoding_ == Encoding::Ascii) return asciiValue();
        if (bytes_.size() - pos_ < static_cast<std::size_t>(size)) fail(path_, "truncated PLY file (unexpected end of data)");
        unsigned char b[8];
        std::memcpy(b, bytes_.data() + pos_, size);
        pos_ += size;
        if (encoding_ == Encoding::BigEndian) std::reverse(b, b + size);  // to little endian
        std::uint64_t u = 0;
        for (int i = size - 1; i >= 0; --i) u = (u << 8) | b[i];
        if (isFloat) {
            if (size == 4) {
                float f;
                std::uint32_t u32 = static_cast<std::uint32_t>(u);
                std::memcpy(&f, &u32, 4);
                return f;
            }
            double d;
            std::memcpy(&d, &u, 8);
            return d;
        }
        if (isSigned && size < 8 && (u >> (8 * size - 1)) & 1)
            return static_cast<double>(static_cast<std::int64_t>(u - (std::uint64_t{1} << (8 * size))));
        return static_cast<double>(u);
    }

    //! What is left after the last value read: non-blank lines (ASCII) or bytes (binary).
    std::string leftover() const
    {
        if (encoding_ != Encoding::Ascii) return pos_ < bytes_.size() ? std::to_string(bytes_.size() - pos_) + " bytes" : "";
        int lines = 0;
        bool blank = true;
        for (std::size_t i = pos_; i < bytes_.size(); ++i) {
            if (bytes_[i] == '\n')
                lines += !blank, blank = true;
            else if (!std::isspace(static_cast<unsigned char>(bytes_[i])))
                blank = false;
        }
        lines += !blank;
        return lines > 0 ? std::to_string(lines) + " lines" : "";
    }

private:
    double asciiValue()
    {
        while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
        if (start == pos_) fail(path_, "truncated PLY file (unexpected end of data)");
        const std::string_view token(bytes_.data() + start, pos_ - start);
        double value = 0;  // of the current face
        if (!parseNumber(token, value))
            fail(path_, (isOutOfRange(token) ? "number out of range (not a finite double) " : "malformed number ") +
                            quoteInput(token) + " in the PLY data");
        return value;
    }

    const std::string& path_;
    const std::string& bytes_;
    std::size_t pos_;
    Encoding encoding_;
};

//! Parses the header, line by line up to the one that is "end_header" (the words may occur in
//! a comment); returns the offset of the body.
std::size_t parseHeader(const std::string& path, const std::string& bytes, Encoding& encoding, std::vector<Element>& elements,
                        std::vector<std::string>& textureFiles)
{
    std::size_t pos = byteOrderMarkLength(bytes);
    auto notPly = [&] { fail(path, "not a PLY file (no 'ply' ... 'end_header' header)"); };
    if (bytes.compare(pos, 3, "ply") != 0 || bytes.find("end_header") == std::string::npos) notPly();
    bool formatSeen = false, ended = false;
    while (!ended && pos < bytes.size()) {
        std::size_t end = bytes.find('\n', pos);
        if (end == std::string::npos) end = bytes.size();
        const std::string line = bytes.substr(pos, end - pos);
        pos = std::min(end + 1, bytes.size());
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "end_header") {
            ended = true;
            continue;
        }
        if (std::string word; keyword == "comment" && words >> word && word == "TextureFile") {
            // MeshLab's texture image name: the rest of the line (it may hold spaces).
            std::string name;
            std::getline(words >> std::ws, name);
            textureFiles.push_back(name.substr(0, name.find_last_not_of("\r \t") + 1));
            continue;
        }
        auto bad = [&] {
            fail(path,
                 "malformed PLY header line " + quoteInput(std::string_view(line).substr(0, line.find_last_not_of("\r") + 1)));
        };
        if (keyword == "format") {
            std::string format;
            words >> format;
            if (format == "ascii")
                encoding = Encoding::Ascii;
            else if (format == "binary_little_endian")
                encoding = Encoding::LittleEndian;
            else if (format == "binary_big_endian")
                encoding = Encoding::BigEndian;
            else
                bad();
            formatSeen = true;
        } else if (keyword == "element") {
            Element e;
            if (!(words >> e.name >> e.count) || e.count < 0) bad();
            elements.push_back(e);
        } else if (keyword == "property") {
            std::string type, name;
            words >> type;
            if (elements.empty()) bad();
            Property p;
            if (type == "list") {
                std::string countType, itemType;
                words >> countType >> itemType;
                const Property count = scalarType(countType);
                p = scalarType(itemType);
                if (count.size == 0 || count.isFloat) bad();
                p.countSize = count.size;
                p.countSigned = count.isSigned;
            } else {
                p = scalarType(type);
            }
            if (p.size == 0 || !(words >> p.name)) bad();
            elements.back().properties.push_back(p);
        } else if (keyword != "ply" && keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
            bad();
        }
    }
    if (!ended) notPly();
    if (!formatSeen) fail(path, "PLY header has no format line");
    return pos;
}

//! MeshLab's per-face texture coordinates (`property list uchar float texcoord`, 2 per corner) and
//! texture index (`texnumber`, into the `TextureFile` comments), read alongside the faces; the
//! first inconsistency makes them all dropped (the geometry stays).
class PlyTexture {
public:
    PlyTexture(MeshTexture* target, const std::vector<std::string>& files) : target_(target)
    {
        if (!target_) return;
        for (const std::string& file : files) target_->materials.push_back({"", file});
        if (files.empty()) target_->materials.push_back({"", ""});
    }
    bool active() const { return target_ != nullptr; }
    //! Faces from `firstFace` on came from face element row `row` (`polygon`, `coordinates`, `texnumber`).
    void addFaces(const TriMesh& mesh, std::size_t firstFace, const std::vector<int>& polygon,
                  const std::vector<double>& coordinates, double texnumber, long long row)
    {
        if (!target_ || firstFace == mesh.faces.size()) return;
        uv_.clear();
        if (coordinates.size() == 2 * polygon.size())
            for (std::size_t j = 0; j < polygon.size(); ++j) uv_.emplace_back(coordinates[2 * j], coordinates[2 * j + 1]);
        else
            problem(row,
                    std::to_string(coordinates.size()) + " texcoord values for " + std::to_string(polygon.size()) + " corners");
        textured_ |= !coordinates.empty();
        const int materials = static_cast<int>(target_->materials.size());
        if (!(texnumber >= 0 && texnumber < materials && texnumber == std::floor(texnumber))) {
            problem(row, "texnumber " + indexText(texnumber) + " out of range (" + std::to_string(materials) + " textures)");
            texnumber = 0;
        }
        appendCornerTexture(mesh, firstFace, polygon, uv_, static_cast<int>(texnumber), *target_);
    }
    void finish(MeshReadInfo& info)
    {
        if (!target_) return;
        if (textured_ && !problem_.empty()) info.warnings.push_back("texture coordinates dropped: " + problem_);
        if (!textured_ || !problem_.empty()) *target_ = MeshTexture{};
    }

private:
    void problem(long long row, const std::string& what)
    {
        if (problem_.empty()) problem_ = "face " + std::to_string(row) + ": " + what;
    }

    MeshTexture* target_;
    std::vector<Vec2> uv_;
    bool textured_ = false;
    std::string problem_;
};

//! The index of the face element's scalar property `name` (the caller's face property, e.g.
//! --region's); IOError naming the scalar properties the faces do have when it is missing.
int scalarFaceProperty(const std::string& path, const Element& e, const std::string& name)
{
    std::string names;
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
        if (e.properties[i].countSize != 0) continue;
        if (e.properties[i].name == name) return static_cast<int>(i);
        names += (names.empty() ? "" : ", ") + e.properties[i].name;
    }
    fail(path,
         "PLY faces have no scalar property " + quoteInput(name) + " (they have: " + (names.empty() ? "none" : names) + ")");
}

}  // namespace

TriMesh readPly(const std::string& path, const std::string& bytes, MeshReadInfo& info, VertexAttributes& attributes,
                MeshTexture* texture)
{
    Encoding encoding = Encoding::Ascii;
    std::vector<Element> elements;
    std::vector<std::string> textureFiles;
    const std::size_t body = parseHeader(path, bytes, encoding, elements, textureFiles);
    PlyTexture plyTexture(texture, textureFiles);
    BodyReader in(path, bytes, body, encoding);
    TriMesh mesh;
    // Every element takes at least one byte per property: a lying count fails at the end of the
    // data instead of allocating for it.
    const long long capacity = static_cast<long long>(bytes.size());
    for (const Element& e : elements) {
        const bool isVertex = e.name == "vertex", isFace = e.name == "face";
        if ((isVertex || isFace) && e.count > std::numeric_limits<int>::max()) fail(path, "too many " + e.name + " elements");
        int coordinate[3] = {-1, -1, -1};
        int indexList = -1, texcoordList = -1, texnumber = -1;
        for (std::size_t i = 0; i < e.properties.size(); ++i) {
            const Property& p = e.properties[i];
            if (isFace && p.name == (p.countSize > 0 ? "texcoord" : "texnumber"))
                (p.countSize > 0 ? texcoordList : texnumber) = static_cast<int>(i);
            for (int k = 0; k < 3; ++k)
                if (isVertex && p.countSize == 0 && p.name == std::string(1, "xyz"[k])) coordinate[k] = static_cast<int>(i);
            if (isFace && p.countSize > 0 && !p.isFloat && (p.name == "vertex_indices" || p.name == "vertex_index"))
                indexList = static_cast<int>(i);
        }
        if (isVertex && std::count(coordinate, coordinate + 3, -1) > 0) fail(path, "PLY vertices lack an x, y or z property");
        // Optional per-vertex groups: used when all three are scalar properties, noted otherwise.
        struct Group {
            const char* names[3];
            std::vector<Vec3>* target;
            int property[3];
            bool use;
        };
        Group groups[2] = {{{"nx", "ny", "nz"}, &attributes.normals, {-1, -1, -1}, false},
                           {{"rosy_x", "rosy_y", "rosy_z"}, &attributes.rosy, {-1, -1, -1}, false}};
        for (Group& g : groups) {
            if (!isVertex) break;
            int found = 0, lists = 0;
            for (std::size_t i = 0; i < e.properties.size(); ++i)
                for (int k = 0; k < 3; ++k)
                    if (e.properties[i].name == g.names[k]) {
                        if (e.properties[i].countSize > 0)
                            ++lists;
                        else if (g.property[k] < 0)
                            g.property[k] = static_cast<int>(i), ++found;
                    }
            g.use = found == 3 && lists == 0;
            if (!g.use && (found > 0 || lists > 0))
                info.notes.push_back(std::string("PLY vertex properties ") + g.names[0] + " " + g.names[1] + " " + g.names[2] +
                                     " incomplete or not scalar: ignored");
            if (g.use) g.target->reserve(static_cast<std::size_t>(std::min(e.count, capacity)));
        }
        if (isFace && indexList < 0) fail(path, "PLY faces lack a vertex_indices list");
        const int faceValue =
            isFace && !attributes.faceProperty.empty() ? scalarFaceProperty(path, e, attributes.faceProperty) : -1;
        double value = 0;  // of the current face
        if (isVertex) mesh.vertices.reserve(static_cast<std::size_t>(std::min(e.count, capacity)));
        std::vector<int> polygon;
        std::vector<double> texcoords;
        // Without properties an element has no bytes: nothing to read, however many it claims.
        for (long long n = 0; n < e.count && !e.properties.empty(); ++n) {
            double xyz[3] = {0, 0, 0}, textureIndex = 0;
            const std::size_t firstFace = mesh.faces.size();
            Vec3 groupValue[2] = {Vec3::Zero(), Vec3::Zero()};
            for (std::size_t i = 0; i < e.properties.size(); ++i) {
                const Property& p = e.properties[i];
                if (p.countSize == 0) {
                    const double v = in.value(p.size, p.isFloat, p.isSigned);
                    if (static_cast<int>(i) == faceValue) value = v;
                    if (texnumber == static_cast<int>(i)) textureIndex = v;
                    for (int k = 0; k < 3; ++k) {
                        if (coordinate[k] == static_cast<int>(i)) xyz[k] = v;
                        for (int g = 0; g < 2; ++g)
                            if (groups[g].use && groups[g].property[k] == static_cast<int>(i)) groupValue[g][k] = v;
                    }
                    continue;
                }
                const double items = in.value(p.countSize, false, p.countSigned);
                if (!(items >= 0) || items > capacity) fail(path, "invalid list length in PLY element " + quoteInput(e.name));
                if (static_cast<int>(i) == indexList) polygon.clear();
                if (static_cast<int>(i) == texcoordList) texcoords.clear();
                for (long long j = 0; j < static_cast<long long>(items); ++j) {
                    const double v = in.value(p.size, p.isFloat, p.isSigned);
                    if (static_cast<int>(i) == texcoordList) texcoords.push_back(v);
                    if (static_cast<int>(i) != indexList) continue;
                    if (!(v >= 0) || v >= mesh.vertexCount() || v != static_cast<int>(v))
                        fail(path, "face " + std::to_string(n) + " has vertex index " + indexText(v) + " out of range (" +
                                       std::to_string(mesh.vertexCount()) + " vertices)");
                    polygon.push_back(static_cast<int>(v));
                }
                if (static_cast<int>(i) != indexList) continue;
                if (polygon.size() < 3)
                    fail(path, "face " + std::to_string(n) + " has " + std::to_string(polygon.size()) + " corners");
                addPolygon(mesh, polygon, info);
            }
            // The face's value on each of its triangles (the value may come before or after the list).
            if (faceValue >= 0) attributes.faceValues.resize(mesh.faces.size(), value);
            if (isFace && texcoordList >= 0) plyTexture.addFaces(mesh, firstFace, polygon, texcoords, textureIndex, n);
            if (isVertex) {
                mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
                for (int g = 0; g < 2; ++g)
                    if (groups[g].use) groups[g].target->push_back(groupValue[g]);
            }
        }
    }
    plyTexture.finish(info);
    // Never dropped unsaid: e.g. faces beyond the count the header declares.
    if (const std::string rest = in.leftover(); !rest.empty()) {
        std::string declared;
        for (const Element& e : elements) declared += (declared.empty() ? "" : ", ") + std::to_string(e.count) + " " + e.name;
        info.warnings.push_back("PLY data goes on after the elements its header declares (" + declared + "): " + rest +
                                " ignored");
    }
    return mesh;
}

}  // namespace fieldcvt::io_detail
