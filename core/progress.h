#pragma once
#include <functional>
#include <string>

namespace fieldcvt {

//! Progress report: stage and overall percent in [0, 100]. The stage is a name ("prepare",
//! "field", "sampling", "lloyd", "cvt", "features", "fcvt", "rdt", "valence", "metrics", "done"),
//! followed in the iterative stages by the step and the budget ("cvt 12/65"): the first word
//! names the stage. Returning false cancels the computation (the core then throws
//! CancelledError). An empty function reports nothing.
using Progress = std::function<bool(const std::string& stage, double percent)>;

//! The stage's name in a Progress stage string: its first word ("cvt" for "cvt 12/65").
inline std::string stageName(const std::string& stage) { return stage.substr(0, stage.find(' ')); }

}  // namespace fieldcvt
