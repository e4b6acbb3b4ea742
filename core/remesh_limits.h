#pragma once
// The ranges remesh() accepts and how the front ends name its parameters in messages (core/remesh.h).
#include <string>

namespace fieldcvt {

//! The vertex counts remesh() takes (RemeshParams::vertexCount), one limit for every front end
//! (the CLI's --vertices and --target-length, the MeshLab filter's vertexCount and
//! targetLength); memory grows with the count (docs/tuning.md, "kMaxVertexCount").
constexpr int kMinVertexCount = 4;
constexpr int kMaxVertexCount = 5000000;
//! RemeshParams::threads at most (0 = all cores).
constexpr int kMaxThreads = 4096;
//! "between 4 and 5000000", the one wording of that limit in every message.
std::string vertexCountRange();

//! A target edge length turned into a vertex count, for the front ends' size-by-length option.
struct VertexCountFromLength {
    int vertexCount = kMinVertexCount;
    std::string warning;  //!< non-empty when the length asked for fewer than kMinVertexCount vertices
};
//! An equilateral triangulation with edge `length` has about 2 faces per vertex, each of area
//! sqrt(3) length^2 / 4: 2 area / (sqrt(3) length^2) vertices. Throws InvalidInputError naming
//! `parameter` (as its front end calls it) when the length is not > 0 or gives more than
//! kMaxVertexCount; fewer than kMinVertexCount give that minimum and a warning that says so.
VertexCountFromLength vertexCountForLength(double area, double length, const std::string& parameter);

//! How a front end names the parameters in its messages (checkRemeshParams): the CLI by its
//! options ("--vertices"), the MeshLab filter by label and script name ("'Target vertices'
//! (vertexCount)"). The defaults are the core's own words.
struct ParameterNames {
    std::string vertexCount = "the vertex count";
    std::string lambda = "lambda";
    std::string lloydIterations = "the Lloyd iteration count";
    std::string cvtIterations = "the CVT iteration count";
    std::string fcvtIterations = "the FCVT iteration count";
    std::string threads = "the thread count";
    std::string timeLimit = "the time limit";
    std::string featureAngle = "the feature angle";
    std::string gradation = "the gradation";
};

}  // namespace fieldcvt
