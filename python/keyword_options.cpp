#include "keyword_options.h"

#include "errors.h"

#include <algorithm>

namespace fieldcvt::python {

namespace {

//! The option a keyword names: `feature_angle` -> `feature-angle`, `lambda_` -> `lambda`.
std::string optionName(std::string keyword)
{
    if (!keyword.empty() && keyword.back() == '_') keyword.pop_back();
    std::replace(keyword.begin(), keyword.end(), '_', '-');
    return keyword;
}

}  // namespace

frontend::Arguments argumentsFromKeywords(const py::kwargs& keywords, const frontend::OptionNames& names)
{
    std::vector<std::string> args;
    for (const auto& [key, value] : keywords) {
        const std::string keyword = py::str(key).cast<std::string>();
        const std::string name = optionName(keyword);
        const bool flag = names.flags.count(name) > 0 && name != "help";
        if (!flag && names.valued.count(name) == 0) throw frontend::UsageError("unknown option " + quoteInput("--" + name));
        if (flag) {
            if (!py::isinstance<py::bool_>(value) && !py::isinstance(value, py::module_::import("numpy").attr("bool_")))
                throw frontend::UsageError("option '--" + name + "' is a flag: " + keyword + "= takes True or False, got " +
                                           quoteInput(py::str(value).cast<std::string>()));
            if (value.cast<bool>()) args.push_back("--" + name);
        } else if (!value.is_none()) {
            args.push_back("--" + name);
            args.push_back(py::str(value).cast<std::string>());  // a float's shortest exact text
        }
    }
    return frontend::Arguments(args, names.valued, names.flags);
}

}  // namespace fieldcvt::python
