#pragma once
// The files around a textured mesh: the OBJ's .mtl material libraries and the texture images they
// and PLY's TextureFile comments name, read with the side-file discipline (io/side_files.h), and
// the material library written for the output.
#include "mesh_texture.h"
#include "side_files.h"

#include <string>
#include <vector>

namespace fieldcvt::cli {

//! An input material library that was read and parses as one.
struct MaterialLibrary {
    std::string name;  //!< as the OBJ's `mtllib` names it (relative to the mesh's folder)
    std::string text;
};

//! Reads the input's .mtl files (relative to `inPath`'s folder) and fills the materials' images
//! (`map_Kd` of each `newmtl`). A library that is not a regular file, is over the size limit or
//! does not parse as a material library is a warning and is left out; an image that is not a
//! regular file is a warning and is dropped from its material; a missing image is a warning and
//! keeps its name. The texture coordinates are always kept. Returns the libraries that were read.
std::vector<MaterialLibrary> lookUpMaterialImages(MeshTexture& texture, const std::string& inPath,
                                                  std::vector<std::string>& warnings);

//! Marks the files the input names (its libraries, their images and maps, the materials' images)
//! as protected in `names`: a run never writes over them.
void protectInputFiles(const MeshTexture& texture, const std::vector<MaterialLibrary>& libraries, const std::string& inPath,
                       SideFileNames& names);

//! `image` (a path relative to `inPath`'s folder, or absolute) as seen from `outPath`'s folder.
std::string rebaseImage(const std::string& image, const std::string& inPath, const std::string& outPath);

//! Makes `texture` (read from `inPath`, images looked up, `libraries` as read) resolve from
//! `outPath`'s folder: image paths rebased there; an OBJ output gets a material library of its
//! own, `<OUT stem>.mtl` (or the name `names` gives instead), holding the input's libraries with
//! their file names rebased, or, when there were none (PLY input, a baked image), one material per
//! image. Input files are never written.
void placeTextureFiles(MeshTexture& texture, const std::vector<MaterialLibrary>& libraries, const std::string& inPath,
                       const std::string& outPath, SideFileNames& names, std::vector<std::string>& warnings);

}  // namespace fieldcvt::cli
