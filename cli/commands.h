#pragma once
// The subcommands of `fcvt`; each takes the arguments after its name and returns the exit code.
// They throw UsageError (exit 2) and fieldcvt::Error / std::exception (exit 1); main reports.
#include <string>
#include <vector>

namespace fieldcvt::cli {

int runRemesh(const std::vector<std::string>& args);
int runMetrics(const std::vector<std::string>& args);
int runField(const std::vector<std::string>& args);
int runCompare(const std::vector<std::string>& args);
int runConvert(const std::vector<std::string>& args);
int runTextureCompare(const std::vector<std::string>& args);

}  // namespace fieldcvt::cli
