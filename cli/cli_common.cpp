#include "cli_common.h"

#include "errors.h"
#include "mesh_format.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace fieldcvt::cli {

namespace {

//! Where writing `path` would put the bytes: symbolic links followed (dangling ones too, which
//! the write would create), then made absolute and normal.
std::filesystem::path writeTarget(std::filesystem::path path)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(path, ec)); ++hops) {
        const fs::path target = fs::read_symlink(path, ec);
        if (ec) break;
        path = target.is_absolute() ? target : path.parent_path() / target;
    }
    const fs::path resolved = fs::weakly_canonical(path, ec);
    return ec ? fs::absolute(path, ec).lexically_normal() : resolved;
}

//! Whether `a` and `b` are one file, existing or not yet: the same inode, or the same place once
//! links are followed and the path is made normal.
bool sameFile(const std::string& a, const std::string& b)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec)) return true;
    return writeTarget(a) == writeTarget(b);
}

}  // namespace

void checkWritable(const std::string& path, const std::string& input)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw IOError(path + ": is a directory, not a file to write");
    const bool existed = fs::exists(path, ec);
    if (sameFile(path, input))
        throw IOError(path + ": is the input file " + input + "; choose another output (it would be overwritten)");
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::is_directory(parent, ec))
        throw IOError(path + ": cannot write: directory " + parent.string() + " does not exist");
    std::FILE* probe = std::fopen(path.c_str(), "ab");  // append: an existing file keeps its bytes
    if (probe == nullptr) throw IOError(path + ": cannot write: " + std::strerror(errno));
    std::fclose(probe);
    if (!existed) fs::remove(path, ec);
}

void checkDistinctOutputs(const std::string& path, const std::string& other, const std::string& what)
{
    if (sameFile(path, other))
        throw IOError(path + ": is also the " + what + " " + other + "; choose another file (one would overwrite the other)");
}

void checkOutputPath(const std::string& path, const std::string& input)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_directory(path, ec)) checkMeshExtension(path);  // a directory: "is a directory", not "unknown extension ''"
    checkWritable(path, input);
}

bool isPlyPath(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".ply";
}

bool isObjPath(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".obj";
}

const std::vector<Vec3>& userField(const std::string& path, const VertexAttributes& attributes)
{
    if (attributes.rosy.empty())
        throw IOError(path + ": no rosy_x rosy_y rosy_z vertex properties (--field user takes the field from them)");
    for (std::size_t v = 0; v < attributes.rosy.size(); ++v)
        if (!attributes.rosy[v].allFinite())
            throw IOError(path + ": vertex " + std::to_string(v) + " has a non-finite rosy_x rosy_y rosy_z vector");
    return attributes.rosy;
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

const std::vector<std::string>& fileArguments(const Arguments& a, size_t count, const std::string& command,
                                              const std::string& what)
{
    if (a.positional().size() != count)
        throw UsageError(command + " needs " + what + ", got " + std::to_string(a.positional().size()) +
                         " file arguments (try 'fcvt " + command + " --help')");
    return a.positional();
}

InputOutput inputAndOutput(const Arguments& a, const std::string& command)
{
    const std::vector<std::string>& files = fileArguments(a, 2, command, "an input and an output file");
    return {files[0], files[1]};
}

bool printedHelp(const Arguments& a, void (*printUsage)())
{
    if (!a.flag("help")) return false;
    printUsage();
    return true;
}

}  // namespace fieldcvt::cli
