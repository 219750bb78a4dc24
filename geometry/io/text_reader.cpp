#include "geometry/io/text_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "optim/errors.h"

namespace sa::io {
namespace {

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
}

std::string open_failure(const std::string& path, int error) {
    return path + ": cannot open (" + std::strerror(error) + ")";
}

}  // namespace

std::string quote(std::string_view token) {
    // Built by appending: `"'" + std::string(...)` trips GCC 12's -Wrestrict (bug 105329).
    const bool shorten = token.size() > 40;
    std::string quoted;
    quoted.reserve(44);
    quoted.push_back('\'');
    quoted.append(shorten ? token.substr(0, 37) : token);
    if (shorten) quoted.append("...");
    quoted.push_back('\'');
    return quoted;
}

std::string format_number(double value) {
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof text, value);
    return error == std::errc() ? std::string(text, end) : std::string("?");
}

std::string lower_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

std::string replace_extension(const std::string& path, const std::string& extension) {
    return std::filesystem::path(path).replace_extension(extension).string();
}

void check_readable(const std::string& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw InputError(open_failure(path, EISDIR));
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(open_failure(path, errno != 0 ? errno : ENOENT));
}

TextReader::TextReader(std::string path, bool hash_comments)
    : path_(std::move(path)), hash_comments_(hash_comments) {
    check_readable(path_);
    std::ifstream in(path_, std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw InputError(path_ + ": cannot read (" + std::strerror(errno) + ")");
    text_ = std::move(buffer).str();
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) position_ = 3;  // a UTF-8 byte-order mark
}

bool TextReader::next_line() {
    const bool found = advance();
    token_index_ = tokens_.size();  // next_token() continues on the next line
    return found;
}

bool TextReader::advance() {
    tokens_.clear();
    token_index_ = 0;
    while (position_ < text_.size()) {
        const std::size_t end = text_.find('\n', position_);
        const std::size_t stop = end == std::string::npos ? text_.size() : end;
        std::string_view raw(text_.data() + position_, stop - position_);
        position_ = end == std::string::npos ? text_.size() : end + 1;
        ++line_number_;
        for (std::size_t i = 0; i < raw.size(); ++i) {
            const auto c = static_cast<unsigned char>(raw[i]);
            if ((c < 0x20 && !is_space(raw[i])) || c == 0x7f) {
                char byte[8];
                std::snprintf(byte, sizeof byte, "0x%02x", c);
                fail("not a text file (byte " + std::string(byte) + " in column " +
                     std::to_string(i + 1) + "): a binary or compressed file?");
            }
        }
        comment_ = {};
        if (hash_comments_) {
            const std::size_t hash = raw.find('#');
            if (hash != std::string_view::npos) {
                comment_ = trim(raw.substr(hash + 1));
                raw = raw.substr(0, hash);
            }
        }
        line_ = trim(raw);
        if (line_.empty()) continue;
        std::size_t i = 0;
        while (i < line_.size()) {
            while (i < line_.size() && is_space(line_[i])) ++i;
            const std::size_t start = i;
            while (i < line_.size() && !is_space(line_[i])) ++i;
            if (i > start) tokens_.push_back(line_.substr(start, i - start));
        }
        return true;
    }
    line_ = {};
    comment_ = {};
    return false;
}

bool TextReader::next_token(std::string_view& token) {
    while (token_index_ >= tokens_.size()) {
        if (!advance()) return false;
    }
    token = tokens_[token_index_++];
    return true;
}

void TextReader::fail(const std::string& what) const {
    fail_at(line_number_, what);
}

void TextReader::fail_at(int line, const std::string& what) const {
    throw InputError(path_ + ":" + std::to_string(line) + ": " + what);
}

void TextReader::fail_file(const std::string& what) const {
    throw InputError(path_ + ": " + what);
}

double TextReader::to_double(std::string_view token, const char* what) const {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range)
        fail(std::string(what) + " " + quote(token) + " is out of the range of a double");
    if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
        fail(std::string("bad ") + what + " " + quote(token));
    if (!std::isfinite(value)) fail(std::string(what) + " " + quote(token) + " is not finite");
    return value;
}

long long TextReader::to_integer(std::string_view token, const char* what) const {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    long long value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range)
        fail(std::string(what) + " " + quote(token) + " is out of range");
    if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
        fail(std::string("expected an integer ") + what + ", found " + quote(token));
    return value;
}

long long TextReader::fitting(long long count, long long numbers_each) const {
    const auto remaining = static_cast<long long>(text_.size() - position_);
    if (numbers_each <= 0) return count;
    return std::max(0LL, std::min(count, (remaining + 1) / (2 * numbers_each)));
}

void TextReader::check_room(long long index, long long allocated, const char* what) const {
    if (index >= allocated) fail(std::string("more ") + what + " than the file can hold");
}

int TextReader::to_count(std::string_view token, const char* what) const {
    const long long value = to_integer(token, what);
    if (value < 0) fail(std::string(what) + " " + quote(token) + " is negative");
    if (value > std::numeric_limits<int>::max())
        fail(std::string(what) + " " + quote(token) + " is too large");
    return static_cast<int>(value);
}

}  // namespace sa::io
