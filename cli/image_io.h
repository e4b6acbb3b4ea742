#pragma once
// Texture images read and written by the fcvt command (issue 36): PNG, JPEG, BMP, TGA in
// through stb_image, PNG out through stb_image_write (Debian's libstb-dev, header-only here).
#include "mesh_texture.h"
#include "texture_image.h"

#include <string>
#include <vector>

namespace fieldcvt {

//! The picture in `path` as 8-bit RGB (grey and alpha dropped to RGB); throws fieldcvt::Error
//! with the file name and stb's reason when it cannot be read.
TextureImage readImage(const std::string& path);

//! The images of `texture`'s materials (one each, looked up beside `meshPath`'s file); throws
//! fieldcvt::Error naming the first that is missing or cannot be read.
std::vector<TextureImage> readMaterialImages(const MeshTexture& texture, const std::string& meshPath);

//! Writes `image` as a PNG; throws fieldcvt::Error when it cannot.
void writePng(const std::string& path, const TextureImage& image);

}  // namespace fieldcvt
