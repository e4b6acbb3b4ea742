#pragma once
// Pieces shared by the fcvt subcommands: output path checks, the user field from a PLY file,
// timing; and the names of the front-end library (frontend/: options, reports) the CLI shares
// with the Python module.
#include "arguments.h"
#include "remesh_options.h"
#include "remesh_report.h"
#include "report.h"

#include "field.h"
#include "mesh.h"
#include "mesh_io.h"
#include "remesh.h"

#include <chrono>
#include <string>
#include <vector>

namespace fieldcvt::cli {

using frontend::Arguments;
using frontend::UsageError;

using frontend::applyTargetLength;
using frontend::checkOptions;
using frontend::fieldOption;
using frontend::fieldOptionNames;
using frontend::fieldParams;
using frontend::remeshOptionNames;
using frontend::remeshOptions;
using frontend::sizedArea;
using frontend::textureMethodFromText;

using frontend::energyHistoryJson;
using frontend::fieldJson;
using frontend::metricsJson;
using frontend::regionJson;
using frontend::remeshReport;
using frontend::repairJson;
using frontend::textureSummaryJson;
using frontend::topologyJson;
using frontend::valenceJson;
using frontend::writeJsonFile;

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
