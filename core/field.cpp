#include "field.h"

#include "curvature.h"
#include "errors.h"
#include "field_hierarchy.h"
#include "mesh_edges.h"

#include <algorithm>
#include <cmath>

namespace fieldcvt {

namespace {

void checkMesh(const TriMesh& mesh)
{
    if (mesh.vertices.empty() || mesh.faces.empty()) throw InvalidInputError("field: the mesh has no triangles");
    for (int f = 0; f < mesh.faceCount(); ++f)
        for (int v : mesh.faces[f])
            if (v < 0 || v >= mesh.vertexCount())
                throw InvalidInputError("field: face " + std::to_string(f) + " has an out-of-range vertex index");
}

void checkField(const TriMesh& mesh, const DirectionField& field)
{
    if (static_cast<int>(field.normals.size()) != mesh.vertexCount() ||
        static_cast<int>(field.directions.size()) != mesh.vertexCount())
        throw InvalidInputError("field: " + std::to_string(field.directions.size()) + " directions for " +
                                std::to_string(mesh.vertexCount()) + " vertices");
}

// Boundary edges and edges whose dihedral angle exceeds `sharpAngle` fix the direction of their
// vertices to the compatible average of their tangents (Jakob et al. 2015 constrain the field to
// boundaries and creases the same way).
// `constrainingBorderLength` (when given) gets the total length of the border edges that
// constrain the field (0: no border constraint).
FieldConstraints edgeConstraints(const TriMesh& mesh, const std::vector<Vec3>& normals, double sharpAngle, bool alignToBorder,
                                 double* constrainingBorderLength = nullptr)
{
    if (constrainingBorderLength) *constrainingBorderLength = 0;
    const int n = mesh.vertexCount();
    const double cosSharp = sharpAngle > 0 ? std::cos(sharpAngle * kPi / 180.0) : -2.0;
    std::vector<Vec3> faceNormals(mesh.faces.size());
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Vec3 fn = faceNormal(mesh, f);
        const double len = fn.norm();
        faceNormals[f] = len > 0 ? Vec3(fn / len) : Vec3::Zero();
    }
    std::vector<std::pair<int, Vec3>> tangents;  // (vertex, edge tangent), in edge order
    const EdgeTable edges = buildEdgeTable(mesh);
    for (int e = 0; e < edges.edgeCount(); ++e) {
        bool constrained = edges.isBorder(e) && alignToBorder;
        if (edges.faceCount(e) == 2 && sharpAngle > 0) {
            // Dihedral angle = angle between the face normals (0 on a flat edge).
            constrained = faceNormals[edges.face(e, 0)].dot(faceNormals[edges.face(e, 1)]) < cosSharp;
        }
        if (!constrained) continue;
        const auto [a, b] = edges.ends[e];
        const Vec3 t = mesh.vertices[b] - mesh.vertices[a];
        const double len = t.norm();
        if (!(len > 0)) continue;
        if (constrainingBorderLength && edges.isBorder(e)) *constrainingBorderLength += len;
        tangents.emplace_back(a, t / len);
        tangents.emplace_back(b, t / len);
    }
    std::stable_sort(tangents.begin(), tangents.end(), [](const auto& x, const auto& y) { return x.first < y.first; });

    FieldConstraints c;
    c.fixed.assign(n, 0);
    c.directions.assign(n, Vec3::Zero());
    std::vector<Vec3> list;
    for (std::size_t s = 0; s < tangents.size();) {
        const int v = tangents[s].first;
        list.clear();
        for (; s < tangents.size() && tangents[s].first == v; ++s) list.push_back(tangents[s].second);
        if (averageCompatible(normals[v], list.data(), static_cast<int>(list.size()), c.directions[v])) c.fixed[v] = 1;
    }
    return c;
}

DirectionField solveWithConstraints(const TriMesh& mesh, std::vector<Vec3> normals, const FieldConstraints& constraints,
                                    std::uint64_t seed, int iterations, FieldReport* report, bool intrinsic = false,
                                    FieldHierarchyLevels* hierarchy = nullptr)
{
    DirectionField field;
    if (constraints.count() == mesh.vertexCount()) {
        field.directions = constraints.directions;  // nothing left to smooth
        if (report) *report = FieldReport{};
    } else {
        field.directions = solveField(mesh, normals, constraints, seed, std::max(iterations, 0), report, intrinsic, hierarchy);
    }
    if (report) report->constrainedVertices = constraints.count();
    field.normals = std::move(normals);
    return field;
}

}  // namespace

