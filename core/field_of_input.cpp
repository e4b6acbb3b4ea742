#include "field_of_input.h"

#include "errors.h"
#include "working_frame.h"

namespace fieldcvt {

InputField fieldOfInput(const TriMesh& input, const FieldParams& params, const std::vector<Vec3>* userVectors)
{
    InputField out;
    out.clean = prepareInput(input, out.report);
    const Normalisation frame = workingFrame(out.clean, out.clean.vertexCount());
    const TriMesh work = inFrame(out.clean, frame);
    if (userVectors != nullptr) {
        if (userVectors->size() != input.vertices.size())
            throw InvalidInputError("the user field has " + std::to_string(userVectors->size()) + " vectors for " +
                                    std::to_string(input.vertices.size()) + " vertices");
        std::vector<Vec3> clean(out.clean.vertices.size(), Vec3::Zero());
        for (std::size_t v = 0; v < userVectors->size(); ++v)
            if (out.report.cleanIndex[v] >= 0) clean[out.report.cleanIndex[v]] = (*userVectors)[v];
        out.field = fieldFromVectors(work, clean, params.seed);
    } else {
        out.field = computeField(work, params);
    }
    out.singularities = findSingularities(work, out.field);
    for (Singularity& s : out.singularities) s.position = frame.fromWork(s.position);
    return out;
}

}  // namespace fieldcvt
