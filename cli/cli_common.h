#pragma once
// Pieces shared by the fcvt subcommands: option translation to core types, output path checks,
// the user field from a PLY file, timing.
#include "arguments.h"

#include "field.h"
#include "mesh.h"
#include "mesh_io.h"
#include "remesh.h"

#include <chrono>
#include <string>
#include <vector>

namespace fieldcvt::cli {

//! `--field NAME` as a FieldSource (fieldcvt::fieldSourceFromName); `fallback` when absent. An
//! unknown name, or "user" when `allowUser` is false, is a UsageError listing the valid names.
FieldSource fieldOption(const Arguments& a, FieldSource fallback, bool allowUser);

//! What would make the final write of `path` fail or destroy the input, found before the long
//! part rather than after it (IOError, exit 1): a directory, the file `input` itself (also
//! through another path or a link), a missing directory, or a file that cannot be opened for
//! writing (a read-only directory or file, /proc). The check opens the file without truncating
//! it, and removes it again if that created it.
void checkWritable(const std::string& path, const std::string& input);

//! Throws IOError when `path` and `other` name the same file, whether or not it exists yet:
//! through another spelling, `..`, a symbolic link (also a dangling one) or a hard link. Used
//! for two files one command writes (the mesh and its report), where the second would
//! silently replace the first.
void checkDistinctOutputs(const std::string& path, const std::string& other, const std::string& what);

//! checkWritable, and a mesh extension writeMesh handles.
void checkOutputPath(const std::string& path, const std::string& input);

//! The core's parameter check (checkRemeshParams) with the options' names: a UsageError.
void checkOptions(const RemeshParams& params);

//! True when the path ends in .ply (any case).
bool isPlyPath(const std::string& path);
//! True if the path ends in .obj (any case).
bool isObjPath(const std::string& path);

//! The `rosy_x rosy_y rosy_z` vectors read with `path`, checked: present for every vertex and
//! finite (IOError naming the file otherwise, saying that --field user needs them).
const std::vector<Vec3>& userField(const std::string& path, const VertexAttributes& attributes);

double secondsSince(std::chrono::steady_clock::time_point start);

//! --help (or -h) given: prints the command's usage and returns true (the command then returns 0).
bool printedHelp(const Arguments& a, void (*printUsage)());

//! The command's file arguments, which must be exactly `count` (described as `what`, e.g. "an
//! input and an output file"); otherwise a UsageError naming the command's --help.
const std::vector<std::string>& fileArguments(const Arguments& a, size_t count, const std::string& command,
                                              const std::string& what);

//! The file arguments of a command that takes an input and an output file (fileArguments).
struct InputOutput {
    std::string in, out;
};
InputOutput inputAndOutput(const Arguments& a, const std::string& command);

}  // namespace fieldcvt::cli
