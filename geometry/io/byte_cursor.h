#pragma once
// Internal to geometry/io: a whole file in memory, read as whitespace-separated ASCII tokens (with
// line numbers) or as binary values, for the formats that mix a text header with a text or binary
// body (legacy VTK, PLY). Errors are InputError `FILE:LINE: what` in text, `FILE: byte N: what`
// once the reader has switched to binary (line numbers mean nothing past binary data).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace sa::io {

/// A scalar type of a binary format: its size in bytes and how its bits are read.
struct BinaryType {
    int bytes = 4;
    bool floating = false;
    bool is_signed = true;
};

class ByteCursor {
  public:
    /// Reads the whole file; throws InputError `FILE: cannot open (reason)` when it cannot.
    explicit ByteCursor(std::string path);

    const std::string& path() const { return path_; }
    std::string_view bytes() const { return bytes_; }
    std::size_t position() const { return position_; }
    std::size_t remaining() const { return bytes_.size() - position_; }
    /// 1-based line of the last token read (of the last line with a token at the end).
    int line() const { return line_; }

    /// The next run of non-whitespace bytes, "" at the end of the file.
    std::string_view next_token();
    /// The next token without consuming it.
    std::string_view peek_token();
    /// The next token; fails `the file ends where WHAT belongs` at the end of the file.
    std::string_view token(const std::string& what);
    /// The text from the current position up to (not including) the next '\n'.
    std::string_view rest_of_line() const;
    /// Moves past the next '\n' (to the end of the file when there is none).
    void skip_line();

    /// From now on, errors name the byte offset instead of the line.
    void set_binary() { binary_ = true; }
    bool binary() const { return binary_; }
    /// The next value of `type` (big- or little-endian) as a double or an integer; the caller
    /// checks remaining() first. to_integer fails on a floating type or an unsigned value above
    /// the range of int64, naming `what`.
    double binary_double(const BinaryType& type, bool big_endian);
    std::int64_t binary_integer(const BinaryType& type, bool big_endian, const std::string& what);

    /// `text` as a number (std::from_chars, the whole token); fails `WHAT holds 'text' where a
    /// number belongs` (`a whole number` for integers).
    double to_double(std::string_view text, const std::string& what) const;
    long long to_integer(std::string_view text, const std::string& what) const;

    /// Throws `FILE:LINE: what` (text) or `FILE: byte N: what` (binary).
    [[noreturn]] void fail(const std::string& what) const;

  private:
    std::uint64_t read_bits(int bytes, bool big_endian);

    std::string path_;
    std::string bytes_;
    std::size_t position_ = 0;
    int line_ = 1;
    bool binary_ = false;
};

/// `'token'` for messages: at most 40 bytes, bytes that are not printable as \xNN.
std::string quoted_bytes(std::string_view token);

/// The offset of the first byte in `bytes` that is neither printable nor whitespace, or npos.
std::size_t first_control_byte(std::string_view bytes);

/// `not a text file (byte 0xNN at offset N)` for the byte at `offset`.
std::string control_byte_message(std::string_view bytes, std::size_t offset);

/// Whether `token` is `keyword` (given in lower case), whatever its case.
bool is_keyword(std::string_view token, std::string_view keyword);

}  // namespace sa::io
