#pragma once
// Strict command-line parsing: every malformed or out-of-range argument is a UsageError (exit
// code 2), so a typo never silently becomes a default.
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace fieldcvt::frontend {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

//! The options and positional arguments of one command. Options are `--name value`,
//! `--name=value` or, for flags, `--name`; `-h` means `--help`.
class Arguments {
public:
    //! `valued` and `flags` are the option names the command accepts (without "--").
    Arguments(const std::vector<std::string>& args, const std::set<std::string>& valued, const std::set<std::string>& flags);

    const std::vector<std::string>& positional() const { return positional_; }
    bool flag(const std::string& name) const { return flags_.count(name) > 0; }
    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::optional<std::string> text(const std::string& name) const;

    //! The option's value as an integer in [min, max], or `fallback` when absent.
    long long integer(const std::string& name, long long fallback, long long min, long long max) const;
    std::uint64_t unsignedInteger(const std::string& name, std::uint64_t fallback) const;
    //! Whether the lower bound of number() is itself allowed.
    enum class Bound { Inclusive, Exclusive };
    //! A finite number >= min (> min with Bound::Exclusive; NaN and infinities are refused).
    double number(const std::string& name, double fallback, double min = -std::numeric_limits<double>::infinity(),
                  Bound bound = Bound::Inclusive) const;
    //! An integer of any size, saturated to int's range: the core's parameter check
    //! (checkRemeshParams) says what range it takes.
    int saturatedInt(const std::string& name, int fallback) const;

private:
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
    std::set<std::string> flags_;
};

}  // namespace fieldcvt::frontend
