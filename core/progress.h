#pragma once
#include <functional>
#include <string>

namespace fieldcvt {

//! Progress report: stage name and overall percent in [0, 100]. Returning false cancels the
//! computation (the core then throws CancelledError). An empty function reports nothing.
using Progress = std::function<bool(const std::string& stage, double percent)>;

}  // namespace fieldcvt