FieldSource fieldSourceFromName(const std::string& name)
{
    if (name == "extrinsic") return FieldSource::Extrinsic;
    if (name == "curvature-max") return FieldSource::CurvatureMax;
    if (name == "curvature-min") return FieldSource::CurvatureMin;
    if (name == "user") return FieldSource::User;
    throw InvalidInputError("unknown field source " + quoteInput(name) +
                            " (expected extrinsic, curvature-max, curvature-min or user)");
}

std::string fieldSourceName(FieldSource source)
{
    switch (source) {
    case FieldSource::Extrinsic: return "extrinsic";
    case FieldSource::CurvatureMax: return "curvature-max";
    case FieldSource::CurvatureMin: return "curvature-min";
    case FieldSource::User: return "user";
    }
    return "extrinsic";
}

std::vector<Vec3> vertexNormals(const TriMesh& mesh)
{
    // Σ of unnormalised face normals = area weighting (their length is twice the area).
    std::vector<Vec3> sum(mesh.vertices.size(), Vec3::Zero());
    std::vector<int> firstFace(mesh.vertices.size(), -1);
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Vec3 fn = faceNormal(mesh, f);
        for (int v : mesh.faces[f]) {
            sum[v] += fn;
            if (firstFace[v] < 0 && fn.squaredNorm() > 0) firstFace[v] = f;
        }
    }
    for (std::size_t v = 0; v < sum.size(); ++v) {
        const double len = sum[v].norm();
        if (len > 1e-300)
            sum[v] /= len;
        else if (firstFace[v] >= 0)  // faces cancel (a fold): any one of them
            sum[v] = faceNormal(mesh, firstFace[v]).normalized();
        else
            sum[v] = Vec3(0, 0, 1);
    }
    return sum;
}

double extrinsicEnergy(const TriMesh& mesh, const DirectionField& field)
{
    checkField(mesh, field);
    double energy = 0;
    for (const auto& [a, b] : buildEdgeTable(mesh).ends)
        energy += rosy::edgeEnergy(field.directions[a], field.normals[a], field.directions[b], field.normals[b]);
    return energy;
}

DirectionField computeField(const TriMesh& mesh, const FieldParams& params) { return computeField(mesh, params, nullptr); }

namespace {

//! FieldSmoothness::Auto's threshold on border length / sqrt(area).
constexpr double kLongBorder = 2.0;

}  // namespace

DirectionField computeField(const TriMesh& mesh, const FieldParams& params, FieldReport* report, FieldHierarchyLevels* hierarchy)
{
    checkMesh(mesh);
    std::vector<Vec3> normals = vertexNormals(mesh);
    switch (params.source) {
    case FieldSource::Extrinsic: {
        double borderLength = 0;
        const FieldConstraints constraints =
            edgeConstraints(mesh, normals, params.sharpAngle, params.alignToBorder, &borderLength);
        // A border constraint and the extrinsic energy disagree wherever the surface bends
        // along the border (a cylinder's rims: the extrinsic optimum inside is axis-aligned, 30°
        // off the rim direction mod 60°, and the field twists in between); the intrinsic energy
        // lets the border's direction propagate (FieldSmoothness).
        // Auto: only where the border is long for the surface (at least twice the root of its
        // area), so that it decides the field. Short borders keep the extrinsic field, which
        // measured better there (docs/tuning.md, "kLongBorder").
        const bool longBorder = borderLength > 0 && borderLength >= kLongBorder * std::sqrt(surfaceArea(mesh));
        const bool intrinsic =
            params.smoothness == FieldSmoothness::Intrinsic || (params.smoothness == FieldSmoothness::Auto && longBorder);
        return solveWithConstraints(mesh, std::move(normals), constraints, params.seed, params.smoothingIterations, report,
                                    intrinsic, hierarchy);
    }
    case FieldSource::CurvatureMax:
    case FieldSource::CurvatureMin: {
        // Reliable principal directions are kept as they are; the umbilic and flat vertices
        // get the smooth extrinsic field that interpolates them (the same solver, with the
        // reliable vertices as constraints).
        const PrincipalCurvature pc = computePrincipalCurvature(mesh, normals);
        FieldConstraints constraints;
        constraints.fixed = pc.reliable;
        constraints.directions = params.source == FieldSource::CurvatureMax ? pc.dirMax : pc.dirMin;
        DirectionField field =
            solveWithConstraints(mesh, std::move(normals), constraints, params.seed, params.smoothingIterations, report);
        if (report) report->umbilicVertices = mesh.vertexCount() - constraints.count();
        return field;
    }
    case FieldSource::User: throw InvalidInputError("field source 'user' needs per-vertex vectors (fieldFromVectors)");
    }
    throw InvalidInputError("unknown field source");
}

