// Side files: the checks before a read, the bounded read itself, the material library's syntax,
// the write by rename and the choice of names that never land on the input's files.
#include "side_files.h"

#include "errors.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <set>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fieldcvt {

namespace fs = std::filesystem;

namespace {

std::string megabytes(std::uintmax_t bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, bytes >= (1u << 20) ? "%.0f MB" : "%.1f MB", double(bytes) / (1u << 20));
    return text;
}

std::string notRegular(mode_t mode)
{
    if (S_ISDIR(mode)) return "is a directory, not a file";
    if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
    if (S_ISSOCK(mode)) return "is a socket, not a regular file";
    if (S_ISCHR(mode)) return "is a character device, not a regular file";
    if (S_ISBLK(mode)) return "is a block device, not a regular file";
    return "is not a regular file";
}

std::string sizeProblem(std::uintmax_t size, std::uintmax_t maxBytes)
{
    return size > maxBytes ? "is " + megabytes(size) + ", over the " + megabytes(maxBytes) + " limit of such a file" : "";
}

//! The directory entry `path` names: its folder made canonical, its own name kept (a link at the
//! end stays the link: a rename replaces the entry, not what it points to).
fs::path entryOf(const std::string& path)
{
    std::error_code ec;
    const fs::path p = fs::absolute(fs::path(path), ec).lexically_normal();
    fs::path folder = fs::weakly_canonical(p.parent_path(), ec);
    if (ec) folder = p.parent_path();
    return folder / p.filename();
}

//! `path` with every link followed (dangling ones too).
fs::path targetOf(const std::string& path)
{
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(fs::absolute(fs::path(path), ec), ec);
    return ec ? entryOf(path) : resolved;
}

bool entryExists(const fs::path& path)
{
    std::error_code ec;
    return fs::exists(fs::symlink_status(path, ec));
}

const std::set<std::string>& materialKeywords()
{
    static const std::set<std::string> keywords = {"newmtl", "Ka",   "Kd", "Ks",    "Ke",        "Kt",   "Tf",     "Ns",
                                                   "Ni",     "d",    "Tr", "illum", "sharpness", "bump", "disp",   "decal",
                                                   "refl",   "norm", "Pr", "Pm",    "Ps",        "Pc",   "Pcr",    "aniso",
                                                   "anisor", "Km",   "Nf", "Ts",    "Tw",        "Ao",   "opacity"};
    return keywords;
}

}  // namespace

const SideFileLimits& sideFileLimits()
{
    static const SideFileLimits limits;
    return limits;
}

std::string sideFileProblem(const std::string& path, std::uintmax_t maxBytes)
{
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0)
        return errno == ENOENT ? "does not exist" : std::string("cannot be read: ") + std::strerror(errno);
    if (!S_ISREG(status.st_mode)) return notRegular(status.st_mode);
    return sizeProblem(std::uintmax_t(status.st_size), maxBytes);
}

bool isSpecialFile(const std::string& path)
{
    struct stat status {};
    return ::stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode);
}

std::string readSideFile(const std::string& path, std::uintmax_t maxBytes)
{
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer, forever.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) throw IOError(path + ": " + (errno == ENOENT ? std::string("does not exist") : std::strerror(errno)));
    struct stat status {};
    std::string problem;
    if (::fstat(fd, &status) != 0)
        problem = std::strerror(errno);
    else if (!S_ISREG(status.st_mode))
        problem = notRegular(status.st_mode);
    else
        problem = sizeProblem(std::uintmax_t(status.st_size), maxBytes);
    if (!problem.empty()) {
        ::close(fd);
        throw IOError(path + ": " + problem);
    }
    // A file that grows while it is read is read only to the limit, plus one byte to notice it.
    std::string bytes(std::size_t(status.st_size), '\0');
    std::size_t done = 0;
    char extra = 0;
    while (true) {
        const bool full = done == bytes.size();
        const ssize_t n = full ? ::read(fd, &extra, 1) : ::read(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const std::string why = std::strerror(errno);
            ::close(fd);
            throw IOError(path + ": read error: " + why);
        }
        if (n == 0) break;
        if (full) {
            if (bytes.size() >= maxBytes) {
                ::close(fd);
                throw IOError(path + ": grew over the " + megabytes(maxBytes) + " limit of such a file while read");
            }
            bytes.push_back(extra);
        }
        done += std::size_t(n);
    }
    ::close(fd);
    bytes.resize(done);
    return bytes;
}

