#include "errors.h"

#include <cstdio>

namespace fieldcvt {

namespace {

bool isControl(unsigned char c) { return c < 0x20 || c == 0x7f; }

void appendEscaped(std::string& out, unsigned char c)
{
    char hex[5];
    std::snprintf(hex, sizeof hex, "\\x%02X", c);
    out += hex;
}

}  // namespace

std::string quoteInput(std::string_view text, std::size_t maxChars)
{
    std::string out = "'";
    std::size_t shown = 0;
    for (char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        const bool continuation = (c & 0xC0) == 0x80;  // a UTF-8 character is counted (and cut) whole
        if (!continuation && shown == maxChars) return out + "'...";
        if (isControl(c))
            appendEscaped(out, c);
        else
            out += ch;  // UTF-8 passes through: names in any script stay readable
        shown += continuation ? 0 : 1;
    }
    return out + "'";
}

std::string escapeControlCharacters(std::string_view message)
{
    std::string out;
    out.reserve(message.size());
    for (char ch : message) {
        const auto c = static_cast<unsigned char>(ch);
        if (isControl(c))
            appendEscaped(out, c);
        else
            out += ch;
    }
    return out;
}

}  // namespace fieldcvt
