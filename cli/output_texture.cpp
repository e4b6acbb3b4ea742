// Keep or bake: the transfer (core/texture_transfer.h) and the bake (core/texture_bake.h) with
// the images read and written here.
#include "output_texture.h"

#include "arguments.h"
#include "cli_common.h"
#include "texture_files.h"

#include "errors.h"
#include "image_io.h"
#include "texture_bake.h"
#include "texture_transfer.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace fieldcvt::cli {

namespace fs = std::filesystem;

TextureMode textureModeFromText(const std::string& text)
{
    if (text == "auto") return TextureMode::Auto;
    if (text == "keep") return TextureMode::Keep;
    if (text == "bake") return TextureMode::Bake;
    throw UsageError("--texture must be auto, keep or bake (got '" + text + "')");
}

namespace {

std::string percentText(double share)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.2f %%", 100 * share);
    return text;
}

//! The input's images, one per material; empty with a warning when one cannot be read.
std::vector<TextureImage> inputImages(const MeshTexture& texture, const std::string& inPath, std::vector<std::string>& warnings)
{
    std::vector<TextureImage> images;
    const fs::path folder = fs::path(inPath).parent_path();
    for (const TextureMaterial& m : texture.materials) {
        if (m.image.empty()) {
            warnings.push_back(inPath + ": material '" + m.name + "' names no image: no texture to bake, the atlas is kept");
            return {};
        }
        try {
            images.push_back(readImage((folder / m.image).string()));
        } catch (const Error& e) {
            warnings.push_back(std::string(e.what()) + ": no texture to bake, the atlas is kept");
            return {};
        }
    }
    return images;
}

//! The new image's file: OUT's name with "_texture.png", beside it.
fs::path bakedImagePath(const std::string& outPath)
{
    fs::path path(outPath);
    return path.parent_path() / (path.stem().string() + "_texture.png");
}

}  // namespace

OutputTexture makeOutputTexture(const TriMesh& input, const MeshTexture& inputTexture, const TriMesh& output, int threads,
                                const std::string& inPath, const std::string& outPath, TextureMode mode,
                                std::vector<std::string>& warnings)
{
    OutputTexture result;
    if (inputTexture.empty()) return result;
    if (!isPlyPath(outPath) && !isObjPath(outPath)) {
        warnings.push_back(outPath + ": texture coordinates not written (only .obj and .ply hold them)");
        return result;
    }
    const auto start = std::chrono::steady_clock::now();
    TextureTransferParams transferParams;
    transferParams.threads = threads;
    MeshTexture withImages = inputTexture;  // the materials' images looked up in the .mtl files
    lookUpMaterialImages(withImages, inPath, warnings);
    TextureTransferResult kept = transferTexture(input, withImages, output, transferParams);
    result.charts = kept.charts;
    result.continuedFaces = kept.continuedFaces;
    result.continuedShare = kept.continuedShare;

    const bool bake = mode == TextureMode::Bake || (mode == TextureMode::Auto && kept.continuedShare > kBakeAboveContinuedShare);
    std::vector<TextureImage> images;
    if (bake) images = inputImages(withImages, inPath, warnings);
    if (bake && !images.empty()) {
        TextureBakeParams bakeParams;
        bakeParams.threads = threads;
        TextureBakeResult baked = bakeTexture(input, withImages, images, output, bakeParams);
        const fs::path imagePath = bakedImagePath(outPath);
        writePng(imagePath.string(), baked.image);
        baked.texture.materials[0].image = imagePath.filename().string();
        result.texture = std::move(baked.texture);
        result.method = "bake";
        result.bakedImage = imagePath.string();
        result.bakedWidth = baked.image.width;
        result.bakedHeight = baked.image.height;
        result.cellSize = baked.cellSize;
        placeTextureFiles(result.texture, outPath, outPath);  // the image is already beside OUT: an .mtl for an OBJ
    } else {
        result.texture = std::move(kept.texture);
        result.method = "keep_atlas";
        placeTextureFiles(result.texture, inPath, outPath);
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

std::string textureNote(const OutputTexture& texture)
{
    if (texture.texture.empty()) return {};
    const std::string keep = std::to_string(texture.charts) + " charts, " + std::to_string(texture.continuedFaces) +
                             " output faces (" + percentText(texture.continuedShare) + ") across a seam";
    if (texture.method == "bake")
        return "texture baked into " + texture.bakedImage + " (" + std::to_string(texture.bakedWidth) + " x " +
               std::to_string(texture.bakedHeight) + ", one triangle per face): keeping the input's atlas (" + keep +
               ") would stretch them";
    return "texture kept in the input's atlas: " + keep + ", continued there";
}

nlohmann::ordered_json textureJson(const MeshTexture& input, bool dropped, const OutputTexture& texture)
{
    nlohmann::ordered_json json = {
        {"input_has_texture", dropped ? nlohmann::ordered_json() : nlohmann::ordered_json(!input.empty())},
        {"no_texture_option", dropped},
        {"kept", !texture.texture.empty()}};
    if (texture.texture.empty()) return json;
    json["mode"] = texture.method;
    json["charts"] = texture.charts;
    json["materials"] = texture.texture.materials.size();
    json["continued_faces"] = texture.continuedFaces;
    json["continued_share"] = texture.continuedShare;
    if (texture.method == "bake") {
        json["baked_image"] = texture.bakedImage;
        json["baked_width"] = texture.bakedWidth;
        json["baked_height"] = texture.bakedHeight;
        json["cell_texels"] = texture.cellSize;
    }
    json["time_s"] = texture.seconds;  // part of the write time: the transfer or bake and the texture files
    return json;
}

}  // namespace fieldcvt::cli