std::string materialLibraryProblem(const std::string& text)
{
    if (text.find('\0') != std::string::npos) return "holds binary data, not a material library";
    std::istringstream lines(text);
    std::string line;
    int statements = 0, unknown = 0, materials = 0;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string keyword;
        if (!(words >> keyword) || keyword[0] == '#') continue;
        ++statements;
        if (keyword == "newmtl") ++materials;
        if (keyword.rfind("map_", 0) != 0 && !materialKeywords().count(keyword)) ++unknown;
    }
    if (materials == 0) return "defines no material (no newmtl statement): not a material library";
    // A library may carry a few statements of some exporter's own; prose or another format does not.
    if (4 * unknown > statements)
        return std::to_string(unknown) + " of its " + std::to_string(statements) +
               " statements are not material statements: not a material library";
    return {};
}

void writeFileReplacing(const std::string& path, const std::function<void(const std::string& temporary)>& write)
{
    const fs::path target(path);
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::string temporary = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
    const int fd = ::mkstemp(temporary.data());
    if (fd < 0) throw IOError(path + ": cannot write: " + std::strerror(errno));
    // mkstemp's 0600 would make the file private; a new file gets the usual 0666 less the umask.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    ::close(fd);
    try {
        write(temporary);
    } catch (...) {
        ::unlink(temporary.c_str());
        throw;
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        ::unlink(temporary.c_str());
        throw IOError(path + ": cannot write: " + why);
    }
}

void writeFileReplacing(const std::string& path, const std::string& bytes)
{
    writeFileReplacing(path, [&](const std::string& temporary) {
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC | O_NOFOLLOW);
        if (fd < 0) throw IOError(path + ": cannot write: " + std::strerror(errno));
        std::size_t done = 0;
        std::string problem;
        while (done < bytes.size()) {
            const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                problem = std::string("write error: ") + std::strerror(n < 0 ? errno : ENOSPC);
                break;
            }
            done += std::size_t(n);
        }
        if (::close(fd) != 0 && problem.empty()) problem = std::string("write error: ") + std::strerror(errno);
        if (!problem.empty()) throw IOError(path + ": " + problem);
    });
}

void SideFileNames::protect(const std::string& path)
{
    protected_.push_back(entryOf(path).string());
    protected_.push_back(targetOf(path).string());
}

void SideFileNames::reserve(const std::string& path) { reserved_.push_back(entryOf(path).string()); }

bool SideFileNames::isProtected(const std::string& path) const
{
    const std::string entry = entryOf(path).string(), target = targetOf(path).string();
    // The target too: a link to an input file is how others may reach it.
    for (const std::string& p : protected_)
        if (p == entry || p == target) return true;
    return false;
}

bool SideFileNames::isReserved(const std::string& path) const
{
    const std::string entry = entryOf(path).string();
    for (const std::string& r : reserved_)
        if (r == entry) return true;
    return false;
}

std::string SideFileNames::choose(const std::string& wanted, std::vector<std::string>& warnings)
{
    const fs::path w(wanted);
    std::string reason;
    for (int i = 1; i < 10000; ++i) {
        const std::string candidate =
            i == 1 ? wanted : (w.parent_path() / (w.stem().string() + "_" + std::to_string(i) + w.extension().string())).string();
        std::error_code ec;
        const fs::file_status status = fs::symlink_status(candidate, ec);
        std::string why;
        if (isProtected(candidate))
            why = "is one of the input's own files";
        else if (isReserved(candidate))
            why = "is another file this run writes";
        else if (entryExists(candidate) && (!overwrite_ || fs::is_directory(status)))
            why = fs::is_directory(status) ? "is a directory"
                                           : "exists and was not written by this run (--overwrite replaces such files)";
        if (why.empty()) {
            if (i > 1) warnings.push_back(wanted + " " + reason + ": written as " + candidate + " instead");
            reserved_.push_back(entryOf(candidate).string());
            return candidate;
        }
        if (i == 1) reason = why;
    }
    throw IOError(wanted + ": " + reason + ", and no free name was found beside it");
}

}  // namespace fieldcvt
