#pragma once
// Line and token scanning for the text formats we parse ourselves (OBJ, OFF): LF or CRLF line
// ends, '#' comments, strict locale-independent numbers, and errors that name file and line.
#include <string>
#include <string_view>
#include <vector>

namespace fieldcvt::io_detail {

//! Strict, locale-independent: true if the whole token is one number (a leading '+' allowed).
//! A decimal that underflows (1e-400) reads as strtod reads it (0 or a subnormal); one that
//! overflows (1e400) is refused.
bool parseNumber(std::string_view token, double& value);

//! True if the whole token is a well-formed number outside double's range (underflow or overflow).
bool isOutOfRange(std::string_view token);

//! 3 if `text` starts with a UTF-8 byte order mark (which some Windows editors write), else 0.
std::size_t byteOrderMarkLength(std::string_view text);

class TextScanner {
public:
    //! A leading byte order mark is skipped. With `continuation` (OBJ), a line ending in a
    //! backslash goes on on the next line.
    TextScanner(const std::string& path, std::string_view text, bool continuation = false)
        : path_(path), text_(text), pos_(byteOrderMarkLength(text)), continuation_(continuation)
    {
    }

    //! Moves to the next line that has at least one token; false at the end of the text. The
    //! line number is that of the line's last part when it was continued.
    bool nextLine();
    const std::vector<std::string_view>& tokens() const { return tokens_; }
    int lineNumber() const { return line_; }

    //! The token as a number (the whole token must be one); fails naming the line otherwise.
    double number(std::string_view token) const;
    long long integer(std::string_view token) const;

    //! Throws IOError("<path>: line <n>: <what>").
    [[noreturn]] void fail(const std::string& what) const;

private:
    const std::string& path_;
    std::string_view text_;
    std::size_t pos_ = 0;
    bool continuation_ = false;
    int line_ = 0;
    std::vector<std::string_view> tokens_;
};

}  // namespace fieldcvt::io_detail
