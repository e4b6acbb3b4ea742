// libFuzzer target: fieldcvt::remesh on tiny meshes decoded from bytes (≤ 15 vertices, ≤ 24
// faces, ≤ 20 output vertices, ≤ 5 iterations per stage, one thread, no distance metrics). Coordinates come from a
// small grid scaled by 10^-6..10^6 and offset by up to 10^6, with NaN, Inf, huge and tiny
// values reachable; indices may be out of range. remesh must return a mesh with valid indices
// and finite coordinates or throw fieldcvt::Error; any other exception, crash, hang, leak or
// sanitizer report is a finding.
#include "errors.h"
#include "remesh.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

namespace {

struct Bytes {
    const std::uint8_t* data;
    std::size_t size, at = 0;
    std::uint8_t next() { return at < size ? data[at++] : 0; }
    std::int16_t next16()
    {
        const std::uint16_t lo = next(), hi = next();
        return static_cast<std::int16_t>(lo | (hi << 8));
    }
};

double coordinate(Bytes& in, double scale, double offset)
{
    const std::int16_t raw = in.next16();
    switch (raw) {
    case std::numeric_limits<std::int16_t>::min(): return std::numeric_limits<double>::quiet_NaN();
    case std::numeric_limits<std::int16_t>::max(): return std::numeric_limits<double>::infinity();
    case std::numeric_limits<std::int16_t>::min() + 1: return -std::numeric_limits<double>::infinity();
    case std::numeric_limits<std::int16_t>::max() - 1: return 1e300;
    case std::numeric_limits<std::int16_t>::max() - 2: return 1e-300;
    default: return raw / 4096.0 * scale + offset;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size < 8) return 0;
    Bytes in{data, size};
    const int vertices = 3 + in.next() % 13;
    const int faces = 1 + in.next() % 24;
    fieldcvt::RemeshParams params;
    params.vertexCount = 4 + in.next() % 17;
    const std::uint8_t iterations = in.next();
    params.lloydIterations = iterations % 6;
    params.cvtIterations = (iterations / 6) % 6;
    const std::uint8_t field = in.next();
    params.fcvtIterations = field % 6;
    params.lambda = (field / 6) % 2 ? 0.3 : 0.0;
    const std::uint8_t misc = in.next();
    params.boundaryIterations = misc % 6;
    // d_RMS / d_H use ~200k dense samples per side whatever the mesh size (seconds per input
    // under the sanitizers): off, so that the fuzzer explores the remeshing itself.
    params.computeDistances = false;
    params.seed = misc;
    params.threads = 1;
    const std::uint8_t frame = in.next();
    const double scale = std::pow(10.0, frame % 13 - 6);
    const double offset = (frame / 13) % 2 ? std::pow(10.0, (frame / 26) % 7) : 0.0;

    fieldcvt::TriMesh mesh;
    for (int v = 0; v < vertices; ++v) {
        const double x = coordinate(in, scale, offset), y = coordinate(in, scale, offset), z = coordinate(in, scale, offset);
        mesh.vertices.emplace_back(x, y, z);
    }
    for (int f = 0; f < faces && in.at < in.size; ++f) {
        fieldcvt::Face t;
        for (int& c : t) c = in.next() % (vertices + 1);  // `vertices` itself is out of range
        mesh.faces.push_back(t);
    }
    try {
        const fieldcvt::RemeshResult result = fieldcvt::remesh(mesh, params);
        for (const fieldcvt::Face& t : result.mesh.faces)
            for (int c : t)
                if (c < 0 || c >= result.mesh.vertexCount()) __builtin_trap();
        for (const fieldcvt::Vec3& p : result.mesh.vertices)
            if (!p.allFinite()) __builtin_trap();
    } catch (const fieldcvt::Error&) {
        // A clear refusal (invalid input, solver failure): the documented outcome.
    }
    return 0;
}