DirectionField fieldFromVectors(const TriMesh& mesh, const std::vector<Vec3>& vectors, std::uint64_t seed)
{
    checkMesh(mesh);
    if (static_cast<int>(vectors.size()) != mesh.vertexCount())
        throw InvalidInputError("field: " + std::to_string(vectors.size()) + " user vectors for " +
                                std::to_string(mesh.vertexCount()) + " vertices");
    std::vector<Vec3> normals = vertexNormals(mesh);
    FieldConstraints constraints;
    constraints.fixed.assign(vectors.size(), 0);
    constraints.directions.assign(vectors.size(), Vec3::Zero());
    for (std::size_t v = 0; v < vectors.size(); ++v) {
        if (!vectors[v].allFinite())
            throw InvalidInputError("field: user vector of vertex " + std::to_string(v) + " is not finite");
        const Vec3 t = rosy::projectTangent(vectors[v], normals[v]);
        const double len = t.norm();
        // "Nearly parallel to the normal": less than ~0.06° off it, or zero.
        if (len > 1e-3 * vectors[v].norm() && len > 1e-300) {
            constraints.fixed[v] = 1;
            constraints.directions[v] = t / len;
        }
    }
    FieldParams params;
    return solveWithConstraints(mesh, std::move(normals), constraints, seed, params.smoothingIterations, nullptr);
}

// ---------------------------------------------------------------------------------------------
// Singularities.
//
// A discrete Levi-Civita connection on vertex tangent planes (the vertex-based construction of
// Knöppel, Crane, Pinkall, Schröder 2013, "Globally optimal direction fields", §5): at vertex v
// the incident edges get chart angles = cumulative corner angles, scaled by s_v = 2π/Θ_v
// (Θ_v = Σ corner angles; s_v = 1 at border vertices). Transport along i→j adds
// ρ_ij = θ_ji − θ_ij + π. Around a face f the transports add up to
// K_f = Σ_{corners c of f} (s_c − 1)·α_c modulo 2π, and Σ_f K_f = Σ_v (2π − Θ_v) = 2π·χ on a
// closed surface (discrete Gauss–Bonnet).
//
// With θ_v the chart angle of d_v, the field turns along i→j by δ_ij = θ_j − θ_i − ρ_ij,
// reduced to the nearest representative: δ'_ij ∈ (−π/6, π/6] (the 6-RoSy matching after
// parallel transport). The index of f, in sixths of a turn, is
//     I_f = (Σ_{edges of f} δ'_ij + K_f) · 6 / (2π),
// an integer because the θ's cancel around the face and Σρ ≡ K_f (mod 2π). Each edge's δ' is
// computed once and used with opposite signs by its two faces, so Σ_f I_f = 6·χ exactly on a
// closed surface, whatever the field.
// ---------------------------------------------------------------------------------------------

