#include "text_scan.h"

#include "errors.h"
#include "io_detail.h"

#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdlib>
#include <locale.h>

namespace fieldcvt::io_detail {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

//! from_chars rejects a leading '+', which some exporters write.
std::string_view dropPlus(std::string_view token) { return token.size() > 1 && token[0] == '+' ? token.substr(1) : token; }

}  // namespace

bool isOutOfRange(std::string_view token)
{
    const std::string_view t = dropPlus(token);
    double value = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    return ec == std::errc::result_out_of_range && end == t.data() + t.size();
}

bool parseNumber(std::string_view token, double& value)
{
    const std::string_view t = dropPlus(token);
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (end != t.data() + t.size()) return false;
    if (ec == std::errc()) return true;
    if (ec != std::errc::result_out_of_range) return false;
    // Well formed but out of double's range: an underflow (1e-400) is read as strtod reads it,
    // 0 or a subnormal of the right sign; an overflow (1e400) is not a finite coordinate.
    static const locale_t cLocale = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(0));
    const std::string copy(t);
    char* parsedEnd = nullptr;
    const double parsed = strtod_l(copy.c_str(), &parsedEnd, cLocale);
    if (parsedEnd != copy.c_str() + copy.size() || !std::isfinite(parsed)) return false;
    value = parsed;
    return true;
}

std::size_t byteOrderMarkLength(std::string_view text) { return text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0; }

bool TextScanner::nextLine()
{
    tokens_.clear();
    bool continued = false;
    while ((tokens_.empty() || continued) && pos_ < text_.size()) {
        std::size_t end = text_.find('\n', pos_);
        if (end == std::string_view::npos) end = text_.size();
        std::string_view line = text_.substr(pos_, end - pos_);
        pos_ = end + 1;
        ++line_;
        line = line.substr(0, line.find('#'));
        const std::size_t last = line.find_last_not_of(" \t\r\v\f");
        continued = continuation_ && last != std::string_view::npos && line[last] == '\\';
        if (continued) line = line.substr(0, last);
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && isSpace(line[i])) ++i;
            const std::size_t start = i;
            while (i < line.size() && !isSpace(line[i])) ++i;
            if (i > start) tokens_.push_back(line.substr(start, i - start));
        }
    }
    return !tokens_.empty();
}

double TextScanner::number(std::string_view token) const
{
    double value = 0;
    if (!parseNumber(token, value))
        fail((isOutOfRange(token) ? "number out of range (not a finite double) " : "malformed number ") + quoteInput(token));
    return value;
}

long long TextScanner::integer(std::string_view token) const
{
    const std::string_view t = dropPlus(token);
    long long value = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || end != t.data() + t.size()) fail("malformed integer " + quoteInput(token));
    return value;
}

void TextScanner::fail(const std::string& what) const { io_detail::fail(path_, "line " + std::to_string(line_) + ": " + what); }

}  // namespace fieldcvt::io_detail
