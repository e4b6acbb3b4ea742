#pragma once
// The files around a textured mesh (issue 36): the OBJ's .mtl material libraries and the texture
// images they and PLY's TextureFile comments name, so that the output's references resolve.
#include "mesh_texture.h"

#include <string>
#include <vector>

namespace fieldcvt::cli {

//! Fills the materials' images from the input's .mtl files (OBJ: `map_Kd` of each `newmtl`),
//! read relative to `inPath`'s folder; a library that cannot be read is a warning, never an error.
void lookUpMaterialImages(MeshTexture& texture, const std::string& inPath, std::vector<std::string>& warnings);

//! Makes `texture` (read from `inPath`, images looked up) resolve from `outPath`'s folder: image
//! paths rebased there; for an OBJ output in another folder the input's .mtl files copied next to
//! it with their image paths rebased, or, when the input named images but no .mtl (PLY), one
//! `<out>.mtl` written.
//! `image` (a path relative to `inPath`'s folder, or absolute) as seen from `outPath`'s folder.
std::string rebaseImage(const std::string& image, const std::string& inPath, const std::string& outPath);

void placeTextureFiles(MeshTexture& texture, const std::string& inPath, const std::string& outPath);

}  // namespace fieldcvt::cli
