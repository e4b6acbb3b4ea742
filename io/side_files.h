#pragma once
// The files a mesh names (an OBJ's material libraries, their images, a PLY's TextureFile) and the
// files a run writes beside its output (OUT.mtl, OUT_texture.png), handled with the discipline of
// the mesh file itself: only regular files are read, reads are bounded, writes go to a temporary
// name in the same folder and are renamed into place (never through a symbolic link).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace fieldcvt {

//! The bounds on what a side file may hold; a larger file is not read (a warning, never an error).
struct SideFileLimits {
    //! A material library: a real one is a few kB; 16 MiB leaves room for thousands of materials.
    std::uintmax_t materialLibraryBytes = 16u << 20;
    //! An image file as stored (PNG, JPEG, ...): 256 MiB.
    std::uintmax_t imageBytes = 256u << 20;
    //! An image's pixels once decoded: 64 Mpixel (8192 x 8192, 192 MiB as RGB).
    std::uint64_t imagePixels = std::uint64_t(8192) * 8192;
    //! An image's width or height on its own.
    int imageSide = 32768;
};

//! The limits every reader of side files uses (the CLI, the filter, texture-compare).
const SideFileLimits& sideFileLimits();

//! Empty when `path` (links followed) is a regular file of at most `maxBytes`; otherwise why it
//! is not read, as a phrase that follows the file's name: "does not exist", "is a FIFO (named
//! pipe), not a regular file", "is a directory, not a file", "is 200 MB, over the 16 MB limit".
std::string sideFileProblem(const std::string& path, std::uintmax_t maxBytes);

//! Whether `path` (links followed) is there but is no regular file: a FIFO, device, socket or
//! directory, which a reader (MeshLab) would hang on or fail at.
bool isSpecialFile(const std::string& path);

//! The bytes of the regular file `path`, at most `maxBytes` of them. It is opened without
//! blocking and checked once open (a FIFO put in its place after a check cannot hang the read).
//! Throws IOError("<path>: <why>") otherwise.
std::string readSideFile(const std::string& path, std::uintmax_t maxBytes);

//! Empty when `text` reads as a Wavefront material library (only .mtl statements, comments and
//! blank lines, at least one `newmtl`); otherwise why not, in a phrase.
std::string materialLibraryProblem(const std::string& text);

//! Writes `bytes` to `path` as a new file: to a temporary name in the same folder, then renamed
//! over `path`. A symbolic link at `path` is replaced, its target never written; a reader never
//! sees half a file. Throws IOError("<path>: <why>").
void writeFileReplacing(const std::string& path, const std::string& bytes);

//! The same for a writer that takes a file name (vcglib's exporters): `write` writes the
//! temporary file it is given, which is then renamed over `path` (removed if `write` throws).
void writeFileReplacing(const std::string& path, const std::function<void(const std::string& temporary)>& write);

//! Where a run may put the files it writes beside its output, and which it must never touch.
class SideFileNames {
public:
    //! `overwrite`: existing files this run did not create may be replaced.
    explicit SideFileNames(bool overwrite) : overwrite_(overwrite) {}

    //! Marks `path` as an input (the mesh, a file it names): never written over, even with
    //! `overwrite`, nor through a link to it replaced.
    void protect(const std::string& path);

    //! Marks `path` as written (or to be written) by this run: the output mesh, the report.
    void reserve(const std::string& path);

    //! `wanted` when this run may write it, else the first free `stem_2.ext`, `stem_3.ext`, ... in
    //! the same folder, with a warning in `warnings` that says why. The name returned is reserved.
    std::string choose(const std::string& wanted, std::vector<std::string>& warnings);

private:
    bool isProtected(const std::string& path) const;
    bool isReserved(const std::string& path) const;
    std::vector<std::string> protected_;
    std::vector<std::string> reserved_;
    bool overwrite_;
};

}  // namespace fieldcvt
