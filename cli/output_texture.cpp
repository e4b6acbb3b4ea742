// Keep or bake: the transfer (core/texture_transfer.h) and the bake (core/texture_bake.h) with
// the images read and written here.
#include "output_texture.h"

#include "cli_common.h"
#include "texture_files.h"

#include "errors.h"
#include "image_io.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace fieldcvt::cli {

namespace fs = std::filesystem;

namespace {

std::string percentText(double share)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.2f %%", 100 * share);
    return text;
}

//! The new image's file: OUT's name with "_texture.png", beside it.
fs::path bakedImagePath(const std::string& outPath)
{
    fs::path path(outPath);
    return path.parent_path() / (path.stem().string() + "_texture.png");
}

}  // namespace

WrittenTexture writeOutputTexture(const TriMesh& input, const MeshTexture& inputTexture, const TriMesh& output,
                                  const std::vector<int>& faceOrigin, int threads, const std::string& inPath,
                                  const std::string& outPath, TextureMethod method, SideFileNames& names,
                                  std::vector<std::string>& warnings)
{
    WrittenTexture result;
    if (inputTexture.empty()) return result;
    if (!isPlyPath(outPath) && !isObjPath(outPath)) {
        warnings.push_back(outPath + ": texture coordinates not written (only .obj and .ply hold them)");
        return result;
    }
    const auto start = std::chrono::steady_clock::now();
    MeshTexture withImages = inputTexture;  // the materials' images looked up in the .mtl files
    const std::vector<MaterialLibrary> libraries = lookUpMaterialImages(withImages, inPath, warnings);
    protectInputFiles(inputTexture, libraries, inPath, names);
    protectInputFiles(withImages, libraries, inPath, names);
    OutputTextureParams params;
    params.method = method;
    params.threads = threads;
    // Keeping the atlas never needs the images; a bake without them keeps it, with a warning.
    std::vector<TextureImage> images;
    std::string imageProblem;
    try {
        if (method != TextureMethod::Keep) images = readMaterialImages(withImages, inPath);
    } catch (const Error& e) {
        imageProblem = e.what();
    }
    result.made = makeOutputTexture(input, withImages, images, output, faceOrigin, params);
    if (result.made.tooManyFacesToBake)
        warnings.push_back("too many faces to bake a texture within " + std::to_string(params.bakeMaxSize) + " x " +
                           std::to_string(params.bakeMaxSize) + " texels: the input's atlas is kept");
    else if (result.made.bakeImpossible)
        warnings.push_back(imageProblem + ": no texture to bake, the atlas is kept");
    MeshTexture& texture = result.made.texture;
    if (result.made.baked) {
        const fs::path imagePath = names.choose(bakedImagePath(outPath).string(), warnings);
        writePng(imagePath.string(), result.made.bakedImage);
        result.made.bakedImage = {};  // written: its memory back
        result.bakedImage = imagePath.string();
        // One material file for all, written beside OUT: the baked image there, the input's
        // (the kept faces of a selection) as seen from there.
        for (int m = 0; m < result.made.bakedMaterial; ++m)
            texture.materials[m].image = rebaseImage(texture.materials[m].image, inPath, outPath);
        texture.materials[result.made.bakedMaterial].image = imagePath.filename().string();
        placeTextureFiles(texture, {}, outPath, outPath, names, warnings);
    } else {
        placeTextureFiles(texture, libraries, inPath, outPath, names, warnings);
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

std::string textureNote(const WrittenTexture& written)
{
    const fieldcvt::OutputTexture& texture = written.made;
    if (texture.texture.empty()) return {};
    const std::string keep = std::to_string(texture.charts) + " charts, " + std::to_string(texture.continuedFaces) +
                             " output faces (" + percentText(texture.continuedShare) + ") across a seam";
    if (texture.baked)
        return "texture baked into " + written.bakedImage + " (" + std::to_string(texture.cellSize) +
               " texels a cell, one triangle per face): keeping the input's atlas (" + keep + ") would stretch them";
    return "texture kept in the input's atlas: " + keep + ", continued there";
}

nlohmann::ordered_json textureJson(const MeshTexture& input, bool dropped, const WrittenTexture& written)
{
    const fieldcvt::OutputTexture& texture = written.made;
    nlohmann::ordered_json json = textureSummaryJson(!input.empty(), dropped, !texture.texture.empty());
    if (texture.texture.empty()) return json;
    json["mode"] = texture.baked ? "bake" : "keep_atlas";
    json["charts"] = texture.charts;
    json["materials"] = texture.texture.materials.size();
    json["continued_faces"] = texture.continuedFaces;
    json["continued_share"] = texture.continuedShare;
    if (texture.baked) {
        json["baked_image"] = written.bakedImage;
        json["cell_texels"] = texture.cellSize;
    }
    json["time_s"] = written.seconds;
    return json;
}

}  // namespace fieldcvt::cli
