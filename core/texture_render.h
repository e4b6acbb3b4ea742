#pragma once
// Unlit textured renders of a mesh and their comparison: how much a remeshed
// model's texture differs from its input's, seen from the same cameras. A small software
// rasteriser, so that the figure needs no GPU, no X server and no viewer's version.
#include "mesh.h"
#include "mesh_texture.h"
#include "texture_image.h"

#include <vector>

namespace fieldcvt {

//! An orthographic camera: pixel (x, y) of a size × size picture sees, along `forward`, the
//! points p with (p - centre)·right = (x + 0.5 - size / 2 - shift.x) · pixelSize and
//! (p - centre)·up = (size / 2 - y - 0.5 + shift.y) · pixelSize.
struct RenderCamera {
    Vec3 centre = Vec3::Zero();
    Vec3 right = Vec3::UnitX();
    Vec3 up = Vec3::UnitY();
    Vec3 forward = -Vec3::UnitZ();
    double pixelSize = 1.0;
    int size = 512;
    Eigen::Vector2d shift = Eigen::Vector2d::Zero();  //!< in pixels: the picture moved right and up
};

//! `views` cameras around `mesh` (default 6: every 60° of azimuth about the y axis, "up" in OBJ
//! files and MeshLab, 20° above the bounding box's middle), each fitting the box's sphere in `size` pixels.
std::vector<RenderCamera> camerasAround(const TriMesh& mesh, int views = 6, int size = 512);

//! A render: the colour of each pixel (0 .. 255 per channel) and whether the mesh covers it.
struct TextureRender {
    int size = 0;
    std::vector<Eigen::Vector3f> colour;  //!< row by row, row 0 at the top
    std::vector<char> covered;
};

//! `mesh` seen by `camera`, each pixel the texture colour (no light) of the nearest face at its
//! centre; `images` holds one image per material of `texture` (an empty one renders mid-grey).
TextureRender renderTextured(const TriMesh& mesh, const MeshTexture& texture, const std::vector<TextureImage>& images,
                             const RenderCamera& camera);

struct RenderDifference {
    double meanAbsolute = 0.0;  //!< mean over the pixels both cover of |a - b|, averaged over R, G, B (0 .. 255)
    long long pixels = 0;       //!< pixels both cover
    long long onlyOne = 0;      //!< pixels exactly one covers (silhouette difference)
};

RenderDifference compareRenders(const TextureRender& a, const TextureRender& b);

}  // namespace fieldcvt
