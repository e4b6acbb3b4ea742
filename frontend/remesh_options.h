#pragma once
// The options of `fcvt remesh` and `fcvt field` as the core's parameters, shared by the CLI and
// the Python module (python/): one set of names, defaults and checks for both front ends. The
// syntax is checked by Arguments, the ranges by the core's one check (checkRemeshParams) in the
// options' names; every failure is a UsageError with the one line the CLI prints.
#include "arguments.h"

#include "field.h"
#include "remesh.h"
#include "texture_output.h"

#include <set>
#include <string>
#include <vector>

namespace fieldcvt::frontend {

//! The option names a command accepts (without "--"): those with a value and the flags.
struct OptionNames {
    std::set<std::string> valued;
    std::set<std::string> flags;
};

//! `fcvt remesh`'s options ("help" among the flags).
const OptionNames& remeshOptionNames();
//! `fcvt field`'s options ("help" among the flags).
const OptionNames& fieldOptionNames();

//! `--field NAME` as a FieldSource (fieldcvt::fieldSourceFromName); `fallback` when absent. An
//! unknown name, or "user" when `allowUser` is false, is a UsageError listing the valid names.
FieldSource fieldOption(const Arguments& a, FieldSource fallback, bool allowUser);

//! The core's parameter check (checkRemeshParams) with the options' names: a UsageError.
void checkOptions(const RemeshParams& params);

//! "auto", "keep" or "bake" (a UsageError otherwise).
TextureMethod textureMethodFromText(const std::string& text);

//! One remesh run's settings from `fcvt remesh`'s options, before the input is read.
struct RemeshOptions {
    RemeshParams params;
    double targetLength = 0;  //!< --target-length (> 0), or 0 with --vertices
    bool quiet = false;
    bool report = false;  //!< --report given
};

//! The options as the core's parameters: exactly one of --vertices and --target-length, every
//! value checked (UsageError). Distances are computed unless quiet without a report (nothing
//! would show them), singularities only for a report (only it lists them).
RemeshOptions remeshOptions(const Arguments& a);

//! With --target-length: the vertex count for `area` (the input's, or its region's) set in
//! `options.params`; returns the warning when the length asks for too few vertices (else empty).
//! A length that does not fit the input is a UsageError, as the other options' errors.
std::string applyTargetLength(RemeshOptions& options, double area);

//! The area --target-length applies to: `input`'s, or with a region (`selected` not empty, one
//! flag per face) the selected faces'.
double sizedArea(const TriMesh& input, const std::vector<char>& selected);

//! `fcvt field`'s --field and --seed as the field's parameters (UsageError when invalid).
FieldParams fieldParams(const Arguments& a);

}  // namespace fieldcvt::frontend
