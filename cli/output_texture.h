#pragma once
// The output's texture for `fcvt remesh` (issue 36): the input's atlas kept, or a new texture
// baked, chosen per mesh (--texture), with the files around it (.mtl, images) placed next to OUT.
#include "mesh.h"
#include "mesh_texture.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace fieldcvt::cli {

enum class TextureMode { Auto, Keep, Bake };

//! "auto", "keep" or "bake" (a UsageError otherwise).
TextureMode textureModeFromText(const std::string& text);

struct OutputTexture {
    MeshTexture texture;     //!< empty: the output has no texture coordinates
    std::string method;      //!< "keep_atlas" or "bake"
    int charts = 0;          //!< the input atlas's charts
    int continuedFaces = 0;  //!< output faces continued across a seam when keeping the atlas
    double continuedShare = 0.0;
    std::string bakedImage;  //!< the new image's path (bake)
    int bakedWidth = 0, bakedHeight = 0, cellSize = 0;
    double seconds = 0.0;
};

//! The texture for `output`, remeshed from `input` (read from `inPath`, to be written to
//! `outPath`); warnings when it cannot be made as asked (no image to bake from: the atlas kept).
OutputTexture makeOutputTexture(const TriMesh& input, const MeshTexture& inputTexture, const TriMesh& output, int threads,
                                const std::string& inPath, const std::string& outPath, TextureMode mode,
                                std::vector<std::string>& warnings);

//! The information line on the texture (empty without one).
std::string textureNote(const OutputTexture& texture);

//! The report's texture object; `input_has_texture` is null with --no-texture (not read then).
nlohmann::ordered_json textureJson(const MeshTexture& input, bool dropped, const OutputTexture& texture);

}  // namespace fieldcvt::cli