std::vector<Singularity> findSingularities(const TriMesh& mesh, const DirectionField& field)
{
    checkMesh(mesh);
    checkField(mesh, field);
    const int nv = mesh.vertexCount(), nf = mesh.faceCount();
    const std::vector<Vec3>& p = mesh.vertices;

    // Corners (3f + k) grouped by vertex.
    std::vector<int> cornerOffsets(nv + 1, 0), corners(3 * nf);
    for (const Face& f : mesh.faces)
        for (int v : f) ++cornerOffsets[v + 1];
    for (int v = 0; v < nv; ++v) cornerOffsets[v + 1] += cornerOffsets[v];
    {
        std::vector<int> fill(cornerOffsets.begin(), cornerOffsets.end() - 1);
        for (int c = 0; c < 3 * nf; ++c) corners[fill[mesh.faces[c / 3][c % 3]]++] = c;
    }
    auto nextOf = [&](int c) { return mesh.faces[c / 3][(c % 3 + 1) % 3]; };
    auto prevOf = [&](int c) { return mesh.faces[c / 3][(c % 3 + 2) % 3]; };

    std::vector<double> alpha(3 * nf);  // corner angles
    for (int c = 0; c < 3 * nf; ++c) {
        const Vec3& o = p[mesh.faces[c / 3][c % 3]];
        const Vec3 e1 = p[nextOf(c)] - o, e2 = p[prevOf(c)] - o;
        alpha[c] = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
    }

    std::vector<double> thetaNext(3 * nf), thetaPrev(3 * nf), scale(nv, 1.0), thetaField(nv, 0.0);
    std::vector<int> fan;
    std::vector<unsigned char> used;
    for (int v = 0; v < nv; ++v) {
        const int begin = cornerOffsets[v], end = cornerOffsets[v + 1];
        if (begin == end) continue;
        // Order the corners counter-clockwise: the successor of c is the corner whose `next`
        // is c's `prev`. A border fan starts where no corner precedes it.
        fan.clear();
        used.assign(end - begin, 0);
        bool closed = true;
        while (static_cast<int>(fan.size()) < end - begin) {
            int start = -1;
            for (int s = begin; s < end && start < 0; ++s) {
                if (used[s - begin]) continue;
                bool hasPredecessor = false;
                for (int r = begin; r < end; ++r)
                    if (r != s && prevOf(corners[r]) == nextOf(corners[s])) hasPredecessor = true;
                if (!hasPredecessor) start = s;
            }
            if (start < 0)
                for (int s = begin; s < end && start < 0; ++s)
                    if (!used[s - begin]) start = s;
            const std::size_t fanStart = fan.size();
            for (int s = start; s >= 0;) {
                used[s - begin] = 1;
                fan.push_back(corners[s]);
                const int target = prevOf(corners[s]);
                int next = -1;
                for (int r = begin; r < end && next < 0; ++r)
                    if (!used[r - begin] && nextOf(corners[r]) == target) next = r;
                s = next;
            }
            // Closed iff this single fan holds every corner and wraps around to its start.
            if (fanStart != 0 || static_cast<int>(fan.size()) != end - begin || prevOf(fan.back()) != nextOf(fan.front()))
                closed = false;
        }
        double total = 0;
        for (int c : fan) total += alpha[c];
        const double s = closed && total > 0 ? 2 * kPi / total : 1.0;
        scale[v] = s;
        double cumulative = 0;
        for (int c : fan) {
            thetaNext[c] = s * cumulative;
            thetaPrev[c] = s * (cumulative + alpha[c]);
            cumulative += alpha[c];
        }
        // Chart angle of d_v: the corner whose wedge contains d_v (measured in the face plane),
        // or the nearest one where projections disagree.
        double bestOutside = 1e300, bestTheta = 0;
        for (int c : fan) {
            const int f = c / 3;
            const Vec3 fn = faceNormal(mesh, f);
            const double len = fn.norm();
            if (!(len > 0)) continue;
            const Vec3 n = fn / len;
            const Vec3 e = p[nextOf(c)] - p[v];
            const Vec3 d = rosy::projectTangent(field.directions[v], n);
            const double beta = std::atan2(e.cross(d).dot(n), e.dot(d));
            const double outside = std::max({-beta, beta - alpha[c], 0.0});
            if (outside < bestOutside) {
                bestOutside = outside;
                bestTheta = thetaNext[c] + s * std::clamp(beta, 0.0, alpha[c]);
            }
        }
        thetaField[v] = bestTheta;
    }

    // δ' once per edge, oriented a → b (a < b).
    const EdgeTable edges = buildEdgeTable(mesh);
    std::vector<double> turn(edges.edgeCount(), 0.0);
    std::vector<unsigned char> done(edges.edgeCount(), 0);
    const double sixth = kPi / 3;
    for (int f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k) {
            const int e = edges.edgeOf(f, k);
            if (done[e]) continue;
            done[e] = 1;
            const int i = mesh.faces[f][k], j = mesh.faces[f][(k + 1) % 3];
            const double rho = thetaPrev[3 * f + (k + 1) % 3] - thetaNext[3 * f + k] + kPi;  // θ_ji − θ_ij + π
            double delta = thetaField[j] - thetaField[i] - rho;
            delta -= sixth * std::round(delta / sixth);
            if (delta <= -sixth / 2) delta += sixth;  // half-open (−π/6, π/6]
            turn[e] = i == edges.ends[e][0] ? delta : -delta;
        }

    std::vector<Singularity> result;
    for (int f = 0; f < nf; ++f) {
        double sum = 0;
        for (int k = 0; k < 3; ++k) {
            const int i = mesh.faces[f][k], e = edges.edgeOf(f, k);
            sum += i == edges.ends[e][0] ? turn[e] : -turn[e];
            sum += (scale[i] - 1) * alpha[3 * f + k];
        }
        const int index = static_cast<int>(std::lround(sum / sixth));
        if (index != 0) {
            Singularity s;
            s.face = f;
            s.index = index;
            s.position = (p[mesh.faces[f][0]] + p[mesh.faces[f][1]] + p[mesh.faces[f][2]]) / 3;
            result.push_back(s);
        }
    }
    return result;
}

}  // namespace fieldcvt
