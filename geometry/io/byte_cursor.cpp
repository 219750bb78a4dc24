#include "geometry/io/byte_cursor.h"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "geometry/io/text_reader.h"
#include "optim/errors.h"

namespace sa::io {
namespace {

bool is_space(char c) {
    return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f' || c == '\v';
}

}  // namespace

ByteCursor::ByteCursor(std::string path) : path_(std::move(path)) {
    check_readable(path_);
    std::ifstream in(path_, std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw InputError(path_ + ": cannot read (" + std::strerror(errno) + ")");
    bytes_ = std::move(buffer).str();
}

std::string_view ByteCursor::next_token() {
    const int line = line_;
    while (position_ < bytes_.size() && is_space(bytes_[position_])) {
        if (bytes_[position_] == '\n') ++line_;
        ++position_;
    }
    if (position_ == bytes_.size()) line_ = line;
    const std::size_t begin = position_;
    while (position_ < bytes_.size() && !is_space(bytes_[position_])) ++position_;
    return std::string_view(bytes_).substr(begin, position_ - begin);
}

std::string_view ByteCursor::peek_token() {
    const std::size_t position = position_;
    const int line = line_;
    const std::string_view token = next_token();
    position_ = position;
    line_ = line;
    return token;
}

std::string_view ByteCursor::token(const std::string& what) {
    const std::string_view token = next_token();
    if (token.empty()) fail("the file ends where " + what + " belongs");
    return token;
}

std::string_view ByteCursor::rest_of_line() const {
    const std::size_t end = std::min(bytes_.find('\n', position_), bytes_.size());
    return std::string_view(bytes_).substr(position_, end - position_);
}

void ByteCursor::skip_line() {
    const std::size_t end = bytes_.find('\n', position_);
    position_ = end == std::string::npos ? bytes_.size() : end + 1;
    if (end != std::string::npos) ++line_;
}

std::uint64_t ByteCursor::read_bits(int bytes, bool big_endian) {
    std::uint64_t bits = 0;
    for (int b = 0; b < bytes; ++b) {
        const auto byte =
            static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[position_++]));
        bits |= big_endian ? byte << 8 * (bytes - 1 - b) : byte << 8 * b;
    }
    return bits;
}

double ByteCursor::binary_double(const BinaryType& type, bool big_endian) {
    const std::uint64_t bits = read_bits(type.bytes, big_endian);
    if (type.floating) {
        if (type.bytes == 4) {
            float value;
            const auto narrow = static_cast<std::uint32_t>(bits);
            std::memcpy(&value, &narrow, 4);
            return value;
        }
        double value;
        std::memcpy(&value, &bits, 8);
        return value;
    }
    const int shift = 64 - 8 * type.bytes;
    if (type.is_signed)
        return static_cast<double>(static_cast<std::int64_t>(bits << shift) >> shift);
    return static_cast<double>(bits);
}

std::int64_t ByteCursor::binary_integer(const BinaryType& type, bool big_endian,
                                        const std::string& what) {
    if (type.floating) fail(what + " holds floating-point values where whole numbers belong");
    const std::uint64_t bits = read_bits(type.bytes, big_endian);
    const int shift = 64 - 8 * type.bytes;
    if (type.is_signed) return static_cast<std::int64_t>(bits << shift) >> shift;  // sign-extended
    if (bits > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        fail(what + " holds a value out of range");
    return static_cast<std::int64_t>(bits);
}

double ByteCursor::to_double(std::string_view text, const std::string& what) const {
    double value = 0;
    const char* end = text.data() + text.size();
    const char* begin = text.data() + (!text.empty() && text[0] == '+' ? 1 : 0);
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (error != std::errc() || stop != end || text.empty())
        fail(what + " holds " + quoted_bytes(text) + " where a number belongs");
    return value;
}

long long ByteCursor::to_integer(std::string_view text, const std::string& what) const {
    long long value = 0;
    const char* end = text.data() + text.size();
    const char* begin = text.data() + (!text.empty() && text[0] == '+' ? 1 : 0);
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (error != std::errc() || stop != end || text.empty())
        fail(what + " holds " + quoted_bytes(text) + " where a whole number belongs");
    return value;
}

void ByteCursor::fail(const std::string& what) const {
    if (binary_) throw InputError(path_ + ": byte " + std::to_string(position_) + ": " + what);
    throw InputError(path_ + ":" + std::to_string(line_) + ": " + what);
}

std::string quoted_bytes(std::string_view token) {
    std::string text = "'";
    for (const char c : token.substr(0, 40)) {
        if (std::isprint(static_cast<unsigned char>(c)) != 0) {
            text.push_back(c);
        } else {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\x%02x", static_cast<unsigned char>(c));
            text.append(escape);
        }
    }
    return text + (token.size() > 40 ? "...'" : "'");
}

std::size_t first_control_byte(std::string_view bytes) {
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if ((c < 0x20 && !is_space(static_cast<char>(c))) || c == 0x7f) return i;
    }
    return std::string_view::npos;
}

std::string control_byte_message(std::string_view bytes, std::size_t offset) {
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(bytes[offset]));
    return std::string("not a text file (byte ") + byte + " at offset " + std::to_string(offset) +
           ")";
}

bool is_keyword(std::string_view token, std::string_view keyword) {
    if (token.size() != keyword.size()) return false;
    for (std::size_t i = 0; i < token.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(token[i])) != keyword[i]) return false;
    }
    return true;
}

}  // namespace sa::io
