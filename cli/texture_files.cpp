// .mtl files read, copied and written; image paths rebased from the input's folder to the output's.
#include "texture_files.h"

#include "cli_common.h"
#include "errors.h"

#include <filesystem>
#include <fstream>
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
    return keyword.rfind("map_", 0) == 0 || keyword == "bump" || keyword == "disp" || keyword == "decal" || keyword == "refl";
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

bool readText(const fs::path& path, std::string& text)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
    return !in.bad();
}

void writeText(const fs::path& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) throw IOError(path.string() + ": cannot write the material library");
}

}  // namespace

void lookUpMaterialImages(MeshTexture& texture, const std::string& inPath, std::vector<std::string>& warnings)
{
    const fs::path folder = folderOf(inPath);
    for (const std::string& library : texture.libraries) {
        std::string text;
        if (!readText(folder / library, text)) {
            warnings.push_back(inPath + ": material library " + library + " cannot be read: texture images unknown");
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
    }
    for (const TextureMaterial& m : texture.materials)
        if (!m.image.empty() && !fs::exists(folder / m.image))
            warnings.push_back(inPath + ": texture image " + m.image + " not found (the texture coordinates are kept)");
}

std::string rebaseImage(const std::string& image, const std::string& inPath, const std::string& outPath)
{
    return rebase(image, folderOf(inPath), folderOf(outPath));
}

void placeTextureFiles(MeshTexture& texture, const std::string& inPath, const std::string& outPath)
{
    const fs::path from = folderOf(inPath), to = folderOf(outPath);
    const bool objOutput = isObjPath(outPath);
    if (objOutput && texture.libraries.empty()) {
        bool images = false;
        for (const TextureMaterial& m : texture.materials) images |= !m.image.empty();
        if (!images) return;
        // Images without a material library (PLY's TextureFile): one written for the output.
        const fs::path mtl = fs::path(outPath).replace_extension(".mtl");
        std::string text = "# written by fcvt\n";
        for (std::size_t i = 0; i < texture.materials.size(); ++i) {
            TextureMaterial& m = texture.materials[i];
            m.name = "material_" + std::to_string(i);
            text += "newmtl " + m.name + "\nKd 1 1 1\n" + (m.image.empty() ? "" : "map_Kd " + rebase(m.image, from, to) + "\n");
        }
        writeText(mtl, text);
        texture.libraries = {mtl.filename().string()};
        return;
    }
    if (objOutput && !sameFolder(from, to)) {
        for (std::string& library : texture.libraries) {
            std::string text;
            const fs::path target = to / fs::path(library).filename();
            if (!readText(from / library, text)) continue;  // already a warning; the name stays
            std::istringstream lines(text);
            std::string line, copy;
            while (std::getline(lines, line)) {
                const std::string keyword = firstWord(line);
                const std::string file = lastWord(line);
                if (namesFile(keyword) && !file.empty())
                    line =
                        line.substr(0, line.rfind(file)) + rebase(file, from, to) + line.substr(line.rfind(file) + file.size());
                copy += line + "\n";
            }
            writeText(target, copy);
            library = target.filename().string();
        }
    }
    for (TextureMaterial& m : texture.materials) m.image = rebase(m.image, from, to);
}

}  // namespace fieldcvt::cli
