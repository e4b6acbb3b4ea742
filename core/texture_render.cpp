// The rasteriser behind texture_render.h: orthographic projection, a depth buffer, texture
// coordinates interpolated per pixel centre (exact for an orthographic camera) and sampled
// bilinearly.
#include "texture_render.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fieldcvt {

std::vector<RenderCamera> camerasAround(const TriMesh& mesh, int views, int size)
{
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::max()), high = -low;
    for (const Vec3& p : mesh.vertices) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    if (mesh.vertices.empty()) low = high = Vec3::Zero();
    const Vec3 extent = high - low;
    // The model turns about the y axis, "up" in OBJ and glTF files and in MeshLab's default view.
    const Vec3 spin = Vec3::UnitY(), across = Vec3::UnitZ(), third = spin.cross(across);
    const double radius = std::max(0.5 * extent.norm(), 1e-12);
    const double elevation = 20.0 * M_PI / 180.0;
    std::vector<RenderCamera> cameras;
    for (int i = 0; i < views; ++i) {
        const double azimuth = 2.0 * M_PI * i / views;
        const Vec3 horizontal = std::cos(azimuth) * across + std::sin(azimuth) * third;
        RenderCamera c;
        c.centre = 0.5 * (low + high);
        c.forward = -(std::cos(elevation) * horizontal + std::sin(elevation) * spin).normalized();
        c.right = spin.cross(c.forward).normalized();
        c.up = c.forward.cross(c.right).normalized();
        c.size = size;
        c.pixelSize = 2.0 * radius * 1.02 / size;
        cameras.push_back(c);
    }
    return cameras;
}

namespace {

//! A point in pixel units (x right, y down) and its depth along the camera's forward axis.
Vec3 project(const RenderCamera& c, const Vec3& p)
{
    const Vec3 d = p - c.centre;
    return {d.dot(c.right) / c.pixelSize + 0.5 * c.size + c.shift.x(), 0.5 * c.size - d.dot(c.up) / c.pixelSize - c.shift.y(),
            d.dot(c.forward)};
}

}  // namespace

TextureRender renderTextured(const TriMesh& mesh, const MeshTexture& texture, const std::vector<TextureImage>& images,
                             const RenderCamera& camera)
{
    const int n = camera.size;
    TextureRender render;
    render.size = n;
    render.colour.assign(static_cast<std::size_t>(n) * n, Eigen::Vector3f::Zero());
    render.covered.assign(static_cast<std::size_t>(n) * n, 0);
    std::vector<double> depth(static_cast<std::size_t>(n) * n, std::numeric_limits<double>::infinity());
    const bool textured = !texture.empty();
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Face& face = mesh.faces[f];
        const Vec3 a = project(camera, mesh.vertices[face[0]]), b = project(camera, mesh.vertices[face[1]]),
                   c = project(camera, mesh.vertices[face[2]]);
        const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
        if (!(std::abs(area) > 1e-12)) continue;  // seen edge-on (or not finite)
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
        const int x1 = std::min(n - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
        const int y1 = std::min(n - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
        const TextureImage* image = nullptr;
        if (textured) {
            const int material = texture.faceMaterial[f];
            if (material >= 0 && material < static_cast<int>(images.size()) && !images[material].empty())
                image = &images[material];
        }
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                // Barycentric coordinates of the pixel centre: the signed areas opposite each corner.
                const double wa = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) / area;
                const double wb = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) / area;
                const double wc = 1.0 - wa - wb;
                // A pixel centre on an edge belongs to both faces (rounding must not leave a hole there).
                constexpr double kOnEdge = -1e-9;
                if (wa < kOnEdge || wb < kOnEdge || wc < kOnEdge) continue;
                const std::size_t i = static_cast<std::size_t>(y) * n + x;
                const double z = wa * a.z() + wb * b.z() + wc * c.z();
                if (z >= depth[i]) continue;
                depth[i] = z;
                render.covered[i] = 1;
                if (!image) {
                    render.colour[i] = Eigen::Vector3f::Constant(128.0f);
                    continue;
                }
                const std::size_t k = 3 * static_cast<std::size_t>(f);
                const Vec2 uv = wa * texture.uv[k] + wb * texture.uv[k + 1] + wc * texture.uv[k + 2];
                render.colour[i] = image->sample(uv.x(), uv.y()).cast<float>();
            }
    }
    return render;
}

RenderDifference compareRenders(const TextureRender& a, const TextureRender& b)
{
    RenderDifference d;
    if (a.size != b.size) return d;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.covered.size(); ++i) {
        if (a.covered[i] && b.covered[i]) {
            sum += (a.colour[i] - b.colour[i]).cwiseAbs().sum() / 3.0;
            ++d.pixels;
        } else if (a.covered[i] != b.covered[i]) {
            ++d.onlyOne;
        }
    }
    d.meanAbsolute = d.pixels ? sum / d.pixels : 0.0;
    return d;
}

}  // namespace fieldcvt
