#pragma once
// The output's texture for `fcvt remesh` (issue 36): the input's atlas kept, or a new texture
// baked, chosen per mesh (--texture), with the files around it (.mtl, images) placed next to OUT.
#include "mesh.h"
#include "mesh_texture.h"
#include "side_files.h"
#include "texture_output.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace fieldcvt::cli {

//! The output's texture (core/texture_output.h) with its files in place.
struct WrittenTexture {
    fieldcvt::OutputTexture made;  //!< `made.texture` empty: the output has no texture coordinates
    std::string bakedImage;        //!< the new image's path (baked)
    double seconds = 0.0;          //!< the transfer or bake and the texture files
};

//! The texture for `output`, remeshed from `input` (read from `inPath`, to be written to
//! `outPath`; `faceOrigin` as RegionRemeshResult's after a selection-only run, else empty);
//! warnings when it cannot be made as asked (no image to bake from: the atlas kept). The files
//! written beside OUT (its .mtl, the baked image) get their names from `names`.
WrittenTexture writeOutputTexture(const TriMesh& input, const MeshTexture& inputTexture, const TriMesh& output,
                                  const std::vector<int>& faceOrigin, int threads, const std::string& inPath,
                                  const std::string& outPath, TextureMethod method, SideFileNames& names,
                                  std::vector<std::string>& warnings);

//! The information line on the texture (empty without one).
std::string textureNote(const WrittenTexture& texture);

//! The report's texture object; `input_has_texture` is null with --no-texture (not read then).
nlohmann::ordered_json textureJson(const MeshTexture& input, bool dropped, const WrittenTexture& texture);

}  // namespace fieldcvt::cli
