// A tolerant Wavefront OBJ reader of our own: MeshLab 2020.09's vcglib importer aborts on files
// with `f a//n` corners, normals and CRLF line ends, which are common in the wild.
#include "errors.h"
#include "formats.h"
#include "io_detail.h"
#include "text_scan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace fieldcvt::io_detail {

namespace {

//! The vertex of one face corner `a`, `a/t`, `a//n` or `a/t/n`: 1-based, or negative = relative
//! to the vertices read so far. Returns the 0-based index, or fails naming the line.
int cornerVertex(const TextScanner& scan, std::string_view corner, int vertexCount)
{
    const long long raw = scan.integer(corner.substr(0, corner.find('/')));
    const long long index = raw < 0 ? vertexCount + raw : raw - 1;
    if (raw == 0 || index < 0 || index >= vertexCount)
        scan.fail("face corner " + quoteInput(corner) + " refers to a vertex that does not exist (" +
                  std::to_string(vertexCount) + " vertices so far)");
    return static_cast<int>(index);
}

//! What a file's texture coordinates (`vt`, `f v/vt`, `usemtl`, `mtllib`) amount to, read alongside
//! the geometry; the first inconsistency makes them all dropped (the geometry stays).
class ObjTexture {
public:
    explicit ObjTexture(MeshTexture* target) : target_(target) {}

    void addCoordinates(const std::vector<std::string_view>& t)
    {
        double u = NAN, v = 0;
        if (t.size() < 2 || !parseNumber(t[1], u) || (t.size() > 2 && !parseNumber(t[2], v))) u = NAN;
        coordinates_.emplace_back(u, v);  // a malformed one is caught as not finite when used
    }
    void useMaterial(const std::vector<std::string_view>& t)
    {
        material_ = materialIndex(t.size() > 1 ? std::string(t[1]) : std::string());
    }
    void addLibraries(const std::vector<std::string_view>& t)
    {
        if (target_)
            for (std::size_t i = 1; i < t.size(); ++i) target_->libraries.emplace_back(t[i]);
    }
    //! The corners' coordinates, before the polygon is triangulated: `uv` empty when none.
    void polygonCoordinates(int line, const std::vector<std::string_view>& t, std::vector<Vec2>& uv)
    {
        uv.clear();
        if (!target_) return;
        int given = 0;
        for (std::size_t c = 1; c < t.size(); ++c) {
            const std::string_view corner = t[c];
            const std::size_t slash = corner.find('/');
            const std::string_view index = slash == std::string_view::npos
                                               ? std::string_view()
                                               : corner.substr(slash + 1, corner.find('/', slash + 1) - slash - 1);
            if (index.empty()) continue;
            ++given;
            double raw = 0;
            const long long count = static_cast<long long>(coordinates_.size());
            const long long i = parseNumber(index, raw) && raw == std::floor(raw) && std::fabs(raw) < 9e18
                                    ? (raw < 0 ? count + static_cast<long long>(raw) : static_cast<long long>(raw) - 1)
                                    : -1;
            if (raw == 0 || i < 0 || i >= count) {
                problem(line, "texture coordinate index " + quoteInput(index) + " out of range");
                uv.emplace_back(NAN, NAN);
            } else {
                uv.push_back(coordinates_[static_cast<std::size_t>(i)]);
            }
        }
        if (given > 0 && given < static_cast<int>(t.size()) - 1)
            problem(line, "a face with texture coordinates at some corners only");
        if (given == 0) uv.clear();
        if (given == 0 && !coordinates_.empty()) untextured_ = true;
        textured_ |= given > 0;
    }
    //! Faces from `firstFace` on came from the polygon with coordinates `uv` (empty: none).
    void addFaces(const TriMesh& mesh, std::size_t firstFace, const std::vector<int>& polygon, const std::vector<Vec2>& uv)
    {
        if (target_) appendCornerTexture(mesh, firstFace, polygon, uv, material_ < 0 ? materialIndex("") : material_, *target_);
    }
    void finish(MeshReadInfo& info)
    {
        if (!target_) return;
        if (textured_ && untextured_ && problem_.empty()) problem_ = "some faces have no texture coordinates";
        if (!textured_ || !problem_.empty()) {
            if (textured_) info.warnings.push_back("texture coordinates dropped: " + problem_);
            *target_ = MeshTexture{};
        }
    }

private:
    int materialIndex(const std::string& name)
    {
        const auto found = materials_.find(name);
        if (found != materials_.end()) return found->second;
        if (target_) target_->materials.push_back({name, ""});
        return materials_[name] = static_cast<int>(materials_.size());
    }
    void problem(int line, const std::string& what)
    {
        if (problem_.empty()) problem_ = "line " + std::to_string(line) + ": " + what;
    }

    MeshTexture* target_;
    std::vector<Vec2> coordinates_;
    std::map<std::string, int> materials_;
    int material_ = -1;
    bool textured_ = false, untextured_ = false;
    std::string problem_;
};

}  // namespace

TriMesh readObj(const std::string& path, const std::string& text, MeshReadInfo& info, MeshTexture* texture)
{
    TriMesh mesh;
    TextScanner scan(path, text, true);  // a line ending in a backslash goes on
    ObjTexture objTexture(texture);
    std::vector<int> polygon;
    std::vector<Vec2> uv;
    while (scan.nextLine()) {
        const auto& t = scan.tokens();
        if (t[0] == "v") {
            if (t.size() < 4) scan.fail("vertex with fewer than 3 coordinates");
            mesh.vertices.emplace_back(scan.number(t[1]), scan.number(t[2]), scan.number(t[3]));
            if (mesh.vertices.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) scan.fail("too many vertices");
        } else if (t[0] == "f") {
            if (t.size() < 4) scan.fail("face with fewer than 3 corners");
            polygon.clear();
            for (std::size_t i = 1; i < t.size(); ++i) polygon.push_back(cornerVertex(scan, t[i], mesh.vertexCount()));
            const std::size_t firstFace = mesh.faces.size();
            objTexture.polygonCoordinates(scan.lineNumber(), t, uv);
            addPolygon(mesh, polygon, info);
            objTexture.addFaces(mesh, firstFace, polygon, uv);
        } else if (texture && t[0] == "vt") {
            objTexture.addCoordinates(t);
        } else if (texture && t[0] == "usemtl") {
            objTexture.useMaterial(t);
        } else if (texture && t[0] == "mtllib") {
            objTexture.addLibraries(t);
        }
        // vn, g, o, s, l, p ... carry nothing the remesher uses.
    }
    objTexture.finish(info);
    return mesh;
}

}  // namespace fieldcvt::io_detail
