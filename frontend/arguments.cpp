#include "arguments.h"

#include "errors.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cmath>
#include <cstdlib>

namespace fieldcvt::frontend {

Arguments::Arguments(const std::vector<std::string>& args, const std::set<std::string>& valued,
                     const std::set<std::string>& flags)
{
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "-h") {
            flags_.insert("help");
            continue;
        }
        if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
            if (arg.size() > 1 && arg[0] == '-') throw UsageError("unknown option " + quoteInput(arg));
            positional_.push_back(arg);
            continue;
        }
        const std::size_t eq = arg.find('=');
        const std::string name = arg.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
        if (flags.count(name)) {
            if (eq != std::string::npos) throw UsageError("option '--" + name + "' takes no value");
            flags_.insert(name);
        } else if (valued.count(name)) {
            if (values_.count(name)) throw UsageError("option '--" + name + "' given twice");
            if (eq != std::string::npos) {
                values_[name] = arg.substr(eq + 1);
            } else {
                if (i + 1 >= args.size()) throw UsageError("option '--" + name + "' needs a value");
                values_[name] = args[++i];
            }
        } else {
            throw UsageError("unknown option " + quoteInput("--" + name));
        }
    }
}

std::optional<std::string> Arguments::text(const std::string& name) const
{
    const auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

namespace {

//! The whole of `s` as a decimal integer; `outOfRange` is set when it does not fit a long long (the
//! value is then saturated, as strtoll does). Throws a UsageError naming --name otherwise.
long long parseInteger(const std::string& name, const std::string& s, bool& outOfRange)
{
    char* end = nullptr;
    errno = 0;
    const long long n = std::strtoll(s.c_str(), &end, 10);
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0])) || *end != '\0')
        throw UsageError("--" + name + " expects an integer, got " + quoteInput(s));
    outOfRange = errno == ERANGE;
    return n;
}

}  // namespace

long long Arguments::integer(const std::string& name, long long fallback, long long min, long long max) const
{
    const auto value = text(name);
    if (!value) return fallback;
    bool outOfRange = false;
    const long long n = parseInteger(name, *value, outOfRange);
    if (outOfRange) throw UsageError("--" + name + " expects an integer, got " + quoteInput(*value));
    if (n < min || n > max)
        throw UsageError("--" + name + " must be between " + std::to_string(min) + " and " + std::to_string(max) + ", got " +
                         *value);
    return n;
}

int Arguments::saturatedInt(const std::string& name, int fallback) const
{
    const auto value = text(name);
    if (!value) return fallback;
    bool outOfRange = false;  // saturated, as int's range is below
    const long long n = parseInteger(name, *value, outOfRange);
    return static_cast<int>(std::clamp<long long>(n, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

std::uint64_t Arguments::unsignedInteger(const std::string& name, std::uint64_t fallback) const
{
    const auto value = text(name);
    if (!value) return fallback;
    const std::string& s = *value;
    char* end = nullptr;
    errno = 0;
    // strtoull accepts "-1" (as 2^64 - 1): only digits are a valid unsigned integer here.
    const std::uint64_t n = std::strtoull(s.c_str(), &end, 10);
    if (s.empty() || !std::isdigit(static_cast<unsigned char>(s[0])) || *end != '\0' || errno == ERANGE)
        throw UsageError("--" + name + " expects a non-negative integer, got " + quoteInput(s));
    return n;
}

double Arguments::number(const std::string& name, double fallback, double min, Bound bound) const
{
    const auto value = text(name);
    if (!value) return fallback;
    const std::string& s = *value;
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(s.c_str(), &end);
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0])) || *end != '\0' || errno == ERANGE || !std::isfinite(x))
        throw UsageError("--" + name + " expects a finite number, got " + quoteInput(s));
    if (x < min || (bound == Bound::Exclusive && x == min)) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", min);
        throw UsageError("--" + name + (bound == Bound::Exclusive ? " must be > " : " must be >= ") + text + ", got " + s);
    }
    return x;
}

}  // namespace fieldcvt::frontend
