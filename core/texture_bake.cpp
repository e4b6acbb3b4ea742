// Per-face packing and texel sampling behind texture_bake.h.
#include "texture_bake.h"

#include "closest_point.h"
#include "morton_order.h"
#include "thread_budget.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>

namespace fieldcvt {

namespace {

constexpr double kMargin = 1.5;  // texels between a face's triangle and its cell's border or its neighbour

//! The triangle of cell slot 0 (lower-left) or 1 (upper-right), in texels from the cell's top-left corner.
std::array<Vec2, 3> slotTriangle(int slot, int cell)
{
    const double s = cell, m = kMargin, c = kMargin * std::sqrt(2.0);  // c / sqrt 2 = the margin to the diagonal
    if (slot == 0) return {Vec2(m, m), Vec2(s - c - m, m), Vec2(m, s - c - m)};
    return {Vec2(s - m, s - m), Vec2(s - m, c + m), Vec2(c + m, s - m)};
}

int gridColumns(std::size_t faces) { return std::max(1, static_cast<int>(std::ceil(std::sqrt(0.5 * faces)))); }

int gridRows(std::size_t faces, int columns)
{
    const std::size_t cells = (faces + 1) / 2;
    return std::max(1, static_cast<int>((cells + columns - 1) / columns));
}

//! Where each face goes: slot 2 c + h is half h of cell c; cell c lies at column cellAt[c][0],
//! row cellAt[c][1] of the grid.
struct Layout {
    std::vector<int> faceOfSlot;
    std::vector<std::array<int, 2>> cellAt;
};

Layout cellLayout(const TriMesh& output, int columns, int rows)
{
    Layout layout;
    std::vector<Vec3> centroids;
    centroids.reserve(output.faces.size());
    for (const Face& f : output.faces)
        centroids.push_back((output.vertices[f[0]] + output.vertices[f[1]] + output.vertices[f[2]]) / 3.0);
    layout.faceOfSlot = mortonIndexOrder(centroids);
    std::vector<Vec3> grid;  // the cells' places, in the plane
    grid.reserve(static_cast<std::size_t>(columns) * rows);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) grid.emplace_back(c, r, 0.0);
    const std::vector<int> order = mortonIndexOrder(grid);
    const std::size_t cells = (output.faces.size() + 1) / 2;
    for (std::size_t i = 0; i < cells; ++i) layout.cellAt.push_back({order[i] % columns, order[i] / columns});
    return layout;
}

Vec3 inputColour(const MeshTexture& texture, const std::vector<TextureImage>& images, const ClosestPoint& cp)
{
    const int material = texture.faceMaterial[cp.face];
    if (material < 0 || material >= static_cast<int>(images.size()) || images[material].empty()) return Vec3::Constant(128.0);
    const std::size_t k = 3 * static_cast<std::size_t>(cp.face);
    const Vec2 uv =
        cp.barycentric[0] * texture.uv[k] + cp.barycentric[1] * texture.uv[k + 1] + cp.barycentric[2] * texture.uv[k + 2];
    return images[material].sample(uv.x(), uv.y());
}

}  // namespace

int bakeCellSize(const TriMesh& input, const MeshTexture& inputTexture, const std::vector<TextureImage>& inputImages,
                 const TriMesh& output, const TextureBakeParams& params)
{
    const int columns = gridColumns(output.faces.size()), rows = gridRows(output.faces.size(), columns);
    const int fitting = std::max(4, params.maxSize / std::max(columns, rows));
    if (params.cellSize > 0) return std::min(params.cellSize, fitting);
    // Texels of the input's images on its surface, through its texture coordinates.
    double texels = 0.0;
    for (int f = 0; f < input.faceCount(); ++f) {
        const int material = inputTexture.faceMaterial[f];
        if (material < 0 || material >= static_cast<int>(inputImages.size()) || inputImages[material].empty()) continue;
        const std::size_t k = 3 * static_cast<std::size_t>(f);
        const Vec2 e0 = inputTexture.uv[k + 1] - inputTexture.uv[k], e1 = inputTexture.uv[k + 2] - inputTexture.uv[k];
        const double uvArea = 0.5 * std::abs(e0.x() * e1.y() - e0.y() * e1.x());
        if (std::isfinite(uvArea)) texels += std::min(uvArea, 1.0) * inputImages[material].width * inputImages[material].height;
    }
    // A cell's two triangles hold about (s - 3)^2 texels. Eight times the input's texels per
    // output face, and cells of at least 16 texels: smaller ones blur the picture where the
    // margins take most of a triangle (docs/tuning.md, "Baked texture: cells of 16 texels at least").
    const double perFace = output.faces.empty() ? 0.0 : 8.0 * texels / output.faces.size();
    const int wanted = static_cast<int>(std::ceil(std::sqrt(perFace) + 3.0));
    return std::min(std::clamp(wanted, 16, 64), fitting);
}

