#pragma once
// Early check of an output path, so a long run does not end on "unknown extension".
#include <string>

namespace fieldcvt {

//! Throws IOError unless the path ends in a mesh extension readMesh/writeMesh handle.
void checkMeshExtension(const std::string& path);

}  // namespace fieldcvt
