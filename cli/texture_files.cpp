// .mtl files read and written; image paths rebased from the input's folder to the output's.
#include "texture_files.h"

#include "cli_common.h"
#include "errors.h"

#include <filesystem>
#include <sstream>

namespace fieldcvt::cli {

namespace {

namespace fs = std::filesystem;

fs::path folderOf(const std::string& path)
{
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

bool sameFolder(const fs::path& a, const fs::path& b)
{
    std::error_code ec;
    return fs::equivalent(a, b, ec) && !ec;
}

//! `file` (relative to `from`, or absolute) as seen from `to`.
std::string rebase(const std::string& file, const fs::path& from, const fs::path& to)
{
    if (file.empty() || fs::path(file).is_absolute() || sameFolder(from, to)) return file;
    std::error_code ec;
    const fs::path target = fs::weakly_canonical(fs::absolute(from / file, ec), ec);
    const fs::path base = fs::weakly_canonical(fs::absolute(to, ec), ec);
    const fs::path relative = target.lexically_relative(base);
    return (relative.empty() ? target : relative).generic_string();
}

//! The .mtl statements that name a file (as their last word).
bool namesFile(const std::string& keyword)
{
    return keyword.rfind("map_", 0) == 0 || keyword == "bump" || keyword == "disp" || keyword == "decal" || keyword == "refl" ||
           keyword == "norm";
}

//! A material file line's keyword (newmtl, map_Kd, ...).
std::string firstWord(const std::string& line)
{
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    return keyword;
}

std::string lastWord(const std::string& line)
{
    const std::size_t end = line.find_last_not_of(" \t\r");
    if (end == std::string::npos) return {};
    const std::size_t start = line.find_last_of(" \t", end);
    return line.substr(start == std::string::npos ? 0 : start + 1, end - (start == std::string::npos ? 0 : start + 1) + 1);
}

//! `text` (a library read from `from`) with the files it names as seen from `to`; a statement
//! naming a special file is dropped.
std::string rebasedLibrary(const std::string& text, const fs::path& from, const fs::path& to)
{
    std::istringstream lines(text);
    std::string line, copy;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::string keyword = firstWord(line);
        const std::string file = lastWord(line);
        if (namesFile(keyword) && !file.empty()) {
            if (isSpecialFile((from / file).string())) continue;
            const std::size_t at = line.rfind(file);
            line = line.substr(0, at) + rebase(file, from, to) + line.substr(at + file.size());
        }
        copy += line + "\n";
    }
    return copy;
}

}  // namespace

std::vector<MaterialLibrary> lookUpMaterialImages(MeshTexture& texture, const std::string& inPath,
                                                  std::vector<std::string>& warnings)
{
    const fs::path folder = folderOf(inPath);
    std::vector<MaterialLibrary> read;
    for (const std::string& library : texture.libraries) {
        const std::string path = (folder / library).string();
        std::string text;
        try {
            text = readSideFile(path, sideFileLimits().materialLibraryBytes);
        } catch (const IOError& e) {
            warnings.push_back("material library " + std::string(e.what()) + ": cannot be read, texture images unknown");
            continue;
        }
        if (const std::string problem = materialLibraryProblem(text); !problem.empty()) {
            warnings.push_back("material library " + path + " " + problem + ": not used, texture images unknown");
            continue;
        }
        std::istringstream lines(text);
        std::string line, material;
        while (std::getline(lines, line)) {
            const std::string keyword = firstWord(line);
            if (keyword == "newmtl") material = lastWord(line);
            if (keyword != "map_Kd") continue;
            for (TextureMaterial& m : texture.materials)
                if (m.name == material && m.image.empty()) m.image = lastWord(line);
        }
        read.push_back({library, text});
    }
    for (TextureMaterial& m : texture.materials) {
        if (m.image.empty()) continue;
        const std::string path = (folder / m.image).string();
        const std::string problem = sideFileProblem(path, sideFileLimits().imageBytes);
        if (problem == "does not exist") {
            warnings.push_back(inPath + ": texture image " + m.image + " not found (the texture coordinates are kept)");
        } else if (isSpecialFile(path)) {
            warnings.push_back(inPath + ": texture image " + path + " " + problem +
                               ": not read nor named by the output (the texture coordinates are kept)");
            m.image.clear();
        }
    }
    return read;
}

void protectInputFiles(const MeshTexture& texture, const std::vector<MaterialLibrary>& libraries, const std::string& inPath,
                       SideFileNames& names)
{
    const fs::path folder = folderOf(inPath);
    names.protect(inPath);
    for (const std::string& library : texture.libraries) names.protect((folder / library).string());
    for (const TextureMaterial& m : texture.materials)
        if (!m.image.empty()) names.protect((folder / m.image).string());
    for (const MaterialLibrary& library : libraries) {
        std::istringstream lines(library.text);
        std::string line;
        while (std::getline(lines, line))
            if (namesFile(firstWord(line)) && !lastWord(line).empty()) names.protect((folder / lastWord(line)).string());
    }
}

std::string rebaseImage(const std::string& image, const std::string& inPath, const std::string& outPath)
{
    return rebase(image, folderOf(inPath), folderOf(outPath));
}

void placeTextureFiles(MeshTexture& texture, const std::vector<MaterialLibrary>& libraries, const std::string& inPath,
                       const std::string& outPath, SideFileNames& names, std::vector<std::string>& warnings)
{
    const fs::path from = folderOf(inPath), to = folderOf(outPath);
    texture.libraries.clear();
    std::string text;
    if (isObjPath(outPath)) {
        if (!libraries.empty()) {
            for (const MaterialLibrary& library : libraries)
                text += "# from " + library.name + "\n" + rebasedLibrary(library.text, from, to);
        } else {
            // Images without a material library (PLY's TextureFile, a baked image): one material each.
            bool images = false;
            for (const TextureMaterial& m : texture.materials) images |= !m.image.empty();
            for (std::size_t i = 0; images && i < texture.materials.size(); ++i) {
                TextureMaterial& m = texture.materials[i];
                m.name = "material_" + std::to_string(i);
                text +=
                    "newmtl " + m.name + "\nKd 1 1 1\n" + (m.image.empty() ? "" : "map_Kd " + rebase(m.image, from, to) + "\n");
            }
        }
    }
    for (TextureMaterial& m : texture.materials) m.image = rebase(m.image, from, to);
    if (text.empty()) return;
    // The output's own library, never the input's: other meshes may share that one.
    const std::string mtl = names.choose(fs::path(outPath).replace_extension(".mtl").string(), warnings);
    writeFileReplacing(mtl, "# written by fcvt\n" + text);
    texture.libraries = {fs::path(mtl).filename().string()};
}

}  // namespace fieldcvt::cli