TextureBakeResult bakeTexture(const TriMesh& input, const MeshTexture& inputTexture, const std::vector<TextureImage>& inputImages,
                              const TriMesh& output, const TextureBakeParams& params, const ClosestPointTree* inputTree)
{
    TextureBakeResult result;
    const int cell = bakeCellSize(input, inputTexture, inputImages, output, params);
    const int columns = gridColumns(output.faces.size()), rows = gridRows(output.faces.size(), columns);
    result.cellSize = cell;
    TextureImage& image = result.image;
    image.width = columns * cell;
    image.height = rows * cell;
    image.rgb.assign(3 * static_cast<std::size_t>(image.width) * image.height, 255);

    // Viewers sample a texture through mipmaps: seen from afar, a texel is the mean of a block
    // of its neighbours. So neighbours in the image hold neighbours on the surface: faces in the
    // Morton order of their centroids, two to a cell, cells along a Morton curve of the grid
    // (unrelated faces side by side turned a remeshed model into a mosaic in MeshLab's view).
    const Layout layout = cellLayout(output, columns, rows);
    MeshTexture& texture = result.texture;
    texture.materials = {TextureMaterial{"fcvt_baked", ""}};
    texture.faceMaterial.assign(output.faces.size(), 0);
    texture.uv.resize(3 * output.faces.size());
    for (std::size_t slot = 0; slot < layout.faceOfSlot.size(); ++slot) {
        const int f = layout.faceOfSlot[slot];
        const std::array<int, 2>& at = layout.cellAt[slot / 2];
        const Vec2 origin(at[0] * cell, at[1] * cell);
        const std::array<Vec2, 3> corners = slotTriangle(static_cast<int>(slot % 2), cell);
        for (int k = 0; k < 3; ++k) {
            const Vec2 texel = origin + corners[k];
            texture.uv[3 * static_cast<std::size_t>(f) + k] = Vec2(texel.x() / image.width, 1.0 - texel.y() / image.height);
        }
    }
    if (output.faces.empty()) return result;

    std::unique_ptr<const ClosestPointTree> ownTree;
    if (!inputTree) ownTree = std::make_unique<const ClosestPointTree>(input);
    const ClosestPointTree& tree = inputTree ? *inputTree : *ownTree;
    const int threads = openMpThreads(params.threads);
    const long long cells = (static_cast<long long>(output.faces.size()) + 1) / 2;
    // Each cell writes only its own texels: the same image on any thread count.
#pragma omp parallel for num_threads(threads) schedule(dynamic, 16) if (threads > 1)
    for (long long c = 0; c < cells; ++c) {
        std::array<int, 2> hint = {-1, -1};
        for (int y = 0; y < cell; ++y)
            for (int x = 0; x < cell; ++x) {
                const int slot = (x + y + 1 < cell || 2 * c + 1 >= output.faceCount()) ? 0 : 1;
                const int f = layout.faceOfSlot[static_cast<std::size_t>(2 * c + slot)];
                const std::array<Vec2, 3> t = slotTriangle(slot, cell);
                // The texel centre's closest point in the face's triangle, as barycentric coordinates.
                Vec3 w;
                closestPointOnTriangle(Vec3(x + 0.5, y + 0.5, 0.0), Vec3(t[0].x(), t[0].y(), 0.0), Vec3(t[1].x(), t[1].y(), 0.0),
                                       Vec3(t[2].x(), t[2].y(), 0.0), &w);
                const Face& face = output.faces[f];
                const Vec3 p =
                    w[0] * output.vertices[face[0]] + w[1] * output.vertices[face[1]] + w[2] * output.vertices[face[2]];
                const ClosestPoint cp = hint[slot] >= 0 ? tree.closest(p, hint[slot]) : tree.closest(p);
                hint[slot] = cp.face;
                const Vec3 colour = inputColour(inputTexture, inputImages, cp);
                const std::array<int, 2>& at = layout.cellAt[static_cast<std::size_t>(c)];
                image.set(at[0] * cell + x, at[1] * cell + y, colour);
            }
    }
    return result;
}

}  // namespace fieldcvt
