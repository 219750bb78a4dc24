#pragma once
// Internal to geometry/io: reads a text file line by line and token by token, parses numbers
// strictly, and throws InputError messages of the form `FILE:LINE: what is wrong`.
//
// Lines are returned without their line ending (LF or CRLF), without a `#` comment (when
// comments are enabled) and without leading and trailing whitespace; blank lines are skipped. A
// UTF-8 byte-order mark at the start of the file is skipped. A line with a NUL byte or another
// control character than tab, CR, form feed or vertical tab is an error, `FILE:LINE: not a text
// file (...)`: a compressed or binary file read by mistake is named as such instead of being
// parsed (or skipped) as text.

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

    /// How many items of `numbers_each` numbers to allocate for `count` read from the file:
    /// `count`, or fewer when the rest of the file cannot hold that many (each number takes a
    /// character and a separator). Reading the items of such a file fails (the file ends, a row is
    /// short) before more are stored, with the message it would have had anyway, and a corrupt
    /// count never allocates more memory than the file's size.
    long long fitting(long long count, long long numbers_each) const;

    /// Throws `FILE:LINE: more WHAT than the file can hold` when `index` >= `allocated`: a guard
    /// where a reader stores item `index` in `allocated` rows from fitting() (never reached).
    void check_room(long long index, long long allocated, const char* what) const;

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

/// The shortest text that reads back as `value` ("0.3", "1e+308"), for messages.
std::string format_number(double value);

/// The file's extension in lower case, with its dot (".obj"), or "" when it has none.
std::string lower_extension(const std::string& path);

/// The path with its extension replaced by `extension` (which includes the dot).
std::string replace_extension(const std::string& path, const std::string& extension);

/// Throws InputError `FILE: cannot open (reason)` unless the file can be opened for reading.
void check_readable(const std::string& path);

}  // namespace sa::io
