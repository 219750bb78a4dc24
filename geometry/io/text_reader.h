#pragma once
// Internal to geometry/io: reads a text file line by line and token by token, parses numbers
// strictly, and throws InputError messages of the form `FILE:LINE: what is wrong`.
//
// Lines are returned without their line ending (LF or CRLF), without a `#` comment (when
// comments are enabled) and without leading and trailing whitespace; blank lines are skipped.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace sa::io {

class TextReader {
  public:
    /// Reads the whole file; throws InputError `FILE: cannot open (reason)` when it cannot.
    explicit TextReader(std::string path, bool hash_comments = true);

    /// Moves to the next non-blank line and splits it into tokens; false at the end of the file.
    bool next_line();
    /// The tokens of the current line.
    const std::vector<std::string_view>& tokens() const { return tokens_; }
    /// The current line (trimmed, without its comment).
    std::string_view line() const { return line_; }
    /// The comment of the current line (the text after `#`), empty when it has none.
    std::string_view comment() const { return comment_; }
    /// 1-based number of the current line (of the last token returned by next_token()).
    int line_number() const { return line_number_; }

    /// The next token, crossing lines; false at the end of the file. After next_line(), the
    /// next token is the first of the following line.
    bool next_token(std::string_view& token);
    /// True when every token of the current line has been consumed by next_token().
    bool line_consumed() const { return token_index_ >= tokens_.size(); }

    const std::string& path() const { return path_; }

    /// Throws InputError `FILE:LINE: what` for the current line.
    [[noreturn]] void fail(const std::string& what) const;
    /// Throws InputError `FILE:LINE: what` for the given line.
    [[noreturn]] void fail_at(int line, const std::string& what) const;
    /// Throws InputError `FILE: what` (no line known).
    [[noreturn]] void fail_file(const std::string& what) const;

    /// Parses a finite floating-point number; on failure throws naming `what` and the token.
    double to_double(std::string_view token, const char* what = "number") const;
    /// Parses an integer (no fraction, no exponent) in the range of long long.
    long long to_integer(std::string_view token, const char* what = "integer") const;
    /// Parses a count: a non-negative integer that fits in an int.
    int to_count(std::string_view token, const char* what = "count") const;

  private:
    bool advance();  // moves to the next non-blank line with token_index_ = 0

    std::string path_;
    std::string text_;
    std::size_t position_ = 0;
    bool hash_comments_;
    int line_number_ = 0;
    std::string_view line_;
    std::string_view comment_;
    std::vector<std::string_view> tokens_;
    std::size_t token_index_ = 0;
};

/// `'token'` quoted and shortened to at most 40 characters, for messages.
std::string quote(std::string_view token);

/// The file's extension in lower case, with its dot (".obj"), or "" when it has none.
std::string lower_extension(const std::string& path);

/// The path with its extension replaced by `extension` (which includes the dot).
std::string replace_extension(const std::string& path, const std::string& extension);

/// Throws InputError `FILE: cannot open (reason)` unless the file can be opened for reading.
void check_readable(const std::string& path);

}  // namespace sa::io
